"""Tasks for the render-service tests (not a test file): small jobs a worker process can run.

The tests put this folder on ``sys.path`` before starting workers, so a spawned worker
imports this module by its name, as it imports :mod:`lab.app.live.drawing` in the app.
"""
from __future__ import annotations

import os
import time
from typing import NamedTuple


class SleepJob(NamedTuple):
    n: int
    seconds: float = 0.0


def sleep_then_tell(job: SleepJob) -> dict:
    """Sleep, then say which job and which process."""
    time.sleep(job.seconds)
    return {"n": job.n, "pid": os.getpid(), "nice": os.nice(0), "lp": os.environ.get("LP_NUM_THREADS")}


def fail(job: SleepJob) -> dict:
    raise ValueError("a bad\n  value")


def warm_nothing() -> None:
    pass


def warm_badly() -> None:
    raise RuntimeError("no OpenGL here")
