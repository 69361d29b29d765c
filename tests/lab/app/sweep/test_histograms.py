"""Histograms: one figure per grid key that varies, of compared cases only."""
from __future__ import annotations

import json

from PIL import Image

from lab.app.sweep.histograms import grid_values, write_histograms


def row(shading, lights, mean, coverage=0.0, status="ok"):
    return {"status": status, "settings": json.dumps({"shading": shading, "lights": lights, "size": "64x48"}),
            "delta_e_2000_mean": mean, "coverage_mismatch": coverage}


ROWS = [row("flat", "key", 0.0), row("phong", "key", 0.02, 1e-5), row("flat", "spot", 0.3, 0.001),
        row("phong", "spot", 1.2), row("flat", "key", 9.0, status="timeout")]


def test_the_values_of_each_key_are_listed_in_the_order_met():
    assert grid_values(ROWS) == {"shading": ["flat", "phong"], "lights": ["key", "spot"], "size": ["64x48"]}


def test_a_figure_per_varying_key_is_written(tmp_path):
    written = write_histograms(ROWS, tmp_path)
    assert [p.name for p in written] == ["shading.png", "lights.png"], "size does not vary: no figure"
    with Image.open(written[0]) as image:
        assert image.size == (1100, 360)


def test_without_a_grid_one_figure_shows_all_cases_and_without_compared_cases_none(tmp_path):
    plain = [{**r, "settings": "{}"} for r in ROWS]
    assert [p.name for p in write_histograms(plain, tmp_path)] == ["all.png"]
    assert write_histograms([r for r in ROWS if r["status"] != "ok"], tmp_path / "none") == []
