"""renderer/breakages.py: each "break it" entry breaks exactly its one rule, and leaves its inputs alone.

Whether each broken render really fails the parity bars against VTK is checked where the
lessons show them (the site build fails otherwise: tests/lessons/test_site.py).
"""
from __future__ import annotations

import re

import numpy as np
import pytest

from lab.loading import load_scene
from renderer.breakages import BREAKAGES, apply_breakage
from renderer.pipeline import RenderOptions

JAPANESE = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")


def test_the_registry_holds_the_six_rules_the_lessons_break():
    assert set(BREAKAGES) == {"face-normals", "transposed-matrix", "fill-rule", "painter", "light-frame",
                              "screen-interpolation"}


@pytest.mark.parametrize("name", sorted(BREAKAGES))
def test_every_entry_is_named_and_explained_in_english_and_japanese(name):
    b = BREAKAGES[name]
    assert b.name == name
    for text in (b.label, b.rule):
        assert set(text) == {"en", "ja"}
        assert text["en"] and not JAPANESE.search(text["en"])
        assert JAPANESE.search(text["ja"]), text["ja"]


def test_an_unknown_name_is_refused_with_the_known_ones():
    with pytest.raises(KeyError, match="known: face-normals"):
        apply_breakage("wrong-winding", load_scene("cube"), RenderOptions())


def test_the_fill_rule_gives_ties_to_bottom_and_right_edges():
    scene = load_scene("fill-rule")
    broken, options = apply_breakage("fill-rule", scene, RenderOptions())
    assert broken is scene and options == RenderOptions(fill_rule="bottom-right")


def test_screen_interpolation_changes_only_the_options():
    scene = load_scene("tilted-plane")
    broken, options = apply_breakage("screen-interpolation", scene, RenderOptions(fill_rule="top-left"))
    assert broken is scene and options == RenderOptions(fill_rule="top-left", interpolation="screen")


def test_the_painter_replaces_the_z_buffer_and_nothing_else():
    scene = load_scene("cube")
    broken, options = apply_breakage("painter", scene, RenderOptions())
    assert broken.render.hidden_surface == "painter" and scene.render.hidden_surface == "zbuffer"
    assert broken.objects is scene.objects and options == RenderOptions()


def test_the_light_frame_reads_camera_lights_as_scene_lights_and_keeps_headlights():
    scene = load_scene("camera-lights")
    scene = scene.__class__(**{**scene.__dict__, "lights": scene.lights + (load_scene("cube").lights[0],)})
    broken, _ = apply_breakage("light-frame", scene, RenderOptions())
    assert [li.kind for li in scene.lights] == ["camera", "camera", "headlight"]
    assert [li.kind for li in broken.lights] == ["scene", "scene", "headlight"]
    assert [li.position for li in broken.lights] == [li.position for li in scene.lights]


def test_face_normals_drop_the_point_normals_and_keep_the_triangles():
    scene = load_scene("cylinder-cone")
    broken, _ = apply_breakage("face-normals", scene, RenderOptions())
    for before, after in zip(scene.objects, broken.objects):
        assert before.mesh.point_normals is not None and after.mesh.point_normals is None
        np.testing.assert_array_equal(after.mesh.triangles, before.mesh.triangles)
        assert after.shading == before.shading


def test_the_transposed_matrix_is_the_column_convention_read_as_rows():
    scene = load_scene("cylinder-cone")
    broken, _ = apply_breakage("transposed-matrix", scene, RenderOptions())
    for before, after in zip(scene.objects, broken.objects):
        np.testing.assert_array_equal(after.model_to_world, before.model_to_world.T)
        assert not np.array_equal(after.model_to_world, before.model_to_world)
