"""Isolation of one case: the worker's side of its warm case process (:mod:`.child`).

Why a process of its own, and not the Dask worker's thread: a thread that hangs cannot be
stopped from Python, and a crash in compiled code (numba, VTK, Mesa) takes the whole worker
down. Dask would restart that worker and run the case again elsewhere, losing the warm
state and blaming the case only after killing a second worker, and it has no per-task
time limit at all. With the case in a child process the worker stays up and decides:

- no answer within the time limit: the child is killed, the case is a ``timeout``;
- the child dies (a signal or an exit): the case ``crashed``, with the signal's name and
  the last line the child wrote on stderr (:mod:`faulthandler`'s report for a crash);
  a SIGKILL that the worker did not send is most often the kernel's out-of-memory killer,
  which the error says;
- a MemoryError in the child (its address space is limited, ``--memory-limit``): the case
  ran ``out of memory``; the child exits after answering.

A new child is started (and warmed up) for the next case after any of these. What the
worker itself survives, Dask handles: a worker lost mid-case (its process killed, its
machine gone) has its case run again on another worker once (see :mod:`.cluster`).
"""
from __future__ import annotations

import os
import pickle
import select
import signal
import subprocess
import sys
import tempfile
import time

from lab.app.sweep.protocol import HEADER, encode

STARTUP_TIMEOUT = 900.0
"""Seconds a new case process may take to warm up (a cold kernel cache compiles everything)."""


class CaseProcessError(RuntimeError):
    """The case process could not be started or warmed up (the message says why)."""


def _signal_name(returncode: int) -> str:
    if returncode < 0:
        try:
            return signal.Signals(-returncode).name
        except ValueError:
            return f"signal {-returncode}"
    return f"exit status {returncode}"


class CaseProcess:
    """A warm child process that runs cases one at a time, restarted after a bad end.

    ``memory_limit`` is the child's address-space limit in bytes (0: none).
    """

    def __init__(self, memory_limit: int = 0, startup_timeout: float = STARTUP_TIMEOUT):
        self.memory_limit = memory_limit
        self.startup_timeout = startup_timeout
        self.proc: subprocess.Popen | None = None
        self.warm_up_s: float | None = None
        self.starts = 0
        self._log = tempfile.TemporaryFile(prefix="scanlab-case-", suffix=".log")

    # ------------------------------------------------------------------ the child's life
    def start(self) -> None:
        """Start a child and wait until it is warm; raise CaseProcessError if it does not get there."""
        self.close()
        self._log.truncate(0)
        command = [sys.executable, "-m", "lab.app.sweep.child", "--memory-limit", str(self.memory_limit),
                   "--parent", str(os.getpid())]
        self.proc = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=self._log)
        self.starts += 1
        reply = self._read(time.monotonic() + self.startup_timeout)
        if not isinstance(reply, dict) or not reply.get("ready"):
            why = "did not get ready in time" if reply == "timeout" else f"ended ({self._death()})"
            self.close()
            raise CaseProcessError(f"the case process {why} while warming up{self._stderr_tail()}")
        self.warm_up_s = reply["warm_up_s"]

    def alive(self) -> bool:
        return self.proc is not None and self.proc.poll() is None

    def close(self) -> None:
        """End the child (it also ends by itself when its stdin closes or this process dies)."""
        if self.proc is not None:
            if self.proc.poll() is None:
                self.proc.kill()
            self.proc.wait()
            for pipe in (self.proc.stdin, self.proc.stdout):
                pipe.close()
            self.proc = None

    # ------------------------------------------------------------------ one case
    def run(self, request: dict, timeout: float) -> dict:
        """Send one request (see :func:`lab.app.sweep.run_case.execute`) and return its
        response, or a response saying the case timed out or crashed."""
        if not self.alive():
            self.start()
        self._log.truncate(0)
        started = time.monotonic()
        try:
            self.proc.stdin.write(encode(request))
            self.proc.stdin.flush()
        except BrokenPipeError:
            pass  # it died between cases; _read sees the end and reports it
        reply = self._read(started + timeout)
        seconds = time.monotonic() - started
        if reply == "timeout":
            self.close()
            return {"status": "timeout", "error": f"no answer within the time limit of {timeout:g} s; "
                                                  f"its process was killed", "case_s": seconds}
        if reply is None:
            death = self._death()
            tail = self._stderr_tail()
            self.close()
            hint = " (most often the system's out-of-memory killer)" if death == "SIGKILL" else ""
            return {"status": "crashed", "error": f"the case's process died: {death}{hint}{tail}", "case_s": seconds}
        if reply.get("status") == "out of memory":
            self.close()
        return reply

    # ------------------------------------------------------------------ plumbing
    def _read(self, deadline: float):
        """The next message, None if the child closed its end, or "timeout"."""
        fd = self.proc.stdout.fileno()
        data = b""
        need = HEADER.size
        body_size = None
        while len(data) < need:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([fd], [], [], left)[0]:
                return "timeout"
            chunk = os.read(fd, max(need - len(data), 1 << 16))
            if not chunk:
                return None
            data += chunk
            if body_size is None and len(data) >= HEADER.size:
                body_size = HEADER.unpack(data[:HEADER.size])[0]
                need = HEADER.size + body_size
        return pickle.loads(data[HEADER.size:need])

    def _death(self) -> str:
        try:
            return _signal_name(self.proc.wait(timeout=10))
        except subprocess.TimeoutExpired:
            return "closed its output but did not exit"

    def _stderr_tail(self) -> str:
        self._log.seek(0)
        lines = [ln for ln in self._log.read()[-8000:].decode("utf-8", "replace").splitlines() if ln.strip()]
        interesting = [ln for ln in lines if "Fatal Python error" in ln or "Error" in ln] or lines
        return f"; it said: {interesting[-1].strip()[:300]}" if interesting else ""
