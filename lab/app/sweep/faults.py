"""Test-only faults: ways to make one case misbehave on purpose (grid key ``fault``).

Tests need a case that hangs, one that crashes its process, one that runs out of memory and
one whose worker dies, to check that a sweep records them and goes on. The grid key
``fault`` exists only with ``SCANLAB_SWEEP_TEST_FAULTS=1`` in the environment
(:func:`lab.app.sweep.settings.grid_keys`); a user never meets it. Each fault runs in the
case's own process (:mod:`lab.app.sweep.child`) just before the comparison.

``marker`` is a file path unique to the case, under the sweep's output folder: a fault that
should strike once (``lose-worker``) leaves it behind to know it already has.
"""
from __future__ import annotations

import os
import resource
import signal
import time
from pathlib import Path


def none(marker: Path) -> None:
    """No fault: the case runs as usual (so a grid of faults can hold well-behaved cases too)."""


def hang(marker: Path) -> None:
    """Sleep for ever: the case's time limit must end it."""
    while True:
        time.sleep(3600)


def crash(marker: Path) -> None:
    """Die of a segmentation fault, as a bug in compiled code would."""
    os.kill(os.getpid(), signal.SIGSEGV)
    time.sleep(60)


def out_of_memory(marker: Path) -> None:
    """Ask for twice the process's address-space limit (refused at once: no memory is touched
    beyond the limit). Refuses to run without a limit, so a test cannot fill the machine."""
    limit = resource.getrlimit(resource.RLIMIT_AS)[0]
    if limit == resource.RLIM_INFINITY:
        raise RuntimeError("the oom fault needs a memory limit (--memory-limit)")
    import numpy as np

    np.ones(2 * limit // 8)


def error(marker: Path) -> None:
    """Raise an ordinary Python exception."""
    raise RuntimeError("a test-only failure raised on purpose")


def lose_worker(marker: Path) -> None:
    """Kill the Dask worker running the case (this process's parent) the first time only, so
    the retry on another worker succeeds."""
    if marker.exists():
        return
    marker.parent.mkdir(parents=True, exist_ok=True)
    marker.touch()
    lose_worker_always(marker)


def lose_worker_always(marker: Path) -> None:
    """Kill the Dask worker running the case every time: the retry dies too, and the sweep
    must record the case as ``worker lost``."""
    os.kill(os.getppid(), signal.SIGKILL)
    time.sleep(60)  # the child's watchdog ends this process when it sees its parent gone


FAULTS = {"none": none, "hang": hang, "crash": crash, "oom": out_of_memory, "error": error, "lose-worker": lose_worker,
          "lose-worker-always": lose_worker_always}
"""The faults by the value the grid key ``fault`` takes."""
