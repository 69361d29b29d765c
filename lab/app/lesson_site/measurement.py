"""Measuring one lesson figure: our renderer and VTK on the same scene, and the verdict.

This is the one place where the lesson site calls the renderers and the metrics
(:func:`measure_figure`); the figure directive, the plots and ``scanlab lessons
measure`` all go through it, so a figure on a page and the command printed under it
give the same numbers.

A figure is a :class:`FigureSpec`: a scene file, optional overrides (shading, model),
an optional "break it" entry (:mod:`renderer.breakages`) applied to *our* side only,
and an optional forced reference (``"vtk-native"``: VTK's own lighting for every
object). Its expectation is ``"pass"`` (the parity bars hold) or ``"fail"`` (they must
not: every "break it" figure, and contrasts such as textbook Gouraud against VTK's
per-pixel lighting).
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

import numpy as np

EXPECTATIONS = ("pass", "fail")


@dataclass(frozen=True)
class FigureSpec:
    """What to draw and measure.

    scene : path of the scene file (TOML).
    shading, model : overrides for every object (None: as the file says).
    breakage : a key of :data:`renderer.breakages.BREAKAGES`, applied to our render only.
    reference : None (VTK's render the comparison run picks) or "vtk-native".
    expectation : "pass" or "fail" to state the verdict a lesson promises (None: :attr:`expect`).
    """

    scene: str
    shading: str | None = None
    model: str | None = None
    breakage: str | None = None
    reference: str | None = None
    expectation: str | None = None

    @property
    def expect(self) -> str:
        """``expectation`` when given; else "fail" for a "break it" figure or a forced native
        reference (VTK's lighting against a textbook model), "pass" otherwise."""
        if self.expectation:
            return self.expectation
        return "fail" if self.breakage or self.reference else "pass"


class Measurement(NamedTuple):
    """Both frames, the ΔE2000 map and masks, the metrics and the verdict of one figure.

    ours, ref : :class:`lab.frame.Frame` (rgb (H, W, 3) uint8 row 0 at the top, depth, coverage).
    de : (H, W) float ΔE2000, 0 where coverage is not shared; shared, mismatch : (H, W) bool.
    metrics : :func:`compare.metrics.compare_frames`'s dict plus ``"reference"`` (its name)
        and ``"failed_bars"`` (the parity bars missed, [] = pass).
    """

    ours: object
    ref: object
    de: np.ndarray
    shared: np.ndarray
    mismatch: np.ndarray
    metrics: dict


def load(spec: FigureSpec):
    """The scene of ``spec`` with its overrides (the intact scene VTK draws)."""
    from lab.loading import load_scene

    return load_scene(spec.scene).with_overrides(shading=spec.shading, model=spec.model)


def measure_figure(spec: FigureSpec) -> Measurement:
    """Draw ``spec`` with our renderer (broken if asked) and with VTK (intact); measure."""
    from compare.metrics import compare_frames, coverage_masks, failed_bars
    from compare.reference import render_reference
    from compare.report import reference_label
    from renderer import RenderOptions, render
    from renderer.breakages import apply_breakage

    scene = load(spec)
    ours_scene, options = scene, RenderOptions()
    if spec.breakage:
        ours_scene, options = apply_breakage(spec.breakage, scene, options)
    ours = render(ours_scene, options)
    ref = render_reference(scene, reference=spec.reference)
    metrics, de = compare_frames(ours, ref)
    shared, mismatch = coverage_masks(ours, ref)
    metrics = {**metrics, "reference": reference_label(scene, spec.reference), "failed_bars": failed_bars(metrics)}
    return Measurement(ours, ref, de, shared, mismatch, metrics)


def judged(metrics: dict, expect: str):
    """The comparison run's verdict (:class:`compare.verdict.Verdict`) on a figure's metrics;
    a figure expected to fail is judged as a scene meant to fail."""
    from compare.verdict import Verdict

    why = "the lesson breaks a rule, or contrasts two models, on purpose" if expect == "fail" else None
    return Verdict(failed=tuple(metrics["failed_bars"]), meant_to_fail=why)


def verdict(metrics: dict, expect: str) -> str:
    """"pass" (passes, as it should), "fails as meant", or the surprise: "FAIL" / "PASSES?"."""
    return judged(metrics, expect).status


def as_expected(metrics: dict, expect: str) -> bool:
    """Whether a figure's verdict is the one the lesson promises (``Verdict.ok``)."""
    return judged(metrics, expect).ok


def command(spec: FigureSpec, root: Path, out: str = "out/figure") -> str:
    """The command that reproduces ``spec`` from the repository root ``root``.

    ``scanlab compare`` when our side is the intact pipeline; ``scanlab lessons measure``
    (the same measurement as the page, with ``--break``) when a rule is broken on purpose.
    """
    try:
        scene = Path(spec.scene).resolve().relative_to(root).as_posix()
    except ValueError:
        scene = Path(spec.scene).name
    words = ["scanlab", "lessons measure" if spec.breakage else "compare", scene]
    for flag, value in (("--shading", spec.shading), ("--model", spec.model), ("--break", spec.breakage),
                        ("--reference", spec.reference)):
        if value:
            words += [flag, value]
    return " ".join(words + ["--out", out])
