"""One case in its process: the comparison gives what `scanlab compare` writes; failures become statuses."""
from __future__ import annotations

import io
import json

import numpy as np
import pytest

from compare.comparison import compare_scene
from lab.app.sweep.run_case import execute, run_one_case
from lab.loading import load_scene


def request(key="cube", kind="shape", **settings):
    return {"kind": kind, "key": key, "name": key, "settings": tuple(settings.items()), "marker": "/nonexistent"}


def test_the_one_comparison_gives_the_metrics_compare_scene_writes(tmp_path):
    scene = load_scene("textured-sphere").with_overrides(size=(96, 72), shading="gouraud", model="classic")
    written = compare_scene(scene, tmp_path, name="x")
    assert json.loads((tmp_path / "metrics.json").read_text()) == written
    outcome = run_one_case(scene, "x")
    timings = ("ours_ms", "reference_ms")
    assert {k: v for k, v in outcome.metrics.items() if k not in timings} == \
        {k: v for k, v in written.items() if k not in timings}
    assert outcome.verdict == "pass" and outcome.ours.shape == (72, 96, 3)


def test_a_failing_case_gets_the_bars_it_misses():
    """Judged as scanlab compare judges it: the painter's preset fails, as it is meant to."""
    outcome = run_one_case(load_scene("painter-fails").with_overrides(size=(96, 72)), "painter")
    assert outcome.verdict == "fails as meant" and any("coverage_mismatch" in b or "mean" in b for b in outcome.failed_bars)


def test_a_request_gives_metrics_verdict_and_the_frames():
    response = execute(request(shading="phong", size="64x48"))
    assert response["status"] == "ok" and response["verdict"] == "pass"
    assert response["metrics"]["size"] == [64, 48] and response["metrics"]["shading"] == "phong"
    with np.load(io.BytesIO(response["frames"])) as frames:
        assert frames["ours"].shape == frames["reference"].shape == (48, 64, 3)
        assert frames["delta_e"].dtype == np.float32 and frames["shared"].dtype == bool
    assert 0 <= response["load_s"] <= response["case_s"]


def test_the_reference_setting_is_passed_to_the_comparison():
    auto = execute(request(model="classic", shading="gouraud", size="64x48"))
    native = execute(request(model="classic", shading="gouraud", size="64x48", reference="vtk-native"))
    assert native["metrics"]["reference"] == "vtk-native" != auto["metrics"]["reference"]


@pytest.mark.parametrize("req, status, message", [
    (request("/no/such/file.ply", kind="mesh"), "error", "cannot load: /no/such/file.ply"),
    (request(fault="error"), "error", "RuntimeError: a test-only failure"),
])
def test_a_case_that_fails_gives_a_status_and_one_line_not_an_exception(req, status, message):
    response = execute(req)
    assert response["status"] == status and message in response["error"] and "\n" not in response["error"]
    assert "Traceback" in response["traceback"]
