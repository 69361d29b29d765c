"""GL_SEPARATE_SPECULAR_COLOR on a shiny textured sphere (the ``separate-specular`` preset),
against VTK: the lit colours come from the independent numpy lighting (flat and Gouraud,
as float vertex attributes) or a replaced GLSL shader (phong); VTK rasterises, samples the
texture and modulates; the separate specular colour is added after that modulation in the
same render.
"""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from compare.metrics import compare_frames, failed_bars, measure
from compare.reference import render_reference
from compare.report import reference_label
from lab.loading import load_scene
from renderer import render


def sphere(separate: bool, shading: str = "gouraud"):
    scene = load_scene("separate-specular").with_overrides(shading=shading)
    return dataclasses.replace(scene, render=dataclasses.replace(scene.render, separate_specular=separate))


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
@pytest.mark.parametrize("separate", [True, False], ids=["separate", "single"])
def test_matches_vtk(separate, shading):
    scene = sphere(separate, shading)
    m = measure(render(scene), render_reference(scene))
    assert not failed_bars(m), failed_bars(m)


def test_metrics_name_the_composed_reference():
    assert reference_label(sphere(True)) == "vtk-unlit-colours+separate-specular"
    assert reference_label(sphere(True, "phong")) == "vtk-shader-replacement+separate-specular"
    assert reference_label(sphere(False)) == "vtk-unlit-colours"


def specular_levels(scene) -> np.ndarray:
    """Grey levels the specular term alone gives each pixel (texture, ambient and diffuse
    removed)."""
    objs = tuple(dataclasses.replace(o, texture=None, material=dataclasses.replace(
        o.material, ambient_color=(0.0, 0.0, 0.0), diffuse_color=(0.0, 0.0, 0.0))) for o in scene.objects)
    scene = dataclasses.replace(scene, objects=objs,
                                render=dataclasses.replace(scene.render, global_ambient=(0.0, 0.0, 0.0)))
    return render(scene).rgb.max(axis=-1)


def test_the_difference_sits_on_the_highlight():
    """Single colour against separate specular: the visible highlight (specular ≥ 8 grey
    levels, under a third of the sphere) holds over 95 % of all the ΔE2000 between them,
    and where the specular term is under one level they differ by at most one."""
    separate, single = render(sphere(True)), render(sphere(False))
    metrics, de = compare_frames(separate, single)
    de = np.nan_to_num(de)
    levels = specular_levels(sphere(True))
    highlight = levels >= 8
    assert metrics["pixels_over_1"] > 0.1
    assert highlight[separate.coverage].mean() < 1 / 3
    assert de[highlight].sum() > 0.95 * de.sum()
    unlit = levels < 1
    assert np.abs(separate.rgb[unlit].astype(int) - single.rgb[unlit]).max() <= 1
