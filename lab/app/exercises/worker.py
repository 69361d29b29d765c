"""A grading worker: judges one submission after another for :mod:`lab.app.exercises.grader`.

Run as ``python -m lab.app.exercises.worker``. It reads one JSON job per line on stdin —
``{"exercise": name, "file": path, "out": folder, "stem": name, "limits": {...}}`` —
judges it with :func:`lab.app.exercises.checker.check_file` (the student's code itself
runs in a sandboxed child of this worker), writes the panels into ``out`` and answers
with one JSON line (:func:`row`). The protocol has its own file descriptor: everything
else this process prints (VTK, numba, matplotlib) goes to stderr, so no library can
garble an answer. Staying alive between jobs keeps VTK, numba's kernels and the
reference pictures loaded.
"""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path


def row(report, panels: list[Path], out: Path) -> dict:
    """One submission's line of ``grades.csv`` and its page row, JSON-ready."""
    return {"file": Path(report.file).name, "verdict": report.verdict, "status": report.status,
            "codes": report.codes, "seconds": round(report.seconds, 2),
            "messages": {lang: report.messages(lang) for lang in ("en", "ja")}, "checked": report.checked,
            "panels": [p.relative_to(out).as_posix() for p in panels],
            "output": report.output.strip().splitlines()[-5:] if report.status == 2 else []}


def judge(job: dict) -> dict:
    from lab.app.exercises.checker import check_file
    from lab.app.exercises.exercise_registry import get
    from lab.app.exercises.sandbox import Limits

    report = check_file(get(job["exercise"]), job["file"], Limits(**job.get("limits", {})))
    out = Path(job["out"])
    panels = report.write_panels(out / "panels", job["stem"]) if report.panels else []
    return row(report, panels, out)


def main() -> None:
    protocol = os.fdopen(os.dup(1), "w", encoding="utf-8", buffering=1)
    os.dup2(2, 1)  # anything printed from here on goes to stderr
    sys.stdout = sys.stderr
    for line in sys.stdin:
        if not line.strip():
            continue
        job = json.loads(line)
        try:
            answer = judge(job)
        except Exception as exc:  # noqa: BLE001 -- reported as this submission's checker error
            answer = {"error": f"{type(exc).__name__}: {exc}"}
        protocol.write(json.dumps(answer) + "\n")


if __name__ == "__main__":
    main()
