"""What a comparison run reports: the labels that name a run (model, shading, reference),
its one-line summary, the files it writes (:data:`OUTPUT_FILES`) and ``metrics.json``.

The run itself, both renderers measured and judged, is :mod:`compare.comparison`
(:func:`compare.comparison.compare_scene` writes these files into a folder).
"""
from __future__ import annotations

import json
import time
from pathlib import Path

from compare.textbook_reference import scene_reference, uses_separate_specular
from lab.atomic import write_text

OUTPUT_FILES = ("ours.png", "vtk.png", "delta_e.png", "side_by_side.png", "metrics.json")
"""The files :func:`compare.comparison.compare_scene` writes into its folder (and ``stages.png`` with the stages)."""


def timed_render(scene, warm: bool = True):
    """scanlab's render of ``scene`` and its time in ms (a warm call: kernels loaded)."""
    from renderer import render

    if warm:
        render(scene)
    t0 = time.perf_counter()
    frame = render(scene)
    return frame, (time.perf_counter() - t0) * 1e3


def shading_label(scene) -> str:
    """The scene's shading mode, or "mixed" when its objects differ."""
    modes = {o.shading for o in scene.objects}
    return modes.pop() if len(modes) == 1 else "mixed"


def model_label(scene) -> str:
    """The scene's reflection model, or "mixed" when its objects differ."""
    models = {o.material.model for o in scene.objects}
    return models.pop() if len(models) == 1 else "mixed"


def write_json(path: Path, data: dict) -> None:
    """Write JSON atomically (:func:`lab.atomic.atomic_file`): a temporary file, then a rename."""
    write_text(path, json.dumps(data, indent=2) + "\n")


def reference_label(scene, reference: str | None = None) -> str:
    """The reference's name for ``metrics.json``: :func:`compare.textbook_reference.scene_reference`,
    with ``+separate-specular`` when opengl objects have their specular colour added after
    the texture (a float vertex attribute or the replaced shader's own term, added after
    VTK's texture modulation in the same render)."""
    name = scene_reference(scene, reference)
    separate = any(uses_separate_specular(o, scene) for o in scene.objects)
    return name + "+separate-specular" if separate and name != "vtk-native" else name


def summary_line(m: dict) -> str:
    """One line for the terminal: the figures of a ``metrics.json`` dict."""
    de = m["delta_e_2000"]
    line = (f"{m['scene']} [{m['model']}/{m['shading']} vs {m['reference']}]: ΔE2000 mean {de['mean']:.3f}, "
            f"p99.9 {de['p999']:.2f}, max {de['max']:.2f}; over 1: {100 * m['pixels_over_1']:.3f} %; "
            f"coverage mismatch {100 * m['coverage_mismatch']:.3f} %; max channel diff {m['max_channel_diff']}")
    if m.get("depth"):
        line += f"; depth max {m['depth']['max_steps']} step(s)"
    if m.get("ours_ms") is not None and m.get("reference_ms") is not None:
        line += f"; ours {m['ours_ms']:.1f} ms, VTK {m['reference_ms']:.1f} ms"
    return line
