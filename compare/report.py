"""One comparison run: both renderers, the verdict, the files a person opens.

:func:`compare_scene` draws a scene with scanlab's renderer and with VTK, measures them
(:mod:`compare.metrics`) and writes ``ours.png``, ``vtk.png``, ``delta_e.png``,
``side_by_side.png`` and ``metrics.json`` into a folder.
"""
from __future__ import annotations

import json
import time
from pathlib import Path

from compare.images import delta_e_figure, side_by_side_figure
from lab.png import write_png
from compare.metrics import compare_frames, coverage_masks
from compare.reference import render_reference
from compare.textbook_reference import scene_reference, uses_separate_specular
from lab.atomic import write_text

OUTPUT_FILES = ("ours.png", "vtk.png", "delta_e.png", "side_by_side.png", "metrics.json")
"""The files :func:`compare_scene` writes into its folder, and the only ones."""


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


def compare_scene(scene, out_dir, name: str | None = None, reference: str | None = None) -> dict:
    """Render ``scene`` both ways, measure, write the five output files; return the metrics.

    The metrics dict is what ``metrics.json`` holds (see the README): scene, shading,
    size, delta_e_2000 {mean, median, p95, p99, p999, max}, pixels_over_1,
    coverage_mismatch, max_channel_diff, ours_ms, reference_ms, and the reference used
    (picked per object by :func:`compare.textbook_reference.object_reference`;
    ``reference="vtk-native"`` forces VTK's own shading everywhere).
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    ours, ours_ms = timed_render(scene)
    timings: dict = {}
    ref = render_reference(scene, timings=timings, reference=reference)
    metrics, de = compare_frames(ours, ref)
    shared, mismatch = coverage_masks(ours, ref)
    result = {"scene": name or scene.source, "shading": shading_label(scene), "size": list(scene.image.size),
              **metrics, "ours_ms": round(ours_ms, 3), "reference_ms": round(timings["reference_ms"], 3),
              "model": model_label(scene), "reference": reference_label(scene, reference)}
    write_png(out / "ours.png", ours.rgb)
    write_png(out / "vtk.png", ref.rgb)
    delta_e_figure(de, mismatch, out / "delta_e.png", shared=shared)
    side_by_side_figure(ours.rgb, ref.rgb, de, mismatch, result, out / "side_by_side.png",
                        title=result["scene"], shared=shared)
    write_json(out / "metrics.json", result)
    return result


def summary_line(m: dict) -> str:
    """One line for the terminal: the verdict in numbers."""
    de = m["delta_e_2000"]
    return (f"{m['scene']} [{m['model']}/{m['shading']} vs {m['reference']}]: ΔE2000 mean {de['mean']:.3f}, p99.9 {de['p999']:.2f}, max {de['max']:.2f}; "
            f"over 1: {100 * m['pixels_over_1']:.3f} %; coverage mismatch {100 * m['coverage_mismatch']:.3f} %; "
            f"max channel diff {m['max_channel_diff']}; ours {m['ours_ms']:.1f} ms, VTK {m['reference_ms']:.1f} ms")
