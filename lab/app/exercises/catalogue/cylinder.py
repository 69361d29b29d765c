"""Exercise ``cylinder``: a closed cylinder with smooth sides and flat caps (the textbook's exercise).

Reference: :func:`lab.shapes.cylinder` — around the z axis from −height/2 to +height/2,
the side's points carrying the radial normals (cos θ, sin θ, 0), each cap its own centre
and ring with (0, 0, ±1). Area and volume are the reference's (the polygonal prism's);
the surface is convex around the origin. Drawn with Gouraud shading, where a faceted
side or a curved cap shows.
"""
from __future__ import annotations

import numpy as np

from lab import shapes
from lab.app.exercises.meshcheck import Expected, convex_outward
from lab.app.exercises.meshexercise import MeshExercise, judge_meshes
from lab.app.exercises.normalcheck import RoundShape, normal_findings
from lab.app.exercises.exercise_registry import Case, Exercise, Output, register
from lab.app.exercises.starters import MESH_CONVENTIONS, starter
from lab.app.exercises.views import View
from lab.measure import enclosed_volume, surface_area

CASES = ((24, 0.5, 1.0), (3, 0.5, 1.0), (7, 1.0, 0.5), (32, 0.3, 1.5))

TITLE = {"en": "a cylinder with smooth sides", "ja": "側面がなめらかな円柱"}

STATEMENT = {
    "en": "Build a closed cylinder around the z axis, from z = −height/2 to z = +height/2, whose side is smooth-shaded "
          "and whose caps are flat. The circle is the regular polygon with corners at θ_k = 2πk/segments, the first on "
          "+x. Give every point a unit normal: the side's points the direction away from the axis, (cos θ, sin θ, 0), "
          "shared by the neighbouring side faces; each cap its own centre and ring of points with the normal "
          "(0, 0, ±1) — the rim's positions appear twice, once for the side and once for the cap. The checker tries "
          "four sizes, checks closure, orientation, area and volume and every normal, and draws the first with "
          "Gouraud shading beside the reference.",
    "ja": "z 軸を中心に z = −height/2 から z = +height/2 までの閉じた円柱を作ってください。側面はスムーズシェーディング、ふたは"
          "平らにします。円は θ_k = 2πk/segments に頂点をもつ正多角形で、最初の頂点は +x 上です。すべての点に単位法線を与えます。"
          "側面の点には軸から外向きの方向 (cos θ, sin θ, 0) を与え、隣り合う側面で共有します。ふたにはそれぞれ専用の中心点と縁の点を"
          "作り、法線は (0, 0, ±1) です（縁の位置は側面用とふた用に 2 回現れます）。採点では 4 通りの大きさで、閉じているか、向き、"
          "表面積と体積、すべての法線を調べ、最初のものをグーローシェーディングで参照と並べて描画します。",
}

DOCSTRING = f"""A closed cylinder with a smooth side and flat caps, around the z axis.

The side runs from z = -height/2 to z = +height/2; the circle of ``radius`` is the
regular polygon with corners at theta_k = 2*pi*k/segments (k = 0 ... segments-1), the
first on +x. ``segments`` >= 3.

Returns
-------
points : float array (N, 3).
triangles : int array (M, 3).
normals : float array (N, 3): one unit normal per point, model space.
    Side points: (cos theta, sin theta, 0), shared by the neighbouring side faces, so
    Gouraud and Phong shading make the side look round. Each cap has its own centre
    and ring of points with the normal (0, 0, +1) on top and (0, 0, -1) at the bottom:
    a rim position appears twice, once for the side, once for the cap.

{MESH_CONVENTIONS}
"""


def round_shape(case: Case) -> RoundShape:
    segments, radius, height = case.args
    return RoundShape(segments, radius, height, lambda t: np.column_stack([np.cos(t), np.sin(t), np.zeros_like(t)]),
                      "(cos θ_k, sin θ_k, 0)")


def expected(case: Case) -> Expected:
    reference = shapes.cylinder(*case.args)
    return Expected(bounds=reference.bounds(), area=surface_area(reference), volume=enclosed_volume(reference),
                    outward=convex_outward(), merged=False, max_triangles=40 * case.args[0])


SPEC = MeshExercise(name="cylinder", expected=expected, reference=lambda case: shapes.cylinder(*case.args),
                    view=View(position=(2.6, 1.2, 1.4), shading="gouraud", view_up=(0.0, 0.0, 1.0)), render_case=0,
                    normals=lambda call, p, t, n, case: normal_findings(call, p, t, n, round_shape(case)))


def call(args) -> str:
    return f"cylinder({args[0]}, {args[1]:g}, {args[2]:g})"


register(Exercise(
    name="cylinder", lesson="09-shading", title=TITLE, statement=STATEMENT,
    parameters=("segments", "radius", "height"),
    outputs=(Output("points", (None, 3), "fiu"), Output("triangles", (None, 3), "iu"),
             Output("normals", ("@points", 3), "f")),
    starter=starter("cylinder", "09-shading", TITLE["en"], "cylinder(segments: int, radius: float, height: float)",
                    DOCSTRING),
    cases=lambda: [Case(args, call(args)) for args in CASES],
    judge=lambda cases, results: judge_meshes(SPEC, cases, results)))
