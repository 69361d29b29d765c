"""Stage 7, visibility buffer → 8-bit RGB: per-fragment normals, positions and lighting.

For each covered pixel the screen-space weights from :mod:`renderer.raster` are made
perspective-correct (divide by clip w, renormalise), carried back through clipping to the
source triangle, and used to interpolate its view-space position and normal; then
:func:`renderer.lighting.vtk_lighting` colours the fragment and :func:`unorm8` stores it.
All vectors in view space.

Normals by shading mode (VTK's OpenGL2 rules):

- ``flat``: the triangle's plane normal (v1 − v0) × (v2 − v0), turned toward the viewer
  (perspective: so that n·P ≤ 0; parallel: n.z ≥ 0). Point normals are never used;
  back faces are lit.
- ``gouraud`` / ``phong`` with point normals: the perspective-correct interpolation of
  the (unnormalised) view-space vertex normals, normalised, negated on back faces
  (two-sided lighting). VTK has no per-vertex lighting, so both are per-pixel here.
- without point normals every mode falls back to ``flat``.
"""
from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from renderer.lighting import vtk_lighting


@njit(cache=True, inline="always")
def unorm8(c):
    """Linear 0..1 → the framebuffer's 8 bits: ``round_half_even(clamp(c, 0, 1)·255)`` in float32."""
    f = np.float32(min(max(c, 0.0), 1.0)) * np.float32(255.0)
    return np.uint8(np.rint(f))


@njit(cache=True)
def _to_8bit(flat, out):
    for i in range(flat.shape[0]):
        out[i] = unorm8(flat[i])


def to_8bit(rgb: np.ndarray) -> np.ndarray:
    """Apply :func:`unorm8` to every value of a float array; returns uint8 of the same shape."""
    flat = np.ascontiguousarray(rgb, dtype=np.float64).reshape(-1)
    out = np.empty(flat.shape, np.uint8)
    _to_8bit(flat, out)
    return out.reshape(np.shape(rgb))


@njit(cache=True, inline="always")
def fragment_weights(k, l1, l2, tri_clip, clip_bary, perspective, out):
    """Weights of the *source* triangle's vertices at a fragment.

    ``l1, l2`` are screen-space weights of clipped triangle ``k``'s vertices 1 and 2.
    Perspective-correct (what GPUs and VTK do): each is divided by that vertex's clip w
    and the three renormalised. ``perspective=False`` keeps them screen-linear, as the
    course's scanline slides interpolate. Then they are mapped through the clipped
    vertices' own weights in the source triangle.
    """
    l0 = 1.0 - l1 - l2
    if perspective:
        b0, b1, b2 = l0 / tri_clip[k, 0, 3], l1 / tri_clip[k, 1, 3], l2 / tri_clip[k, 2, 3]
        s = b0 + b1 + b2
        b0, b1, b2 = b0 / s, b1 / s, b2 / s
    else:
        b0, b1, b2 = l0, l1, l2
    for j in range(3):
        out[j] = b0 * clip_bary[k, 0, j] + b1 * clip_bary[k, 1, j] + b2 * clip_bary[k, 2, j]


@njit(cache=True, inline="always")
def plane_normal(a, b, c, n):
    """Unit (b − a) × (c − a) into ``n`` (zero for a degenerate triangle)."""
    ux, uy, uz = b[0] - a[0], b[1] - a[1], b[2] - a[2]
    vx, vy, vz = c[0] - a[0], c[1] - a[1], c[2] - a[2]
    n[0], n[1], n[2] = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    length = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
    if length > 0.0:
        n[0], n[1], n[2] = n[0] / length, n[1] / length, n[2] / length


@njit(cache=True, parallel=True)
def shade(tri_index, bary, front, tri_clip, clip_bary, clip_source, triangles, verts_view, normals_view,
          tri_object, obj_smooth, obj_complexity, obj_amb, obj_dif, obj_spe, obj_power, parallel_camera, perspective,
          l_dir, l_pos, l_col, l_positional, l_cos_cone, l_exponent, l_att, background, rgb):
    """Light every covered pixel and store 8-bit RGB (the loop kernel).

    Rows are independent and each pixel is written once, so ``prange`` over rows gives
    the same bytes as a serial loop. ``background`` is the 8-bit clear colour.
    """
    height, width = tri_index.shape
    for row in prange(height):
        w = np.empty(3)
        n = np.empty(3)
        p = np.empty(3)
        out = np.empty(3)
        for col in range(width):
            k = tri_index[row, col]
            if k < 0:
                for c in range(3):
                    rgb[row, col, c] = background[c]
                continue
            fragment_weights(k, bary[row, col, 0], bary[row, col, 1], tri_clip, clip_bary, perspective, w)
            s = clip_source[k]
            o = tri_object[s]
            i0, i1, i2 = triangles[s, 0], triangles[s, 1], triangles[s, 2]
            for c in range(3):
                p[c] = w[0] * verts_view[i0, c] + w[1] * verts_view[i1, c] + w[2] * verts_view[i2, c]
            if obj_smooth[o]:
                for c in range(3):
                    n[c] = w[0] * normals_view[i0, c] + w[1] * normals_view[i1, c] + w[2] * normals_view[i2, c]
                length = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
                if length > 0.0:
                    for c in range(3):
                        n[c] /= length
                if not front[k]:
                    for c in range(3):
                        n[c] = -n[c]
            else:
                plane_normal(verts_view[i0], verts_view[i1], verts_view[i2], n)
                if (n[2] < 0.0) if parallel_camera else (n[0] * p[0] + n[1] * p[1] + n[2] * p[2] > 0.0):
                    for c in range(3):
                        n[c] = -n[c]
            vtk_lighting(n, p, obj_complexity[o], obj_amb[o], obj_dif[o], obj_spe[o], obj_power[o],
                         l_dir, l_pos, l_col, l_positional, l_cos_cone, l_exponent, l_att, out)
            for c in range(3):
                rgb[row, col, c] = unorm8(out[c])
