"""Stage 1, model → world (and on to view and clip): points and normals through 4×4 matrices.

Points are row vectors, ``[x', y', z', w'] = [x, y, z, 1] @ M`` (the convention of
:mod:`lab.matrices`, where the matrices are built).

The per-vertex products run in numba loops (:func:`transform_vertices`), not through
numpy's ``@``: a matrix product of a large array goes to the BLAS library, whose threads
then fight the renderer's own (measured: 300 ms instead of 8 for 328k vertices), and whose
rounding depends on which kernel it picks on this processor. Here each component is
``x·m0 + y·m1 + z·m2 + m3``, summed in that order, the same everywhere.
"""
from __future__ import annotations

import numpy as np

from renderer.clip import outcode
from renderer.jit import njit, prange
from renderer.window import map_point


def to_homogeneous(points: np.ndarray) -> np.ndarray:
    """(N, 3) → (N, 4) with w = 1."""
    return np.concatenate([points, np.ones((len(points), 1))], axis=1)


def transform_points(points: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    """Apply a row-vector 4×4 matrix to (N, 3) points; returns (N, 4) homogeneous rows."""
    points = np.ascontiguousarray(points, dtype=np.float64)
    out = np.empty((len(points), 4))
    points_through(points, np.ascontiguousarray(matrix, dtype=np.float64), out)
    return out


def normal_matrix(matrix: np.ndarray) -> np.ndarray:
    """The 3×3 that carries normals under ``matrix`` (row vectors): inverse-transpose of its 3×3."""
    return np.linalg.inv(matrix[:3, :3]).T


@njit(cache=True, parallel=True)
def points_through(points, m, out):
    """``out[i] = [points[i], 1] @ m`` (the loop kernel of :func:`transform_points`)."""
    for i in prange(points.shape[0]):
        x, y, z = points[i, 0], points[i, 1], points[i, 2]
        for c in range(4):
            out[i, c] = x * m[0, c] + y * m[1, c] + z * m[2, c] + m[3, c]


@njit(cache=True, parallel=True)
def transform_vertices(points, model_to_view, view_to_clip, size, verts_view, verts_clip, codes, window, fixed, cells):
    """Stages 1–3 for one object's vertices (the loop kernel), into plain arrays, and stage 5
    for each of them while they are at hand.

    ``verts_view[i] = ([p, 1] @ model_to_view)[:3]``, ``verts_clip[i] = ([p, 1] @ model_to_view)
    @ view_to_clip`` (the full homogeneous view vector, w included). ``codes[i]`` is the
    clip-space vertex's outcode (:func:`renderer.clip.outcode`), worked out here for the
    clipper's trivial accept and reject: a kernel of its own cost a parallel kernel's compile
    on a cold start (0.3 s). When ``window`` has rows, each vertex is also mapped to a window
    ``size`` (width, height) pixels into ``window``, ``fixed`` and ``cells``
    (:func:`renderer.window.map_point`, the bits of :func:`renderer.window.window_into`).
    Normals: :func:`normals_to_view`.

    Two parallel loops: the matrix products, then the outcodes and the mapping, which read the
    clip-space rows back. In one loop, with the rounding to int64 and the outcode's bits among
    its stores, the whole ran at about a third of the speed of its parts on a processor
    without AVX-512 (which has no vector conversion of doubles to int64): the 1M-triangle
    scan's 537k vertices took 7.1–7.6 ms in one loop and 5.0–6.0 in two (the kernel alone,
    the two alternating in one process; two threads), whole frames 0.94–0.99 of the time
    (docs/performance.md). The second loop compiles in about 0.2 s more.
    """
    m, p = model_to_view, view_to_clip
    width, height = size
    mapped = window.shape[0] > 0
    for i in prange(points.shape[0]):
        x, y, z = points[i, 0], points[i, 1], points[i, 2]
        vx = x * m[0, 0] + y * m[1, 0] + z * m[2, 0] + m[3, 0]
        vy = x * m[0, 1] + y * m[1, 1] + z * m[2, 1] + m[3, 1]
        vz = x * m[0, 2] + y * m[1, 2] + z * m[2, 2] + m[3, 2]
        vw = x * m[0, 3] + y * m[1, 3] + z * m[2, 3] + m[3, 3]
        verts_view[i, 0], verts_view[i, 1], verts_view[i, 2] = vx, vy, vz
        for c in range(4):
            verts_clip[i, c] = vx * p[0, c] + vy * p[1, c] + vz * p[2, c] + vw * p[3, c]
    for i in prange(points.shape[0]):
        codes[i] = outcode(verts_clip, i)
        if mapped:
            map_point(verts_clip, i, width, height, window, fixed, cells)


@njit(cache=True, parallel=True)
def normals_to_view(normals, normal_m, normals_view):
    """``normals_view[i] = normals[i] @ normal_m`` (:func:`normal_matrix`) for one object's
    vertices; when ``normals`` has no rows (a mesh without normals), ``normals_view`` is zeroed."""
    has_normals = normals.shape[0] > 0
    for i in prange(normals_view.shape[0]):
        if has_normals:
            nx, ny, nz = normals[i, 0], normals[i, 1], normals[i, 2]
            for c in range(3):
                normals_view[i, c] = nx * normal_m[0, c] + ny * normal_m[1, c] + nz * normal_m[2, c]
        else:
            normals_view[i, 0], normals_view[i, 1], normals_view[i, 2] = 0.0, 0.0, 0.0
