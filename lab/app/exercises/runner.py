"""The child side of the sandbox: run one student file's function on the exercise's cases.

Started by :func:`lab.app.exercises.sandbox.run_submission` as
``python -I runner.py JOB_DIR`` in a fresh process (isolated mode: no ``PYTHON*``
variables, no user site, the script's folder not on ``sys.path``), with a clean
environment. It imports only the standard library and numpy, so it can run anywhere the
student's code can.

``JOB_DIR/job.json`` says what to do::

    {"file": "/abs/menger.py", "function": "menger", "cases": [[0], [1]],
     "n_outputs": 2, "limits": {"cpu_seconds": 10, "memory_mb": 1024, "file_mb": 256}}

The runner first limits itself (``resource.setrlimit``: CPU seconds — the kernel sends
SIGXCPU, then SIGKILL —, address space, size of any file written, no core files; and
``signal.alarm`` after the wall time, and death with its parent on Linux, should the
parent be gone), then
compiles and executes the student's file as the module ``submission``, looks the function
up and calls it once per case. Lists among the arguments are passed as float64 numpy
arrays. Each returned value (a tuple of ``n_outputs`` items, or one item when
``n_outputs`` is 1) goes through ``numpy.asarray`` and, when it is an array of numbers
or booleans, to ``JOB_DIR/c<case>_<item>.npy`` (``allow_pickle=False``: nothing is ever
pickled, so the parent reads plain arrays and runs none of the student's code).

It ends by writing ``JOB_DIR/status.json`` — ``{"kind": "ok"}`` or the first problem:
``syntax-error``, ``exception`` (also on import), ``not-implemented``,
``missing-function``, ``memory-limit`` (a MemoryError), ``exited`` (``sys.exit``/``exit()``)
or ``wrong-return-type`` — with the details the diagnosis needs (line, message, case),
and leaves with ``os._exit`` so no thread the student started can keep it alive. What
the student prints goes to stdout, which the parent reads through a pipe of limited size.
"""
from __future__ import annotations

import json
import os
import resource
import sys
import traceback
import types

STATUS = "status.json"


def apply_limits(limits: dict) -> None:
    """CPU time (s), address space (MiB), largest file written (MiB), no core dumps, and an
    alarm after the wall time (s): the child ends itself even if its parent is gone."""
    import signal

    signal.alarm(max(1, int(float(limits.get("wall_seconds", 25))) + 1))
    die_with_parent()
    cpu = max(1, int(round(float(limits.get("cpu_seconds", 10)))))
    resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
    memory = int(limits.get("memory_mb", 1024)) * 2 ** 20
    resource.setrlimit(resource.RLIMIT_AS, (memory, memory))
    size = int(limits.get("file_mb", 256)) * 2 ** 20
    resource.setrlimit(resource.RLIMIT_FSIZE, (size, size))
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))


def die_with_parent() -> None:
    """On Linux, ask the kernel to kill this process when the checker that started it ends
    (``prctl(PR_SET_PDEATHSIG, SIGKILL)``); elsewhere the alarm alone stops it."""
    import ctypes
    import signal

    parent = os.getppid()
    try:
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL), 0, 0, 0)  # 1 = PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        return
    if os.getppid() != parent:  # the parent ended before the request
        os._exit(1)


def write_status(job_dir: str, status: dict) -> None:
    """``status.json``, written under a temporary name and renamed (never half a file)."""
    tmp = os.path.join(job_dir, STATUS + ".part")
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(status, f)
    os.replace(tmp, os.path.join(job_dir, STATUS))


def student_line(tb, file: str) -> int | None:
    """The line of the student's file nearest to where the exception was raised."""
    line = None
    for frame in traceback.extract_tb(tb):
        if os.path.abspath(frame.filename) == file:
            line = frame.lineno
    return line


def describe(exc: BaseException, file: str) -> dict:
    """What went wrong, for the diagnosis: kind, exception type, message, line in the file."""
    if isinstance(exc, MemoryError):
        kind = "memory-limit"
    elif isinstance(exc, SystemExit):
        kind = "exited"
    elif isinstance(exc, NotImplementedError):
        kind = "not-implemented"
    else:
        kind = "exception"
    message = str(exc)
    if isinstance(exc, SystemExit):
        message = repr(exc.code)
    return {"kind": kind, "type": type(exc).__name__, "message": message[:500],
            "line": student_line(exc.__traceback__, file)}


def as_outputs(value, n_outputs: int):
    """The returned value as a list of ``n_outputs`` items, or a problem sentence."""
    if n_outputs == 1:
        if isinstance(value, tuple) and len(value) == 1:
            value = value[0]
        return [value], None
    if not isinstance(value, (tuple, list)) or len(value) != n_outputs:
        what = f"{type(value).__name__} of {len(value)} items" if isinstance(value, (tuple, list)) else \
            type(value).__name__
        return None, f"returned a {what}; expected a tuple of {n_outputs} arrays"
    return list(value), None


def run(job_dir: str) -> dict:
    with open(os.path.join(job_dir, "job.json"), encoding="utf-8") as f:
        job = json.load(f)
    apply_limits(job.get("limits", {}))
    import numpy as np

    file = os.path.abspath(job["file"])
    try:
        with open(file, "rb") as f:
            source = f.read()
        code = compile(source, file, "exec")
    except SyntaxError as exc:
        return {"kind": "syntax-error", "type": type(exc).__name__, "message": str(exc.msg), "line": exc.lineno,
                "text": (exc.text or "").strip()[:200]}
    except (OSError, ValueError) as exc:
        return {"kind": "exception", "type": type(exc).__name__, "message": str(exc)[:500], "line": None,
                "stage": "import"}
    module = types.ModuleType("submission")
    module.__file__ = file
    sys.modules["submission"] = module
    try:
        exec(code, module.__dict__)
    except BaseException as exc:  # noqa: BLE001 -- anything the file does on import is reported
        return {**describe(exc, file), "stage": "import"}
    name = job["function"]
    function = module.__dict__.get(name)
    if not callable(function):
        defined = sorted(k for k, v in module.__dict__.items() if isinstance(v, types.FunctionType))
        return {"kind": "missing-function", "function": name, "defined": defined[:20]}
    n_outputs = int(job["n_outputs"])
    for i, args in enumerate(job["cases"]):
        args = [np.array(a, dtype=np.float64) if isinstance(a, list) else a for a in args]
        try:
            value = function(*args)
            items, problem = as_outputs(value, n_outputs)
            if problem:
                return {"kind": "wrong-return-type", "case": i, "message": problem}
            arrays = []
            for j, item in enumerate(items):
                try:
                    array = np.asarray(item)
                except Exception as exc:  # noqa: BLE001 -- ragged lists and the like
                    return {"kind": "wrong-return-type", "case": i, "item": j,
                            "message": f"item {j + 1} cannot be made an array ({type(exc).__name__}: {exc})"[:300]}
                if array.dtype.kind not in "biuf":
                    return {"kind": "wrong-return-type", "case": i, "item": j,
                            "message": f"item {j + 1} is not an array of numbers (dtype {array.dtype})"}
                arrays.append(array)
        except BaseException as exc:  # noqa: BLE001 -- the student's exception, whatever it is
            return {**describe(exc, file), "stage": "call", "case": i}
        for j, array in enumerate(arrays):
            try:
                np.save(os.path.join(job_dir, f"c{i}_{j}.npy"), array, allow_pickle=False)
            except OSError:
                return {"kind": "wrong-return-type", "case": i, "item": j,
                        "message": f"item {j + 1} is too large to hand back ({array.nbytes:,} bytes; the limit is "
                                   f"{job.get('limits', {}).get('file_mb', 256)} MiB)"}
    return {"kind": "ok", "cases": len(job["cases"])}


def main(argv: list[str]) -> None:
    job_dir = os.path.abspath(argv[1])
    try:
        status = run(job_dir)
    except BaseException as exc:  # noqa: BLE001 -- even a MemoryError here must leave a status
        status = {"kind": "memory-limit" if isinstance(exc, MemoryError) else "exception",
                  "type": type(exc).__name__, "message": str(exc)[:500], "line": None, "stage": "runner"}
    try:
        sys.stdout.flush()
    except BaseException:  # noqa: BLE001 -- a student may have closed or replaced stdout
        pass
    write_status(job_dir, status)
    os._exit(0)


if __name__ == "__main__":
    main(sys.argv)
