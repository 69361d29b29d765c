"""Reading typed values out of one table of a scene file, with one-line errors.

The scene loader (:mod:`lab.loading`) and the CSG parser (:mod:`lab.csg.parse`) read
every value through :class:`Table`, so a problem reads the same wherever it is:
``file: table.key: message``, e.g. ``scene.toml: camera.view_angle: 0 is outside (0, 180)``.
The ``table`` part is the path to the table in the file (``light[1]``,
``object[0].csg.children[2]``); a table with no path (the top level) names the key alone.

Every number must be finite and within ±MAX_MAGNITUDE (:mod:`lab.values`), besides its
own range. Values are shown with :func:`lab.values.show`, so a message stays one short
line whatever the file holds.
"""
from __future__ import annotations

import math
from collections.abc import Iterable, Mapping

from lab.suggest import did_you_mean
from lab.values import MAX_MAGNITUDE, real, show

__all__ = ["REQUIRED", "SceneError", "Table", "quantise_colour"]


class SceneError(ValueError):
    """A scene file, shape name or option that cannot be used; the message says why."""


class _Required:
    def __repr__(self):
        return "REQUIRED"


REQUIRED = _Required()
"""A default meaning "the key must be given": a missing key is an error naming it."""


def quantise_colour(c) -> tuple[float, float, float]:
    """Round a linear 0..1 RGB colour to k/255, as ``vtkColor``/``pv.Color`` store it."""
    return tuple(round(float(x) * 255.0) / 255.0 for x in c)


class Table:
    """The values of one table (a dict) read from file ``source`` at path ``where``.

    ``table`` must be a mapping (anything else is the error "expected a table").

    ``allowed``, when given, are the keys the table may hold; any other key is an error
    with a "did you mean" hint (or the list of valid keys when nothing is close). A
    reader's ``default`` is used when the key is absent; :data:`REQUIRED` makes absence
    an error, and ``None`` (for vectors and colours) means "no value".
    """

    def __init__(self, source: str, where: str, table: Mapping, allowed: Iterable[str] | None = None):
        self.source, self.where, self.table = source, where, table
        if not isinstance(table, Mapping):
            raise self.error(None, f"expected a table, got {show(table)}")
        if allowed is not None:
            self.check_keys(allowed)

    def check_keys(self, allowed: Iterable[str]) -> None:
        """Refuse any key not in ``allowed``, naming it and the nearest allowed key."""
        allowed = sorted(allowed)
        for key in self.table:
            if key not in allowed:
                hint = (did_you_mean(key, allowed) if isinstance(key, str) else "") or f" (valid: {', '.join(allowed)})"
                raise self.error(key if str(key).isidentifier() else show(key, 40), f"unknown key{hint}")

    def error(self, key: str | None, message: str) -> SceneError:
        """The error for ``key`` of this table (``None``: the table itself)."""
        where = self.where if key is None else f"{self.where}.{key}" if self.where else key
        return SceneError(f"{self.source}: {where}: {message}" if self.source else f"{where}: {message}")

    def tables(self, key: str) -> list["Table"]:
        """The non-empty list of tables under ``key``, each named ``where.key[i]``."""
        v = self.table.get(key)
        if not isinstance(v, (list, tuple)) or not v:
            raise self.error(key, f"expected a non-empty list of tables, got {show(v)}")
        return [Table(self.source, f"{self.where}.{key}[{i}]", t) for i, t in enumerate(v)]

    def get(self, key, default):
        """The raw value of ``key``, or ``default`` when absent (:data:`REQUIRED`: an error)."""
        if key not in self.table and default is REQUIRED:
            raise self.error(None, f"missing key '{key}'")
        return self.table.get(key, default)

    def number(self, key, default, lo=-math.inf, hi=math.inf, lo_open=False, hi_open=False) -> float:
        """A finite number in [lo, hi] (an open end excludes its bound)."""
        raw = self.get(key, default)
        v = real(raw)
        if v is None:
            raise self.error(key, f"expected a number, got {show(raw)}")
        if not math.isfinite(v):
            raise self.error(key, f"must be finite, got {show(raw)}")
        lo, hi = max(lo, -MAX_MAGNITUDE), min(hi, MAX_MAGNITUDE)
        if v < lo or v > hi or (lo_open and v == lo) or (hi_open and v == hi):
            lb = "(" if lo_open else "["
            hb = ")" if hi_open else "]"
            raise self.error(key, f"{v:g} is outside {lb}{lo:g}, {hi:g}{hb}")
        return v

    def vector(self, key, default, n=3, lo=-math.inf, hi=math.inf, lo_open=False) -> tuple[float, ...] | None:
        """A list of ``n`` finite numbers, each in [lo, hi] (``lo_open``: above lo), as a tuple of floats."""
        v = self.get(key, default)
        if v is None:
            return None
        if not isinstance(v, (list, tuple)) or len(v) != n:
            raise self.error(key, f"expected a list of {n} numbers, got {show(v)}")
        lo, hi = max(lo, -MAX_MAGNITUDE), min(hi, MAX_MAGNITUDE)
        out = []
        for x in map(real, v):
            if x is None or not math.isfinite(x):
                raise self.error(key, f"expected {n} finite numbers, got {show(v)}")
            if x < lo or x > hi or (lo_open and x == lo):
                raise self.error(key, f"values must lie in {'(' if lo_open else '['}{lo:g}, {hi:g}], got {show(v)}")
            out.append(x)
        return tuple(out)

    def colour(self, key, default) -> tuple[float, float, float] | None:
        """A linear RGB colour of three numbers in [0, 1], quantised to k/255."""
        c = self.vector(key, default, 3, 0.0, 1.0)
        return None if c is None else quantise_colour(c)

    def flag(self, key, default) -> bool:
        """``true`` or ``false`` (a number is not a flag)."""
        v = self.get(key, default)
        if not isinstance(v, bool):
            raise self.error(key, f"expected true or false, got {show(v)}")
        return v

    def choice(self, key, default, choices, noun: str | None = None) -> str:
        """One of the strings ``choices``.

        The message says ``'x' is not one of a, b``; with a ``noun`` (what the value
        names: "op", "primitive") it says ``unknown op 'x'; valid: a, b``.
        """
        v = self.get(key, default)
        if not isinstance(v, str) or v not in choices:
            hint = did_you_mean(v, choices) if isinstance(v, str) else ""
            if noun:
                raise self.error(key, f"unknown {noun} {show(v)}{hint}; valid: {', '.join(choices)}")
            raise self.error(key, f"{show(v)} is not one of {', '.join(choices)}{hint}")
        return v
