"""Figures the lessons show, each made from measured renders (``scanlab lessons figures``).

- ``interpolation.png``: Gouraud colours on a floor seen at a grazing angle, interpolated
  linearly in screen space (the course's scanline way) beside perspective-correct
  interpolation (what GPUs and VTK do), with the ΔE2000 map between them. The floor is
  clipped at the window first, as in the course's pipeline, and the new corners carry
  their true colours: the error grows with the size of each clipped triangle on screen.
- ``gouraud-vs-vtk.png``: the textbook's OpenGL Gouraud sphere beside VTK's per-pixel
  "Gouraud" with the nearest equivalent material: the difference sits on the highlights.
- ``separate-specular.png``: a shiny textured sphere in OpenGL's single-colour mode (the
  texture tints the highlight) beside ``GL_SEPARATE_SPECULAR_COLOR`` (the highlight keeps
  the light's colour), with the ΔE2000 map between them: it is the highlight.

The figures are kept in git: they carry no timings, so making them again gives the same
bytes (tested), and a change shows in ``git status`` only when a picture changed.
"""
from __future__ import annotations

import dataclasses
import os
import tempfile
from pathlib import Path

from compare.comparison import settings_line
from compare.images import PanelText, side_by_side_figure
from compare.metrics import compare_frames, coverage_masks
from lab.loading import load_scene
from renderer import RenderOptions, render


def facing(scene):
    """The same scene with every object turned to face the camera (no rotation: the quad faces +z)."""
    from lab.matrices import model_matrix

    objs = tuple(dataclasses.replace(o, model_to_world=model_matrix(translate=(0.0, 0.3, -1.0)))
                 for o in scene.objects)
    cam = dataclasses.replace(scene.camera, position=(0.0, 0.3, 3.0), focal_point=(0.0, 0.3, 0.0))
    return dataclasses.replace(scene, objects=objs, camera=cam)


def interpolation_metrics(scene) -> tuple[dict, tuple]:
    """Metrics of screen-linear against perspective-correct interpolation of one scene."""
    screen = render(scene, RenderOptions(interpolation="screen"))
    perspective = render(scene, RenderOptions(interpolation="perspective"))
    metrics, de = compare_frames(screen, perspective)
    return metrics, (screen, perspective, de)


def interpolation_figure(out: Path) -> dict:
    """Write ``interpolation.png``; return the metrics for the tilted and the facing plane."""
    tilted = load_scene("tilted-plane")
    m_tilted, (screen, perspective, de) = interpolation_metrics(tilted)
    m_facing, _ = interpolation_metrics(facing(tilted))
    shared, mismatch = coverage_masks(screen, perspective)
    side_by_side_figure(screen.rgb, perspective.rgb, de, mismatch, m_tilted, out / "interpolation.png",
                        PanelText(title="Gouraud colours on a tilted floor",
                                  labels=("screen-linear (course scanline)", "perspective-correct (GPU, VTK)"),
                                  settings=settings_line(tilted, "none, both images are scanlab's",
                                                         interpolation="screen (left) | perspective (right)")),
                        shared=shared, coverage=(screen.coverage, perspective.coverage))
    return {"tilted": m_tilted, "facing": m_facing}


def gouraud_vs_vtk_figure(out: Path) -> dict:
    """Write ``gouraud-vs-vtk.png`` (textbook sphere, OpenGL Gouraud vs VTK native)."""
    from compare.comparison import compare_scene
    from compare.report import OUTPUT_FILES

    scene = load_scene("textbook-sphere").with_overrides(model="opengl", shading="gouraud")
    work = Path(tempfile.mkdtemp(dir=out, prefix=".gouraud-vs-vtk."))  # new, so everything in it is ours
    try:
        m = compare_scene(scene, work, name="textbook-sphere: OpenGL Gouraud vs VTK", reference="vtk-native")
        os.replace(work / "side_by_side.png", out / "gouraud-vs-vtk.png")  # atomic: the same folder tree
    finally:
        for name in OUTPUT_FILES:  # only what compare_scene wrote
            (work / name).unlink(missing_ok=True)
        work.rmdir()
    return m


def separate_specular_figure(out: Path) -> dict:
    """Write ``separate-specular.png`` (single colour vs separate specular, both ours; each
    is checked against its VTK reference in the tests)."""
    scene = load_scene("separate-specular")
    single = render(dataclasses.replace(scene, render=dataclasses.replace(scene.render, separate_specular=False)))
    separate = render(dataclasses.replace(scene, render=dataclasses.replace(scene.render, separate_specular=True)))
    metrics, de = compare_frames(single, separate)
    shared, mismatch = coverage_masks(single, separate)
    side_by_side_figure(single.rgb, separate.rgb, de, mismatch, metrics, out / "separate-specular.png",
                        PanelText(title="A textured shiny sphere: where does the highlight go?",
                                  labels=("GL_SINGLE_COLOR (texture × everything)", "GL_SEPARATE_SPECULAR_COLOR"),
                                  settings=settings_line(scene, "none, both images are scanlab's",
                                                         specular_colour="single (left) | separate (right)")),
                        shared=shared, coverage=(single.coverage, separate.coverage))
    return metrics


def build_figures(out: Path) -> dict:
    """Make every lesson figure into ``out``; returns their metrics by figure name."""
    out.mkdir(parents=True, exist_ok=True)
    return {"interpolation": interpolation_figure(out), "gouraud-vs-vtk": gouraud_vs_vtk_figure(out),
            "separate-specular": separate_specular_figure(out)}
