"""The sandbox: student code runs in a separate, limited process, and every way it can end
is one result — never an exception or a hang in the checker.

Each case writes a tiny student file and runs it with short limits (1–2 s of CPU).
"""
from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np
import pytest

from lab.app.exercises.sandbox import Limits, read_results, run_submission

FAST = Limits(cpu_seconds=5, wall_seconds=30)
"""Generous: the machine is shared, and a memory bomb needs CPU time to fill its gigabyte."""


def run(tmp_path: Path, body: str, cases=((2,),), n_outputs=2, limits=FAST, name="solution.py"):
    path = tmp_path / name
    path.write_text("import numpy as np\nimport os, sys, time\n\n" + body)
    return run_submission(path, "f", [list(c) for c in cases], n_outputs, limits)


def test_arrays_come_back_case_by_case(tmp_path):
    r = run(tmp_path, "def f(n):\n    print('hello', n)\n    return np.arange(n), [[1.5, 2, 3]] * n\n",
            cases=[(2,), (3,)])
    assert r.ok and r.output == "hello 2\nhello 3\n"
    assert [a.tolist() for a in r.results[1]] == [[0, 1, 2], [[1.5, 2, 3]] * 3]


def test_lists_among_the_arguments_arrive_as_float_arrays(tmp_path):
    r = run(tmp_path, "def f(v, n):\n    return np.array([v.dtype == np.float64, isinstance(n, int)])\n",
            cases=[([1, 2], 3)], n_outputs=1)
    assert r.results[0][0].tolist() == [True, True]


@pytest.mark.parametrize("body, code, detail", [
    ("def f(n)\n    return 1\n", "syntax-error", {"line": 4}),
    ("def f(n):\n    return [0][n]\n", "exception", {"type": "IndexError", "line": 5, "case": 0}),
    ("raise ValueError('at import')\n", "exception", {"type": "ValueError", "stage": "import"}),
    ("def f(n):\n    raise NotImplementedError\n", "not-implemented", {"line": 5}),
    ("def g(n):\n    return 1\n", "missing-function", {"defined": ["g"]}),
    ("def f(n):\n    sys.exit(3)\n", "exited", {"message": "3"}),
    ("def f(n):\n    os._exit(4)\n", "exited", {"message": "4"}),
    ("def f(n):\n    return 'abc', {1: 2}\n", "wrong-return-type", {"item": 0}),
    ("def f(n):\n    return np.zeros(2)\n", "wrong-return-type", {"case": 0}),
    ("def f(n):\n    return np.zeros((10**6, 10**6)), 1\n", "memory-limit", {"memory_mb": 1024}),
    ("def f(n):\n    x = []\n    while True:\n        x.append(bytearray(10**7))\n", "memory-limit", {}),
    ("def f(n):\n    while True:\n        print('x' * 1000)\n", "output-limit", {"bytes": 65536}),
    ("def f(n):\n    import ctypes\n    ctypes.string_at(0)\n", "crashed", {"signal": "SIGSEGV"}),
])
def test_every_way_to_fail_is_reported_as_such(tmp_path, body, code, detail):
    r = run(tmp_path, body)
    assert r.code == code, (r.code, r.details)
    assert detail.items() <= r.details.items(), r.details


def test_an_endless_loop_is_stopped_by_its_cpu_limit(tmp_path):
    """(A generous wall clock: on a loaded machine one CPU second can take several.)"""
    limits = Limits(cpu_seconds=1, wall_seconds=30)
    started = time.perf_counter()
    r = run(tmp_path, "def f(n):\n    while True:\n        pass\n", limits=limits)
    assert (r.code, r.details["clock"]) == ("time-limit", "cpu")
    assert time.perf_counter() - started < limits.wall


def test_a_sleeper_is_stopped_by_the_wall_clock(tmp_path):
    limits = Limits(cpu_seconds=1, wall_seconds=3)
    started = time.perf_counter()
    r = run(tmp_path, "def f(n):\n    time.sleep(60)\n", limits=limits)
    assert (r.code, r.details["clock"]) == ("time-limit", "wall")
    assert time.perf_counter() - started < limits.wall + 5


def test_a_forked_child_does_not_outlive_the_run(tmp_path):
    marker = tmp_path / "alive"
    r = run(tmp_path, f"def f(n):\n    if os.fork() == 0:\n        time.sleep(2)\n        open({str(marker)!r}, 'w')\n"
                      f"        os._exit(0)\n    return np.zeros(2), np.zeros(2)\n")
    assert r.ok
    time.sleep(2.5)
    assert not marker.exists(), "the forked process was left running"


def test_the_child_sees_none_of_the_parent_s_environment(tmp_path, monkeypatch):
    monkeypatch.setenv("SCANLAB_TEST_SECRET", "hunter2")
    r = run(tmp_path, "def f(n):\n    raise RuntimeError(repr(sorted(os.environ)) + ' ' + "
                      "repr(os.environ.get('SCANLAB_TEST_SECRET')))\n")
    assert "None" in r.details["message"] and "hunter2" not in r.details["message"]
    assert "NUMBA_CACHE_DIR" in r.details["message"]


def test_a_forged_header_cannot_make_the_parent_read_or_allocate_much(tmp_path):
    """A result whose header claims more data than the file holds, or an object array, is refused."""
    with open(tmp_path / "c0_0.npy", "wb") as f:
        np.lib.format.write_array_header_1_0(f, {"descr": "<f8", "fortran_order": False, "shape": (10 ** 9,)})
        f.write(np.zeros(3).tobytes())
    with pytest.raises(ValueError, match="too large"):
        read_results(tmp_path, 1, 1, budget=10 ** 12)
    np.save(tmp_path / "c0_0.npy", np.array([{}], dtype=object), allow_pickle=True)
    with pytest.raises(ValueError, match="not an array of numbers"):
        read_results(tmp_path, 1, 1, budget=10 ** 9)


NUMBA_SOLUTION = '''import math

import numba
import numpy as np


@numba.njit(cache=True)
def half_angle(view_angle):
    return math.radians(view_angle) / 2


@numba.njit(cache=True)
def half_height(view_angle, near):
    return near * math.tan(half_angle(view_angle))


def perspective(view_angle, aspect, near, far):
    top = half_height(view_angle, near)
    return np.array([[near / (top * aspect), 0, 0, 0], [0, near / top, 0, 0],
                     [0, 0, -(far + near) / (far - near), -1], [0, 0, -2 * far * near / (far - near), 0]])
'''


def test_a_student_s_numba_cache_never_serves_an_older_version(tmp_path):
    """numba.njit(cache=True) in a solution: an edit between two checks (same size, same time
    stamp, only the callee changed) gives the new verdict, because each run's NUMBA_CACHE_DIR
    is a fresh folder, deleted afterwards."""
    from lab.app.exercises.checker import check_file
    from lab.app.exercises.exercise_registry import get

    path = tmp_path / "perspective.py"
    path.write_text(NUMBA_SOLUTION)
    stamp = os.stat(path).st_mtime_ns
    assert check_file(get("perspective"), path).verdict == "right"
    path.write_text(NUMBA_SOLUTION.replace("math.radians(view_angle) / 2", "math.radians(view_angle) * 1"))
    os.utime(path, ns=(stamp, stamp))
    assert os.stat(path).st_size == len(NUMBA_SOLUTION)
    report = check_file(get("perspective"), path)
    assert (report.verdict, report.codes) == ("wrong", ["fov-not-halved"])


def test_each_run_has_its_own_empty_numba_cache_folder_which_is_then_removed(tmp_path):
    body = ("def f(n):\n    d = os.environ['NUMBA_CACHE_DIR']\n"
            "    raise RuntimeError(d + '|' + repr(os.listdir(d)))\n")
    seen = []
    for _ in range(2):
        r = run(tmp_path, body)
        folder, listing = r.details["message"].split("|")
        assert listing == "[]"
        seen.append(folder)
        assert not Path(folder).exists(), "the cache folder must go with the run"
    assert seen[0] != seen[1]


def test_the_child_ends_with_the_checker_that_started_it(tmp_path):
    """A checker killed mid-run (a grader's worker that overran) takes its sleeping student with it."""
    import signal
    import subprocess
    import sys

    marker = tmp_path / "student.pid"
    (tmp_path / "s.py").write_text(f"import os, time\ndef f(n):\n    open({str(marker)!r}, 'w').write(str(os.getpid()))\n"
                                   "    time.sleep(60)\n")
    code = (f"from lab.app.exercises.sandbox import Limits, run_submission\n"
            f"run_submission({str(tmp_path / 's.py')!r}, 'f', [[1]], 1, Limits(cpu_seconds=5, wall_seconds=60))\n")
    checker = subprocess.Popen([sys.executable, "-c", code])
    deadline = time.time() + 60
    while not marker.exists() and time.time() < deadline:
        time.sleep(0.1)
    student = int(marker.read_text())
    checker.send_signal(signal.SIGKILL)
    checker.wait()
    for _ in range(50):
        try:
            os.kill(student, 0)
        except ProcessLookupError:
            return
        time.sleep(0.1)
    os.kill(student, signal.SIGKILL)
    raise AssertionError("the student's process outlived its checker")
