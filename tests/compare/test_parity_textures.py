"""Textures against VTK: a tilted, textured quad in every filter and wrap mode."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from compare.metrics import failed_bars, measure
from compare.reference import render_reference
from lab.mesh import Mesh
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject
from lab.texture import load_texture
from renderer import render
from lab.matrices import model_matrix

EARTH = Path(pytest.importorskip("pyvista").__file__).parent / "examples" / "2k_earth_daymap.jpg"


def tilted_quad(filt, wrap):
    """A quad tilted 60° away, tcoords reaching past 0..1 so that wrapping shows."""
    pts = np.array([[-1, -0.5, 0], [1, -0.5, 0], [1, 0.5, 0], [-1, 0.5, 0.0]])
    tc = np.array([[-0.2, -0.1], [1.6, -0.1], [1.6, 1.1], [-0.2, 1.1]])
    mesh = Mesh(pts, [[0, 1, 2], [0, 2, 3]], tcoords=tc)
    obj = SceneObject(mesh=mesh, material=Material(color=(1, 1, 1), ambient=0.1, diffuse=0.9, specular=0.3,
                                                   specular_power=20.0),
                      model_to_world=model_matrix(rotate=(-60, 0, 0)), texture=load_texture(EARTH, filt, wrap))
    return Scene(image=Image(size=(480, 300)), camera=Camera(position=(0, 0, 2.2)),
                 lights=(Light(kind="scene", position=(1, 1, 3)),), objects=(obj,))


@pytest.mark.parametrize("wrap", ["repeat", "clamp"])
@pytest.mark.parametrize("filt", ["nearest", "linear"])
def test_textured_quad_matches_vtk(filt, wrap):
    """Perspective-correct texture coordinates, the texture multiplying the lit colour: within the bars."""
    scene = tilted_quad(filt, wrap)
    m = measure(render(scene), render_reference(scene))
    assert not failed_bars(m), m


def test_wrong_filter_fails_the_bars():
    """Sampling nearest where VTK filters linearly is caught (the check can fail)."""
    m = measure(render(tilted_quad("nearest", "repeat")), render_reference(tilted_quad("linear", "repeat")))
    assert failed_bars(m)


@pytest.mark.parametrize("filt", ["nearest", "linear"])
@pytest.mark.parametrize("name", ["globe", "textured-sphere"])
def test_globe_and_textured_sphere_match_vtk(name, filt):
    """PyVista's globe (its mesh and earth texture) and the built-in uv sphere, both filters: within the bars."""
    import dataclasses

    from lab.loading import load_scene

    scene = load_scene(name)
    obj = scene.objects[0]
    obj = dataclasses.replace(obj, texture=dataclasses.replace(obj.texture, filter=filt))
    scene = dataclasses.replace(scene, objects=(obj,))
    m = measure(render(scene), render_reference(scene))
    assert not failed_bars(m), m


def test_objects_each_sample_their_own_texture():
    """Three quads side by side — earth texture, none, a small checkerboard — drawn as one
    scene: each textured object samples its own texels (they share one flat array, with
    rows only for textured objects), against VTK within the bars."""
    import dataclasses

    from lab.texture import Texture

    checker = np.indices((8, 8)).sum(axis=0) % 2
    board = Texture(texels=np.stack([checker, 0.5 + 0 * checker, 1 - checker], axis=-1).astype(np.float64),
                    filter="nearest", wrap="repeat", source="checkerboard")
    base = tilted_quad("linear", "repeat").objects[0]
    objects = []
    for x, texture in ((-1.1, base.texture), (0.0, None), (1.1, board)):
        m = model_matrix(scale=(0.5, 0.5, 0.5), rotate=(-60, 0, 0), translate=(x, 0, 0))
        objects.append(dataclasses.replace(base, model_to_world=m, texture=texture))
    scene = dataclasses.replace(tilted_quad("linear", "repeat"), objects=tuple(objects))
    ours = render(scene)
    m = measure(ours, render_reference(scene))
    assert not failed_bars(m), m
    colours = {tuple(c) for c in ours.rgb[ours.coverage][:, :3].reshape(-1, 3)}
    assert len(colours) > 50  # the textures show (not one flat colour per quad)
