"""Parity of the textbook models (fixed-function OpenGL, the course's) against references.

flat and gouraud: VTK draws colours lit by compare/lit_reference/ (numpy, written
apart from renderer/) unlit; phong: VTK with its fragment lighting replaced by the
textbook formula. The bars are the foundation's.
"""
from __future__ import annotations

import dataclasses

import pytest

from compare.metrics import measure
from compare.reference import render_reference
from compare.textbook_reference import scene_reference
from compare.metrics import PARITY_BARS as BARS, failed_bars
from lab.normals import scene_with_normals
from lab.loading import load_scene
from lab.normals import with_normals
from lab.shapes import icosphere
from renderer import RenderOptions, render

SEEDS = ["textbook-cube", "textbook-icosahedron", "textbook-sphere", "course-gouraud", "course-phong",
         "directional-cubes", "flat-shading"]


def verdict(scene, **kwargs):
    return measure(render(scene), render_reference(scene, **kwargs))


def assert_within_bars(m):
    assert not failed_bars(m), m



@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
@pytest.mark.parametrize("model", ["opengl", "classic"])
@pytest.mark.parametrize("name", SEEDS)
def test_seed_scenes_match_their_reference(name, model, shading):
    """Each seed scene in each textbook model and shading: within the bars of its reference."""
    scene = scene_with_normals(load_scene(name), 30.0).with_overrides(model=model, shading=shading)
    expected = {"flat": "vtk-unlit-colours", "gouraud": "vtk-unlit-colours", "phong": "vtk-shader-replacement"}
    assert scene_reference(scene) == expected[shading]
    assert_within_bars(verdict(scene))


@pytest.mark.parametrize("level", range(6))
@pytest.mark.parametrize("normals", ["face", "radial"])
def test_subdivided_sphere_levels(level, normals):
    """The textbook's sphere, levels 0–5, flat (face normals) and smooth (vertex position as normal)."""
    scene = load_scene("textbook-sphere")
    obj = scene.objects[0]
    mesh = with_normals(icosphere(level=level), normals)
    scene = dataclasses.replace(scene, objects=(dataclasses.replace(obj, mesh=mesh),))
    assert_within_bars(verdict(scene))


def test_textbook_gouraud_differs_from_vtk_gouraud():
    """--reference vtk-native: textbook Gouraud (per-vertex) is measurably not VTK's per-pixel 'Gouraud'."""
    scene = load_scene("course-gouraud")
    m = verdict(scene, reference="vtk-native")
    assert m["pixels_over_1"] > BARS["pixels_over_1"]


def test_wrong_specular_model_fails_the_bars():
    """The classic model's reflection vector in place of OpenGL's half vector shows up (the check can fail)."""
    scene = load_scene("textbook-sphere")
    as_classic = scene.with_overrides(model="classic")
    m = measure(render(as_classic), render_reference(scene))
    assert m["delta_e_2000"]["mean"] > BARS["mean"]


def test_screen_linear_colour_interpolation_fails_the_bars():
    """Gouraud colours interpolated linearly in screen space (the course's scanline way) miss the perspective-correct reference on a floor lit by a lamp."""
    scene = scene_with_normals(load_scene("positional-lamp"), 30.0).with_overrides(model="classic", shading="gouraud")
    ref = render_reference(scene)
    assert_within_bars(measure(render(scene), ref))
    m = measure(render(scene, RenderOptions(interpolation="screen")), ref)
    assert m["pixels_over_1"] > BARS["pixels_over_1"]


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
@pytest.mark.parametrize("model", ["opengl", "classic"])
def test_lighting_off_draws_the_unlit_colour_in_every_model(model, shading):
    """``lighting = false``: no reflection model, so the textbook models draw VTK's unlit
    ``ambient·color + diffuse·color``, checked against VTK's own unlit render (and not lit)."""
    scene = scene_with_normals(load_scene("textbook-sphere"), 30.0).with_overrides(model=model, shading=shading)
    unlit = dataclasses.replace(scene, objects=tuple(
        dataclasses.replace(o, material=dataclasses.replace(o.material, lighting=False, ambient=0.2, diffuse=0.7))
        for o in scene.objects))
    assert scene_reference(unlit) == "vtk-native"
    ours = render(unlit)
    assert_within_bars(measure(ours, render_reference(unlit)))
    colours = ours.rgb[ours.coverage]
    assert (colours == colours[0]).all()  # one colour: nothing lit it
