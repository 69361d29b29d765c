"""Exercise ``icosahedron_fractal``: the textbook's icosahedron flake (recursion 3).

Reference: :func:`lab.shapes.icosahedron_fractal` — 12^N icosahedra of circumradius
s^N, s = 1/(1 + φ), each copy at c + (1 − s)·R·v_i; neighbours share an edge, nothing
overlaps, so the area and volume are 12^N·s^(2N) and 12^N·s^(3N) times the unit
icosahedron's. A face is outward when it faces away from the centre of the copy it
lies on (the nearest centre); the scale factor is read from the edge lengths, all
e0·s^N (e0 = 2/√(1 + φ²), the unit-circumradius edge).
"""
from __future__ import annotations

import numpy as np

from lab import shapes
from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.meshcheck import INWARD, OUTWARD, STRAY, Expected
from lab.app.exercises.meshexercise import MeshExercise, judge_meshes
from lab.app.exercises.exercise_registry import Case, Exercise, Output, register
from lab.app.exercises.starters import MESH_CONVENTIONS, starter
from lab.app.exercises.views import View
from lab.measure import enclosed_volume, surface_area

LEVELS = (0, 1, 2, 3)
S = 1.0 / (1.0 + shapes.PHI)
UNIT = shapes.icosahedron(1.0)
EDGE = float(np.linalg.norm(UNIT.points[0] - UNIT.points[11]))
INRADIUS = float(np.linalg.norm(UNIT.points[UNIT.triangles[0]].mean(axis=0)))  # a face's centre is its foot

TITLE = {"en": "the icosahedron fractal", "ja": "正二十面体フラクタル"}

STATEMENT = {
    "en": "Build the icosahedron flake of the textbook's exercise. Level 0 is the regular icosahedron with "
          "circumradius 1 centred at the origin (vertices (0, ±1, ±φ) and their cyclic shifts, scaled). Each level "
          "replaces every icosahedron (centre c, circumradius R) by 12 copies scaled by s = 1/(1 + φ), centred at "
          "c + (1 − s)·R·v for each of its unit vertex directions v, so that each copy touches the parent's "
          "circumsphere at a vertex and neighbouring copies share an edge. Keep each icosahedron a closed surface, "
          "faces counter-clockwise from outside. The checker calls levels 0 to 3, checks counts, closure, "
          "orientation, the scale factor, area and volume, and draws level 3 beside the reference.",
    "ja": "教科書の演習の正二十面体フラクタルを作ってください。レベル 0 は原点を中心とする外接球半径 1 の正二十面体です（頂点は "
          "(0, ±1, ±φ) とその巡回置換を拡大縮小したもの）。各段で、すべての正二十面体（中心 c、外接球半径 R）を、s = 1/(1 + φ) "
          "倍に縮小した 12 個のコピーに置き換えます。コピーの中心は各頂点方向の単位ベクトル v について c + (1 − s)·R·v で、"
          "各コピーは親の外接球に頂点で接し、隣り合うコピーは辺を共有します。各正二十面体は閉じた面のままにし、面は外から見て"
          "反時計回りにします。採点ではレベル 0〜3 で呼び、三角形の数、閉じているか、向き、縮小率、表面積と体積を調べ、レベル 3 "
          "を参照と並べて描画します。",
}

DOCSTRING = f"""The icosahedron fractal of recursion ``level`` (0, 1, 2, 3, ...).

Level 0: the regular icosahedron of circumradius 1 centred at the origin, from the
golden-ratio vertices (0, +-1, +-phi) and their cyclic shifts, scaled to length 1;
20 faces. Each level replaces every icosahedron (centre c, circumradius R) by 12
copies scaled by s = 1 / (1 + phi), centred at c + (1 - s) * R * v for its 12 unit
vertex directions v (the copies keep the parent's orientation). Level N has 12**N
icosahedra and 20 * 12**N triangles; each icosahedron stays a closed surface (points
may be shared between neighbouring copies or not).

Returns
-------
points : float array (N, 3).
triangles : int array (M, 3).

{MESH_CONVENTIONS}
"""


def centres(level: int) -> np.ndarray:
    """The 12^level centres of the copies, as the built-in shape places them."""
    c, radius = np.zeros((1, 3)), 1.0
    for _ in range(level):
        c = (c[:, None, :] + (1.0 - S) * radius * UNIT.points[None, :, :]).reshape(-1, 3)
        radius *= S
    return c


def outward_test(level: int):
    from scipy.spatial import cKDTree

    c = centres(level)
    tree = cKDTree(c)
    inradius = INRADIUS * S ** level

    def outward(probes, normals):
        _, nearest = tree.query(probes)
        side = np.einsum("ij,ij->i", normals, probes - c[nearest])
        on_a_copy = np.abs(np.abs(side) - inradius) <= 1e-6 * inradius
        return np.where(~on_a_copy, STRAY, np.where(side > 0, OUTWARD, INWARD))

    return outward


def expected(case: Case) -> Expected:
    n = case.args[0]
    reference = shapes.icosahedron_fractal(n)

    def early(call, points, tris):
        if n == 0:
            return []
        edges = np.linalg.norm(points[tris] - points[np.roll(tris, -1, axis=1)], axis=2)
        factor = (float(np.median(edges)) / EDGE) ** (1.0 / n)
        if np.isclose(factor, S, rtol=1e-6):
            return []
        return [Finding("wrong-scale-factor", {"case": call, "factor": factor, "expected": S})]

    count = 12 ** n
    return Expected(bounds=reference.bounds(), area=count * S ** (2 * n) * surface_area(UNIT),
                    volume=count * S ** (3 * n) * enclosed_volume(UNIT), outward=outward_test(n),
                    triangles=20 * count, merged=False, max_triangles=40 * count, early=early)


SPEC = MeshExercise(name="icosahedron_fractal", expected=expected,
                    reference=lambda case: shapes.icosahedron_fractal(case.args[0]),
                    view=View(position=(1.2, 2.2, 3.6)), render_case=3)

register(Exercise(
    name="icosahedron_fractal", lesson="01-polygon-model", title=TITLE, statement=STATEMENT, parameters=("level",),
    outputs=(Output("points", (None, 3), "fiu"), Output("triangles", (None, 3), "iu")),
    starter=starter("icosahedron_fractal", "01-polygon-model", TITLE["en"], "icosahedron_fractal(level: int)",
                    DOCSTRING),
    cases=lambda: [Case((n,), f"icosahedron_fractal({n})") for n in LEVELS],
    judge=lambda cases, results: judge_meshes(SPEC, cases, results)))
