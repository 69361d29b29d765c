"""Exercise ``cone``: a closed cone with a smooth side and a flat base (the textbook's exercise).

Reference: :func:`lab.shapes.cone` — base circle at z = −height/2, apex at +height/2; side
normals n(θ) = (h·cos θ, h·sin θ, r)/√(h² + r²) (tilted up toward the apex), one apex
point per side triangle; the base its own centre and ring with (0, 0, −1). Area and
volume are the reference's (the polygonal pyramid's); convex around the origin.
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

TITLE = {"en": "a cone with a smooth side", "ja": "側面がなめらかな円錐"}

STATEMENT = {
    "en": "Build a closed cone around the z axis: the base circle at z = −height/2, the apex at z = +height/2. The "
          "circle is the regular polygon with corners at θ_k = 2πk/segments, the first on +x. The side is "
          "smooth-shaded: a base-ring point of the side carries the cone's normal at its angle, "
          "n(θ) = (h·cos θ, h·sin θ, r)/√(h² + r²), which leans up toward the apex. The apex has no single normal: "
          "give each side triangle its own apex point with the normal at the middle of its segment. The base is flat, "
          "with its own centre and ring of points and the normal (0, 0, −1). The checker tries four sizes, checks "
          "closure, orientation, area and volume and every normal, and draws the first with Gouraud shading beside "
          "the reference.",
    "ja": "z 軸を中心とする閉じた円錐を作ってください。底面の円は z = −height/2、頂点は z = +height/2 にあります。円は "
          "θ_k = 2πk/segments に頂点をもつ正多角形で、最初の頂点は +x 上です。側面はスムーズシェーディングにします。側面の底の縁の"
          "点には、その角度での円錐の法線 n(θ) = (h·cos θ, h·sin θ, r)/√(h² + r²)（頂点の側へ傾く）を与えます。頂点には一つの"
          "法線が決まらないので、側面の三角形ごとに専用の頂点を作り、その区間の中央の角度での法線を与えます。底面は平らで、専用の"
          "中心点と縁の点をもち、法線は (0, 0, −1) です。採点では 4 通りの大きさで、閉じているか、向き、表面積と体積、すべての"
          "法線を調べ、最初のものをグーローシェーディングで参照と並べて描画します。",
}

DOCSTRING = f"""A closed cone with a smooth side and a flat base, around the z axis.

The base circle of ``radius`` lies at z = -height/2, the apex at z = +height/2; the
circle is the regular polygon with corners at theta_k = 2*pi*k/segments
(k = 0 ... segments-1), the first on +x. ``segments`` >= 3.

Returns
-------
points : float array (N, 3).
triangles : int array (M, 3).
normals : float array (N, 3): one unit normal per point, model space.
    Side points on the base ring: the cone's normal at their angle,
    (h*cos(theta), h*sin(theta), r) / sqrt(h**2 + r**2), leaning up toward the apex.
    The apex has no single normal: give each side triangle its own apex point, with
    the normal at the middle of its segment (theta_k + pi/segments). The base has its
    own centre and ring of points with the normal (0, 0, -1).

{MESH_CONVENTIONS}
"""


def round_shape(case: Case) -> RoundShape:
    segments, radius, height = case.args

    def tilted(t):
        return np.column_stack([height * np.cos(t), height * np.sin(t), np.full_like(t, radius)]) / np.hypot(height,
                                                                                                           radius)

    return RoundShape(segments, radius, height, tilted, "(h·cos θ_k, h·sin θ_k, r) / √(h² + r²)",
                      apex=(0.0, 0.0, height / 2.0))


def expected(case: Case) -> Expected:
    reference = shapes.cone(*case.args)
    return Expected(bounds=reference.bounds(), area=surface_area(reference), volume=enclosed_volume(reference),
                    outward=convex_outward(), merged=False, max_triangles=40 * case.args[0])


SPEC = MeshExercise(name="cone", expected=expected, reference=lambda case: shapes.cone(*case.args),
                    view=View(position=(2.4, 1.1, 1.2), shading="gouraud", view_up=(0.0, 0.0, 1.0)), render_case=0,
                    normals=lambda call, p, t, n, case: normal_findings(call, p, t, n, round_shape(case)))


def call(args) -> str:
    return f"cone({args[0]}, {args[1]:g}, {args[2]:g})"


register(Exercise(
    name="cone", lesson="09-shading", title=TITLE, statement=STATEMENT, parameters=("segments", "radius", "height"),
    outputs=(Output("points", (None, 3), "fiu"), Output("triangles", (None, 3), "iu"),
             Output("normals", ("@points", 3), "f")),
    starter=starter("cone", "09-shading", TITLE["en"], "cone(segments: int, radius: float, height: float)", DOCSTRING),
    cases=lambda: [Case(args, call(args)) for args in CASES],
    judge=lambda cases, results: judge_meshes(SPEC, cases, results)))
