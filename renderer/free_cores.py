"""How many threads a frame uses: as many as numba is set to, but no more than the cores other
processes leave free (the idea of OpenMP's ``OMP_DYNAMIC``, made by the package).

Why: with another process holding one of two cores, the scheduler tends to leave that
process its core and put both of our threads on the other. A second thread then adds only
its costs: the raster's bands each walk every triangle, and two threads used four bands where
one used two (``scanlab bench --contention`` measured 2 threads / 1 up to 1.08 on the Igea
scan, 1.04 on the level-7 icosphere). A frame therefore asks first how busy the machine is.

How busy: the CPU time every process spent (``/proc/stat``, all cores) minus our own (all our
threads, ``/proc/self/stat``; VTK's llvmpipe threads are ours too when both draw in one
process), over the wall time since the last reading, in cores. The readings are refreshed at
most every :data:`SAMPLE_SECONDS` (two small file reads), and a frame between readings
keeps the last answer. Where ``/proc`` cannot be read, every frame gets what it asked for.

The number of threads never changes a byte (``tests/renderer/test_threads.py``), only the time.
``SCANLAB_DYNAMIC_THREADS=0`` turns the check off.
"""
from __future__ import annotations

import contextlib
import math
import os
import time
from typing import NamedTuple

import numba

SAMPLE_SECONDS = 0.1
"""Least time between two readings of the machine's CPU time (``/proc/stat`` counts in
hundredths of a second: over 0.1 s, a busy core reads 10 ± 1)."""

BUSY_SHARE = 0.5
"""A core counts as taken when other processes used at least this share of one (rounded half up)."""


class CpuTimes(NamedTuple):
    """Clock ticks since boot: ``busy`` of all processes on all cores, ``ours`` (this
    process, every thread), ``total`` (busy and idle on all cores)."""

    busy: int
    ours: int
    total: int


def read_cpu_times() -> CpuTimes | None:
    """The machine's and this process's CPU times now, or None where ``/proc`` cannot tell."""
    try:
        with open("/proc/stat", "rb") as f:
            cpu = f.readline().split()
        with open("/proc/self/stat", "rb") as f:
            after_name = f.read().rsplit(b")", 1)[1].split()
    except (OSError, IndexError):
        return None
    user, nice, system, idle, iowait, irq, softirq, steal = (int(v) for v in cpu[1:9])
    busy = user + nice + system + irq + softirq + steal
    utime, stime = int(after_name[11]), int(after_name[12])  # fields 14 and 15 of proc(5)
    return CpuTimes(busy, utime + stime, busy + idle + iowait)


def others_cores(before: CpuTimes, after: CpuTimes, n_cores: int) -> float:
    """Cores the other processes kept busy between two readings (0 … ``n_cores``)."""
    elapsed = after.total - before.total
    if elapsed <= 0:
        return 0.0
    others = (after.busy - before.busy) - (after.ours - before.ours)
    return min(max(others / elapsed * n_cores, 0.0), float(n_cores))


def threads_for(asked: int, n_cores: int, others: float) -> int:
    """``asked`` threads, at most one per core the others leave free, and at least one."""
    taken = math.floor(others + BUSY_SHARE)
    return max(1, min(asked, n_cores - taken))


class FreeCores:
    """The free cores of the machine, read at most every :data:`SAMPLE_SECONDS`.

    ``read`` and ``clock`` are the sources (:func:`read_cpu_times`, ``time.monotonic``;
    tests pass their own). Until a second reading, every core counts as free."""

    def __init__(self, read=read_cpu_times, clock=time.monotonic, n_cores: int | None = None):
        self.read, self.clock = read, clock
        self.n_cores = n_cores or os.cpu_count() or 1
        self.last, self.last_time, self.others = read(), clock(), 0.0
        self.last_frame = None  # threads the last frame used (for ``scanlab bench --contention``)

    def busy_elsewhere(self) -> float:
        """Cores other processes kept busy over the last reading's interval, read again when
        it is :data:`SAMPLE_SECONDS` old."""
        if self.clock() - self.last_time >= SAMPLE_SECONDS:
            self.refresh()
        return self.others

    def refresh(self) -> None:
        """Read now: the others' load since the last reading, however long ago that was (a
        caller that wants the load of the last moment calls it twice, a moment apart)."""
        now, reading = self.clock(), self.read()
        if reading is not None and self.last is not None:
            self.others = others_cores(self.last, reading, self.n_cores)
        self.last, self.last_time = reading, now

    def threads(self, asked: int) -> int:
        """How many of ``asked`` threads a frame should use now."""
        return threads_for(asked, self.n_cores, self.busy_elsewhere())


MACHINE = FreeCores()
"""The process's one reader of the machine's load."""


def enabled() -> bool:
    """False when the user set ``SCANLAB_DYNAMIC_THREADS=0``."""
    return os.environ.get("SCANLAB_DYNAMIC_THREADS", "1") != "0"


@contextlib.contextmanager
def threads_of_this_frame(cores: FreeCores = MACHINE):
    """A ``with`` block in which numba's loops use the threads the machine has free (at most
    as many as numba was set to); numba's setting is put back at the end."""
    asked = numba.get_num_threads()
    use = cores.last_frame = cores.threads(asked) if enabled() else asked
    if use == asked:
        yield asked
        return
    numba.set_num_threads(use)
    try:
        yield use
    finally:
        numba.set_num_threads(asked)
