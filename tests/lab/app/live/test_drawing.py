"""lab/app/live/drawing.py: the workers' two tasks draw exactly what ``scanlab compare`` (and,
with a rule broken, ``scanlab lessons measure``) draws for the same controls."""
from __future__ import annotations

import io
from dataclasses import replace

import numpy as np
from PIL import Image

from compare.comparison import run_comparison
from lab.app.live.controls import controls_for
from lab.app.live.drawing import Job, draw_ours, measure
from lab.loading import load_scene
from renderer import render

SPEC = "spot-attenuation"


def _rgb(png: bytes) -> np.ndarray:
    with Image.open(io.BytesIO(png)) as image:
        return np.asarray(image.convert("RGB"))


def _job(**change) -> Job:
    controls = replace(controls_for(load_scene(SPEC), "preset:" + SPEC), size="256x256", **change)
    return Job(7, controls, SPEC, SPEC)


def test_our_image_is_the_renderers_image_of_the_controls():
    scene = load_scene(SPEC).with_overrides(size=(256, 256), shading="gouraud")
    np.testing.assert_array_equal(_rgb(draw_ours(_job(shading="gouraud"))["png"]), render(scene).rgb)


def test_our_image_shows_the_rule_broken():
    from renderer import RenderOptions
    from renderer.breakages import apply_breakage

    scene = load_scene(SPEC).with_overrides(size=(256, 256))
    broken = render(*apply_breakage("screen-interpolation", scene, RenderOptions())).rgb
    assert not np.array_equal(broken, render(scene).rgb)
    np.testing.assert_array_equal(_rgb(draw_ours(_job(breakage="screen-interpolation"))["png"]), broken)


def test_the_measurement_is_the_comparison_run_of_the_same_scene():
    scene = load_scene(SPEC).with_overrides(size=(256, 256))
    expected = run_comparison(scene, name=SPEC, timings=False)
    got = measure(_job())
    assert got["metrics"] == expected.metrics
    np.testing.assert_array_equal(_rgb(got["vtk"]), expected.reference)
    assert _rgb(got["delta_e"]).shape == (256, 256, 3) and got["stages"] is None


def test_a_broken_rule_breaks_our_side_and_fails_as_meant():
    intact, broken = measure(_job()), measure(_job(breakage="screen-interpolation"))
    assert intact["metrics"]["verdict"]["status"] == "pass"
    assert broken["metrics"]["verdict"]["status"] == "fails as meant"
    assert broken["vtk"] == intact["vtk"] and broken["delta_e"] != intact["delta_e"]


def test_the_stage_views_come_when_asked():
    got = measure(_job()._replace(stages=True))
    assert _rgb(got["stages"]).shape[1] > 3 * 256
