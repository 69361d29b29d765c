"""Parity: scanlab's renderer against a real VTK render of the same scene.

The bars (issue 2): coverage mismatch ≤ 0.02 % of all pixels, pixels with ΔE2000 > 1
≤ 0.2 % of the shared ones, mean ΔE2000 ≤ 0.1. Every preset scene is held to them; a
deliberately wrong pipeline must fail them.
"""
from __future__ import annotations

import dataclasses

import pytest

from compare.metrics import measure
from compare.reference import render_reference
from compare.metrics import PARITY_BARS as BARS, failed_bars
from lab.normals import scene_with_normals
from compare.verdict import meant_to_fail
from lab.loading import load_scene
from lab.presets import SCENES_DIR
from renderer import RenderOptions, render

PRESETS = sorted(p.stem for p in SCENES_DIR.glob("*.toml") if not meant_to_fail(load_scene(p)))
VTK_PRESETS = [n for n in PRESETS if all(o.material.model == "vtk" for o in load_scene(n).objects)]


def assert_within_bars(m):
    assert not failed_bars(m), m



@pytest.fixture(scope="module")
def references():
    """VTK's frame per preset, rendered once for the module."""
    cache = {}

    def get(name):
        if name not in cache:
            cache[name] = render_reference(load_scene(name))
        return cache[name]

    return get


def test_presets_cover_the_required_cases():
    """The parity scenes cover every light kind, both projections and both clipping modes."""
    scenes = [load_scene(n) for n in VTK_PRESETS]
    lights = [li for s in scenes for li in s.lights]
    assert len(scenes) >= 8
    assert {li.kind for li in lights} >= {"scene", "camera", "headlight"}
    assert any(li.positional and li.cone_angle < 90 and li.attenuation != (1.0, 0.0, 0.0) for li in lights)
    assert any(li.positional and li.cone_angle >= 90 for li in lights)
    assert any(not li.on for li in lights) and any(not o.material.lighting for s in scenes for o in s.objects)
    assert sum(1 for s in scenes for li in s.lights if li.kind == "scene" and not li.positional) >= 3
    assert {s.camera.parallel for s in scenes} == {True, False}
    assert {s.camera.clipping_range is None for s in scenes} == {True, False}
    assert any(s.image.size[0] != s.image.size[1] for s in scenes)
    assert any(o.mesh.point_normals is not None for s in scenes for o in s.objects)  # a mesh file


@pytest.mark.parametrize("name", PRESETS)
def test_each_preset_matches_its_reference(name, references):
    """Each preset as written (VTK presets flat, textbook presets in their own model): within the bars."""
    assert_within_bars(measure(render(load_scene(name)), references(name)))


@pytest.mark.parametrize("shading", ["gouraud", "phong"])
@pytest.mark.parametrize("name", VTK_PRESETS)
def test_vtk_smooth_shading_matches_vtk(name, shading):
    """VTK model, gouraud and phong (per-pixel, interpolated normals): file normals or computed ones."""
    scene = scene_with_normals(load_scene(name), 40.0).with_overrides(shading=shading)
    assert_within_bars(measure(render(scene), render_reference(scene)))


def test_near_plane_scene_really_crosses_the_near_plane():
    """The near-plane preset has triangles with vertices on both sides of the near plane."""
    from renderer.camera import clipping_range, view_to_clip, world_to_view
    from renderer.pipeline import transform_scene

    scene = load_scene("near-plane")
    cam = scene.camera
    v2c = view_to_clip(cam, scene.image.size[0] / scene.image.size[1], clipping_range(cam, scene.world_bounds()))
    geo = transform_scene(scene, world_to_view(cam), v2c)
    clip = geo.verts_clip[geo.triangles]
    behind = clip[..., 2] < -clip[..., 3]
    assert (behind.any(axis=1) & ~behind.all(axis=1)).any()


# ---------------------------------------------------------------- the check can fail
def test_wrong_fill_rule_fails_the_bars(references):
    """Giving edge pixels to right/top edges instead of left/bottom breaks coverage parity."""
    m = measure(render(load_scene("fill-rule"), RenderOptions(fill_rule="bottom-right")), references("fill-rule"))
    assert m["coverage_mismatch"] > BARS["coverage_mismatch"]
    assert failed_bars(m)


def test_swapped_light_frame_fails_the_bars(references):
    """Camera lights treated as scene lights (world frame) light the wrong sides."""
    scene = load_scene("camera-lights")
    swapped = dataclasses.replace(scene, lights=tuple(dataclasses.replace(li, kind="scene") for li in scene.lights))
    m = measure(render(swapped), references("camera-lights"))
    assert m["pixels_over_1"] > BARS["pixels_over_1"] and m["delta_e_2000"]["mean"] > BARS["mean"]


def test_screen_linear_interpolation_fails_the_bars(references):
    """Fragment positions (so depth along the view) interpolated linearly in screen space
    instead of perspective-correctly put the spot light's pool in the wrong place."""
    m = measure(render(load_scene("spot-attenuation"), RenderOptions(interpolation="screen")),
                references("spot-attenuation"))
    assert m["pixels_over_1"] > BARS["pixels_over_1"] and m["delta_e_2000"]["mean"] > BARS["mean"]
