"""Moving the camera from the page: orbit by dragging on our image, zoom, reset.

The camera is the controls' camera (:func:`lab.app.live.controls.camera_controls`:
position, focal point and view up in world space, right-handed, y up on screen). A drag
is given as fractions of the image: ``right`` (+ to the right) and ``down`` (+ down, the
browser's y), so the result does not depend on how large the page shows the image.

As VTK's trackball camera style does, a drag across the whole width turns the camera
180° about the view-up axis through the focal point (VTK's ``Azimuth``), and a drag down
the whole height 180° about the camera's right axis (VTK's ``Elevation``): the object
follows the pointer. Unlike ``Elevation`` followed by ``OrthogonalizeViewUp``, the view-up
vector turns with the camera, so going over the top never makes it parallel to the view
direction.
"""
from __future__ import annotations

import math

import numpy as np

DEGREES_PER_DRAG = 180.0
"""Degrees the camera turns for a drag across the whole image."""


def rotation(axis, degrees: float) -> np.ndarray:
    """3×3 matrix turning column vectors right-handedly about ``axis`` (Rodrigues' formula)."""
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a)
    t = math.radians(degrees)
    k = np.array([[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]])
    return np.eye(3) + math.sin(t) * k + (1.0 - math.cos(t)) * (k @ k)


def _frame(camera: dict) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Focal point, focal-to-camera vector, unit right and unit up (orthogonal to the view)."""
    focal = np.asarray(camera["focal_point"], float)
    offset = np.asarray(camera["position"], float) - focal
    back = offset / np.linalg.norm(offset)
    right = np.cross(np.asarray(camera["view_up"], float), back)
    right /= np.linalg.norm(right)
    return focal, offset, right, np.cross(back, right)


def orbit(camera: dict, right: float, down: float) -> dict:
    """The camera after a drag of ``right`` × width and ``down`` × height (see the module docstring)."""
    focal, offset, right_axis, up = _frame(camera)
    turn = rotation(up, -DEGREES_PER_DRAG * right) @ rotation(right_axis, -DEGREES_PER_DRAG * down)
    return {**camera, "position": (focal + turn @ offset).tolist(), "view_up": (turn @ up).tolist()}


def zoom(camera: dict, factor: float) -> dict:
    """Closer by ``factor`` (> 1 enlarges): VTK's ``Dolly`` for a perspective camera (the
    distance to the focal point divided by it), the parallel scale divided by it otherwise."""
    if camera.get("parallel"):
        return {**camera, "parallel_scale": float(camera["parallel_scale"]) / factor}
    focal = np.asarray(camera["focal_point"], float)
    offset = np.asarray(camera["position"], float) - focal
    return {**camera, "position": (focal + offset / factor).tolist()}


def usable(camera) -> bool:
    """Whether ``camera`` holds numbers a move can start from (a field being typed may not)."""
    try:
        points = np.array([camera["position"], camera["focal_point"], camera["view_up"]], float)
    except (KeyError, TypeError, ValueError):
        return False
    if not np.all(np.isfinite(points)):
        return False
    offset, up = points[0] - points[1], points[2]
    return bool(np.linalg.norm(np.cross(up, offset)) > 1e-12 * np.linalg.norm(offset) * np.linalg.norm(up) > 0)
