"""lab/app/live/saving.py: "Save scene" writes only into the folder chosen at start-up, under a
plain name, never over an input or a file it did not write, and what it writes loads back."""
from __future__ import annotations

from dataclasses import replace

import pytest

from lab.app.live.controls import Problems, controls_for, to_render
from lab.app.live.saving import Saver, commands
from lab.loading import load_scene
from lab.presets import SCENES_DIR


def _problem(call) -> str:
    with pytest.raises(Problems) as caught:
        call()
    (path, problem), = caught.value.found.items()
    assert path == "save_name"
    return problem.code


def test_a_saved_scene_loads_back_as_the_scene_on_screen(tmp_path):
    scene = load_scene("spot-attenuation")
    shown = to_render(replace(controls_for(scene, "k"), shading="phong", size="256x256"), scene).scene
    saved = Saver(tmp_path / "saves").write(shown, "my-spot")
    assert saved.path == (tmp_path / "saves" / "my-spot.toml").resolve()
    back = load_scene(saved.path)
    assert back.image == shown.image and back.camera == shown.camera and back.lights == shown.lights
    assert [o.material for o in back.objects] == [o.material for o in shown.objects]
    assert saved.commands == [f"scanlab compare {saved.path} --out out/my-spot"]


@pytest.mark.parametrize("name", ["../escape", "/etc/x", "a/b", "", " ", "a" * 61, "x.y", None, 3, "con:1"])
def test_a_name_that_is_not_plain_is_refused(tmp_path, name):
    assert _problem(lambda: Saver(tmp_path).write(load_scene("cube"), name)) == "name"
    assert list(tmp_path.iterdir()) == []


def test_it_never_overwrites_an_input_or_a_file_it_did_not_write(tmp_path):
    scene = load_scene("course-phong")
    assert _problem(lambda: Saver(SCENES_DIR).write(scene, "course-phong")) == "input"
    (tmp_path / "theirs.toml").write_text("# someone's")
    saver = Saver(tmp_path)
    assert _problem(lambda: saver.write(scene, "theirs")) == "exists"
    assert (tmp_path / "theirs.toml").read_text() == "# someone's"
    saver.write(scene, "mine")
    saver.write(scene, "mine.toml")  # its own file, saved again: fine


def test_with_a_rule_broken_the_commands_break_it_again():
    assert commands(SCENES_DIR / "x.toml", "fill-rule")[1].startswith("scanlab lessons measure")
    assert "--break fill-rule" in commands(SCENES_DIR / "x.toml", "fill-rule")[1]
