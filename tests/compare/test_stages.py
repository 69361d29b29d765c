"""The stages compared: our z-buffer against VTK's, read back from the same render, in 24-bit steps.

Depth parity is a measured number, held to bars like colour parity: on every preset drawn
through the z-buffer, 99 % of the pixels both renderers cover lie within DEPTH_P99 steps and
none more than DEPTH_MAX apart. The larger differences sit where the depth plane is steep
(surfaces seen at a grazing angle, small and thin triangles): there the float32 window
coordinates VTK (llvmpipe) works in, good to about 3·10⁻⁵ pixel, move the depth by
slope × 3·10⁻⁵ — several steps on planes that rise 10⁵ steps per pixel (see docs/parity.md).
"""
from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from PIL import Image

from compare.comparison import run_comparison
from compare.reference import render_reference
from compare.stages import DEPTH_STEPS, depth_difference, depth_metrics, depth_steps, stages_figure
from compare.verdict import meant_to_fail
from lab.loading import load_scene
from lab.presets import preset_names
from renderer import render, render_stages
from renderer.camera import clipping_range

DEPTH_P99 = 4
"""Steps of the 24-bit depth buffer within which 99 % of the shared pixels lie (measured worst: 4,
directional-cubes)."""
DEPTH_MAX = 128
"""Steps no pixel may exceed (measured worst: 116, icosahedron-fractal, on a triangle of one pixel)."""
ZBUFFER_PRESETS = [n for n in preset_names() if not meant_to_fail(load_scene(n))]


def test_depth_is_counted_in_steps_of_the_24_bit_buffer():
    """Hand-made z-buffers: 1.0 is empty; differences in units of 1/(2²⁴ − 1)."""
    step = 1.0 / DEPTH_STEPS
    ours = np.array([[0.5, 0.5 + step, 1.0], [0.25, 0.25 + 3 * step, 0.75]])
    ref = np.array([[0.5, 0.5, 0.3], [0.25, 0.25, 1.0]])
    assert depth_steps([1.0, 0.0])[0] == DEPTH_STEPS
    m = depth_metrics(ours, ref)
    assert m["compared_pixels"] == 4 and m["max_steps"] == 3 and m["pixels_over_1_step"] == 1
    assert m["over_1_step"] == 0.25
    diff = depth_difference(ours, ref)
    assert diff.mask.tolist() == [[False, False, True], [False, False, True]] and diff[1, 1] == 3
    assert depth_metrics(np.ones((2, 2)), np.ones((2, 2)))["compared_pixels"] == 0


@pytest.fixture(scope="module")
def compared():
    cache = {}

    def get(name):
        if name not in cache:
            scene = load_scene(name)
            cache[name] = (scene, render(scene), render_reference(scene))
        return cache[name]

    return get


@pytest.mark.parametrize("name", ZBUFFER_PRESETS)
def test_depth_parity_on_every_preset(name, compared):
    scene, ours, ref = compared(name)
    m = depth_metrics(ours.depth, ref.depth)
    if any(o.material.opacity == 1.0 for o in scene.objects):
        assert m["compared_pixels"] > 1000
    assert m["p99_steps"] <= DEPTH_P99 and m["max_steps"] <= DEPTH_MAX, m


@pytest.mark.parametrize("name", ["spot-attenuation", "torus-mesh"])
def test_a_depth_range_off_by_one_part_in_ten_thousand_fails_the_depth_bars(name, compared):
    """The bars catch a wrong depth: the same scene with the near and far planes 0.01 % further out."""
    scene, _, ref = compared(name)
    near, far = clipping_range(scene.camera, scene.world_bounds())
    moved = dataclasses.replace(scene, camera=dataclasses.replace(scene.camera,
                                                                  clipping_range=(near * 1.0001, far * 1.0001)))
    m = depth_metrics(render(moved).depth, ref.depth)
    assert m["p99_steps"] > DEPTH_P99 or m["max_steps"] > DEPTH_MAX


def test_the_stages_figure_and_the_depth_in_metrics(tmp_path):
    """compare --stages: stages.png is written and metrics.json holds the depth figures of the same render."""
    result = run_comparison(load_scene("open-box"), name="open-box", stages=True, timings=False)
    result.write(tmp_path)
    with Image.open(tmp_path / "stages.png") as im:
        w, h = im.size
    assert w > 3 * 400 and h > 2 * 400
    assert result.metrics["depth"] == depth_metrics(result.ours_frame.depth, result.reference_frame.depth)
    culled = dataclasses.replace(result.scene, render=dataclasses.replace(result.scene.render, cull_backfaces=True))
    m = stages_figure(*render_stages(culled), render_reference(culled), tmp_path / "culled.png", culling=True)
    assert m["max_steps"] <= 3 and (tmp_path / "culled.png").stat().st_size > 10_000
