"""One submission judged: run it in the sandbox, check what it returned, hand it to the
exercise's judge, and say the verdict.

Verdicts and exit statuses (fixed: scripts depend on them): ``right`` 0, ``wrong`` 1 (with
the diagnoses), ``cannot-judge`` 2 (the file does not compile, raises, hits a limit,
returns the wrong kind of value — or, rarely, the checker itself fails on it: then it
says so). The checker never runs the student's code in its own process
(:mod:`lab.app.exercises.sandbox`), and never raises for anything a submission does.
"""
from __future__ import annotations

import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding, status, text
from lab.app.exercises.exercise_registry import Case, Exercise, Output
from lab.app.exercises.sandbox import Limits, run_submission

VERDICTS = {0: "right", 1: "wrong", 2: "cannot-judge"}
VERDICT_JA = {"right": "正解", "wrong": "不正解", "cannot-judge": "採点できません"}


@dataclass
class Report:
    """The verdict on one file, its findings, what was checked and the panels to draw."""

    exercise: str
    file: str
    findings: list[Finding] = field(default_factory=list)
    checked: dict = field(default_factory=lambda: {"en": [], "ja": []})
    panels: list = field(default_factory=list)
    seconds: float = 0.0
    output: str = ""

    @property
    def status(self) -> int:
        return status(self.findings)

    @property
    def verdict(self) -> str:
        return VERDICTS[self.status]

    @property
    def codes(self) -> list[str]:
        return [f.code for f in self.findings]

    def messages(self, lang: str = "en") -> list[str]:
        return [f"[{f.code}] {text(f, lang)}" for f in self.findings]

    def lines(self, lang: str = "en") -> list[str]:
        """What ``scanlab exercise check`` prints: the verdict, each diagnosis, what was checked."""
        name = Path(self.file).name
        if lang == "ja":
            head = f"{self.exercise}: {name}: {VERDICT_JA[self.verdict]}（終了ステータス {self.status}）"
        else:
            head = f"{self.exercise}: {name}: {self.verdict} (exit status {self.status})"
        lines = [head] + [f"  {m}" for m in self.messages(lang)]
        if self.checked.get(lang):
            lines.append("  確認した内容:" if lang == "ja" else "  checked:")
            lines += [f"    {c}" for c in self.checked[lang]]
        if self.output.strip() and self.status == 2:
            shown = self.output.strip().splitlines()[-5:]
            lines.append("  最後の出力:" if lang == "ja" else "  last lines it printed:")
            lines += [f"    | {line[:200]}" for line in shown]
        return lines

    def write_panels(self, folder: Path, stem: str) -> list[Path]:
        """Every panel's PNGs into ``folder``, named from ``stem``; the paths written."""
        paths = []
        for i, panel in enumerate(self.panels):
            paths += panel.write(Path(folder), stem if i == 0 else f"{stem}-{i + 1}")
        return paths


def _dims(output: Output, case: Case, exercise: Exercise, arrays: list[np.ndarray]) -> tuple:
    """The expected shape of ``output`` for ``case``: None = any; "@name" = that output's rows."""
    dims = []
    for d in output.shape:
        if isinstance(d, str) and d.startswith("@"):
            index = [o.name for o in exercise.outputs].index(d[1:])
            dims.append(arrays[index].shape[0] if arrays[index].ndim else None)
        elif isinstance(d, str):
            dims.append(int(case.args[exercise.parameters.index(d)]))
        else:
            dims.append(d)
    return tuple(dims)


def _shape_text(dims: tuple) -> str:
    return "(" + ", ".join("any" if d is None else str(d) for d in dims) + ")"


def type_problem(exercise: Exercise, cases: list[Case], results: list[list[np.ndarray]]) -> Finding | None:
    """The first returned array whose shape or dtype is not the output's, as a
    ``wrong-return-type`` finding; None when every array fits."""
    kinds = {"f": "floats", "i": "integers", "u": "integers", "b": "booleans"}
    kinds_ja = {"f": "浮動小数点数", "i": "整数", "u": "整数", "b": "真偽値"}
    for case, arrays in zip(cases, results):
        for output, array in zip(exercise.outputs, arrays):
            dims = _dims(output, case, exercise, arrays)
            fits = array.ndim == len(dims) and all(d is None or d == s for d, s in zip(dims, array.shape))
            if not fits:
                return Finding("wrong-return-type", {
                    "call": case.call,
                    "message": f"{output.name} has shape {array.shape}; expected {_shape_text(dims)}",
                    "message_ja": f"{output.name} の形が {array.shape} です。正しくは {_shape_text(dims)}"})
            if array.dtype.kind not in output.kinds:
                wanted = " or ".join(dict.fromkeys(kinds[k] for k in output.kinds))
                wanted_ja = "または".join(dict.fromkeys(kinds_ja[k] for k in output.kinds))
                return Finding("wrong-return-type", {
                    "call": case.call, "message": f"{output.name} holds {array.dtype}; expected {wanted}",
                    "message_ja": f"{output.name} の型が {array.dtype} です。{wanted_ja}にしてください"})
    return None


def check_file(exercise: Exercise, path: str | Path, limits: Limits = Limits()) -> Report:
    """Judge the student's ``path`` for ``exercise`` (see the module docstring)."""
    from compare.vtk_backend import ReferenceUnavailable

    started = time.perf_counter()
    report = Report(exercise.name, str(path))
    cases = exercise.cases()
    run = run_submission(path, exercise.function, [list(c.args) for c in cases], len(exercise.outputs), limits)
    report.output = run.output
    if not run.ok:
        details = dict(run.details)
        if isinstance(details.get("case"), int) and 0 <= details["case"] < len(cases):
            details["call"] = cases[details["case"]].call
        report.findings = [Finding(run.code, details)]
    else:
        problem = type_problem(exercise, cases, run.results)
        if problem is not None:
            report.findings = [problem]
        else:
            try:
                judgement = exercise.judge(cases, run.results)
                report.findings, report.checked, report.panels = judgement.findings, judgement.checked, judgement.panels
            except ReferenceUnavailable:
                raise
            except Exception as exc:  # noqa: BLE001 -- a checker bug must not hide the verdict of the others
                where = traceback.extract_tb(exc.__traceback__)[-1]
                report.findings = [Finding("checker-error", {
                    "message": f"{type(exc).__name__}: {exc} at {Path(where.filename).name}:{where.lineno}"})]
    report.seconds = time.perf_counter() - started
    return report
