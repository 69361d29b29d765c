"""One file judged: verdicts and exit statuses, return types, and a checker that never raises."""
from dataclasses import replace

import numpy as np
import pytest

from lab.app.exercises.checker import Report, check_file, type_problem
from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.exercise_registry import get

from .checked_fixtures import FIXTURES, LIMITS, judged

MENGER = get("menger")


@pytest.mark.parametrize("codes, status, verdict", [([], 0, "right"), (["faces-inward"], 1, "wrong"),
                                                    (["faces-inward", "syntax-error"], 2, "cannot-judge")])
def test_the_verdict_follows_the_findings(codes, status, verdict):
    report = Report("menger", "x.py", [Finding(c) for c in codes])
    assert (report.status, report.verdict) == (status, verdict)


def test_return_types_are_checked_against_the_outputs():
    cases = MENGER.cases()[:1]
    points, tris = np.zeros((8, 3)), np.zeros((12, 3), np.int64)
    assert type_problem(MENGER, cases, [[points, tris]]) is None
    bad = type_problem(MENGER, cases, [[points, tris.astype(float)]])
    assert bad.code == "wrong-return-type" and "float64" in bad.details["message"]
    assert "(12, 4)" in type_problem(MENGER, cases, [[points, np.zeros((12, 4), int)]]).details["message"]


def test_outputs_may_depend_on_arguments_and_on_each_other():
    raster, cylinder = get("covered_pixels"), get("cylinder")
    case = raster.cases()[0]
    h, w = case.args[4], case.args[3]
    assert type_problem(raster, [case], [[np.zeros((h, w), bool)]]) is None
    assert type_problem(raster, [case], [[np.zeros((w, h + 1), bool)]]) is not None
    c = cylinder.cases()[0]
    ok = [np.zeros((5, 3)), np.zeros((2, 3), int), np.zeros((5, 3))]
    assert type_problem(cylinder, [c], [ok]) is None
    assert type_problem(cylinder, [c], [[ok[0], ok[1], np.zeros((4, 3))]]) is not None


def test_a_checker_bug_is_reported_not_raised():
    def broken(cases, results):
        raise ZeroDivisionError("a bug in a judge")
    exercise = replace(get("perspective"), judge=broken)
    report = check_file(exercise, FIXTURES / "perspective" / "right.py", LIMITS)
    assert (report.verdict, report.codes) == ("cannot-judge", ["checker-error"])
    assert "ZeroDivisionError: a bug in a judge" in report.findings[0].details["message"]


def test_the_lines_printed_say_verdict_diagnosis_and_what_was_checked():
    lines = judged("menger", "inward").lines("en")
    assert lines[0] == "menger: inward.py: wrong (exit status 1)"
    assert lines[1].startswith("  [faces-inward] 12 of 12 triangles (menger(0)) point inward")
    assert "  checked:" in lines
    assert judged("menger", "inward").lines("ja")[0] == "menger: inward.py: 不正解（終了ステータス 1）"


def test_what_an_unjudgeable_file_printed_is_shown(tmp_path):
    path = tmp_path / "menger.py"
    path.write_text("def menger(level):\n    print('computing level', level)\n    return 1 / 0\n")
    lines = check_file(MENGER, path, LIMITS).lines("en")
    assert lines[0].endswith("cannot-judge (exit status 2)")
    assert "    | computing level 0" in lines


def test_an_edit_to_the_renderer_s_fill_rule_changes_the_raster_exercise_s_reference(tmp_path):
    """The checker's references are the renderer's kernels, cached by the hash of all renderer
    sources (renderer/jit.py): editing the tie rule in raster.py — a callee that coverage.py's
    kernel inlines, in another file — must change the verdict on the right solution in the
    next check, not leave the old kernel in place."""
    import os
    import shutil
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[4]
    tree = tmp_path / "copy"
    for package in ("lab", "renderer", "compare", "lessons"):
        shutil.copytree(root / package, tree / package, ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    env = {k: v for k, v in os.environ.items() if k not in ("SCANLAB_KERNEL_CACHE", "NUMBA_CACHE_DIR")}
    env["PYTHONPATH"] = str(tree)
    solution = FIXTURES / "covered_pixels" / "right.py"

    def check():
        return subprocess.run([sys.executable, "-m", "lab", "exercise", "check", "covered_pixels", str(solution)],
                              cwd=tree, env=env, capture_output=True, text=True, timeout=600)

    first = check()
    assert first.returncode == 0, first.stdout + first.stderr
    raster = tree / "renderer" / "raster.py"
    source = raster.read_text()
    rule = "owned = dx > 0 if rule == TOP_LEFT else dx < 0"
    assert source.count(rule) == 1
    raster.write_text(source.replace(rule, "owned = dx < 0 if rule == TOP_LEFT else dx > 0"))
    edited = check()
    assert edited.returncode == 1, edited.stdout + edited.stderr
    assert "[coverage-differs]" in edited.stdout
