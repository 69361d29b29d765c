"""The render service of the live lab: two warm worker processes, newest request first.

Rendering is CPU-bound, so it runs in processes (a thread cannot be stopped mid-render,
and would hold the server's interpreter while numba or VTK work). There are two
*lanes*, each one worker process kept warm between requests (compiled kernels loaded,
VTK's offscreen context open):

- **ours**: our image alone (:func:`lab.app.live.drawing.draw_ours`), started as soon as
  the worker is free, so a control change shows our new image first;
- **measure**: VTK's image, the ΔE2000 map, the metrics and the verdict
  (:func:`lab.app.live.drawing.measure`), started once the controls have been still for
  :data:`QUIET` seconds, so dragging a slider does not queue up VTK renders.

Newest wins. A lane runs one job at a time and holds at most one waiting: a newer
request replaces the waiting one, which is dropped unstarted. A job still running when a
newer one arrives is let finish if it is young (stopping it would throw away the warm
worker), but a worker busy for longer than :data:`PATIENCE` seconds is stopped and a
fresh one started. Results carry their request number: our image is shown if it is
newer than the one on screen (while a slider moves, each finished image is progress);
a measurement only if no newer request has been made since (its numbers must describe
the images around them). Anything else is stale and dropped.

The two lanes share the machine's cores, and our image is the one a student waits for:
the measure worker runs at a lower priority (:data:`MEASURE_NICE`) and VTK's software
OpenGL (Mesa llvmpipe) draws with one thread in it (:data:`MEASURE_ENV`), so a
measurement in progress slows our next image as little as it can.

The workers ignore Ctrl-C: the server catches it and stops them (:meth:`RenderService.stop`).
A worker that dies is started again; its job is reported as an error.
"""
from __future__ import annotations

import asyncio
import logging
import multiprocessing
import os
import signal
import time
from contextlib import contextmanager
from typing import Callable

from lab.app.live.drawing import Job, draw_ours, measure, warm_measure, warm_ours

QUIET = 0.12
"""Seconds the controls must rest before a measurement starts."""
PATIENCE = 4.0
"""Seconds after which a busy worker is stopped when a newer request waits."""

MEASURE_NICE = 10
"""How much lower the measure worker's priority is (``nice``)."""
MEASURE_ENV = {"LP_NUM_THREADS": "1"}
"""The measure worker's environment over the server's: llvmpipe on one thread (its pixels
do not depend on the number of threads)."""

log = logging.getLogger(__name__)


def _serve(conn, task: Callable, warm: Callable, nice: int = 0) -> None:
    """A worker process: warm up, then run ``task`` on each job received, forever.

    Sends ``("ready", 0, problem)`` once warm (problem None, or why warming failed), then
    ``("done", n, result)`` or ``("error", n, one line)`` for each job.
    """
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    if nice:
        os.nice(nice)
    try:
        warm()
        problem = None
    except Exception as exc:  # noqa: BLE001 -- reported to the page, the worker stays
        problem = _one_line(exc)
    try:
        conn.send(("ready", 0, problem))
    except OSError:  # the server closed the pipe while this worker warmed up: nothing to serve
        return
    while True:
        try:
            job = conn.recv()
        except (EOFError, OSError):
            return
        try:
            conn.send(("done", job.n, task(job)))
        except Exception as exc:  # noqa: BLE001 -- one line for the page, never a traceback
            conn.send(("error", job.n, _one_line(exc)))


def _one_line(exc: BaseException) -> str:
    text = " ".join(str(exc).split()) or type(exc).__name__
    return text if len(text) <= 300 else text[:299] + "…"


class Worker:
    """One warm process running ``task`` (a module-level function) on the jobs it is sent,
    ``nice`` steps below the server's priority, with ``env`` over the server's environment
    (set before the process imports anything)."""

    def __init__(self, name: str, task: Callable, warm: Callable, nice: int = 0, env: dict | None = None):
        self.name, self.task, self.warm, self.nice, self.env = name, task, warm, nice, dict(env or {})
        self.process = self.conn = None
        self.start()

    def start(self) -> None:
        ctx = multiprocessing.get_context("spawn")
        self.conn, child = ctx.Pipe()
        self.process = ctx.Process(target=_serve, args=(child, self.task, self.warm, self.nice), daemon=True,
                                   name=f"scanlab-live-{self.name}")
        with _environment(self.env):  # a spawned process starts with the parent's environment
            self.process.start()
        child.close()

    def stop(self, wait: float = 2.0) -> None:
        """End the process (the pipe closed first, so an idle worker returns by itself),
        waiting at most about ``wait`` seconds for each step; ``wait=0`` only signals it (the
        server's event loop must not block: multiprocessing reaps it later)."""
        if self.process is None:
            return
        self.conn.close()
        self.process.join(min(0.2, wait))
        if self.process.is_alive():
            self.process.terminate()
            self.process.join(wait)
        if self.process.is_alive():
            self.process.kill()
            self.process.join(wait)
        self.process = None


@contextmanager
def _environment(env: dict):
    saved = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        yield
    finally:
        for k, v in saved.items():
            if v is None:
                os.environ.pop(k, None)
            else:
                os.environ[k] = v


class Lane:
    """One worker and its newest-wins queue (see the module docstring).

    ``deliver(kind, n, result)`` is called on the event loop for each finished job
    (``kind`` "done" or "error"); ``quiet`` seconds must pass after a submission before
    its job starts; a job running longer than ``patience`` when a newer one waits is
    stopped with its worker.
    """

    def __init__(self, worker: Worker, deliver: Callable, quiet: float = 0.0, patience: float = PATIENCE):
        self.worker, self.deliver, self.quiet, self.patience = worker, deliver, quiet, patience
        self.loop: asyncio.AbstractEventLoop | None = None
        self.ready = False
        self.problem: str | None = None
        self.running: Job | None = None
        self.started = 0.0
        self.waiting: Job | None = None
        self.due = 0.0
        self.timer = None
        self.dropped = 0

    def attach(self, loop: asyncio.AbstractEventLoop) -> None:
        self.loop = loop
        loop.add_reader(self.worker.conn.fileno(), self._readable)

    def submit(self, job: Job) -> None:
        """Run ``job`` next, in place of any job still waiting."""
        if self.waiting is not None:
            self.dropped += 1
        self.waiting, self.due = job, time.monotonic() + self.quiet
        if self.running is not None and time.monotonic() - self.started > self.patience:
            self.restart()
        if self.loop is None:  # not listening yet: the job starts when the worker is ready
            return
        if self.timer is not None:
            self.timer.cancel()
        self.timer = self.loop.call_later(self.quiet, self._start_next) if self.quiet else None
        self._start_next()

    def _start_next(self) -> None:
        if not self.ready or self.running is not None or self.waiting is None or time.monotonic() < self.due:
            return
        job, self.waiting = self.waiting, None
        try:
            self.worker.conn.send(job)
        except (OSError, ValueError):  # the worker is gone: start another, keep the job
            self.waiting = job
            self.restart()
            return
        self.running, self.started = job, time.monotonic()

    def _readable(self) -> None:
        try:
            kind, n, result = self.worker.conn.recv()
        except (EOFError, OSError):
            lost = self.running
            self.restart()
            if lost is not None:
                self.deliver("error", lost.n, f"the {self.worker.name} worker stopped; started a new one")
            return
        if kind == "ready":
            self.ready, self.problem = True, result
        else:
            self.running = None
            self.deliver(kind, n, result)
        self._start_next()

    def restart(self) -> None:
        """Stop the worker (and whatever it is doing) and start a fresh one; the waiting job
        runs when it is warm."""
        if self.loop is not None and self.worker.conn is not None:
            self.loop.remove_reader(self.worker.conn.fileno())
        self.worker.stop(wait=0.0)  # on the event loop: signal it, never wait for it
        self.running, self.ready = None, False
        self.worker.start()
        if self.loop is not None:
            self.loop.add_reader(self.worker.conn.fileno(), self._readable)

    def stop(self) -> None:
        if self.timer is not None:
            self.timer.cancel()
        if self.loop is not None and self.worker.conn is not None and not self.worker.conn.closed:
            self.loop.remove_reader(self.worker.conn.fileno())
        self.worker.stop()


class RenderService:
    """The two lanes and the stale-result rule (see the module docstring).

    ``show(lane, kind, n, result)`` receives every result worth showing: ``lane`` "ours"
    or "measure", ``kind`` "done" or "error".
    """

    def __init__(self, show: Callable, workers: dict | None = None):
        self.show = show
        workers = workers or {"ours": Worker("ours", draw_ours, warm_ours),
                              "measure": Worker("measure", measure, warm_measure, MEASURE_NICE, MEASURE_ENV)}
        self.lanes = {"ours": Lane(workers["ours"], self._deliver_for("ours")),
                      "measure": Lane(workers["measure"], self._deliver_for("measure"), quiet=QUIET)}
        self.latest = 0
        self.shown = {"ours": 0, "measure": 0}
        self.stale = {"ours": 0, "measure": 0}

    def attach(self, loop: asyncio.AbstractEventLoop) -> None:
        """Listen for results on ``loop`` (the server's event loop)."""
        for lane in self.lanes.values():
            lane.attach(loop)

    def submit(self, job: Job, lanes=("ours", "measure")) -> None:
        """Ask for ``job`` (its ``n`` larger than any before) on ``lanes``."""
        self.latest = max(self.latest, job.n)
        for name in lanes:
            self.lanes[name].submit(job)

    def _deliver_for(self, lane: str) -> Callable:
        def deliver(kind: str, n: int, result) -> None:
            if n <= self.shown[lane] or (lane == "measure" and n < self.latest):
                self.stale[lane] += 1
                return
            self.shown[lane] = n
            self.show(lane, kind, n, result)
        return deliver

    def problems(self) -> dict[str, str]:
        """Why a lane's worker could not warm up (e.g. no OpenGL for VTK), by lane."""
        return {name: lane.problem for name, lane in self.lanes.items() if lane.problem}

    def stop(self) -> None:
        for lane in self.lanes.values():
            lane.stop()
