"""The case process: one per Dask worker, kept warm, running that worker's cases one by one.

Started by :class:`lab.app.sweep.isolation.CaseProcess` as ``python -m lab.app.sweep.child
--memory-limit BYTES --parent PID``. It

1. limits its own address space (``RLIMIT_AS``) to ``BYTES`` (0: no limit), so a case that
   asks for too much memory gets a MemoryError here instead of the machine's OOM killer;
2. turns on :mod:`faulthandler`, so a crash in compiled code leaves a traceback on stderr;
3. points fd 1 at stderr and keeps the original stdout for messages (:mod:`.protocol`);
4. watches its parent: if the worker dies, this process ends within a second even when a
   case hangs (a thread polls ``os.getppid()``);
5. warms up — imports the renderer and VTK, checks the offscreen OpenGL context once and
   compares a tiny cube, so that start-up is not counted in the first case's time (nor
   against its time limit) — and says it is ready;
6. answers requests (:func:`lab.app.sweep.run_case.execute`) until its stdin closes. After
   a MemoryError it answers and exits, since the process may be left in a poor state.
"""
from __future__ import annotations

import argparse
import faulthandler
import os
import resource
import sys
import threading
import time

from lab.app.sweep.protocol import read_message, write_message


def _watch_parent(parent: int) -> None:
    while True:
        if os.getppid() != parent:
            os._exit(3)
        time.sleep(0.5)


def warm_up() -> float:
    """Load what every case needs — the renderer, VTK, the offscreen OpenGL context check and
    the compiled kernels of a flat-shaded VTK-model scene — by comparing a 32×24 cube; return
    the seconds it took. Kernels of other models and shadings load (from the kernel cache) in
    the first case that needs them."""
    from lab.app.sweep.run_case import run_one_case
    from lab.loading import load_scene

    started = time.perf_counter()
    run_one_case(load_scene("cube").with_overrides(size=(32, 24), shading="flat", model="vtk"), "warm-up")
    return time.perf_counter() - started


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m lab.app.sweep.child")
    parser.add_argument("--memory-limit", type=int, default=0, help="address-space limit in bytes (0: none)")
    parser.add_argument("--parent", type=int, required=True, help="the worker's process id")
    args = parser.parse_args(argv)
    if args.memory_limit > 0:
        resource.setrlimit(resource.RLIMIT_AS, (args.memory_limit, args.memory_limit))
    faulthandler.enable()
    replies = os.fdopen(os.dup(1), "wb")
    os.dup2(2, 1)
    threading.Thread(target=_watch_parent, args=(args.parent,), daemon=True).start()

    from lab.app.sweep.run_case import execute

    write_message(replies, {"ready": True, "pid": os.getpid(), "warm_up_s": warm_up()})
    requests = sys.stdin.buffer
    while (request := read_message(requests)) is not None:
        response = execute(request)
        write_message(replies, response)
        if response["status"] == "out of memory":
            return 0
    return 0


if __name__ == "__main__":
    sys.exit(main())
