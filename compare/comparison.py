"""One comparison, in memory: both renders, the ΔE2000 map, the figures and the verdict.

:func:`run_comparison` draws a scene with scanlab's renderer and with VTK and measures
them; the :class:`Comparison` it returns can write the files of ``scanlab compare``
(:meth:`Comparison.write`), show itself in a notebook (``_repr_png_``, ``_repr_html_``)
and carries ``metrics`` — exactly what ``metrics.json`` holds — and the ``verdict``
(:mod:`compare.verdict`). :func:`compare` is the Python API's front door: it takes a
scene, a scene name (preset, shape, file) or a PyVista ``Plotter``.
"""
from __future__ import annotations

import base64
import html
import io
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from compare.images import PanelText, delta_e_figure, side_by_side_figure
from compare.metrics import compare_frames, coverage_masks
from compare.report import OUTPUT_FILES, model_label, reference_label, shading_label, summary_line, timed_render, \
    write_json
from compare.stages import STAGE_FILES, depth_metrics, stages_figure
from compare.textbook_reference import uses_separate_specular
from compare.verdict import Verdict, judge, meant_to_fail
from compare.worst import pixel_report, worst_pixels
from lab.atomic import atomic_file
from lab.frame import Frame
from lab.png import write_png

def settings_line(scene, reference: str, **shown) -> str:
    """The settings that made a comparison's images, as one line for its panel.

    Model and shading ("mixed" when objects differ), interpolation, hidden-surface
    removal, back-face culling, transparency (when an object is translucent), separate
    specular (when it applies), the reference, the image size, lights and objects.
    ``shown`` replaces a part's value (``interpolation="screen | perspective"`` for a
    figure whose two images differ in it).
    """
    r = scene.render
    lights = sum(1 for li in scene.lights if li.on)
    w, h = scene.image.size
    parts = {"model": model_label(scene), "shading": shading_label(scene), "interpolation": r.interpolation,
             "hidden surfaces": r.hidden_surface, "back faces": "culled" if r.cull_backfaces else "drawn"}
    if any(o.material.opacity < 1.0 for o in scene.objects):
        parts["transparency"] = r.transparency
    if any(uses_separate_specular(o, scene) for o in scene.objects):
        parts["specular colour"] = "separate"
    parts["reference"] = reference
    parts.update({k.replace("_", " "): v for k, v in shown.items()})
    n = len(scene.objects)
    return " · ".join([f"{k} {v}" for k, v in parts.items()]
                      + [f"{w}×{h} px", f"{n} object{'s' * (n != 1)}, {lights} light{'s' * (lights != 1)} on"])


@dataclass(eq=False)
class Comparison:
    """Both renders of one scene, measured and judged.

    Attributes
    ----------
    scene : the :class:`lab.scene.Scene` drawn.
    name : its name in titles and ``metrics.json``.
    ours_frame, reference_frame : the two :class:`lab.frame.Frame` (rgb, depth, coverage).
    delta_e : (H, W) float, ΔE2000 per pixel, 0 where coverage is not shared.
    metrics : the ``metrics.json`` dict (see the README), ``"verdict"`` and ``"depth"`` included.
    verdict : the :class:`compare.verdict.Verdict`.
    stages : our :class:`renderer.Stages` when asked for (``stages=True``), else None.
    """

    scene: object
    name: str
    ours_frame: Frame
    reference_frame: Frame
    delta_e: np.ndarray
    metrics: dict
    verdict: Verdict
    stages: object = None
    settings: str = ""
    _png: bytes | None = field(default=None, repr=False)

    @property
    def ours(self) -> np.ndarray:
        """(H, W, 3) uint8, scanlab's image, row 0 at the top."""
        return self.ours_frame.rgb

    @property
    def reference(self) -> np.ndarray:
        """(H, W, 3) uint8, VTK's image, row 0 at the top."""
        return self.reference_frame.rgb

    @property
    def passed(self) -> bool:
        """Whether the two images met every bar (a scene meant to fail has ``passed`` False
        and ``verdict.ok`` True)."""
        return self.verdict.met_bars

    def _panel(self, target) -> None:
        shared, mismatch = coverage_masks(self.ours_frame, self.reference_frame)
        side_by_side_figure(self.ours, self.reference, self.delta_e, mismatch, self.metrics, target,
                            PanelText(title=self.name, settings=self.settings, verdict=self.verdict.line()),
                            shared=shared, coverage=(self.ours_frame.coverage, self.reference_frame.coverage))

    def panel_png(self) -> bytes:
        """The side-by-side panel as PNG bytes (made once)."""
        if self._png is None:
            buf = io.BytesIO()
            self._panel(buf)
            self._png = buf.getvalue()
        return self._png

    def _repr_png_(self) -> bytes:
        return self.panel_png()

    def _repr_html_(self) -> str:
        colour = "#070" if self.verdict.ok else "#c00"
        image = base64.b64encode(self.panel_png()).decode("ascii")
        return (f"<div><p style='font-weight:bold;color:{colour}'>{html.escape(self.verdict.line())}</p>"
                f"<p>{html.escape(summary_line(self.metrics))}</p>"
                f"<img src='data:image/png;base64,{image}' style='max-width:100%' "
                f"alt='{html.escape(self.name)}: scanlab, VTK and ΔE2000'></div>")

    def write(self, out_dir) -> Path:
        """Write the five files of ``scanlab compare`` (and ``stages.png`` when the stages
        were kept) into ``out_dir``, created if missing; return the folder."""
        out = Path(out_dir)
        out.mkdir(parents=True, exist_ok=True)
        shared, mismatch = coverage_masks(self.ours_frame, self.reference_frame)
        write_png(out / "ours.png", self.ours)
        write_png(out / "vtk.png", self.reference)
        delta_e_figure(self.delta_e, mismatch, out / "delta_e.png", shared=shared)
        if self._png is not None:  # already made for a notebook: the same bytes
            with atomic_file(out / "side_by_side.png") as f:
                f.write(self._png)
        else:
            self._panel(out / "side_by_side.png")
        if self.stages is not None:
            stages_figure(self.ours_frame, self.stages, self.reference_frame, out / STAGE_FILES[0],
                          title=f"{self.name}: the stages before the colours",
                          culling=self.scene.render.cull_backfaces)
        write_json(out / "metrics.json", self.metrics)
        return out


def run_comparison(scene, name: str | None = None, reference: str | None = None, bars: dict | None = None,
                   stages: bool = False, timings: bool = True, ours: tuple | None = None,
                   meant: str | None = None) -> Comparison:
    """Draw ``scene`` both ways, measure and judge it (nothing is written).

    Parameters
    ----------
    scene : :class:`lab.scene.Scene`.
    name : its name in ``metrics.json`` and titles (default: ``scene.source``).
    reference : None (per object: VTK's own shading, or the textbook references) or
        "vtk-native" (VTK's own shading for every object).
    bars : the bars to judge against (default :data:`compare.verdict.PARITY_BARS`).
    stages : keep our stage buffers (:func:`renderer.render_stages`) for ``stages.png``.
    timings : time one warm frame of each renderer (``ours_ms``, ``reference_ms``; each
        side draws twice). Without, both keys are None.
    ours : (scene, :class:`renderer.RenderOptions`) for our renderer instead of (``scene``,
        the default options): a "break it" entry (:mod:`renderer.breakages`) breaks our side
        only, while VTK draws ``scene`` intact.
    meant : why our side is made to fail on purpose (e.g. the rule ``ours`` breaks), judged
        as :func:`compare.verdict.meant_to_fail` is for the scene; None: only that.
    """
    from compare.reference import render_reference
    from renderer import RenderOptions, render, render_stages

    ours_scene, options = ours if ours is not None else (scene, RenderOptions())
    ours, kept = render_stages(ours_scene, options) if stages else (None, None)
    ours_ms = None
    if timings:
        frame, ours_ms = timed_render(ours_scene, options=options)
        ours = frame if ours is None else ours
    elif ours is None:
        ours = render(ours_scene, options)
    clock: dict = {}
    ref = render_reference(scene, timings=clock if timings else None, reference=reference)
    figures, de = compare_frames(ours, ref)
    ref_name = reference_label(scene, reference)
    metrics = {"scene": name or scene.source, "shading": shading_label(scene), "size": list(scene.image.size),
               **figures, "depth": depth_metrics(ours.depth, ref.depth),
               "ours_ms": None if ours_ms is None else round(ours_ms, 3),
               "reference_ms": round(clock["reference_ms"], 3) if "reference_ms" in clock else None,
               "model": model_label(scene), "reference": ref_name}
    metrics["worst_pixel"] = worst_pixel(ours, ref, de)
    verdict = judge(metrics, bars, meant or meant_to_fail(scene))
    metrics["verdict"] = verdict.to_json()
    return Comparison(scene=scene, name=metrics["scene"], ours_frame=ours, reference_frame=ref, delta_e=de,
                      metrics=metrics, verdict=verdict, stages=kept, settings=settings_line(scene, ref_name))


def worst_pixel(ours: Frame, ref: Frame, de: np.ndarray) -> dict | None:
    """The worst pixel (:func:`compare.worst.worst_pixels`) for ``metrics.json``: x (column),
    y (row from the top), both 8-bit colours, ΔE2000, coverage and a one-line caption;
    None when the two images are identical."""
    _, mismatch = coverage_masks(ours, ref)
    marks = worst_pixels(de, mismatch, 1)
    if not marks:
        return None
    p = pixel_report(ours.rgb, ref.rgb, de, ours.coverage, ref.coverage, *marks[0])
    return {"x": p.col, "y": p.row, "ours": list(p.ours), "reference": list(p.reference),
            "delta_e": round(p.delta_e, 4), "coverage": p.coverage, "caption": p.caption()}


def compare_scene(scene, out_dir, name: str | None = None, reference: str | None = None, bars: dict | None = None,
                  stages: bool = False) -> dict:
    """Render ``scene`` both ways, measure, judge, write the five output files; return the metrics.

    The metrics dict is what ``metrics.json`` holds (see the README): scene, shading,
    size, delta_e_2000 {mean, median, p95, p99, p999, max}, pixels_over_1,
    coverage_mismatch, max_channel_diff, depth, ours_ms, reference_ms, model, the
    reference used (picked per object by :func:`compare.textbook_reference.object_reference`;
    ``reference="vtk-native"`` forces VTK's own shading everywhere) and the verdict
    against ``bars`` (:mod:`compare.verdict`). ``stages`` adds ``stages.png``.
    """
    result = run_comparison(scene, name=name, reference=reference, bars=bars, stages=stages)
    result.write(out_dir)
    return result.metrics


def compare(scene_or_plotter, *, name: str | None = None, shading: str | None = None,
            size: tuple[int, int] | None = None, model: str | None = None, reference: str | None = None,
            bars: dict | None = None, stages: bool = False, timings: bool = True) -> Comparison:
    """Draw a scene with scanlab and with VTK, measure and judge: the Python API.

    Parameters
    ----------
    scene_or_plotter : a :class:`lab.scene.Scene`; a preset name, built-in shape spec,
        scene file or mesh file (as ``scanlab compare`` takes); or a PyVista ``Plotter``
        (converted by :func:`compare.from_plotter.scene_from_plotter`).
    name : the name in titles and metrics (default: where the scene came from).
    shading, size, model : override every object's shading ("flat", "gouraud",
        "phong"), the image size (width, height) and every object's reflection model.
    reference : "vtk-native" forces VTK's own shading for every object.
    bars : the bars to judge against, e.g. ``{"mean": 0.05, "p999": 1.0}``.
    stages : keep our stage buffers (``Comparison.stages``; ``write`` adds ``stages.png``).
    timings : time a warm frame of each renderer (each then draws twice).

    Returns
    -------
    :class:`Comparison`: ``ours`` and ``reference`` (H×W×3 uint8), ``metrics``,
    ``verdict``, ``passed``; in a notebook it shows its panel.

    Examples
    --------
    >>> import compare
    >>> result = compare.compare("cube", size=(160, 120), timings=False)   # doctest: +SKIP
    >>> result.passed, result.ours.shape                                    # doctest: +SKIP
    (True, (120, 160, 3))
    """
    scene = _as_scene(scene_or_plotter)
    scene = scene.with_overrides(shading=shading, size=size, model=model)
    return run_comparison(scene, name=name, reference=reference, bars=bars, stages=stages, timings=timings)


def _as_scene(thing):
    from lab.scene import Scene

    if isinstance(thing, Scene):
        return thing
    if isinstance(thing, (str, Path)):
        from lab.loading import load_scene

        return load_scene(thing)
    if hasattr(thing, "renderer") and hasattr(thing, "ren_win"):
        from compare.from_plotter import scene_from_plotter

        return scene_from_plotter(thing)
    raise TypeError(f"expected a Scene, a scene name or file, or a PyVista Plotter; got {type(thing).__name__}")
