"""lab/app/live/catalogue.py: the picker offers presets, lesson scenes, shapes and the named files,
and the browser can name nothing else."""
from __future__ import annotations

import pytest

from lab.app.live.catalogue import Catalogue, initial_parameters, lesson_files, load_spec, shape_defaults
from lab.presets import SCENES_DIR, preset_names
from lab.shapes import SHAPES
from lab.validation import SceneError


@pytest.fixture(scope="module")
def catalogue():
    return Catalogue()


def test_it_offers_every_preset_lesson_scene_and_shape(catalogue):
    groups = {}
    for entry in catalogue.entries.values():
        groups.setdefault(entry.group, []).append(entry)
    assert len(groups["preset"]) == len(preset_names()) and len(groups["shape"]) == len(SHAPES)
    assert len(groups["lesson"]) == len(lesson_files()) >= 30
    assert "lesson:08-lights/red-point.toml" in catalogue.entries


def test_a_key_not_in_the_list_is_refused_whatever_it_looks_like(catalogue):
    for key in ["/etc/passwd", "file:0", "preset:../../etc/passwd", "lesson:../README.md", None, 3, ["x"]]:
        with pytest.raises(SceneError, match="not a scene of this lab"):
            catalogue.spec(key)


def test_a_shape_is_loaded_with_its_parameters_checked_by_the_loader(catalogue):
    assert catalogue.load("shape:icosphere", {"level": "1", "radius": 2}).objects[0].mesh.n_triangles == 80
    with pytest.raises(SceneError, match="level must be a whole number in 0..7"):
        catalogue.load("shape:icosphere", {"level": 99})
    for bad in [{"level": "1,radius=9"}, {"level": "__import__"}, {"level=1,x": 1}, {"level": ""}]:
        with pytest.raises(SceneError, match="expected a number"):
            catalogue.spec("shape:icosphere", bad)
    for bad in [["level", 1], "level=1", 3]:
        with pytest.raises(SceneError, match="expected its parameters by name"):
            catalogue.spec("shape:icosphere", bad)


def test_files_named_on_the_command_line_are_offered_and_checked(tmp_path):
    mesh = SCENES_DIR / "models" / "torus.ply"
    catalogue = Catalogue((str(mesh),))
    assert catalogue.key_for(str(mesh)) == "file:0"
    assert catalogue.load("file:0").objects[0].name == "torus"
    (tmp_path / "bad.toml").write_text("[image]\nsize = [0, 0]\n")
    with pytest.raises(SceneError, match=r"bad.toml: object: the scene has no \[\[object\]\]"):
        Catalogue((str(tmp_path / "bad.toml"),))


def test_the_start_scene_is_found_or_explained(catalogue):
    assert catalogue.key_for("cube") == "preset:cube" if "cube" in preset_names() else True
    assert catalogue.key_for("icosphere:level=3") == "shape:icosphere"
    assert initial_parameters("icosphere:level=3") == {**shape_defaults("icosphere"), "level": 3}
    with pytest.raises(SceneError, match="did you mean 'course-phong'"):
        catalogue.key_for("course-phomg")


def test_a_saved_scene_joins_the_list_once_and_is_read_again_when_rewritten(tmp_path, catalogue):
    path = tmp_path / "mine.toml"
    path.write_text((SCENES_DIR / "course-phong.toml").read_text())
    key = catalogue.add_saved(path)
    assert catalogue.add_saved(path) == key and catalogue.entries[key].group == "saved"
    assert load_spec(catalogue.spec(key)).image.size == (400, 300)
    path.write_text(path.read_text().replace("size = [400, 300]", "size = [200, 100]"))
    assert load_spec(catalogue.spec(key)).image.size == (200, 100)


def test_picker_items_name_their_group(catalogue):
    titles = {g: g.upper() for g in ("preset", "lesson", "shape", "file", "saved")}
    items = catalogue.picker_items(titles)
    assert items[0] == {"type": "subheader", "title": "PRESET"}
    assert {i["value"] for i in items if "value" in i} == set(catalogue.entries)
