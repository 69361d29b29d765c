"""What the live lab's worker processes do with a request: our image first, then the measurement.

A :class:`Job` carries the controls exactly as the page set them, the scene they apply to
(a :func:`lab.loading.load_scene` spec made by :mod:`lab.app.live.catalogue`: never a
string from the browser) and a request number. Each worker checks the controls again
with :func:`lab.app.live.controls.to_render` (the one edge) and draws:

- :func:`draw_ours`: our renderer only, the "break it" entry applied, as a PNG (fast:
  what the page shows first);
- :func:`measure`: the comparison run of ``scanlab compare``
  (:func:`compare.comparison.run_comparison`, VTK drawing the intact scene, our side
  broken if asked), VTK's image, the ΔE2000 map in the colours of the comparison panels
  (:func:`lab.app.lesson_site.figure_images.heat_map`), the ``metrics.json`` figures and the
  verdict; with ``stages``, the stage views of ``scanlab stages`` as well.

With a rule broken on purpose the verdict is judged as a scene meant to fail: "fails as
meant" when it misses a bar, "PASSES?" when the broken rule changed nothing visible.

PNGs are compressed lightly (:func:`lab.png.png_bytes` level 1): they cross a local
connection once, and time spent squeezing them is time before the image is on screen.
"""
from __future__ import annotations

import io
import time
from dataclasses import replace
from typing import NamedTuple

from lab.app.live.catalogue import load_spec
from lab.app.live.controls import Controls, controls_for, to_render
from lab.png import png_bytes
from lab.scene import SHADINGS

FAST_PNG = 1
"""zlib level of the PNGs sent to the page."""


class Job(NamedTuple):
    """One request: ``n`` its number (newer requests have larger numbers), the ``controls``,
    the ``spec`` of the scene they apply to, its ``name`` for the metrics, and whether the
    stage views are wanted."""

    n: int
    controls: Controls
    spec: str
    name: str
    stages: bool = False


def draw_ours(job: Job) -> dict:
    """Our image of ``job``: ``{"png": bytes, "ms": render time}``."""
    from renderer import render

    scene, options = to_render(job.controls, load_spec(job.spec)).ours()
    t0 = time.perf_counter()
    frame = render(scene, options)
    ms = (time.perf_counter() - t0) * 1e3
    return {"png": png_bytes(frame.rgb, FAST_PNG), "ms": ms}


def measure(job: Job) -> dict:
    """The comparison of ``job``: VTK's image, the ΔE2000 map, the metrics, the verdict
    (and the stage views when asked), with ``ms`` the time it took."""
    from compare.comparison import run_comparison
    from compare.metrics import coverage_masks
    from lab.app.lesson_site.figure_images import heat_map
    from renderer.breakages import BREAKAGES

    t0 = time.perf_counter()
    checked = to_render(job.controls, load_spec(job.spec))
    why = f"the rule broken on purpose: {BREAKAGES[checked.breakage].label['en']}" if checked.breakage else None
    result = run_comparison(checked.scene, name=job.name, timings=False, stages=job.stages, ours=checked.ours(),
                            meant=why)
    shared, mismatch = coverage_masks(result.ours_frame, result.reference_frame)
    out = {"vtk": png_bytes(result.reference, FAST_PNG),
           "delta_e": png_bytes(heat_map(result.delta_e, 5.0, mismatch, shared), FAST_PNG),
           "metrics": result.metrics, "stages": None}
    if job.stages:
        out["stages"] = stages_png(result)
    out["ms"] = (time.perf_counter() - t0) * 1e3
    return out


def stages_png(result) -> bytes:
    """The stage views of ``scanlab stages`` (:func:`compare.stages.stages_figure`) as PNG bytes."""
    from compare.stages import stages_figure

    buf = io.BytesIO()
    stages_figure(result.ours_frame, result.stages, result.reference_frame, buf,
                  culling=result.scene.render.cull_backfaces)
    return buf.getvalue()


WARM_SPEC = "icosphere:level=1"


def _warm_job(shading: str = "") -> Job:
    scene = load_spec(WARM_SPEC)
    return Job(0, replace(controls_for(scene, "shape:icosphere"), size="256x256", shading=shading), WARM_SPEC,
               "warm-up")


def warm_ours() -> None:
    """Load our renderer's compiled kernels (each shading's) before the first request."""
    for shading in SHADINGS:
        draw_ours(_warm_job(shading))


def warm_measure() -> None:
    """Load VTK (and open its offscreen context), the kernels and the metrics before the first request."""
    measure(_warm_job())
