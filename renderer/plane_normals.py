"""Plane normals of triangles: the unit normal flat shading lights a triangle with.

``(b − a) × (c − a)`` normalised, for corners a, b, c in the order the triangle lists them:
counter-clockwise seen from the side it points to (the right-hand rule). The pipeline works
them out in view space once per frame, for the triangles a frame shows
(:func:`renderer.pipeline.shown_sources`), or for all.
"""
from __future__ import annotations

import math

import numpy as np

from renderer.jit import njit, prange


@njit(cache=True, inline="always")
def plane_normal(a, b, c, n):
    """Unit (b − a) × (c − a) into ``n`` (zero for a degenerate triangle)."""
    n[0], n[1], n[2] = unit_cross(a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2])


@njit(cache=True, inline="always")
def corners_normal(verts, triangles, t):
    """:func:`plane_normal` of triangle ``t`` of ``triangles`` (T, 3) of ``verts``, as a 3-tuple:
    the same bits as its row of :func:`face_normals_of`, read from the corners themselves."""
    i0, i1, i2 = triangles[t, 0], triangles[t, 1], triangles[t, 2]
    return unit_cross(verts[i0, 0], verts[i0, 1], verts[i0, 2], verts[i1, 0], verts[i1, 1], verts[i1, 2],
                      verts[i2, 0], verts[i2, 1], verts[i2, 2])


@njit(cache=True, inline="always")
def unit_cross(ax, ay, az, bx, by, bz, cx, cy, cz):
    """Unit (b − a) × (c − a) of three points given by their coordinates (zero for a degenerate triangle)."""
    ux, uy, uz = bx - ax, by - ay, bz - az
    vx, vy, vz = cx - ax, cy - ay, cz - az
    nx, ny, nz = uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx
    length = math.sqrt(nx * nx + ny * ny + nz * nz)
    if length > 0.0:
        return nx / length, ny / length, nz / length
    return nx, ny, nz


@njit(cache=True, parallel=True)
def face_normals_of(verts, triangles, which, out):
    """:func:`plane_normal` of triangles ``which`` (M,) int64 of ``triangles`` (T, 3) of
    ``verts`` into their rows of ``out`` (T, 3), once per frame: flat shading reads its
    triangle's, instead of working it out at every pixel. The other rows are left as they
    are (a frame computes the normals of the triangles it shows only,
    :func:`renderer.pipeline.shown_sources`)."""
    for i in prange(which.shape[0]):
        t = which[i]
        plane_normal(verts[triangles[t, 0]], verts[triangles[t, 1]], verts[triangles[t, 2]], out[t])


def face_normals(verts, triangles, out):
    """:func:`face_normals_of` every triangle."""
    face_normals_of(verts, triangles, np.arange(len(triangles), dtype=np.int64), out)
