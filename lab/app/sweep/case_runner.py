"""The Dask worker's side: a worker plugin that keeps one warm case process per worker thread,
and the task that hands it one case.

The plugin (:class:`CaseRunner`) is registered by the sweep on every worker of the cluster,
present and future; its case processes (:class:`lab.app.sweep.isolation.CaseProcess`) start
on a thread's first case and live until the worker closes, so VTK, the offscreen OpenGL check
and the compiled kernels are loaded once per worker, not once per case. The task
(:func:`run_case`) adds to the case's response where and when it ran.
"""
from __future__ import annotations

import os
import socket
import threading
import time

from distributed import WorkerPlugin, get_worker

from lab.app.sweep.isolation import CaseProcess

PLUGIN_NAME = "scanlab-case-runner"


class CaseRunner(WorkerPlugin):
    """Keeps a :class:`CaseProcess` per worker thread; ``memory_limit`` in bytes (0: none)."""

    name = PLUGIN_NAME
    idempotent = False  # a new sweep replaces it: the old case processes close, its memory limit applies

    def __init__(self, memory_limit: int = 0):
        self.memory_limit = memory_limit
        self._processes: dict[int, CaseProcess] = {}
        self._lock = threading.Lock()

    def __getstate__(self):
        return {"memory_limit": self.memory_limit}

    def __setstate__(self, state):
        self.__init__(state["memory_limit"])

    def setup(self, worker) -> None:
        """Nothing to start yet: each thread starts its case process with its first case."""

    def teardown(self, worker) -> None:
        with self._lock:
            for process in self._processes.values():
                process.close()
            self._processes.clear()

    def process(self) -> CaseProcess:
        """This thread's case process (created on first use, started by its first case)."""
        with self._lock:
            return self._processes.setdefault(threading.get_ident(), CaseProcess(self.memory_limit))


def run_case(request: dict, timeout: float) -> dict:
    """Run one case on this worker's warm case process (a Dask task).

    Returns the case's response (:func:`lab.app.sweep.run_case.execute`, or a timeout or
    crash from :class:`CaseProcess`) with ``worker`` (the worker's address), ``host``,
    ``started_at`` and ``finished_at`` (Unix time), ``wall_s`` (seconds on this worker,
    waiting for a case process to warm up included) and ``warm_up_s`` (when a case process
    was started for this case, else None).
    """
    worker = get_worker()
    process = worker.plugins[PLUGIN_NAME].process()
    started_at, clock = time.time(), time.perf_counter()
    starts = process.starts
    if not process.alive():
        process.start()
    response = process.run(request, timeout)
    response.update(worker=worker.address, host=socket.gethostname(), worker_pid=os.getpid(),
                    started_at=started_at, finished_at=time.time(), wall_s=time.perf_counter() - clock,
                    warm_up_s=process.warm_up_s if process.starts > starts else None)
    return response
