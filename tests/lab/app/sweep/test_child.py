"""The case process: it warms up, answers requests on its own channel, and ends with its stdin
or its parent."""
from __future__ import annotations

import os
import subprocess
import sys
import time

from lab.app.sweep.protocol import read_message, write_message


def _child(parent: int) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "lab.app.sweep.child", "--parent", str(parent)],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE)


def test_it_says_it_is_ready_answers_and_ends_when_its_stdin_closes():
    child = _child(os.getpid())
    try:
        ready = read_message(child.stdout)
        assert ready["ready"] and ready["pid"] == child.pid and ready["warm_up_s"] > 0
        write_message(child.stdin, {"kind": "shape", "key": "cube", "name": "cube",
                                    "settings": (("size", "40x30"),), "marker": "/nonexistent"})
        answer = read_message(child.stdout)
        assert answer["status"] == "ok" and answer["metrics"]["size"] == [40, 30]
        child.stdin.close()
        assert child.wait(30) == 0
        assert read_message(child.stdout) is None, "nothing but messages on its message channel"
    finally:
        child.kill()
        child.wait()


def test_it_ends_by_itself_when_its_parent_is_gone():
    """Given a parent id that is not its parent (as after the worker died and it was
    re-parented), the watchdog ends it within a second or so, before it even warms up."""
    child = _child(os.getpid() + 1_000_000)
    try:
        started = time.monotonic()
        assert child.wait(30) == 3
        assert time.monotonic() - started < 30
    finally:
        child.kill()
        child.wait()
