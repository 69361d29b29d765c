"""The parent side of the sandbox: run untrusted student code in a child process, within limits.

Never inside the checker's or grader's own process: :func:`run_submission` starts
``python -I runner.py JOB_DIR`` (:mod:`lab.app.exercises.runner`) in a temporary folder
with a clean environment and its own process group, and

- the child limits itself (CPU seconds, address space, file size, no core files);
- the parent reads what it prints through a pipe and stops it after
  :attr:`Limits.output_bytes` bytes;
- the parent kills the whole process group after :attr:`Limits.wall_seconds` of wall
  time (a submission that sleeps uses no CPU) and in any case when it is done;
- results come back as ``.npy`` files, each header checked against the file's size and
  a byte budget before it is read with ``allow_pickle=False``: no pickle, no student
  code runs in the parent.

Stale compiled code: the child's ``NUMBA_CACHE_DIR`` is a fresh folder inside the
temporary one, deleted afterwards, so a student who uses ``numba.njit(cache=True)``
always gets their current source compiled, never a kernel cached by an earlier check.

Every way a run can end is one :class:`RunResult`: ``ok`` with the arrays, or the code of
a runtime diagnosis (:mod:`lab.app.exercises.diagnoses.runtime_faults`) with its details.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from lab.atomic import write_text

RUNNER = Path(__file__).resolve().with_name("runner.py")
"""The child's entry point, run as a script (not imported) under ``python -I``."""


@dataclass(frozen=True)
class Limits:
    """What one run of a student's file may use.

    cpu_seconds : CPU time of the child (the kernel stops it: SIGXCPU).
    memory_mb : address space of the child, MiB (numpy and numba start in 512).
    output_bytes : bytes it may print (stdout and stderr together).
    wall_seconds : wall-clock time; None = 2·cpu_seconds + 5.
    file_mb : the largest file it may write, MiB (its result arrays included).
    result_mb : the most result bytes the parent reads back, MiB.
    """

    cpu_seconds: float = 10.0
    memory_mb: int = 1024
    output_bytes: int = 64 * 1024
    wall_seconds: float | None = None
    file_mb: int = 256
    result_mb: int = 256

    @property
    def wall(self) -> float:
        return self.wall_seconds if self.wall_seconds is not None else 2.0 * self.cpu_seconds + 5.0


@dataclass
class RunResult:
    """How a run ended. ``code`` is None when it returned for every case; else a runtime
    diagnosis code with ``details`` for its message. ``results[i]`` holds case i's arrays."""

    code: str | None
    details: dict = field(default_factory=dict)
    results: list[list[np.ndarray]] = field(default_factory=list)
    output: str = ""
    seconds: float = 0.0

    @property
    def ok(self) -> bool:
        return self.code is None


def child_environment(tmp: Path) -> dict:
    """A clean environment: nothing of the parent's but PATH; numba's cache in a fresh folder;
    one thread each for numba and the BLAS libraries (the grader runs children side by side)."""
    for sub in ("home", "tmp", "numba-cache"):
        (tmp / sub).mkdir()
    return {"PATH": os.environ.get("PATH", os.defpath), "HOME": str(tmp / "home"), "TMPDIR": str(tmp / "tmp"),
            "NUMBA_CACHE_DIR": str(tmp / "numba-cache"), "NUMBA_NUM_THREADS": "1", "OMP_NUM_THREADS": "1",
            "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1", "LANG": "C.UTF-8", "LC_ALL": "C.UTF-8"}


class _CappedReader(threading.Thread):
    """Reads the child's output; past ``cap`` bytes it kills the process group."""

    def __init__(self, pipe, cap: int, kill):
        super().__init__(daemon=True)
        self.pipe, self.cap, self.kill = pipe, cap, kill
        self.data = bytearray()
        self.exceeded = False

    def run(self):
        try:
            while True:
                chunk = self.pipe.read1(65536) if hasattr(self.pipe, "read1") else self.pipe.read(65536)
                if not chunk:
                    return
                room = self.cap - len(self.data)
                self.data += chunk[:max(room, 0)]
                if len(chunk) > room:
                    self.exceeded = True
                    self.kill()
                    return
        except (OSError, ValueError):
            return


def _kill_group(proc: subprocess.Popen) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def run_submission(file: str | os.PathLike, function: str, cases: list, n_outputs: int,
                   limits: Limits = Limits()) -> RunResult:
    """Run ``function`` of the student's ``file`` on every case (a list of argument lists)
    in a sandboxed child; see the module docstring."""
    started = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="scanlab-exercise-") as tmp_name:
        tmp = Path(tmp_name)
        job_dir = tmp / "job"
        job_dir.mkdir()
        job = {"file": str(Path(file).resolve()), "function": function, "cases": cases, "n_outputs": n_outputs,
               "limits": {"cpu_seconds": limits.cpu_seconds, "memory_mb": limits.memory_mb,
                          "file_mb": limits.file_mb, "wall_seconds": limits.wall}}
        path = job_dir / "job.json"
        write_text(path, json.dumps(job))
        proc = subprocess.Popen([sys.executable, "-I", str(RUNNER), str(job_dir)], cwd=job_dir,
                                env=child_environment(tmp), stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, start_new_session=True)
        reader = _CappedReader(proc.stdout, limits.output_bytes, lambda: _kill_group(proc))
        reader.start()
        timed_out = False
        try:
            proc.wait(timeout=limits.wall)
        except subprocess.TimeoutExpired:
            timed_out = True
        _kill_group(proc)  # anything it left behind, and the child itself after a timeout
        proc.wait()
        reader.join(timeout=5)
        proc.stdout.close()
        output = reader.data.decode("utf-8", "replace")
        seconds = time.perf_counter() - started
        result = _outcome(proc.returncode, timed_out, reader.exceeded, job_dir, len(cases), n_outputs, limits)
        result.output, result.seconds = output, seconds
        return result


def _outcome(returncode: int, timed_out: bool, output_exceeded: bool, job_dir: Path, n_cases: int,
             n_outputs: int, limits: Limits) -> RunResult:
    """Classify how the child ended (see the module docstring)."""
    if output_exceeded:
        return RunResult("output-limit", {"bytes": limits.output_bytes})
    if timed_out:
        return RunResult("time-limit", {"seconds": limits.wall, "clock": "wall"})
    if returncode == -signal.SIGXCPU and not (job_dir / "status.json").exists():
        return RunResult("time-limit", {"seconds": limits.cpu_seconds, "clock": "cpu"})
    if returncode == -signal.SIGALRM and not (job_dir / "status.json").exists():
        return RunResult("time-limit", {"seconds": limits.wall, "clock": "wall"})
    status_file = job_dir / "status.json"
    try:
        status = json.loads(status_file.read_text(encoding="utf-8"))
        if not isinstance(status, dict) or not isinstance(status.get("kind"), str):
            raise ValueError("not a status")
    except (OSError, ValueError):
        if returncode < 0:
            return RunResult("crashed", {"signal": signal.Signals(-returncode).name
                                         if -returncode in signal.valid_signals() else str(-returncode)})
        return RunResult("exited", {"message": str(returncode), "line": None, "stage": "os-exit"})
    kind = status.pop("kind")
    if kind != "ok":
        if kind == "memory-limit":
            status["memory_mb"] = limits.memory_mb
        return RunResult(kind, status)
    try:
        results = read_results(job_dir, n_cases, n_outputs, limits.result_mb * 2 ** 20)
    except ValueError as exc:
        return RunResult("wrong-return-type", {"message": str(exc)})
    return RunResult(None, {}, results)


def read_results(job_dir: Path, n_cases: int, n_outputs: int, budget: int) -> list[list[np.ndarray]]:
    """The child's ``c<case>_<item>.npy`` files as arrays, never more than ``budget`` bytes in all.

    Each header is read first: a dtype that is not numbers or booleans, or a shape whose
    data the file does not hold, or more bytes than the budget left, raises ValueError
    before any data is read.
    """
    results = []
    for i in range(n_cases):
        row = []
        for j in range(n_outputs):
            path = job_dir / f"c{i}_{j}.npy"
            try:
                with open(path, "rb") as f:
                    version = np.lib.format.read_magic(f)
                    read_header = (np.lib.format.read_array_header_1_0 if version == (1, 0)
                                   else np.lib.format.read_array_header_2_0)
                    shape, _, dtype = read_header(f)
                    start = f.tell()
            except (OSError, ValueError) as exc:
                raise ValueError(f"the result of case {i + 1} could not be read back ({exc})") from None
            if dtype.hasobject or dtype.kind not in "biuf":
                raise ValueError(f"item {j + 1} of case {i + 1} is not an array of numbers (dtype {dtype})")
            nbytes = int(np.prod(shape, dtype=np.float64)) * dtype.itemsize
            if nbytes > budget or path.stat().st_size < start + nbytes:
                raise ValueError(f"item {j + 1} of case {i + 1} is too large ({nbytes:,} bytes)")
            budget -= nbytes
            row.append(np.load(path, allow_pickle=False))
        results.append(row)
    return results
