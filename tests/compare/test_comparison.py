"""compare/comparison.py: one comparison in memory, the Python API and what a notebook shows."""
from __future__ import annotations

import dataclasses
import io
import json

import numpy as np
import pytest
from PIL import Image

import compare
from compare.comparison import Comparison, run_comparison, settings_line
from compare.report import OUTPUT_FILES
from lab.loading import load_scene


def test_the_api_takes_a_scene_name_and_returns_both_images_the_metrics_and_the_verdict():
    result = compare.compare("cube", size=(160, 120), timings=False)
    assert isinstance(result, Comparison) and result.passed and result.verdict.ok
    assert result.ours.shape == result.reference.shape == (120, 160, 3) and result.ours.dtype == np.uint8
    m = result.metrics
    assert m["verdict"]["status"] == "pass" and m["ours_ms"] is None and m["depth"]["compared_pixels"] > 1000
    assert set(m) >= {"scene", "shading", "size", "delta_e_2000", "pixels_over_1", "coverage_mismatch",
                      "max_channel_diff", "depth", "worst_pixel", "model", "reference", "verdict"}
    json.dumps(m)  # all of it is JSON


def test_a_notebook_cell_shows_the_panel_and_the_verdict():
    result = compare.compare(load_scene("fill-rule"), timings=False)
    png = result._repr_png_()
    with Image.open(io.BytesIO(png)) as im:
        assert im.size[0] > 3 * 200
    page = result._repr_html_()
    assert "pass" in page and "data:image/png;base64," in page
    assert result.panel_png() is png  # made once


def test_a_failing_scene_is_judged_and_the_bars_can_change(tmp_path):
    """spot-attenuation with screen-linear interpolation fails (44 % of pixels over 1, mean ΔE2000 5.07); lenient
    bars pass it."""
    scene = load_scene("spot-attenuation")
    scene = dataclasses.replace(scene, render=dataclasses.replace(scene.render, interpolation="screen"))
    result = run_comparison(scene, name="screen", timings=False)
    assert not result.passed and result.verdict.status == "FAIL"
    assert [f.split()[0] for f in result.verdict.failed] == ["pixels_over_1", "mean"]
    lenient = run_comparison(scene, name="screen", timings=False, bars={"pixels_over_1": 1.0, "mean": 6.0})
    assert lenient.passed
    result.write(tmp_path)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(OUTPUT_FILES)
    assert json.loads((tmp_path / "metrics.json").read_text())["verdict"]["failed"] == list(result.verdict.failed)


def test_the_worst_pixel_is_in_the_metrics_with_both_colours():
    """menger level 3 has one pixel where VTK's z-buffer picks another face: it is the worst, by ΔE."""
    result = compare.compare("menger:level=3", timings=False)
    worst = result.metrics["worst_pixel"]
    x, y = worst["x"], worst["y"]
    assert result.delta_e[y, x] == result.delta_e.max() == pytest.approx(worst["delta_e"], abs=1e-4)
    assert worst["ours"] == result.ours[y, x].tolist() and worst["reference"] == result.reference[y, x].tolist()
    assert f"x {x}, y {y}" in worst["caption"]
    assert compare.compare("fill-rule", timings=False).metrics["worst_pixel"] is None  # identical images


def test_the_settings_line_names_what_made_the_image():
    line = settings_line(load_scene("translucent-two"), "vtk-native")
    for words in ("model vtk", "shading mixed", "interpolation perspective", "hidden surfaces zbuffer",
                  "back faces drawn", "transparency oit", "reference vtk-native", "480×360 px"):
        assert words in line
    assert "transparency" not in settings_line(load_scene("cube"), "vtk-native")


def test_anything_else_is_refused_with_a_type_error():
    with pytest.raises(TypeError, match="Scene, a scene name or file, or a PyVista Plotter"):
        compare.compare(42)


def test_our_side_can_be_drawn_broken_while_vtk_draws_the_scene_intact():
    from renderer import RenderOptions
    from renderer.breakages import apply_breakage

    scene = load_scene("course-phong")
    scene = dataclasses.replace(scene, image=dataclasses.replace(scene.image, size=(160, 120)))
    intact = run_comparison(scene, timings=False)
    broken = run_comparison(scene, timings=False, ours=apply_breakage("face-normals", scene, RenderOptions()))
    np.testing.assert_array_equal(broken.reference, intact.reference)
    assert not np.array_equal(broken.ours, intact.ours)
    assert broken.metrics["delta_e_2000"]["mean"] > intact.metrics["delta_e_2000"]["mean"]



def test_a_side_broken_on_purpose_is_judged_as_meant_to_fail():
    from renderer import RenderOptions
    from renderer.breakages import apply_breakage

    scene = load_scene("course-phong")
    scene = dataclasses.replace(scene, image=dataclasses.replace(scene.image, size=(160, 120)))
    broken = run_comparison(scene, timings=False, ours=apply_breakage("face-normals", scene, RenderOptions()),
                            meant="face normals on purpose")
    assert broken.verdict.status == "fails as meant" and broken.metrics["verdict"]["status"] == "fails as meant"
    assert broken.metrics["verdict"]["meant_to_fail"] == "face normals on purpose"
    assert run_comparison(scene, timings=False, meant="nothing broken").verdict.status == "PASSES?"
