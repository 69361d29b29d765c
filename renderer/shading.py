"""Stage 7, visibility buffer → linear RGB: per-fragment normals, positions and lighting.

For each covered pixel the screen-space weights from :mod:`renderer.raster` are made
perspective-correct (divide by clip w, renormalise), carried back through clipping to the
source triangle, and used to interpolate its view-space position and normal; then
:func:`renderer.lighting.vtk_lighting` colours the fragment. All vectors in view space.

Normals by shading mode (VTK's OpenGL2 rules):

- ``flat``: the triangle's plane normal, turned toward the viewer (perspective: so that
  n·P ≤ 0; parallel: n.z ≥ 0). Point normals are never used; back faces are lit.
- ``gouraud`` / ``phong`` with point normals: the perspective-correct interpolation of
  the (unnormalised) view-space vertex normals, normalised, negated on back faces
  (two-sided lighting). VTK has no per-vertex lighting, so both are per-pixel here.
- without point normals every mode falls back to ``flat``.
"""
from __future__ import annotations

import numpy as np
from numba import njit, prange

from renderer.lighting import vtk_lighting


@njit(cache=True)
def fragment_weights(k, l1, l2, clip_w, clip_bary, perspective, out):
    """Weights of the *source* triangle's vertices at a fragment.

    ``l1, l2`` are screen-space weights of clipped triangle ``k``'s vertices 1 and 2.
    Perspective-correct (what GPUs and VTK do): each is divided by that vertex's clip w
    and the three renormalised. ``perspective=False`` keeps them screen-linear, as the
    course's scanline slides interpolate. Then they are mapped through the clipped
    vertices' own weights in the source triangle.
    """
    l0 = 1.0 - l1 - l2
    if perspective:
        b0, b1, b2 = l0 / clip_w[k, 0], l1 / clip_w[k, 1], l2 / clip_w[k, 2]
    else:
        b0, b1, b2 = l0, l1, l2
    s = b0 + b1 + b2
    b0, b1, b2 = b0 / s, b1 / s, b2 / s
    for j in range(3):
        out[j] = b0 * clip_bary[k, 0, j] + b1 * clip_bary[k, 1, j] + b2 * clip_bary[k, 2, j]


@njit(cache=True, parallel=True)
def shade(tri_index, bary, front, clip_w, clip_bary, clip_source, tri_view, tri_normal, face_normal,
          tri_object, obj_smooth, obj_complexity, obj_amb, obj_dif, obj_spe, obj_power, parallel_camera, perspective,
          l_dir, l_pos, l_col, l_positional, l_cos_cone, l_exponent, l_att, background, rgb):
    """Light every covered pixel (the loop kernel); rows are independent, so ``prange``
    over rows gives the same bytes as a serial loop."""
    height, width = tri_index.shape
    for row in prange(height):
        w = np.empty(3)
        n = np.empty(3)
        p = np.empty(3)
        out = np.empty(3)
        for col in range(width):
            k = tri_index[row, col]
            if k < 0:
                rgb[row, col] = background
                continue
            fragment_weights(k, bary[row, col, 0], bary[row, col, 1], clip_w, clip_bary, perspective, w)
            s = clip_source[k]
            o = tri_object[s]
            for c in range(3):
                p[c] = w[0] * tri_view[s, 0, c] + w[1] * tri_view[s, 1, c] + w[2] * tri_view[s, 2, c]
            if obj_smooth[o]:
                for c in range(3):
                    n[c] = w[0] * tri_normal[s, 0, c] + w[1] * tri_normal[s, 1, c] + w[2] * tri_normal[s, 2, c]
                length = np.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
                if length > 0.0:
                    n /= length
                if not front[k]:
                    n *= -1.0
            else:
                n[:] = face_normal[s]
                if parallel_camera:
                    if n[2] < 0.0:
                        n *= -1.0
                elif n[0] * p[0] + n[1] * p[1] + n[2] * p[2] > 0.0:
                    n *= -1.0
            vtk_lighting(n, p, obj_complexity[o], obj_amb[o], obj_dif[o], obj_spe[o], obj_power[o],
                         l_dir, l_pos, l_col, l_positional, l_cos_cone, l_exponent, l_att, out)
            rgb[row, col] = out


def face_normals(tri_view: np.ndarray) -> np.ndarray:
    """Unit plane normals (v1 − v0) × (v2 − v0) of (T, 3, 3) triangles; zero if degenerate."""
    n = np.cross(tri_view[:, 1] - tri_view[:, 0], tri_view[:, 2] - tri_view[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n), where=length > 0)


def to_8bit(rgb: np.ndarray) -> np.ndarray:
    """Linear 0..1 float RGB → uint8 as the framebuffer stores it.

    ``round_half_even(clamp(c, 0, 1)·255)`` computed in float32 (GL's unorm8 write).
    """
    c = np.clip(rgb.astype(np.float32), np.float32(0), np.float32(1)) * np.float32(255)
    return np.rint(c).astype(np.uint8)
