"""lab/app/live/controls.py: the controls show a scene as loaded, give it back unchanged, and
every bad value becomes a problem named by its field, never an exception of another kind."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lab.app.live.controls import (KEYS, MATERIAL_RANGES, MAX_LIGHTS, Controls, Problems, controls_for, new_light,
                                   to_render)
from lab.loading import load_scene
from lab.scene_writer import write_scene
from renderer.breakages import BREAKAGES


def _same_scene(a, b):
    assert a.image == b.image and a.camera == b.camera and a.lights == b.lights and a.render == b.render
    assert len(a.objects) == len(b.objects)
    for x, y in zip(a.objects, b.objects):
        assert x.material == y.material and x.shading == y.shading and x.mesh is y.mesh
        np.testing.assert_array_equal(x.model_to_world, y.model_to_world)


@pytest.mark.parametrize("spec", ["course-phong", "lessons/08-lights/red-point.toml", "translucent-two",
                                  "camera-lights", "unlit-parallel", "icosphere:level=2"])
def test_the_controls_of_a_scene_give_the_same_scene_back(spec):
    scene = load_scene(spec)
    controls = replace(controls_for(scene, "key"), size="scene")
    checked = to_render(controls, scene)
    _same_scene(checked.scene, scene)
    assert checked.breakage == "" and checked.ours()[0] is checked.scene


def test_state_keys_round_trip():
    controls = controls_for(load_scene("course-phong"), "preset:course-phong")
    assert Controls.from_state(controls.to_state()) == controls
    assert set(KEYS) == set(controls.to_state())


def test_overrides_reach_every_object_and_the_size():
    scene = load_scene("course-gouraud")
    controls = replace(controls_for(scene, "k"), shading="phong", model="opengl", size="256x256")
    checked = to_render(controls, scene).scene
    assert {o.shading for o in checked.objects} == {"phong"}
    assert {o.material.model for o in checked.objects} == {"opengl"}
    assert checked.image.size == (256, 256)


def test_a_breakage_changes_our_side_only():
    scene = load_scene("directional-cubes")
    checked = to_render(replace(controls_for(scene, "k"), breakage="painter"), scene)
    ours, _ = checked.ours()
    assert checked.scene.render.hidden_surface == "zbuffer" and ours.render.hidden_surface == "painter"


def test_text_typed_into_a_field_counts_as_its_number():
    scene = load_scene("course-phong")
    c = controls_for(scene, "k")
    materials = [{**c.materials[0], "ambient": " 0.25 ", "specular_power": "12,5"}]
    checked = to_render(replace(c, materials=materials), scene).scene
    assert checked.objects[0].material.ambient == 0.25 and checked.objects[0].material.specular_power == 12.5


BAD = [
    (lambda c: {"materials": [{**c.materials[0], "opacity": 1.5}]}, "materials.0.opacity", "range"),
    (lambda c: {"materials": [{**c.materials[0], "ambient": "abc"}]}, "materials.0.ambient", "number"),
    (lambda c: {"materials": [{**c.materials[0], "diffuse": float("nan")}]}, "materials.0.diffuse", "number"),
    (lambda c: {"materials": [{**c.materials[0], "specular": True}]}, "materials.0.specular", "number"),
    (lambda c: {"materials": [{**c.materials[0], "color": "blue"}]}, "materials.0.color", "colour"),
    (lambda c: {"materials": []}, "materials", "objects"),
    (lambda c: {"lights": [{**c.lights[0], "intensity": -1}]}, "lights.0.intensity", "range"),
    (lambda c: {"lights": [{**c.lights[0], "cone_angle": 0}]}, "lights.0.cone_angle", "range"),
    (lambda c: {"lights": [{**c.lights[0], "attenuation": [0, 0, 0]}]}, "lights.0.attenuation", "attenuation"),
    (lambda c: {"lights": [{**c.lights[0], "position": [1, "x", 2]}]}, "lights.0.position.1", "number"),
    (lambda c: {"lights": [{**c.lights[0], "position": [1, 2]}]}, "lights.0.position", "vector"),
    (lambda c: {"lights": [{**c.lights[0], "kind": "sun"}]}, "lights.0.kind", "choice"),
    (lambda c: {"lights": [{**c.lights[0], "on": "yes"}]}, "lights.0.on", "flag"),
    (lambda c: {"lights": [new_light()] * (MAX_LIGHTS + 1)}, "lights", "lights"),
    (lambda c: {"camera": {**c.camera, "position": c.camera["focal_point"]}}, "camera.position", "camera_at_focus"),
    (lambda c: {"camera": {**c.camera, "view_up": [0.0, 0.5, 4.0]}}, "camera.view_up", "camera_up"),
    (lambda c: {"camera": {**c.camera, "view_angle": 180}}, "camera.view_angle", "range"),
    (lambda c: {"shading": "toon"}, "shading", "choice"),
    (lambda c: {"breakage": "everything"}, "breakage", "choice"),
    (lambda c: {"size": "99999x2"}, "size", "choice"),
    (lambda c: {"cull_backfaces": 1}, "cull_backfaces", "flag"),
]


@pytest.mark.parametrize("change,path,code", BAD)
def test_a_bad_value_is_a_problem_named_by_its_field(change, path, code):
    scene = load_scene("course-phong")  # its camera looks from (0, 0.5, 4) at the origin
    controls = controls_for(scene, "k")
    with pytest.raises(Problems) as caught:
        to_render(replace(controls, **change(controls)), scene)
    assert {p: pr.code for p, pr in caught.value.found.items()} == {path: code}


def test_every_bad_field_is_named_at_once():
    scene = load_scene("course-phong")
    c = controls_for(scene, "k")
    with pytest.raises(Problems) as caught:
        to_render(replace(c, shading="x", materials=[{**c.materials[0], "opacity": 2, "ambient": ""}]), scene)
    assert set(caught.value.found) == {"shading", "materials.0.opacity", "materials.0.ambient"}


@pytest.mark.parametrize("end", [0, 1])
def test_every_value_the_controls_accept_makes_a_scene_file_the_loader_accepts(tmp_path, end):
    """The controls' ranges are the loader's: a scene at every bound saves and loads back the same."""
    scene = load_scene("spot-attenuation")
    c = controls_for(scene, "k")
    materials = [{**m, **{k: r[end] for k, r in MATERIAL_RANGES.items()}} for m in c.materials]
    lights = [{**li, "intensity": (0.0, 1000.0)[end], "exponent": (0.0, 128.0)[end], "cone_angle": (1e-9, 180.0)[end],
               "attenuation": [(0.0, 0.0, 1e-9), (1e6, 1e6, 1e6)][end]} for li in c.lights]
    camera = {**c.camera, "view_angle": (1e-9, 179.999)[end], "parallel_scale": (1e-9, 1e6)[end]}
    checked = to_render(replace(c, materials=materials, lights=lights, camera=camera), scene).scene
    back = load_scene(write_scene(checked, tmp_path / "bounds.toml"))
    assert back.lights == checked.lights and back.camera == checked.camera
    assert [o.material for o in back.objects] == [o.material for o in checked.objects]


def test_every_breakage_is_offered():
    scene = load_scene("fill-rule")
    for name in BREAKAGES:
        assert to_render(replace(controls_for(scene, "k"), breakage=name), scene).breakage == name


def test_past_the_shared_ranges_the_loader_and_the_controls_both_refuse(tmp_path):
    """One table (lab.scene.MATERIAL_RANGES, LIGHT_RANGES) for the loader and the page."""
    from lab.scene import LIGHT_RANGES
    from lab.validation import SceneError

    scene = load_scene("spot-attenuation")
    c = controls_for(scene, "k")
    for section, ranges in (("object", MATERIAL_RANGES), ("light", LIGHT_RANGES)):
        for key, (lo, hi) in ranges.items():
            past = hi + 0.5
            text = ("[camera]\nposition = [3.0, 2.0, 4.0]\n[[light]]\nposition = [5.0, 5.0, 0.0]\n"
                    '[[object]]\nshape = "cube"\n')
            text += f"{key} = {past}\n" if section == "object" else ""
            text = text.replace("[[light]]\n", f"[[light]]\n{key} = {past}\n") if section == "light" else text
            (tmp_path / "s.toml").write_text(text)
            with pytest.raises(SceneError, match=f"{key}: {past:g} is outside"):
                load_scene(str(tmp_path / "s.toml"))
            if section == "object":
                bad = replace(c, materials=[{**m, key: past} for m in c.materials])
            else:
                bad = replace(c, lights=[{**li, key: past} for li in c.lights])
            with pytest.raises(Problems):
                to_render(bad, scene)
