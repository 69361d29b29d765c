"""Stages 2–3, world → view → clip: the U-V-N camera frame and VTK's projections.

Row vectors throughout (``P_view = [P_world, 1] @ world_to_view``). View space is
right-handed with the eye at the origin looking down −z, y up (VTK's and OpenGL's).
Clip space is OpenGL's: after division by w, x, y, z in [−1, 1] are visible.
"""
from __future__ import annotations

import math

import numpy as np

# vtkRenderer defaults: ClippingRangeExpansion, and NearClippingPlaneTolerance for a
# depth buffer of more than 16 bits (llvmpipe's is 24).
CLIPPING_RANGE_EXPANSION = 0.5
NEAR_CLIPPING_PLANE_TOLERANCE = 0.001


def uvn_frame(position, focal_point, view_up) -> np.ndarray:
    """The camera's axes in world space, as rows: U (right), V (up), N (toward the eye).

    N = normalize(position − focal_point), U = normalize(up × N), V = N × U — the
    course's U-V-N frame and ``vtkPerspectiveTransform::SetupCamera``.
    """
    n = unit(np.subtract(position, focal_point).astype(np.float64))
    u = unit(cross(view_up, n))
    return np.array([u, cross(n, u), n])


def cross(a, b) -> np.ndarray:
    """a × b of two 3-vectors, float64: each component a product less a product, as
    ``np.cross`` works it out (the same bits), without its general machinery (10 µs a call)."""
    return np.array([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]],
                    dtype=np.float64)


def unit(v: np.ndarray) -> np.ndarray:
    """``v`` (3,) float64 divided by its length, √(v·v) as ``np.linalg.norm`` takes it (the same bits)."""
    return v / math.sqrt(v.dot(v))


def world_to_view(camera) -> np.ndarray:
    """4×4 row-vector matrix: world → view (eye at origin, looking down −z)."""
    uvn = uvn_frame(camera.position, camera.focal_point, camera.view_up)
    m = np.eye(4)
    m[:3, :3] = uvn.T  # columns are U, V, N: x_view = P·U etc.
    m[3, :3] = -uvn @ np.asarray(camera.position, dtype=np.float64)
    return m


def view_to_clip(camera, aspect: float, clipping_range) -> np.ndarray:
    """4×4 row-vector matrix: view → clip, VTK's frustum or ortho for ``aspect`` = W/H.

    Perspective: glFrustum with half-height h = near·tan(view_angle/2) (vertical angle,
    degrees) and half-width h·aspect. Parallel: glOrtho with half-height
    ``parallel_scale`` and half-width ``parallel_scale·aspect``. Depth maps near → −1,
    far → +1.
    """
    near, far = clipping_range
    m = np.zeros((4, 4))
    if camera.parallel:
        h = camera.parallel_scale
        w = h * aspect
        m[0, 0], m[1, 1] = 1.0 / w, 1.0 / h
        m[2, 2] = -2.0 / (far - near)
        m[3, 2] = -(far + near) / (far - near)
        m[3, 3] = 1.0
    else:
        t = math.tan(math.radians(camera.view_angle) / 2.0)
        m[0, 0], m[1, 1] = 1.0 / (t * aspect), 1.0 / t
        m[2, 2] = -(far + near) / (far - near)
        m[3, 2] = -2.0 * far * near / (far - near)
        m[2, 3] = -1.0  # w_clip = −z_view
    return m


def fit_clipping_range(camera, bounds) -> tuple[float, float]:
    """The (near, far) that ``vtkRenderer::ResetCameraClippingRange`` picks for ``bounds``.

    The eight bounding-box corners are measured along the view direction; the range
    between the nearest and farthest is widened to a minimum gap, near is kept in front
    of the eye, both ends are padded (1 % and ``CLIPPING_RANGE_EXPANSION`` of the range,
    the far end measured from the already padded near, as VTK does)
    and near is raised to at least ``NEAR_CLIPPING_PLANE_TOLERANCE``·far.

    Parameters
    ----------
    camera : lab.scene.Camera
    bounds : (xmin, xmax, ymin, ymax, zmin, zmax) in world space.
    """
    pos = [float(p) for p in camera.position]
    a, b, c = (-unit(np.subtract(camera.position, camera.focal_point).astype(np.float64))).tolist()
    bounds = [float(v) for v in bounds]  # Python floats: the same float64 arithmetic, without numpy's per-number cost
    d = -(a * pos[0] + b * pos[1] + c * pos[2])
    near = a * bounds[0] + b * bounds[2] + c * bounds[4] + d
    far = 1e-18
    for k in range(2):
        for j in range(2):
            for i in range(2):
                dist = a * bounds[i] + b * bounds[2 + j] + c * bounds[4 + k] + d
                near = min(near, dist)
                far = max(far, dist)
    if camera.parallel:
        min_gap = 0.1 * camera.parallel_scale
    else:
        min_gap = 0.2 * math.tan(math.radians(camera.view_angle) / 2.0) * far
    if far - near < min_gap:
        min_gap = min_gap - far + near
        far += min_gap / 2.0
        near -= min_gap / 2.0
    near = max(near, 0.0)
    near = 0.99 * near - (far - near) * CLIPPING_RANGE_EXPANSION
    far = 1.01 * far + (far - near) * CLIPPING_RANGE_EXPANSION  # VTK uses the new near here
    if near >= far:
        near = 0.01 * far
    near = max(near, NEAR_CLIPPING_PLANE_TOLERANCE * far)
    return float(near), float(far)


def clipping_range(camera, bounds) -> tuple[float, float]:
    """The camera's explicit range, or the fitted one when the scene gives none."""
    return tuple(camera.clipping_range) if camera.clipping_range is not None else fit_clipping_range(camera, bounds)
