"""One colour per triangle where it cannot change across it (flat shading, a colour of the normal
alone): worked out once per triangle, it is the colour of every pixel the triangle shows."""
from __future__ import annotations

import itertools
from dataclasses import replace

import numpy as np
import pytest

from lab.matrices import model_matrix
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject, headlight
from lab.shapes import icosphere
from renderer import RenderOptions, render
from renderer.held_colours import all_held, held_per_triangle, paint_rows
from renderer.jit import njit
from renderer.pipeline import render_stages
from renderer.reflection.materials import FACE_COLOUR
from renderer.shading import spans_cover_all

from .kernel_inputs import preset_tables

SCENE_LIGHT = Light(kind="scene", position=(3.0, 4.0, 5.0))


def balls(lights, shading=("flat", "flat")):
    """Two spheres of 1,280 triangles side by side, each with its own shading."""
    objects = tuple(SceneObject(mesh=icosphere(level=3), material=Material(color=colour, specular=0.4), shading=s,
                                model_to_world=model_matrix(translate=(x, 0.0, 0.0)))
                    for x, colour, s in zip((-0.9, 0.9), ((0.9, 0.5, 0.2), (0.3, 0.6, 0.9)), shading))
    return Scene(image=Image(size=(160, 90)), camera=Camera(position=(0.0, 0.4, 4.0), clipping_range=(0.5, 30.0)),
                 lights=lights, objects=objects)


@pytest.mark.parametrize("lights", [(headlight(),), (replace(SCENE_LIGHT, on=False),)], ids=["headlight", "unlit"])
def test_every_pixel_of_a_held_triangle_has_its_one_colour(lights):
    """Under a lone headlight or no light, a flat triangle's pixels all show one colour, and two
    neighbouring triangles of a sphere (different normals) show different ones."""
    frame, stages = render_stages(balls(lights))
    shown = stages.triangle[frame.coverage]
    colours = frame.rgb[frame.coverage].astype(np.int64) @ [1, 256, 65536]
    per_triangle = {}
    for t, c in zip(shown.tolist(), colours.tolist()):
        per_triangle.setdefault(t, set()).add(c)
    assert len(per_triangle) > 500
    assert all(len(c) == 1 for c in per_triangle.values())
    if lights[0].on:
        assert len({next(iter(c)) for c in per_triangle.values()}) > 100


def test_a_scene_light_is_not_held_per_triangle():
    """A flat triangle under a scene light is lit at every pixel (the view vector changes across
    it): its pixels do not all share one colour."""
    frame, stages = render_stages(balls((SCENE_LIGHT,)))
    shown, colours = stages.triangle[frame.coverage], frame.rgb[frame.coverage].astype(np.int64) @ [1, 256, 65536]
    varied = sum(len(set(colours[shown == t].tolist())) > 1 for t in np.unique(shown))
    assert varied > 50


def test_held_and_per_pixel_objects_side_by_side_keep_the_bytes_of_pixel_by_pixel_shading():
    """A flat sphere (held per triangle) beside a phong one (lit per pixel) under a headlight."""
    scene = balls((headlight(),), shading=("flat", "phong"))
    np.testing.assert_array_equal(render(scene).rgb, render(scene, RenderOptions(spans=False)).rgb)


def mixed_balls(lights, models):
    """:func:`balls`, flat, the left and right spheres under the reflection ``models`` given
    (opengl's flat triangles are FACE_COLOUR, vtk's PIXEL_FACE_NORMAL)."""
    scene = balls(lights)
    objects = tuple(replace(o, material=replace(o.material, model=m)) for o, m in zip(scene.objects, models))
    return replace(scene, objects=objects)


@njit
def held_by_kernel(materials, lights):
    return [held_per_triangle(o, materials, lights) or materials.shading_path[o] == FACE_COLOUR
            for o in range(materials.model.shape[0])]


def test_the_choice_of_paint_rows_in_python_agrees_with_the_kernels_own_rule():
    """``all_held`` (Python) says yes exactly when every object is held per triangle by the kernels'
    own rule or FACE_COLOUR, on every preset × shading × model the span kernels cover; both occur."""
    answers = set()
    for label, mats, textures, lights in preset_tables():
        if spans_cover_all(mats, textures, lights):
            answer = all_held(mats, lights)
            assert answer == all(held_by_kernel(mats, lights)), label
            answers.add(answer)
    assert answers == {True, False}


@pytest.mark.parametrize("lights, kernel", [((headlight(),), "paint_rows"), ((SCENE_LIGHT,), "shade_rows_lit_spans")],
                         ids=["headlight", "scene-light"])
def test_face_colour_triangles_beside_held_or_lit_ones_keep_the_bytes_of_pixel_by_pixel_shading(
        lights, kernel, monkeypatch):
    """A FACE_COLOUR sphere (opengl, flat) beside a vtk one: under a headlight both are held and
    the frame is painted from the table; under a scene light the vtk sphere is lit per pixel and
    the FACE_COLOUR one copied from the table along its spans. Both: the plain path's bytes."""
    import renderer.shading as shading

    scene = mixed_balls(lights, ("opengl", "vtk"))
    plain = render(scene, RenderOptions(spans=False))
    calls = []
    for name in ("shade_rows", "shade_rows_lit_spans", "paint_rows"):
        original = getattr(shading, name)
        monkeypatch.setattr(shading, name, lambda *a, _k=original, _n=name: calls.append(_n) or _k(*a))
    frame = render(scene)
    assert calls == [kernel]
    assert len(np.unique(plain.rgb[plain.coverage], axis=0)) > 100
    np.testing.assert_array_equal(frame.rgb, plain.rgb)


def test_paint_rows_gives_each_pixel_its_triangles_row_and_empty_ones_the_background():
    """Small by hand, then rows longer than a vector register (the kernel's loop runs in lanes)
    naming the first and the last triangle and empty pixels at random, in one band or
    several, compiled and as plain Python: each pixel its triangle's bytes or the background's."""
    tri_index = np.array([[-1, 0, 0, 2], [1, 1, -1, 2]], np.int32)
    held = np.array([[10, 20, 30], [40, 50, 60], [70, 80, 90]], np.uint8)
    background = np.array([1, 2, 3], np.uint8)
    rng = np.random.default_rng(5)
    wide = rng.integers(-1, 300, (5, 77)).astype(np.int32)
    wide[0, :3] = (0, 299, -1)
    cases = [(tri_index, held), (wide, rng.integers(0, 256, (300, 3)).astype(np.uint8))]
    for (triangles, colours), bands, kernel in itertools.product(cases, (1, 2, 3), (paint_rows, paint_rows.py_func)):
        rgb = np.zeros(triangles.shape + (3,), np.uint8)
        kernel(triangles, colours, background, bands, rgb)
        expected = np.where((triangles < 0)[..., None], background, colours[np.maximum(triangles, 0)])
        np.testing.assert_array_equal(rgb, expected)


@pytest.mark.parametrize("models, kernels", [(("vtk", "vtk"), ["held_colours"]), (("opengl", "classic"), ["face_colours"]),
                                             (("opengl", "vtk"), ["held_colours", "face_colours"])],
                         ids=["held", "face-colour", "both"])
def test_each_table_kernel_runs_only_when_its_kind_of_flat_object_is_in_the_frame(models, kernels, monkeypatch):
    """Under a headlight, vtk flat objects are held (lit once per triangle, held_colours) and
    opengl or classic flat ones carry their lit colour (face_colours): a frame runs, and so
    compiles, only the kernels its objects need."""
    import renderer.held_colours as held

    calls = []
    for name in ("held_colours", "face_colours"):
        original = getattr(held, name)
        monkeypatch.setattr(held, name, lambda *a, _k=original, _n=name: calls.append(_n) or _k(*a))
    render(mixed_balls((headlight(),), models))
    assert calls == kernels
