"""A class graded: the fixture class of the Menger sponge (right, every wrong kind, a syntax
error, an endless loop, a memory bomb, an exception, ...) into grades.csv and index.html,
in parallel, within limits; every row's verdict tested; the page opened in a real browser."""
import csv
import shutil
import subprocess
import sys
import time

import pytest

from lab.app.exercises import grader
from lab.app.exercises.grader import grade_folder, grades_csv
from lab.app.exercises.sandbox import Limits

from ....browser import broken_images, open_browser, watch
from .checked_fixtures import FIXTURES

EXPECTED = {
    "calls_exit.py": ("cannot-judge", "exited"),
    "centre_only.py": ("wrong", "wrong-subcubes"),
    "exception.py": ("cannot-judge", "exception"),
    "infinite_loop.py": ("cannot-judge", "time-limit"),
    "internal_faces.py": ("wrong", "internal-faces-kept"),
    "inward.py": ("wrong", "faces-inward"),
    "memory_bomb.py": ("cannot-judge", "memory-limit"),
    "not_started.py": ("cannot-judge", "not-implemented"),
    "prints_too_much.py": ("cannot-judge", "output-limit"),
    "reference.py": ("right", ""),
    "right.py": ("right", ""),
    "syntax_error.py": ("cannot-judge", "syntax-error"),
    "unmerged.py": ("wrong", "points-not-merged"),
    "unscaled.py": ("wrong", "wrong-scale"),
    "wrong_types.py": ("cannot-judge", "wrong-return-type"),
}
TIME_LIMIT = 4


@pytest.fixture(scope="module")
def graded(tmp_path_factory):
    out = tmp_path_factory.mktemp("grades")
    started = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "lab", "exercise", "grade", "menger", str(FIXTURES / "menger"),
                           "--out", str(out), "--workers", "2", "--time-limit", str(TIME_LIMIT)],
                          capture_output=True, text=True, timeout=900)
    seconds = time.perf_counter() - started
    print(f"graded the {len(EXPECTED)}-file menger class with 2 workers in {seconds:.1f} s")
    return out, done, seconds


def test_the_class_is_graded_into_the_csv_with_every_verdict_right(graded):
    out, done, _ = graded
    assert done.returncode == 0, done.stderr
    with open(out / "grades.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["file"] for r in rows] == sorted(EXPECTED)
    for r in rows:
        verdict, code = EXPECTED[r["file"]]
        assert (r["verdict"], r["codes"].split(" ")[0]) == (verdict, code), r
        assert float(r["seconds"]) > 0


def test_grading_stays_within_the_limits(graded):
    """Fifteen files, two of them stopped by limits, graded side by side: far less than one limit per file."""
    _, done, seconds = graded
    assert seconds < 5 * TIME_LIMIT * 2 + 60
    assert "15 graded in" in done.stdout and "[##############################] 15/15" in done.stdout


def test_the_page_reads_in_a_real_browser(graded, tmp_path):
    out, _, _ = graded
    with open_browser() as browser:
        page = browser.new_page(viewport={"width": 1400, "height": 1000})
        log = watch(page)
        page.goto((out / "index.html").resolve().as_uri())
        page.evaluate("document.querySelectorAll('img').forEach(i => i.loading = 'eager')")
        page.wait_for_load_state("networkidle")
        page.wait_for_function("Array.from(document.images).every(i => i.complete)")
        assert log.problems() == [] and broken_images(page) == []
        assert page.locator("tbody tr").count() == len(EXPECTED)
        images = page.locator("img").count()
        assert images == 2 * sum(v == "right" or v == "wrong" for v, _ in EXPECTED.values())
        assert page.locator("td.v.wrong").count() == 5 and page.locator("td.v.right").count() == 2
        shot = tmp_path / "grades.png"
        page.screenshot(path=str(shot), full_page=True)
    assert shot.stat().st_size > 50_000


def test_a_worker_that_fails_or_hangs_costs_one_row_not_the_class(tmp_path, monkeypatch):
    """A job the worker cannot do, and one that takes longer than allowed, both become checker-error rows."""
    sleeper = tmp_path / "sleeper.py"
    sleeper.write_text("import time\ndef perspective(a, b, c, d):\n    time.sleep(30)\n")
    right = tmp_path / "right.py"
    shutil.copy(FIXTURES / "perspective" / "right.py", right)
    limits = Limits(cpu_seconds=5, wall_seconds=60)           # the sandbox alone would wait a minute
    monkeypatch.setattr(grader, "DRAWING_SECONDS", 10 - limits.wall)  # the grader waits 10 s per submission
    started = time.perf_counter()
    rows = grade_folder("perspective", [sleeper, right], tmp_path / "out", 1, limits)
    assert time.perf_counter() - started < 40
    assert [(r["file"], r["verdict"], r["codes"]) for r in rows] == [
        ("sleeper.py", "cannot-judge", ["checker-error"]), ("right.py", "right", [])]
    assert "no answer within 10 s" in rows[0]["messages"]["en"][0]
    rows = grade_folder("no-such-exercise", [right], tmp_path / "out", 1, limits)
    assert rows[0]["codes"] == ["checker-error"] and "KeyError" in rows[0]["messages"]["en"][0]


def test_the_csv_has_one_line_per_file():
    rows = [{"file": "a.py", "verdict": "wrong", "codes": ["faces-inward", "render-differs"], "seconds": 1.234}]
    assert grades_csv(rows) == "file,verdict,codes,seconds\na.py,wrong,faces-inward render-differs,1.23\n"
