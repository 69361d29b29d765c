"""The verdict of a comparison: does scanlab's image meet the parity bars against VTK's?

One judge for every comparison run — ``scanlab compare``, ``scanlab demo`` and the Python
API (:func:`compare.compare`) — so that they never disagree about a scene.

A *bar* names a figure of ``metrics.json`` and its largest allowed value; a value equal
to the bar passes. The figures a bar may name are the registry :data:`FIGURES`; the
default bars are :data:`PARITY_BARS`:

============================  ==========================================  =========
bar                           figure                                      default
============================  ==========================================  =========
``coverage_mismatch``         fraction 0..1 of *all* pixels drawn by one    0.0002
                              renderer only                                (0.02 %)
``pixels_over_1``             fraction 0..1 of the *shared* pixels with     0.002
                              ΔE2000 > 1                                   (0.2 %)
``mean``                      mean ΔE2000 over the shared pixels            0.1
============================  ==========================================  =========

More bars can be asked for (``p999``, ``max``, ``max_channel_diff``, ``depth_over_1_step``).

A scene may be *meant* to fail (:func:`meant_to_fail`): the painter's algorithm, or no
hidden-surface removal at all, against VTK's z-buffer. Its verdict is then "fails as
meant" when it misses a bar (an expected result, exit status 0) and "PASSES?" when it
does not (the demonstration shows nothing: exit status 1).

>>> v = judge({"coverage_mismatch": 0.0, "pixels_over_1": 0.58, "delta_e_2000": {"mean": 1.56}})
>>> v.status, v.failed[0]
('FAIL', 'pixels_over_1 0.58 > 0.002')
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, NamedTuple

from lab.suggest import did_you_mean


class Figure(NamedTuple):
    """A figure a bar can hold: how to read it from the metrics, and what it is."""

    read: Callable[[dict], float]
    meaning: str


FIGURES: dict[str, Figure] = {
    "coverage_mismatch": Figure(lambda m: m["coverage_mismatch"],
                                "fraction of all pixels that only one renderer drew"),
    "pixels_over_1": Figure(lambda m: m["pixels_over_1"], "fraction of the shared pixels with ΔE2000 > 1"),
    "mean": Figure(lambda m: m["delta_e_2000"]["mean"], "mean ΔE2000 over the shared pixels"),
    "p999": Figure(lambda m: m["delta_e_2000"]["p999"], "99.9th percentile of ΔE2000 over the shared pixels"),
    "max": Figure(lambda m: m["delta_e_2000"]["max"], "largest ΔE2000 of any shared pixel"),
    "max_channel_diff": Figure(lambda m: m["max_channel_diff"], "largest 8-bit difference of any channel"),
    "depth_over_1_step": Figure(lambda m: m["depth"]["over_1_step"],
                                "fraction of the shared pixels whose depths differ by more than one 24-bit step"),
}
"""Every figure a bar can name: its key in the bars, how to read it, what it means."""

PARITY_BARS: dict[str, float] = {"coverage_mismatch": 0.0002, "pixels_over_1": 0.002, "mean": 0.1}
"""The parity bars: coverage mismatch ≤ 0.02 % of all pixels, ΔE2000 > 1 on ≤ 0.2 % of
the shared pixels, mean ΔE2000 ≤ 0.1."""

PASS, FAIL, FAILS_AS_MEANT, PASSES_UNEXPECTEDLY = "pass", "FAIL", "fails as meant", "PASSES?"


def check_bars(bars: dict) -> dict[str, float]:
    """``bars`` with every name and value checked: a known figure, a finite number ≥ 0.

    Raises ValueError with a one-line message (and a "did you mean" for a misspelt name).
    """
    out = {}
    for name, value in bars.items():
        if name not in FIGURES:
            raise ValueError(f"unknown bar {name!r}{did_you_mean(name, FIGURES)}; bars: {', '.join(FIGURES)}")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise ValueError(f"bar {name}: expected a number, got {value!r}") from None
        if not 0.0 <= v < float("inf"):
            raise ValueError(f"bar {name}: expected a finite number of at least 0, got {value!r}")
        out[name] = v
    return out


def parse_bar(text: str) -> tuple[str, float]:
    """``"mean=0.2"`` → ``("mean", 0.2)``, checked (see :func:`check_bars`)."""
    name, eq, value = text.partition("=")
    if not eq:
        raise ValueError(f"expected NAME=VALUE such as mean=0.2, got {text!r}")
    (key, v), = check_bars({name.strip(): value.strip()}).items()
    return key, v


def failed_bars(metrics: dict, bars: dict | None = None) -> list[str]:
    """The bars ``metrics`` misses, each as ``"name value > bar"``; [] = every bar met.

    ``bars`` defaults to :data:`PARITY_BARS`. A bar whose figure the metrics lack (such
    as ``depth_over_1_step`` before the stages were compared) raises KeyError.
    """
    bars = PARITY_BARS if bars is None else bars
    found = {name: FIGURES[name].read(metrics) for name in bars}
    return [f"{name} {found[name]:.4g} > {bar:g}" for name, bar in bars.items() if found[name] > bar]


@dataclass(frozen=True)
class Verdict:
    """A judged comparison.

    failed : one ``"name value > bar"`` per missed bar (empty: every bar met).
    bars : the bars it was judged against.
    meant_to_fail : why the scene is made to fail against VTK, or None.
    """

    failed: tuple[str, ...]
    bars: dict = field(default_factory=lambda: dict(PARITY_BARS))
    meant_to_fail: str | None = None

    @property
    def met_bars(self) -> bool:
        """Whether the comparison met every bar."""
        return not self.failed

    @property
    def status(self) -> str:
        """"pass", "FAIL", "fails as meant" or "PASSES?" (a scene meant to fail that does not)."""
        if self.meant_to_fail:
            return PASSES_UNEXPECTEDLY if self.met_bars else FAILS_AS_MEANT
        return PASS if self.met_bars else FAIL

    @property
    def ok(self) -> bool:
        """Whether this is the expected outcome ("pass" or "fails as meant"): exit status 0."""
        return self.status in (PASS, FAILS_AS_MEANT)

    def line(self) -> str:
        """One line for a terminal or a caption: the status, then the bars missed."""
        text = self.status
        if self.failed:
            text += ": " + "; ".join(self.failed)
        elif self.meant_to_fail:
            text += ": every bar met"
        if self.meant_to_fail:
            text += f" (meant to fail: {self.meant_to_fail})"
        return text

    def to_json(self) -> dict:
        """What ``metrics.json`` holds under ``"verdict"``."""
        return {"status": self.status, "ok": self.ok, "met_bars": self.met_bars, "failed": list(self.failed),
                "bars": dict(self.bars), "meant_to_fail": self.meant_to_fail}


def judge(metrics: dict, bars: dict | None = None, meant_to_fail: str | None = None) -> Verdict:
    """The verdict on ``metrics`` (a ``metrics.json`` dict) against ``bars`` (default
    :data:`PARITY_BARS`); ``meant_to_fail`` says why the scene should fail (see
    :func:`meant_to_fail`)."""
    bars = dict(PARITY_BARS) if bars is None else check_bars(bars)
    return Verdict(failed=tuple(failed_bars(metrics, bars)), bars=bars, meant_to_fail=meant_to_fail)


def meant_to_fail(scene) -> str | None:
    """Why ``scene`` is made to fail against VTK, or None.

    VTK always removes hidden surfaces with its z-buffer, so a scene drawn with the
    painter's algorithm (or with none) shows where that algorithm breaks.
    """
    mode = scene.render.hidden_surface
    if mode == "zbuffer":
        return None
    return f'hidden_surface = "{mode}", while VTK always removes hidden surfaces with its z-buffer'
