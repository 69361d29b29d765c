"""Exercise ``perspective``: the view-to-clip matrix of a perspective camera, row vectors.

Reference: :func:`renderer.camera.view_to_clip` for a perspective camera (glFrustum with
half-height near·tan(view_angle/2), half-width that times aspect; near → −1 and far → +1
after the division by w; w_clip = −z_view). The mistakes it names are built by
:func:`projection` with one rule changed.
"""
from __future__ import annotations

import math
from functools import partial

import numpy as np

from lab.app.exercises.matrixexercise import MatrixExercise, judge_matrices
from lab.app.exercises.exercise_registry import Case, Exercise, Output, register
from lab.app.exercises.starters import starter
from lab.scene import Camera

CASES = ((30.0, 4.0 / 3.0, 0.5, 20.0), (60.0, 1.0, 1.0, 10.0), (45.0, 16.0 / 9.0, 0.1, 100.0), (90.0, 0.5, 2.0, 3.0))

TITLE = {"en": "the perspective projection matrix", "ja": "透視投影行列"}

STATEMENT = {
    "en": "Write the matrix that takes view space (the eye at the origin looking down −z, +y up) to OpenGL's clip "
          "space for a perspective camera with a vertical view angle in degrees, an aspect ratio width / height and "
          "near and far clipping distances. Points are row vectors, [x, y, z, 1] @ P = [x_c, y_c, z_c, w_c]; after "
          "the division by w_c the visible volume is −1 ≤ x, y, z ≤ 1, the near plane at z = −1 and the far plane at "
          "+1. This is the course's x' = x·d/z as a 4×4 matrix. The checker compares it with the renderer's on four "
          "cameras and names the usual mistakes (transposed, Direct3D's depth range, the sign of w, the whole angle "
          "or degrees passed to tan, the aspect upside down).",
    "ja": "視点座標（視点が原点、視線は −z 方向、+y が上）から OpenGL のクリップ座標への、透視投影カメラの行列を書いてください。"
          "縦の画角は度で、アスペクト比は 幅/高さ、near と far は前方・後方クリップ面までの距離です。点は行ベクトルで "
          "[x, y, z, 1] @ P = [x_c, y_c, z_c, w_c]。w_c で割った後の可視領域は −1 ≤ x, y, z ≤ 1 で、前方クリップ面が z = −1、"
          "後方が +1 です。講義の x' = x·d/z を 4×4 行列で表したものです。採点では 4 つのカメラでレンダラーの行列と比べ、よくある"
          "誤り（転置、Direct3D の深度範囲、w の符号、画角全体や度のまま tan に渡す、逆さのアスペクト比）を指摘します。",
}

DOCSTRING = """The perspective projection: view space -> OpenGL clip space, for row vectors.

Parameters
----------
view_angle : the vertical field of view, degrees (0 < view_angle < 180).
aspect : width / height of the image.
near, far : distances from the eye to the clipping planes (0 < near < far).

Returns
-------
P : float array (4, 4) such that [x_c, y_c, z_c, w_c] = [x, y, z, 1] @ P for a
    view-space point (x, y, z).

Conventions
-----------
- View space: the eye at the origin looking down -z, +x right, +y up. Points are
  row vectors, as in the course.
- Clip space is OpenGL's: after the division by w_c, the visible volume is
  -1 <= x, y, z <= 1; the near plane (z = -near) goes to -1, the far plane to +1;
  w_c = -z (the distance in front of the eye).
- The top of the view at distance near is near * tan(view_angle / 2); its right
  edge is that times aspect.
"""


def projection(view_angle, aspect, near, far, zero_to_one=False, w_positive=False, whole_angle=False,
               degrees=False, inverted_aspect=False) -> np.ndarray:
    """The perspective matrix with one rule changed (all False: the right one)."""
    angle = view_angle if degrees else math.radians(view_angle)
    t = math.tan(angle if whole_angle else angle / 2.0)
    m = np.zeros((4, 4))
    m[0, 0] = aspect / t if inverted_aspect else 1.0 / (t * aspect)
    m[1, 1] = 1.0 / t
    if zero_to_one:
        m[2, 2], m[3, 2] = -far / (far - near), -far * near / (far - near)
    else:
        m[2, 2], m[3, 2] = -(far + near) / (far - near), -2.0 * far * near / (far - near)
    m[2, 3] = 1.0 if w_positive else -1.0
    return m


def reference(case: Case) -> np.ndarray:
    from renderer.camera import view_to_clip

    view_angle, aspect, near, far = case.args
    return view_to_clip(Camera(view_angle=view_angle), aspect, (near, far))


VARIANTS = {"depth-range-0-1": partial(projection, zero_to_one=True),
            "w-sign-flipped": partial(projection, w_positive=True),
            "fov-not-halved": partial(projection, whole_angle=True),
            "fov-in-degrees": partial(projection, degrees=True),
            "aspect-inverted": partial(projection, inverted_aspect=True)}

SPEC = MatrixExercise(reference=reference,
                      variants=tuple((code, (lambda make: lambda case: make(*case.args))(make))
                                     for code, make in VARIANTS.items()))


def call(args) -> str:
    return "perspective(" + ", ".join(f"{x:.6g}" for x in args) + ")"


register(Exercise(
    name="perspective", lesson="03-camera", title=TITLE, statement=STATEMENT,
    parameters=("view_angle", "aspect", "near", "far"), outputs=(Output("P", (4, 4), "fiu"),),
    starter=starter("perspective", "03-camera", TITLE["en"],
                    "perspective(view_angle: float, aspect: float, near: float, far: float)", DOCSTRING),
    cases=lambda: [Case(args, call(args)) for args in CASES],
    judge=lambda cases, results: judge_matrices(SPEC, cases, results)))
