"""Panels of a kept case, drawn from its frames with the figures of its row."""
from __future__ import annotations

import json

from PIL import Image

from lab.app.sweep.panels import case_title, draw_panels, metrics_of
from lab.app.sweep.run_case import execute
from lab.app.sweep.table import row_for
from lab.app.sweep.cases import Case
from lab.app.sweep.sources import Source


def test_a_kept_case_gets_both_panels_and_a_case_without_frames_none(tmp_path):
    case = Case(Source("shape", "cube", "cube"), (("shading", "phong"), ("size", "80x60")))
    response = execute({"kind": "shape", "key": "cube", "name": case.label, "settings": case.settings,
                        "marker": "/nonexistent"})
    (tmp_path / "frames.npz").write_bytes(response.pop("frames"))
    row = row_for(case, response, "r")
    assert case_title(row) == "cube · shading=phong · size=80x60"
    assert metrics_of(row)["delta_e_2000"] == response["metrics"]["delta_e_2000"]
    assert draw_panels(tmp_path, row)
    for name in ("side_by_side.png", "delta_e.png"):
        with Image.open(tmp_path / name) as image:
            assert image.width > 160 and image.height > 60
    stamp = (tmp_path / "side_by_side.png").stat().st_mtime_ns
    assert draw_panels(tmp_path, row) and (tmp_path / "side_by_side.png").stat().st_mtime_ns == stamp, \
        "panels newer than the frames are not drawn again"
    assert not draw_panels(tmp_path / "elsewhere", row)
    assert json.loads(row["settings"]) == dict(case.settings)
