"""The exercise geometry against VTK: cylinder and cone in every shading, Menger and the flake."""
from __future__ import annotations

import dataclasses

import pytest

from compare.metrics import measure
from compare.reference import render_reference
from lab.demo import BARS
from lab.loading import load_scene, make_shape
from renderer import render


def assert_within_bars(m):
    assert m["coverage_mismatch"] <= BARS["coverage_mismatch"], m
    assert m["pixels_over_1"] <= BARS["pixels_over_1"], m
    assert m["delta_e_2000"]["mean"] <= BARS["mean"], m


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong"])
def test_cylinder_and_cone_match_vtk(shading):
    """Cylinder and cone with their own normals (smooth sides, sharp rims): flat, gouraud, phong within the bars."""
    scene = load_scene("cylinder-cone").with_overrides(shading=shading)
    assert_within_bars(measure(render(scene), render_reference(scene)))


@pytest.mark.parametrize("shape, level", [("menger", 0), ("menger", 1), ("menger", 2), ("menger", 3),
                                          ("icosahedron_fractal", 1), ("icosahedron_fractal", 2)])
@pytest.mark.parametrize("model", ["vtk", "opengl"])
def test_fractals_match_their_reference(shape, level, model):
    """Menger levels 0–3 and the icosahedron flake, VTK's flat shading and OpenGL's: within the bars."""
    scene = load_scene("menger" if shape == "menger" else "icosahedron-fractal")
    obj = dataclasses.replace(scene.objects[0], mesh=make_shape(shape, {"level": level}))
    scene = dataclasses.replace(scene, objects=(obj,)).with_overrides(model=model)
    assert_within_bars(measure(render(scene), render_reference(scene)))
