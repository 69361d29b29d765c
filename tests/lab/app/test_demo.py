"""scanlab demo: presets, scene files, mesh files and shapes; one judge; a scene file and a command per panel."""
from __future__ import annotations

import json
import shlex

from lab.app.demo import describe, reproduce_command, scene_name
from lab.loading import load_scene


def test_demo_takes_a_preset_a_scene_file_and_a_mesh_file(demo_run):
    out, specs, status = demo_run
    assert status == 0
    rows = json.loads((out / "summary.json").read_text())["scenes"]
    assert [r["scene"] for r in rows] == ["fill-rule", "mine", "torus"]
    assert all(r["verdict"]["status"] == "pass" for r in rows)
    assert rows[1]["description"] == "my own scene: two boxes, parallel camera"
    assert rows[2]["description"].startswith("the mesh file torus.ply (1,024 triangles)")
    for r in rows:
        assert (out / r["scene"] / "side_by_side.png").is_file()


def test_every_panel_has_its_scene_file_beside_it_and_a_command_that_reproduces_it(demo_run, tmp_path):
    from lab.app.cli import main

    out, specs, _ = demo_run
    rows = json.loads((out / "summary.json").read_text())["scenes"]
    from lab.presets import preset_path

    assert (out / "fill-rule" / "scene.toml").read_bytes() == preset_path("fill-rule").read_bytes()
    assert (out / "mine" / "scene.toml").read_text() == open(specs[1]).read()
    torus = load_scene(out / "torus" / "scene.toml")  # written out: it loads on its own
    assert torus.objects[0].mesh.n_triangles == 1024
    # the command, run again into another folder, gives the same metrics
    words = shlex.split(rows[1]["command"])
    assert words[:2] == ["scanlab", "compare"] and words[-2] == "--out"
    assert main(words[1:-1] + [str(tmp_path)]) == 0
    again = json.loads((tmp_path / "metrics.json").read_text())
    assert again["delta_e_2000"] == rows[1]["delta_e_2000"] and again["scene"] == "mine"


def test_names_descriptions_and_commands_of_each_kind_of_scene():
    assert scene_name("globe") == "globe" and scene_name("a/b/suzanne.obj") == "suzanne"
    assert scene_name("icosphere:level=3") == "icosphere_level3"
    assert describe("menger:level=1", load_scene("menger:level=1")).startswith("the built-in shape menger:level=1")
    assert reproduce_command("globe", __import__("pathlib").Path("out/demo/globe")) == \
        "scanlab compare globe --out out/demo/globe"


def test_demo_exits_1_when_a_scene_fails(tmp_path):
    """One judge: a scene file that fails the bars makes the demo exit 1, and the page says FAIL."""
    from lab.app.cli import main
    from tests.lab.app.test_cli import _screen_linear

    assert main(["demo", "--out", str(tmp_path / "o"), str(_screen_linear(tmp_path))]) == 1
    assert "FAIL" in (tmp_path / "o" / "index.html").read_text()
