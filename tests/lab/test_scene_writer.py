"""lab/scene_writer.py: a scene written out loads back as the same scene, and draws the same bytes."""
# mesh readers scale normals to unit length: a normal may come back one bit off
from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from lab.loading import load_scene, parse_scene
from lab.matrices import model_matrix
from lab.presets import preset_names
from lab.scene import Scene
from lab.scene_writer import scene_files, scene_to_toml, write_scene


def same_scene(a: Scene, b: Scene) -> None:
    assert a.image == b.image and a.camera == b.camera and a.lights == b.lights and a.render == b.render
    assert len(a.objects) == len(b.objects)
    for x, y in zip(a.objects, b.objects):
        assert x.material == y.material and x.shading == y.shading and x.name == y.name
        assert np.array_equal(x.model_to_world, y.model_to_world)
        for field in ("points", "triangles", "tcoords"):
            u, v = getattr(x.mesh, field), getattr(y.mesh, field)
            assert (u is None and v is None) or np.array_equal(u, v), field
        u, v = x.mesh.point_normals, y.mesh.point_normals
        assert (u is None and v is None) or np.allclose(u, v, rtol=0, atol=4e-16)
        assert (x.texture is None) == (y.texture is None)
        if x.texture is not None:
            assert np.array_equal(x.texture.texels_8bit, y.texture.texels_8bit)
            assert (x.texture.filter, x.texture.wrap) == (y.texture.filter, y.texture.wrap)


@pytest.mark.parametrize("name", preset_names())
def test_every_preset_round_trips_exactly(name, tmp_path):
    """Every number, mesh and texture comes back as it was (normals to the last bit or so), and our renderer
    draws the same bytes from both."""
    from renderer import render

    scene = load_scene(name)
    back = load_scene(write_scene(scene, tmp_path / f"{name}.toml"))
    same_scene(scene, back)
    a, b = render(scene), render(back)
    assert np.array_equal(a.rgb, b.rgb) and np.array_equal(a.depth, b.depth)


def test_a_sheared_transform_survives_as_a_matrix(tmp_path):
    scene = load_scene("cube")
    shear = model_matrix(rotate=(10, 20, 30), translate=(1, 2, 3))
    shear[1, 0] = 0.4  # no scale/rotate/translate makes this
    scene = dataclasses.replace(scene, objects=(dataclasses.replace(scene.objects[0], model_to_world=shear),))
    text = (tmp_path / "s.toml")
    back = load_scene(write_scene(scene, text))
    assert np.array_equal(back.objects[0].model_to_world, shear) and "matrix = [[" in text.read_text()


def test_a_scene_without_lights_keeps_none(tmp_path):
    """VTK draws unlit colours with no light on; the loader would add a headlight to a file with no
    [[light]], so the writer writes one switched-off light."""
    scene = dataclasses.replace(load_scene("cube"), lights=())
    back = load_scene(write_scene(scene, tmp_path / "dark.toml"))
    assert not any(li.on for li in back.lights)


def test_the_files_beside_the_scene_are_named_in_advance(tmp_path):
    scene = load_scene("globe")
    meshes, textures = scene_files(scene, tmp_path / "g.toml")
    write_scene(scene, tmp_path / "g.toml")
    assert all(p.is_file() for p in meshes) and all(p is None or p.is_file() for p in textures)
    assert meshes[0].parent == tmp_path / "g-files" and textures[0] is not None


def test_the_text_parses_without_files_for_shapes():
    """The text itself is valid for the loader (the mesh names are only checked when read)."""
    text = scene_to_toml(load_scene("cube"), ["m.vtp"], [None])
    with pytest.raises(Exception, match="m.vtp"):
        parse_scene(text.encode())
