"""Exercise ``menger``: the Menger sponge as a polygon model (the textbook's recursion 3).

Reference: :func:`lab.shapes.menger` — a cube of side 1 centred at the origin, the faces
between touching cubes removed, area 2·(20/9)^N + 4·(8/9)^N, volume (20/27)^N.
The inside test probes each face: a point belongs to the sponge when, at every level
k ≤ N, at most one of its base-3 digits is the middle one.
"""
from __future__ import annotations

import numpy as np

from lab import shapes
from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.meshcheck import Expected, probe_outward
from lab.app.exercises.meshexercise import MeshExercise, judge_meshes
from lab.app.exercises.exercise_registry import Case, Exercise, Output, register
from lab.app.exercises.starters import MESH_CONVENTIONS, starter
from lab.app.exercises.views import View

LEVELS = (0, 1, 2, 3)

TITLE = {"en": "the Menger sponge", "ja": "メンガーのスポンジ"}

STATEMENT = {
    "en": "Build the Menger sponge as a polygon model — a point table and a table of triangles, counter-clockwise "
          "seen from outside. Start from a cube of side 1 centred at the origin. At each level divide every cube "
          "into 3 × 3 × 3 and keep the 20 small cubes that have at most one coordinate in the middle (the six face "
          "centres and the centre go). Keep only the outer surface: where two cubes touch, their shared face lies "
          "inside the solid and must go. Triangles that meet share their points. The checker calls your function "
          "for levels 0 to 3, checks each surface (closed, facing outward, area 2·(20/9)^N + 4·(8/9)^N, volume "
          "(20/27)^N) and draws level 3, the textbook's exercise, beside the reference.",
    "ja": "メンガーのスポンジをポリゴンモデル（点の表と、外から見て反時計回りの三角形の表）として作ってください。原点を中心とする"
          "一辺 1 の立方体から始め、各段ですべての立方体を 3 × 3 × 3 に分け、座標のうち中央のものが高々一つの小立方体 20 個を"
          "残します（面の中心 6 個と中心 1 個を除く）。外側の面だけを残します。二つの立方体が接する面は立体の内側なので取り除きます。"
          "接する三角形は点を共有します。採点ではレベル 0〜3 で関数を呼び、それぞれの面（閉じているか、外向きか、表面積 "
          "2·(20/9)^N + 4·(8/9)^N、体積 (20/27)^N）を調べ、教科書の演習と同じレベル 3 を参照と並べて描画します。",
}

DOCSTRING = f"""The Menger sponge of recursion ``level`` (0, 1, 2, 3, ...) as a triangle mesh.

The sponge fills the cube of side 1 centred at the origin, [-0.5, 0.5]^3; level 0 is
that cube. Each level divides every cube into 3 x 3 x 3 smaller cubes and keeps the 20
that have at most one coordinate in the middle (the 6 face centres and the centre go).
Only the outer surface is drawn: a face shared by two touching cubes lies inside the
sponge and is left out (both copies). Each point appears once: triangles that meet
share the index of their common points.

Returns
-------
points : float array (N, 3).
triangles : int array (M, 3).

Area 2*(20/9)**level + 4*(8/9)**level, volume (20/27)**level.

{MESH_CONVENTIONS}
"""


def inside(level: int):
    """The sponge's inside test for points (K, 3) in model units: in the open unit cube and,
    at every level k ≤ N, at most one base-3 digit of (p + ½)·3^k equal to 1."""

    def test(p):
        q = np.asarray(p) + 0.5
        ok = np.all((q > 0.0) & (q < 1.0), axis=1)
        for k in range(1, level + 1):
            digits = np.floor(q * 3 ** k).astype(np.int64) % 3
            ok &= np.count_nonzero(digits == 1, axis=1) <= 1
        return ok

    return test


def expected(case: Case) -> Expected:
    n = case.args[0]

    def explain(call, volume):
        cells = volume * 27 ** n
        if n == 0 or abs(cells - round(cells)) > 1e-3 * max(cells, 1.0):
            return []
        return [Finding("wrong-subcubes", {"case": call, "volume": volume, "cells": round(cells), "side": 3 ** n,
                                           "expected": 20 ** n, "expected_volume": (20 / 27) ** n})]

    return Expected(bounds=np.array([-0.5, 0.5] * 3), area=2 * (20 / 9) ** n + 4 * (8 / 9) ** n,
                    volume=(20 / 27) ** n, outward=probe_outward(inside(n), 0.1 / 3 ** n), merged=True,
                    max_triangles=40 * 20 ** n, explain=explain)


def refine(found: list[Finding], case: Case, points, tris) -> list[Finding]:
    """Faces outside the sponge on both sides with the right volume mean the right number of
    cubes in the wrong places: one diagnosis, the selection, instead of stray faces."""
    n = case.args[0]
    stray = next((f for f in found if f.code == "stray-faces"), None)
    if stray is None or any(f.code == "wrong-subcubes" for f in found):
        return found
    rest = [f for f in found if f.code not in ("stray-faces", "internal-faces-kept", "wrong-area")]
    return rest + [Finding("wrong-subcubes", {"case": case.call, "volume": (20 / 27) ** n, "cells": 20 ** n,
                                              "side": 3 ** n, "expected": 20 ** n, "expected_volume": (20 / 27) ** n,
                                              "misplaced": stray.details["count"]})]


SPEC = MeshExercise(name="menger", expected=expected, reference=lambda case: shapes.menger(case.args[0]),
                    view=View(position=(1.9, 1.5, 2.5)), render_case=3, refine=refine)

register(Exercise(
    name="menger", lesson="01-polygon-model", title=TITLE, statement=STATEMENT, parameters=("level",),
    outputs=(Output("points", (None, 3), "fiu"), Output("triangles", (None, 3), "iu")),
    starter=starter("menger", "01-polygon-model", TITLE["en"], "menger(level: int)", DOCSTRING),
    cases=lambda: [Case((n,), f"menger({n})") for n in LEVELS],
    judge=lambda cases, results: judge_meshes(SPEC, cases, results)))
