"""SOURCES: files, folders, presets and shapes found and checked at the edge; mesh files framed."""
from __future__ import annotations

import numpy as np
import pytest

from lab.app.sweep.sources import find_sources, load_source
from lab.loading import SceneError, load_scene
from lab.meshfiles import write_mesh
from lab.presets import SCENES_DIR

TORUS = SCENES_DIR / "models" / "torus.ply"


def test_each_kind_of_source_is_found_with_its_key_and_name(tmp_path):
    (tmp_path / "a" / "b").mkdir(parents=True)
    write_mesh(load_scene("cube").world_mesh(), tmp_path / "a" / "cube.ply")
    write_mesh(load_scene("icosahedron").world_mesh(), tmp_path / "a" / "b" / "ico.OBJ")
    (tmp_path / "a" / "notes.txt").write_text("not a source")
    (tmp_path / "a" / "scene.toml").write_text('[[object]]\nshape = "quad"\n')
    found = find_sources([str(tmp_path / "a"), "cube", "torus-mesh", "icosphere:level=1", str(TORUS)])
    assert [(s.kind, s.name) for s in found] == [
        ("mesh", "ico"), ("mesh", "cube"), ("scene", "scene"), ("shape", "cube"), ("preset", "torus-mesh"),
        ("shape", "icosphere:level=1"), ("mesh", "torus")]
    assert found[1].key == str((tmp_path / "a" / "cube.ply").resolve()), "files are sorted by path"


def test_a_source_named_twice_is_swept_once(tmp_path, monkeypatch):
    monkeypatch.chdir(SCENES_DIR)
    found = find_sources(["models/torus.ply", str(TORUS), "cube", "cube"])
    assert [s.name for s in found] == ["torus", "cube"]


@pytest.mark.parametrize("text, message", [
    ("cubee", "no such file, folder, preset or shape"), ("icosphere:level=99", "level"),
    ("nowhere/at/all.ply", "no such file")])
def test_a_source_that_is_nothing_is_refused_in_one_line(text, message):
    with pytest.raises(SceneError, match=message):
        find_sources([text])


def test_an_empty_folder_is_refused(tmp_path):
    with pytest.raises(SceneError, match="no scene"):
        find_sources([str(tmp_path)])


def test_a_mesh_source_is_the_scene_scanlab_compare_makes_of_the_file():
    """The sweep frames a mesh file as `scanlab compare FILE` does (lab.framing), a built-in shape's way."""
    scene, shape = load_source("mesh", str(TORUS)), load_scene("cube")
    assert scene.objects[0].material == shape.objects[0].material and scene.lights == shape.lights
    assert scene.objects[0].mesh.n_triangles == load_scene("torus-mesh").objects[0].mesh.n_triangles
    same = load_scene(str(TORUS))
    assert np.allclose(scene.camera.position, same.camera.position) and scene.objects[0].name == "torus"


def test_an_unreadable_mesh_file_gives_a_scene_error_for_its_case(tmp_path):
    bad = tmp_path / "bad.ply"
    bad.write_text("ply\nformat ascii 1.0\nelement vertex 1\n")
    with pytest.raises(SceneError, match="bad.ply"):
        load_source("mesh", str(bad))
