"""Exercise ``look_at``: the world-to-view matrix of the U-V-N camera, row vectors.

Reference: :func:`renderer.camera.world_to_view` (N = normalize(eye − focal point),
U = normalize(up × N), V = N × U; ``p_view = [x, y, z, 1] @ M``). The mistakes it names
are built by :func:`frame` with one rule changed. The panel draws the course's
cylinder-and-cone scene as the student's matrix sees it — every object moved by
M_student·M_reference⁻¹ and drawn through the reference camera, which is the same
picture — against VTK's reference.
"""
from __future__ import annotations

from functools import partial

import numpy as np

from lab.app.exercises.matrixexercise import MatrixExercise, judge_matrices
from lab.app.exercises.exercise_registry import Case, Exercise, Output, register
from lab.app.exercises.starters import starter
from lab.scene import Camera

CASES = (((3.0, 2.0, 4.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
         ((0.0, 0.0, 5.0), (0.0, 0.0, 0.0), (0.0, 1.0, 0.0)),
         ((1.0, -2.0, 0.5), (0.5, 1.0, -1.0), (0.0, 0.0, 1.0)),
         ((-4.0, 1.0, -3.0), (1.0, 0.5, 2.0), (0.3, 1.0, 0.1)))

TITLE = {"en": "the camera's look-at matrix (U-V-N)", "ja": "カメラの視野変換行列（U-V-N）"}

STATEMENT = {
    "en": "Write the world-to-view matrix of a camera at eye, looking at focal_point, with view_up as the up hint — "
          "the course's U-V-N frame: N points from the focal point back toward the eye, U = up × N to the right, "
          "V = N × U up, each of length 1. Points are row vectors: a world point p goes to view space as "
          "[x, y, z, 1] @ M, where the eye is at the origin looking down −z with +y up. The checker compares your "
          "matrix with the renderer's on four cameras, names the usual mistakes (a transposed matrix, a mirrored "
          "frame, N the wrong way, an untilted up) and draws a scene through your camera.",
    "ja": "視点 eye から注視点 focal_point を見る、上方向のヒント view_up のカメラについて、ワールド座標から視点座標への行列を"
          "書いてください。講義の U-V-N 座標系です。N は注視点から視点の側へ向き、U = up × N が右、V = N × U が上で、いずれも"
          "長さ 1 です。点は行ベクトルで、ワールド座標の点 p は [x, y, z, 1] @ M で視点座標に移ります。視点座標では視点が原点、"
          "視線は −z 方向、+y が上です。採点では 4 つのカメラでレンダラーの行列と比べ、よくある誤り（転置、鏡像の座標系、逆向きの "
          "N、直交化していない上方向）を指摘し、あなたのカメラから見たシーンを描画します。",
}

DOCSTRING = """The world-to-view matrix of the U-V-N camera, for row vectors.

Parameters
----------
eye, focal_point, view_up : float arrays of shape (3,), world space. The camera is at
    ``eye`` and looks at ``focal_point``; ``view_up`` is a hint for "up" (not
    necessarily perpendicular to the viewing direction, never parallel to it).

Returns
-------
M : float array (4, 4) such that, for a world point p = (x, y, z),
    [x_view, y_view, z_view, 1] = [x, y, z, 1] @ M   (row vectors, as in the course).

Conventions
-----------
- The camera frame: N = (eye - focal_point) / |eye - focal_point| points back toward
  the eye; U = (view_up x N) / |view_up x N| points right; V = N x U points up.
  All three have length 1 and form a right-handed frame.
- View space: the eye at the origin, looking down -z, +x right, +y up.
"""


def frame(eye, focal_point, view_up, u_flipped=False, v_flipped=False, reverse=False, raw_up=False,
          unnormalised=False, unrotated=False) -> np.ndarray:
    """The look-at matrix with rules changed (all False: the right one).

    u_flipped : U = N × up (then V = N × U turns too: the picture upside down).
    v_flipped : V = U × N. Either alone (with ``u_flipped``, V = U × N keeps V) mirrors.
    reverse : N = focal point − eye. raw_up : V = the up hint, normalised.
    unnormalised : U = up × N not divided by its length. unrotated : the bottom row is −eye.
    """
    eye, focal, up = (np.asarray(v, dtype=np.float64) for v in (eye, focal_point, view_up))
    n = eye - focal
    n /= np.linalg.norm(n)
    if reverse:
        n = -n
    u = np.cross(n, up) if u_flipped else np.cross(up, n)
    if not unnormalised:
        u /= np.linalg.norm(u)
    v = up / np.linalg.norm(up) if raw_up else (np.cross(u, n) if v_flipped else np.cross(n, u))
    m = np.eye(4)
    m[:3, :3] = np.column_stack([u, v, n])
    m[3, :3] = -eye if unrotated else -np.array([u, v, n]) @ eye
    return m


def reference(case: Case) -> np.ndarray:
    from renderer.camera import world_to_view

    eye, focal, up = case.args
    return world_to_view(Camera(position=tuple(eye), focal_point=tuple(focal), view_up=tuple(up)))


VARIANTS = (("camera-mirrored", partial(frame, v_flipped=True)),
            ("camera-mirrored", partial(frame, u_flipped=True, v_flipped=True)),
            ("camera-upside-down", partial(frame, u_flipped=True)),
            ("view-direction-reversed", partial(frame, reverse=True)),
            ("up-not-orthogonalised", partial(frame, raw_up=True)),
            ("axes-not-normalised", partial(frame, unnormalised=True)),
            ("translation-not-rotated", partial(frame, unrotated=True)))
"""The mistakes named, as (code, the matrix it gives) pairs."""


def variant(make):
    return lambda case: make(*case.args)


def panel(case: Case, m: np.ndarray):
    """The cylinder-and-cone scene through the student's camera, or None when the matrix
    is not an invertible affine map (e.g. transposed: its last column is not (0, 0, 0, 1))."""
    from dataclasses import replace

    from lab.loading import load_scene
    from lab.app.exercises.views import compare_scenes

    if not np.allclose(m[:, 3], [0.0, 0.0, 0.0, 1.0], atol=1e-9) or abs(np.linalg.det(m[:3, :3])) < 1e-9:
        return None
    eye, focal, up = case.args
    scene = load_scene("cylinder-cone")
    camera = Camera(position=tuple(eye), focal_point=tuple(focal), view_up=tuple(up), view_angle=40.0)
    scene = replace(scene, camera=camera, image=replace(scene.image, size=(240, 180)))
    move = m @ np.linalg.inv(reference(case))
    student = replace(scene, objects=tuple(replace(o, model_to_world=o.model_to_world @ move) for o in scene.objects))
    return compare_scenes(case.call, student, scene, ("look_at", case.call))


SPEC = MatrixExercise(reference=reference, variants=tuple((code, variant(make)) for code, make in VARIANTS),
                      panel=panel)


def call(args) -> str:
    eye, focal, up = ("(" + ", ".join(f"{x:g}" for x in v) + ")" for v in args)
    return f"look_at({eye}, {focal}, {up})"


register(Exercise(
    name="look_at", lesson="03-camera", title=TITLE, statement=STATEMENT,
    parameters=("eye", "focal_point", "view_up"), outputs=(Output("M", (4, 4), "fiu"),),
    starter=starter("look_at", "03-camera", TITLE["en"], "look_at(eye, focal_point, view_up)", DOCSTRING),
    cases=lambda: [Case(tuple(list(v) for v in args), call(args)) for args in CASES],
    judge=lambda cases, results: judge_matrices(SPEC, cases, results)))
