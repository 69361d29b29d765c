"""The judge shared by the 4×4 matrix exercises (the camera's look-at, the perspective).

Each case's matrix is compared with the reference stage's own matrix (relative 1e-9).
When cases are wrong, the exercise's *variants* — functions that build the matrix a
known mistake gives (the transpose, a mirrored frame, a halved angle …) — are tried on
every wrong case: a variant equal to the student's matrix on all of them names the
mistake (also behind a transpose: then both are reported). Otherwise the first wrong
case's largest wrong entry is quoted (``matrix-wrong``).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.exercise_registry import Case, Judgement

RTOL = 1e-9


@dataclass(frozen=True)
class MatrixExercise:
    """reference : case → the right (4, 4) matrix; variants : (diagnosis code, case → the
    mistaken matrix) pairs, tried in order (a code may have several); panel : (case, student
    matrix) → a panel object or None."""

    reference: Callable[[Case], np.ndarray]
    variants: tuple
    panel: Callable | None = None


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    scale = max(1.0, float(np.max(np.abs(b))))
    return bool(np.allclose(a, b, rtol=0.0, atol=RTOL * scale))


def name_the_mistake(spec: MatrixExercise, wrong: list[tuple[Case, np.ndarray]]) -> list[Finding]:
    """The variant (or transposed variant) that explains every wrong case, as findings."""
    call = wrong[0][0].call
    for code, make in spec.variants:
        if all(_same(m, make(case)) for case, m in wrong):
            return [Finding(code, {"case": call})]
    for code, make in spec.variants:
        if all(_same(m.T, make(case)) for case, m in wrong):
            return [Finding("matrix-transposed", {"case": call}), Finding(code, {"case": call})]
    if all(_same(m.T, spec.reference(case)) for case, m in wrong):
        return [Finding("matrix-transposed", {"case": call})]
    case, m = wrong[0]
    ref = spec.reference(case)
    diff = np.abs(m - ref)
    row, col = np.unravel_index(int(np.argmax(diff)), diff.shape)
    count = int(np.count_nonzero(diff > RTOL * max(1.0, float(np.max(np.abs(ref))))))
    return [Finding("matrix-wrong", {"case": call, "row": int(row), "col": int(col), "got": float(m[row, col]),
                                     "expected": float(ref[row, col]), "count": count})]


def judge_matrices(spec: MatrixExercise, cases: list[Case], results: list[list[np.ndarray]]) -> Judgement:
    judgement = Judgement()
    wrong = []
    for case, arrays in zip(cases, results):
        m = arrays[0].astype(np.float64)
        if not np.isfinite(m).all():
            judgement.findings.append(Finding("nonfinite-values", {"case": case.call,
                                                                   "count": int((~np.isfinite(m)).sum()),
                                                                   "what": "matrix"}))
            return judgement
        ok = _same(m, spec.reference(case))
        judgement.checked["en"].append(f"{case.call}: {'right' if ok else 'wrong'}")
        judgement.checked["ja"].append(f"{case.call}: {'正しい' if ok else '誤り'}")
        if not ok:
            wrong.append((case, m))
    if wrong:
        judgement.findings = name_the_mistake(spec, wrong)
    if spec.panel is not None:
        case, m = wrong[0] if wrong else (cases[0], results[0][0].astype(np.float64))
        panel = spec.panel(case, m)
        if panel is not None:
            judgement.panels.append(panel)
    return judgement
