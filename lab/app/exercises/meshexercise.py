"""The judge shared by the mesh exercises (Menger sponge, icosahedron fractal, icosphere,
cylinder, cone): geometry on every case, normals where the exercise returns them, and a
picture of one case against the reference.

Each case's findings come from :func:`lab.app.exercises.meshcheck.mesh_findings` (and the
exercise's normals check); a code found in several cases is reported once, for the
first (smallest) case, which is the easiest to debug. The picture case is drawn when the
mesh can be drawn at all, whatever else was found, so the panel shows the mistake;
failing the bars adds ``render-differs``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.meshcheck import Expected, mesh_findings
from lab.app.exercises.exercise_registry import Case, Judgement
from lab.app.exercises.views import View, compare_meshes, renderable
from lab.mesh import Mesh


@dataclass(frozen=True)
class MeshExercise:
    """What one mesh exercise supplies to :func:`judge_meshes`.

    name : the exercise (keys the cached reference pictures).
    expected : case → :class:`~lab.app.exercises.meshcheck.Expected`.
    reference : case → the reference solution's :class:`lab.mesh.Mesh` (the built-in shape).
    view : how the picture is drawn; render_case : the index of the case drawn.
    normals : (call, points, triangles, normals, case) → findings, for exercises returning normals.
    refine : (findings, case, points, triangles) → findings, the exercise's reading of them.
    """

    name: str
    expected: Callable[[Case], Expected]
    reference: Callable[[Case], Mesh]
    view: View
    render_case: int
    normals: Callable | None = None
    refine: Callable | None = None


STOPPERS = {"no-triangles", "too-many-triangles", "nonfinite-values", "index-out-of-range", "wrong-scale",
            "not-centred", "not-closed", "cracks"}
"""Findings after which the normals of a case are not looked at."""


def judge_meshes(spec: MeshExercise, cases: list[Case], results: list[list[np.ndarray]]) -> Judgement:
    judgement = Judgement()
    seen: dict[str, Finding] = {}
    for case, arrays in zip(cases, results):
        points, tris = arrays[0].astype(np.float64).reshape(-1, 3), arrays[1].astype(np.int64).reshape(-1, 3)
        found = mesh_findings(case.call, points, tris, spec.expected(case))
        if spec.normals is not None and not any(f.code in STOPPERS for f in found):
            found += spec.normals(case.call, points, tris, arrays[2].astype(np.float64).reshape(-1, 3), case)
        if spec.refine is not None:
            found = spec.refine(found, case, points, tris)
        for f in found:
            seen.setdefault(f.code, f)
        codes = ", ".join(f.code for f in found)
        judgement.checked["en"].append(f"{case.call}: {len(tris):,} triangles, {len(points):,} points — "
                                       + (codes if found else "right"))
        judgement.checked["ja"].append(f"{case.call}: 三角形 {len(tris):,}、点 {len(points):,} — "
                                       + (codes if found else "正しい"))
    judgement.findings = list(seen.values())

    case, arrays = cases[spec.render_case], results[spec.render_case]
    normals = arrays[2].astype(np.float64).reshape(-1, 3) if len(arrays) > 2 else None
    if normals is not None and len(normals) != len(arrays[0]):
        normals = None
    student = Mesh(arrays[0], arrays[1].astype(np.int64), normals)
    reference = spec.reference(case)
    if renderable(student, reference):
        comparison = compare_meshes(case.call, student, reference, spec.view, (spec.name, spec.render_case))
        judgement.panels.append(comparison)
        figures = comparison.figures()
        judgement.checked["en"].append(f"{case.call} drawn by scanlab against VTK's reference: {figures}")
        judgement.checked["ja"].append(f"{case.call} を scanlab で描画し VTK の参照と比較: {figures}")
        if comparison.failed:
            judgement.findings.append(Finding("render-differs", {"case": case.call,
                                                                  "failed": "; ".join(comparison.failed)}))
    return judgement
