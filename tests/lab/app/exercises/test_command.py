"""``scanlab exercise list|start|check|grade``: names, outputs and exit statuses as fixed."""
import subprocess
import sys

import pytest

from lab.app.cli import main

from .checked_fixtures import FIXTURES


def scanlab(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "lab", "exercise", *map(str, args)], capture_output=True, text=True,
                          timeout=600, cwd=cwd)


def test_list_names_every_exercise_with_its_lesson(capsys):
    assert main(["exercise", "list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) >= 8
    assert any(line.split()[:2] == ["menger", "01-polygon-model"] for line in lines)
    assert main(["exercise", "list", "--lang", "ja"]) == 0
    assert "メンガーのスポンジ" in capsys.readouterr().out


def test_start_writes_the_starter_once(tmp_path, capsys):
    assert main(["exercise", "start", "cone", str(tmp_path / "work")]) == 0
    starter = tmp_path / "work" / "cone.py"
    assert "raise NotImplementedError" in starter.read_text()
    assert f"wrote {starter}" in capsys.readouterr().out
    assert main(["exercise", "start", "cone", str(tmp_path / "work")]) == 2
    assert capsys.readouterr().err.strip() == f"scanlab exercise: {starter}: already exists; remove it or give another folder"


@pytest.mark.parametrize("fixture, status", [("right", 0), ("whole_angle", 1)])
def test_check_exits_0_when_right_and_1_when_wrong(fixture, status):
    done = scanlab("check", "perspective", FIXTURES / "perspective" / f"{fixture}.py")
    assert done.returncode == status, done.stdout + done.stderr
    assert done.stdout.splitlines()[0].endswith(f"(exit status {status})")


def test_check_exits_2_when_the_file_cannot_be_judged(tmp_path):
    (tmp_path / "p.py").write_text("def perspective(view_angle, aspect, near, far)\n    pass\n")
    done = scanlab("check", "perspective", tmp_path / "p.py", "--lang", "ja")
    assert done.returncode == 2 and "[syntax-error]" in done.stdout and "採点できません" in done.stdout


def test_the_starter_itself_cannot_be_judged_yet(tmp_path):
    assert main(["exercise", "start", "menger", str(tmp_path)]) == 0
    done = scanlab("check", "menger", tmp_path / "menger.py")
    assert done.returncode == 2 and "[not-implemented]" in done.stdout


@pytest.mark.parametrize("args, message", [
    (["check", "mengre", "x.py"], "no exercise called 'mengre' (did you mean menger?"),
    (["check", "menger", "no-such.py"], "no-such.py: no such file"),
    (["grade", "menger", "no-such-folder", "--out", "o"], "no-such-folder: not a folder"),
    (["start", "nothing"], "no exercise called 'nothing'"),
])
def test_usage_errors_are_one_line_and_exit_2(tmp_path, capsys, args, message):
    assert main(["exercise", *args]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and message in err and "Traceback" not in err


def test_check_out_writes_the_panels(tmp_path):
    done = scanlab("check", "look_at", FIXTURES / "look_at" / "mirrored.py", "--out", tmp_path)
    assert done.returncode == 1
    assert sorted(p.name for p in tmp_path.iterdir()) == ["mirrored-panel.png", "mirrored-vtk.png"]
    assert f"wrote {tmp_path / 'mirrored-panel.png'}" in done.stdout
