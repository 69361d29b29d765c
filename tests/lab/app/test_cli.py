"""The scanlab command: outputs, exit statuses and one-line errors."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from lab.app.cli import main

REPO = Path(__file__).resolve().parents[3]


def run(*args, env=None):
    """``python -m lab ARGS`` in a child process: (status, stdout, stderr)."""
    full_env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")]))
    full_env.update(env or {})
    p = subprocess.run([sys.executable, "-m", "lab", *args], capture_output=True, text=True, env=full_env,
                       timeout=300)
    return p.returncode, p.stdout, p.stderr


def test_compare_writes_five_files_and_the_metrics(tmp_path, capsys):
    """compare writes ours/vtk/delta_e/side_by_side PNGs and metrics.json with every documented key."""
    assert main(["compare", "cube", "--size", "160x120", "--out", str(tmp_path / "c")]) == 0
    out = tmp_path / "c"
    for name in ("ours.png", "vtk.png", "delta_e.png", "side_by_side.png", "metrics.json"):
        assert (out / name).stat().st_size > 0, name
    m = json.loads((out / "metrics.json").read_text())
    assert set(m) >= {"scene", "shading", "size", "delta_e_2000", "pixels_over_1", "coverage_mismatch",
                      "max_channel_diff", "ours_ms", "reference_ms", "reference"}
    assert set(m["delta_e_2000"]) == {"mean", "median", "p95", "p99", "p999", "max"}
    assert m["size"] == [160, 120] and m["reference"] == "vtk-native"
    assert "ΔE2000 mean" in capsys.readouterr().out


def test_fail_above_exits_1_only_when_p999_exceeds(tmp_path):
    """--fail-above DE (a p999 bar beside the parity bars): exit 1 when the 99.9th percentile ΔE2000 is above
    DE, else 0."""
    # headlight-icosphere has a few 1-LSB pixels: its p99.9 lies between 0 and 5
    assert main(["compare", "headlight-icosphere", "--out", str(tmp_path / "a"), "--fail-above", "5"]) == 0
    assert main(["compare", "headlight-icosphere", "--out", str(tmp_path / "b"), "--fail-above", "0"]) == 1


def test_shading_and_size_overrides_reach_metrics(tmp_path):
    """--shading and --size override the scene's values."""
    assert main(["compare", "torus-mesh", "--shading", "phong", "--size", "96x64", "--out", str(tmp_path)]) == 0
    m = json.loads((tmp_path / "metrics.json").read_text())
    assert m["shading"] == "phong" and m["size"] == [96, 64]


@pytest.mark.parametrize("args, words", [
    (["render", "no-such-scene"], ["no-such-scene"]),
    (["render", "icosphere:level=x"], ["level"]),
    (["render", "cube:sides=3"], ["sides"]),
])
def test_bad_scene_names_end_in_one_line_and_status_2(args, words, tmp_path):
    """A bad scene or shape: exit 2, one line on stderr naming it, no traceback."""
    status, _, err = run(*args, "-o", str(tmp_path / "x.png"))
    assert status == 2
    assert len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert all(w in err for w in words)


def test_bad_scene_file_key_is_named(tmp_path):
    """An unknown key in a scene file: the message names the file and the key, with a suggestion."""
    bad = tmp_path / "bad.toml"
    bad.write_text('[camera]\nview_angel = 30.0\n[[object]]\nshape = "cube"\n')
    status, _, err = run("render", str(bad), "-o", str(tmp_path / "x.png"))
    assert status == 2 and str(bad) in err and "camera.view_angel" in err and "view_angle" in err
    assert not (tmp_path / "x.png").exists()


def test_no_opengl_context_is_one_line_naming_packages(tmp_path):
    """When EGL finds no driver, scanlab says so in one line and names the Debian packages."""
    status, _, err = run("reference", "cube", "-o", str(tmp_path / "v.png"),
                         env={"__EGL_VENDOR_LIBRARY_FILENAMES": str(tmp_path / "none.json")})
    assert status == 2 and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1
    assert "OpenGL" in err and "libegl1" in err and "libgl1-mesa-dri" in err


def test_python_m_lab_renders_and_prints_the_path(tmp_path):
    """python -m lab works like scanlab and says where the output went."""
    out = tmp_path / "deep" / "dir" / "o.png"
    status, stdout, _ = run("render", "icosahedron", "--size", "64x48", "-o", str(out))
    assert status == 0 and out.is_file() and str(out) in stdout


def test_scenes_lists_every_preset(capsys):
    """scanlab scenes lists each preset with its one-line description."""
    assert main(["scenes"]) == 0
    out = capsys.readouterr().out
    for p in (REPO / "lab" / "scenes").glob("*.toml"):
        assert p.stem in out


@pytest.mark.parametrize("preset", sorted(p.stem for p in (REPO / "lab" / "scenes").glob("*.toml")))
def test_every_preset_compares_from_the_command_line(preset, tmp_path, capsys):
    """scanlab compare PRESET --fail-above 1: exit 0 — a pass (the parity bars and p99.9 ΔE2000 under one
    JND), or, for the presets made to show a failure (the painter's algorithm), a failure as meant."""
    from compare.verdict import meant_to_fail
    from lab.loading import load_scene

    expected = "fails as meant" if meant_to_fail(load_scene(preset)) else "pass"
    assert main(["compare", preset, "--out", str(tmp_path), "--fail-above", "1.0"]) == 0
    m = json.loads((tmp_path / "metrics.json").read_text())
    assert m["scene"] == preset and m["verdict"]["status"] == expected


# --------------------------------------------------------------------------- the verdict
def _screen_linear(tmp_path) -> Path:
    """spot-attenuation with screen-linear interpolation: a scene file that fails the parity bars."""
    text = (REPO / "lab" / "scenes" / "spot-attenuation.toml").read_text()
    assert "[render]" not in text
    path = tmp_path / "screen.toml"
    path.write_text('[render]\ninterpolation = "screen"\n' + text)
    return path


def test_compare_passes_with_exit_0_and_says_so(tmp_path):
    status, out, err = run("compare", "cube", "--size", "160x120", "--out", str(tmp_path))
    assert status == 0 and out.strip().splitlines()[-1] == "pass" and err.strip() == ""
    assert json.loads((tmp_path / "metrics.json").read_text())["verdict"] == {
        "status": "pass", "ok": True, "met_bars": True, "failed": [], "meant_to_fail": None,
        "bars": {"coverage_mismatch": 0.0002, "pixels_over_1": 0.002, "mean": 0.1}}


def test_compare_fails_with_exit_1_naming_the_bars(tmp_path):
    """The issue's case: screen-linear interpolation. FAIL with the bars it missed, exit 1, in metrics.json too."""
    status, out, err = run("compare", str(_screen_linear(tmp_path)), "--out", str(tmp_path / "o"))
    assert status == 1
    assert err.strip().startswith("FAIL: pixels_over_1 ") and "mean " in err and "Traceback" not in err
    v = json.loads((tmp_path / "o" / "metrics.json").read_text())["verdict"]
    assert v["status"] == "FAIL" and not v["ok"] and [f.split()[0] for f in v["failed"]] == ["pixels_over_1", "mean"]


def test_the_bars_can_be_set_from_the_command_line(tmp_path):
    scene = str(_screen_linear(tmp_path))
    assert main(["compare", scene, "--out", str(tmp_path / "a"), "--bar", "pixels_over_1=1", "--bar", "mean=6"]) == 0
    assert main(["compare", "cube", "--out", str(tmp_path / "b"), "--bar", "max_channel_diff=0"]) in (0, 1)
    m = json.loads((tmp_path / "b" / "metrics.json").read_text())
    assert m["verdict"]["bars"]["max_channel_diff"] == 0 and m["verdict"]["met_bars"] == (m["max_channel_diff"] == 0)


def test_stages_writes_the_stage_figure_and_the_depth_figures(tmp_path, capsys):
    assert main(["stages", "open-box", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "depth (ours − VTK, 24-bit steps) max" in out and (tmp_path / "stages.png").stat().st_size > 10_000
    assert set(json.loads((tmp_path / "metrics.json").read_text())["depth"]) == {
        "max_steps", "p99_steps", "pixels_over_1_step", "over_1_step", "compared_pixels"}
    assert main(["compare", "cube", "--size", "96x64", "--stages", "--out", str(tmp_path / "c")]) == 0
    assert (tmp_path / "c" / "stages.png").is_file()


def test_scenes_lists_every_shape_with_its_parameters(capsys):
    from lab.shapes import SHAPES

    assert main(["scenes"]) == 0
    out = capsys.readouterr().out
    for name in SHAPES:
        assert f"  {name}:" in out
    assert "menger:level=2 (0..4),keep_internal=0 (0..1)" in out


def test_export_toml_writes_a_scene_that_loads_back(tmp_path, capsys):
    from lab.loading import load_scene

    assert main(["export", "menger:level=1", "-o", str(tmp_path / "m.toml")]) == 0
    assert load_scene(tmp_path / "m.toml").objects[0].mesh.n_triangles == load_scene(
        "menger:level=1").objects[0].mesh.n_triangles
    assert "m-files" in capsys.readouterr().out


def test_a_mesh_file_is_a_scene_everywhere(tmp_path, capsys):
    torus = str(REPO / "lab" / "scenes" / "models" / "torus.ply")
    assert main(["info", torus]) == 0 and "1024 triangles" in capsys.readouterr().out
    assert main(["compare", torus, "--size", "128x96", "--out", str(tmp_path)]) == 0
    assert json.loads((tmp_path / "metrics.json").read_text())["scene"] == "torus"
