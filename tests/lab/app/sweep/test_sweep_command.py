"""`scanlab sweep`: the help names every grid key and light set; bad input is one line and exit 2."""
from __future__ import annotations

import pytest

from lab.app import cli
from lab.app.sweep.light_sets import LIGHT_SETS
from lab.app.sweep.settings import GRID_KEYS


def test_the_help_lists_every_grid_key_with_its_values_and_every_light_set(capsys):
    assert cli.main(["sweep", "--help"]) == 0
    shown = capsys.readouterr().out
    for name, key in GRID_KEYS.items():
        assert f"  {name:<15} {key.values}" in shown
    for name in LIGHT_SETS:
        assert f"  {name:<15} {LIGHT_SETS[name].description}" in shown
    assert "--scheduler" in shown and "  fault " not in shown, "the test-only key is not offered"


@pytest.mark.parametrize("args, message", [
    (["cube", "--grid", "shadin=flat"], "unknown grid key 'shadin' (did you mean shading?"),
    (["cube", "--grid", "size=12"], "--grid: size: expected WIDTHxHEIGHT"),
    (["cube", "--grid", "lights=sun"], "'sun' is not one of headlight"),
    (["cubee"], "cubee: no such file, folder, preset or shape"),
    ([], "no SOURCES"),
    (["cube", "--grid-file", "/no/grid.toml"], "/no/grid.toml: cannot read"),
    (["cube", "--workers", "0"], "--workers: must be at least 1"),
    (["cube", "--timeout", "-1"], "--timeout: must be more than 0 seconds"),
    (["cube", "--memory-limit", "12X"], "--memory-limit: expected a size such as 8G"),
    (["cube", "--memory-limit", "1M"], "too little"),
    (["cube", "--scheduler", "tcp://127.0.0.1:9", "--workers", "2"], "--workers sets the size of a local cluster"),
])
def test_bad_input_is_one_line_and_exit_status_2(tmp_path, capsys, args, message):
    assert cli.main(["sweep", *args, "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err


def test_an_out_that_is_a_file_is_refused(tmp_path, capsys):
    (tmp_path / "f").write_text("x")
    assert cli.main(["sweep", "cube", "--out", str(tmp_path / "f")]) == 2
    assert "is a file, not a folder" in capsys.readouterr().err
