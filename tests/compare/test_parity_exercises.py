"""The exercise geometry against VTK: cylinder and cone in every shading, Menger and the flake."""
from __future__ import annotations

import dataclasses

import pytest

from compare.metrics import measure
from compare.reference import render_reference
from compare.metrics import failed_bars
from lab.framing import make_shape
from lab.loading import load_scene
from renderer import render


def assert_within_bars(m):
    assert not failed_bars(m), m


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


def test_csg_scene_matches_vtk_and_the_implicit_volume():
    """The CSG preset, (box − sphere) ∩ cylinder: within the bars against VTK, and its mesh volume within 1 %
    of a Monte-Carlo estimate made from the implicit half-space functions alone."""
    import tomllib

    from lab.csg import from_dict, monte_carlo_volume
    from lab.presets import SCENES_DIR
    from lab.measure import enclosed_volume

    scene = load_scene("csg")
    assert_within_bars(measure(render(scene), render_reference(scene)))
    tree = tomllib.loads((SCENES_DIR / "csg.toml").read_text())["object"][0]["csg"]
    estimate, stderr = monte_carlo_volume(from_dict(tree), n=1_000_000, seed=1)
    volume = enclosed_volume(scene.objects[0].mesh)
    assert abs(volume - estimate) < 0.01 * estimate and stderr < 0.003 * estimate
