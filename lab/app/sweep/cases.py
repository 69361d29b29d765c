"""The cases of a sweep: every source crossed with every combination of the grid's values.

A grid maps grid keys (:mod:`lab.app.sweep.settings`) to lists of values. It comes from
``--grid KEY=V1,V2`` options and from a grid file (TOML), whose top-level keys are grid keys
(a value or a list of values) plus an optional ``sources`` list (paths relative to the file):

.. code-block:: toml

    sources = ["meshes/", "cube", "icosphere:level=3"]
    shading = ["flat", "gouraud", "phong"]
    lights = ["headlight", "key-fill", "spot"]
    size = "256x192"

A key given with ``--grid`` replaces the file's values for that key.

A case's identity (:attr:`Case.case_id`) is a hash of its source's key and its settings'
canonical texts, so a sweep run again with the same ``--out`` knows which cases it has
finished, whatever order they were listed or typed in.
"""
from __future__ import annotations

import difflib
import hashlib
import itertools
import json
import tomllib
from dataclasses import dataclass
from pathlib import Path

from lab.app.sweep.settings import grid_keys
from lab.app.sweep.sources import Source


class GridError(ValueError):
    """A grid option or grid file that cannot be used; the message is one line."""


@dataclass(frozen=True)
class Case:
    """One comparison: a source and its settings (grid key → canonical value, in grid order)."""

    source: Source
    settings: tuple[tuple[str, str], ...]

    @property
    def case_id(self) -> str:
        """16 hex digits of SHA-256 over the source key and the settings (sorted JSON)."""
        text = json.dumps({"source": self.source.key, "settings": dict(self.settings)}, sort_keys=True)
        return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]

    @property
    def label(self) -> str:
        """``name shading=flat lights=key`` (the source's short name, then the settings)."""
        return " ".join([self.source.name, *(f"{k}={v}" for k, v in self.settings)])


def _key(name: str, where: str):
    keys = grid_keys()
    if name not in keys:
        near = difflib.get_close_matches(name, list(keys), n=1)
        hint = f"did you mean {near[0]}? " if near else ""
        raise GridError(f"{where}: unknown grid key {name!r} ({hint}keys: {', '.join(keys)})")
    return keys[name]


def _values(name: str, texts: list[str], where: str) -> list[str]:
    key = _key(name, where)
    values: list[str] = []
    for text in texts:
        try:
            value = key.parse(text.strip())
        except ValueError as exc:
            raise GridError(f"{where}: {name}: {exc}") from None
        if value not in values:
            values.append(value)
    if not values:
        raise GridError(f"{where}: {name}: no values")
    return values


def parse_grid_option(text: str) -> tuple[str, list[str]]:
    """``"shading=flat,phong"`` → ``("shading", ["flat", "phong"])``, every value checked."""
    name, eq, rest = text.partition("=")
    if not eq:
        raise GridError(f"--grid {text!r}: expected KEY=V1,V2,... such as shading=flat,phong")
    return name.strip(), _values(name.strip(), rest.split(","), "--grid")


def read_grid_file(path: str | Path) -> tuple[dict[str, list[str]], list[str]]:
    """A grid file's grid and its ``sources`` (made relative to the current folder)."""
    path = Path(path)
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise GridError(f"{path}: cannot read: {exc.strerror or exc}") from None
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise GridError(f"{path}: not a TOML grid file: {exc}") from None
    sources = data.pop("sources", [])
    if not isinstance(sources, list) or not all(isinstance(s, str) for s in sources):
        raise GridError(f"{path}: sources: expected a list of file names, folders, presets or shapes")
    grid = {}
    for name, raw in data.items():
        raw = raw if isinstance(raw, list) else [raw]
        if not all(isinstance(v, (str, int, float)) and not isinstance(v, bool) for v in raw):
            raise GridError(f"{path}: {name}: expected a value or a list of values, got {raw!r}")
        grid[name] = _values(name, [str(v) for v in raw], str(path))
    return grid, [str(path.parent / s) if (path.parent / s).exists() else s for s in sources]


def build_grid(file_grid: dict[str, list[str]], options: list[str]) -> dict[str, list[str]]:
    """The grid file's grid with each ``--grid`` option's key replaced (a key twice on the
    command line is an error)."""
    grid = dict(file_grid)
    seen = set()
    for text in options:
        name, values = parse_grid_option(text)
        if name in seen:
            raise GridError(f"--grid {name}: given twice; list every value once, as {name}=A,B")
        seen.add(name)
        grid[name] = values
    return grid


def expand(sources: list[Source], grid: dict[str, list[str]]) -> list[Case]:
    """Every source × every combination of the grid's values: sources outermost, keys in
    :func:`lab.app.sweep.settings.grid_keys` order (the last key varies fastest)."""
    names = [k for k in grid_keys() if k in grid]
    combos = list(itertools.product(*(grid[k] for k in names)))
    return [Case(source, tuple(zip(names, combo))) for source in sources for combo in combos]
