"""One colour per triangle where it cannot change across it (flat shading, a colour of the normal
alone): worked out once per triangle, it is the colour of every pixel the triangle shows."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lab.matrices import model_matrix
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject, headlight
from lab.shapes import icosphere
from renderer import RenderOptions, render
from renderer.pipeline import render_stages

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
