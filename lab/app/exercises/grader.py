"""A class graded: every ``*.py`` of a folder judged in parallel into ``grades.csv`` and
``index.html``.

``workers`` worker processes (:mod:`lab.app.exercises.worker`, default: one per core)
each judge one submission at a time; each submission's code runs in its own sandboxed
child with the limits given. The grader never hangs and never loses a row: a worker that
takes longer than the limits allow (plus time to draw) or dies is killed and replaced,
and its submission is recorded as ``cannot-judge`` with ``checker-error``.

``grades.csv`` has one row per file: ``file, verdict, codes, seconds`` (codes separated
by spaces; verdicts ``right``, ``wrong``, ``cannot-judge``).
"""
from __future__ import annotations

import csv
import io
import json
import os
import queue
import signal
import subprocess
import sys
import threading
import time
from dataclasses import asdict
from pathlib import Path

from lab.app.exercises.sandbox import Limits

DRAWING_SECONDS = 120.0
"""Time a worker may take beyond the sandbox's wall limit: the references, renders and panels."""


class _Worker:
    """One ``python -m lab.app.exercises.worker`` process in its own process group."""

    def __init__(self, env: dict):
        self.env = env
        self.proc = subprocess.Popen([sys.executable, "-m", "lab.app.exercises.worker"], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, env=env,
                                     start_new_session=True)
        self.answers: queue.Queue = queue.Queue()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self):
        for line in self.proc.stdout:
            self.answers.put(line)
        self.answers.put(None)

    def ask(self, job: dict, timeout: float) -> dict | None:
        """The worker's answer, or None when it died or took longer than ``timeout`` seconds."""
        try:
            self.proc.stdin.write(json.dumps(job) + "\n")
            self.proc.stdin.flush()
            line = self.answers.get(timeout=timeout)
        except (OSError, queue.Empty):
            return None
        return json.loads(line) if line else None

    def stop(self):
        try:
            os.killpg(self.proc.pid, signal.SIGKILL)
        except (ProcessLookupError, PermissionError):
            pass
        self.proc.wait()


def checker_failure(file: Path, message: str, seconds: float) -> dict:
    """The row of a submission the checker itself could not finish."""
    from lab.app.exercises.diagnoses.codes import Finding, text

    finding = Finding("checker-error", {"message": message})
    return {"file": file.name, "verdict": "cannot-judge", "status": 2, "codes": ["checker-error"],
            "seconds": round(seconds, 2), "messages": {lang: [f"[checker-error] {text(finding, lang)}"]
                                                       for lang in ("en", "ja")},
            "checked": {"en": [], "ja": []}, "panels": [], "output": []}


def grade_folder(exercise: str, files: list[Path], out: Path, workers: int, limits: Limits = Limits(),
                 progress=None) -> list[dict]:
    """Judge ``files`` with ``workers`` workers; returns the rows in the order of ``files``.
    ``progress(done, total, row)`` is called as each submission is finished."""
    env = dict(os.environ)
    if workers > 1:
        env["NUMBA_NUM_THREADS"] = "1"  # parallel over submissions, not inside one picture
    jobs: queue.Queue = queue.Queue()
    for i, f in enumerate(files):
        jobs.put((i, f))
    rows: list[dict | None] = [None] * len(files)
    lock = threading.Lock()
    done = [0]
    timeout = max(1.0, limits.wall + DRAWING_SECONDS)

    def serve():
        worker = _Worker(env)
        try:
            while True:
                try:
                    i, f = jobs.get_nowait()
                except queue.Empty:
                    return
                started = time.perf_counter()
                job = {"exercise": exercise, "file": str(f.resolve()), "out": str(out), "stem": f.stem,
                       "limits": asdict(limits)}
                try:
                    answer = worker.ask(job, timeout)
                except Exception as exc:  # noqa: BLE001 -- a garbled answer costs this row, not the class
                    answer = {"error": f"{type(exc).__name__}: {exc}"}
                if answer is None or "error" in answer:
                    message = answer["error"] if answer else f"no answer within {timeout:g} s"
                    answer = checker_failure(f, message, time.perf_counter() - started)
                    worker.stop()
                    worker = _Worker(env)
                with lock:
                    rows[i] = answer
                    done[0] += 1
                    if progress is not None:
                        progress(done[0], len(files), answer)
        finally:
            worker.stop()

    threads = [threading.Thread(target=serve) for _ in range(max(1, min(workers, len(files))))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return rows


def grades_csv(rows: list[dict]) -> str:
    """The CSV text: a header, then ``file, verdict, codes, seconds`` per submission."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(["file", "verdict", "codes", "seconds"])
    for r in rows:
        writer.writerow([r["file"], r["verdict"], " ".join(r["codes"]), f"{r['seconds']:.2f}"])
    return buffer.getvalue()
