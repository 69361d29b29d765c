"""Exercise ``icosphere``: the subdivided icosahedron on the unit sphere (levels 0–5).

Reference: :func:`lab.shapes.icosphere` — each triangle split in four, the edge
midpoints pushed onto the sphere and shared between neighbours: 20·4^N triangles,
10·4^N + 2 points. The surface is convex around the origin; its area and volume are the
reference's (measured, :mod:`lab.measure`), its points lie on the unit sphere.
"""
from __future__ import annotations

import numpy as np

from lab import shapes
from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.meshcheck import Expected, convex_outward
from lab.app.exercises.meshexercise import MeshExercise, judge_meshes
from lab.app.exercises.exercise_registry import Case, Exercise, Output, register
from lab.app.exercises.starters import MESH_CONVENTIONS, starter
from lab.app.exercises.views import View
from lab.measure import enclosed_volume, surface_area

LEVELS = (0, 1, 2, 3, 4, 5)

TITLE = {"en": "the subdivided icosahedron (a sphere)", "ja": "正二十面体の細分割による球"}

STATEMENT = {
    "en": "Approximate the unit sphere as the textbook does: start from the regular icosahedron with its vertices "
          "on the unit sphere, then at each level split every triangle into four through its edge midpoints and "
          "push each midpoint out onto the sphere. Neighbouring triangles share their midpoints, so level N has "
          "20·4^N triangles and 10·4^N + 2 points. The checker calls levels 0 to 5, checks that every point is on "
          "the sphere, the counts, that the surface is closed and faces outward, its area and volume, and draws "
          "level 2 with flat shading beside the reference.",
    "ja": "教科書と同じ方法で単位球を近似してください。頂点が単位球面上にある正二十面体から始め、各段ですべての三角形を辺の中点で"
          " 4 つに分け、各中点を球面上へ押し出します。隣り合う三角形は中点を共有するので、レベル N の三角形は 20·4^N 個、点は "
          "10·4^N + 2 個です。採点ではレベル 0〜5 で呼び、すべての点が球面上にあるか、個数、閉じて外を向いているか、表面積と"
          "体積を調べ、レベル 2 をフラットシェーディングで参照と並べて描画します。",
}

DOCSTRING = f"""The unit sphere approximated by the subdivided icosahedron of ``level`` (0 ... 5).

Level 0: the regular icosahedron with its 12 vertices on the unit sphere (the
golden-ratio vertices (0, +-1, +-phi) and their cyclic shifts, divided by their length).
Each level splits every triangle (a, b, c) into four through the midpoints of its
edges, and pushes every midpoint m out onto the sphere (m / |m|). A midpoint is shared
by the two triangles of its edge: level N has 20 * 4**N triangles and 10 * 4**N + 2
points, all of them at distance 1 from the origin.

Returns
-------
points : float array (N, 3).
triangles : int array (M, 3).

{MESH_CONVENTIONS}
"""


def expected(case: Case) -> Expected:
    n = case.args[0]
    reference = shapes.icosphere(n)

    def early(call, points, tris):
        radius = np.linalg.norm(points[np.unique(tris)], axis=1)
        off = np.abs(radius - 1.0) > 1e-9
        if not off.any():
            return []
        return [Finding("points-off-sphere", {"case": call, "count": int(off.sum()),
                                              "distance": float(radius[off][0])})]

    return Expected(bounds=reference.bounds(), area=surface_area(reference), volume=enclosed_volume(reference),
                    outward=convex_outward(), triangles=20 * 4 ** n, merged=True, max_triangles=40 * 4 ** n,
                    early=early)


SPEC = MeshExercise(name="icosphere", expected=expected, reference=lambda case: shapes.icosphere(case.args[0]),
                    view=View(position=(1.6, 2.4, 3.4)), render_case=2)

register(Exercise(
    name="icosphere", lesson="09-shading", title=TITLE, statement=STATEMENT, parameters=("level",),
    outputs=(Output("points", (None, 3), "fiu"), Output("triangles", (None, 3), "iu")),
    starter=starter("icosphere", "09-shading", TITLE["en"], "icosphere(level: int)", DOCSTRING),
    cases=lambda: [Case((n,), f"icosphere({n})") for n in LEVELS],
    judge=lambda cases, results: judge_meshes(SPEC, cases, results)))
