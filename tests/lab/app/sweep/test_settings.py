"""Grid keys: values checked and made canonical at the edge, applied to a scene in the worker."""
from __future__ import annotations

import pytest

from lab.app.sweep.light_sets import LIGHT_SETS
from lab.app.sweep.settings import GRID_KEYS, TEST_FAULTS_ENV, apply_settings, grid_keys
from lab.loading import load_scene


@pytest.mark.parametrize("key, text, canonical", [
    ("shading", "phong", "phong"), ("model", "classic", "classic"), ("size", "256X192", "256x192"),
    ("size", " 64x48", "64x48"), ("opacity", "0.50", "0.5"), ("opacity", "1", "1.0"), ("opacity", "x", None), ("lights", "spot", "spot"),
    ("interpolation", "screen", "screen"), ("transparency", "sorted", "sorted"), ("hidden_surface", "painter", "painter"),
    ("normals", "computed", "computed"), ("reference", "vtk-native", "vtk-native")])
def test_a_value_is_checked_and_made_canonical(key, text, canonical):
    if canonical is None:
        with pytest.raises(ValueError):
            GRID_KEYS[key].parse(text)
    else:
        assert GRID_KEYS[key].parse(text) == canonical


@pytest.mark.parametrize("key, text, reason", [
    ("shading", "flatt", "did you mean flat?"), ("size", "0x10", "1..8192"), ("size", "big", "WIDTHxHEIGHT"),
    ("opacity", "0", "outside (0, 1]"), ("opacity", "half", "a number"), ("lights", "sun", "not one of")])
def test_a_bad_value_says_why_in_one_line(key, text, reason):
    with pytest.raises(ValueError, match=None) as err:
        GRID_KEYS[key].parse(text)
    assert reason in str(err.value) and "\n" not in str(err.value)


def test_the_fault_key_exists_only_for_tests(monkeypatch):
    monkeypatch.delenv(TEST_FAULTS_ENV, raising=False)
    assert "fault" not in grid_keys()
    monkeypatch.setenv(TEST_FAULTS_ENV, "1")
    assert grid_keys()["fault"].parse("hang") == "hang"


def test_applying_settings_overrides_every_object_and_the_scene_wide_choices():
    scene = load_scene("translucent-two")
    changed = apply_settings(scene, {"shading": "phong", "model": "opengl", "size": "80x60", "lights": "rgb",
                                     "interpolation": "screen", "transparency": "sorted",
                                     "hidden_surface": "painter", "opacity": "0.25", "normals": "face",
                                     "reference": "vtk-native"})
    assert {o.shading for o in changed.objects} == {"phong"}
    assert {o.material.model for o in changed.objects} == {"opengl"}
    assert {o.material.opacity for o in changed.objects} == {0.25}
    assert all(o.mesh.point_normals is None for o in changed.objects)
    assert changed.image.size == (80, 60) and changed.lights == LIGHT_SETS["rgb"].lights
    assert (changed.render.interpolation, changed.render.transparency, changed.render.hidden_surface) == \
        ("screen", "sorted", "painter")
    assert scene.image.size != (80, 60), "the loaded scene itself is left as it was"


def test_no_settings_leave_the_scene_as_it_is():
    scene = load_scene("cube")
    assert apply_settings(scene, {}) is scene
