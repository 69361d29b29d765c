"""Stage 7a, view space → lit colours: once per vertex (Gouraud) and once per triangle (flat).

Objects on the :data:`~renderer.reflection.materials.VERTEX_COLOUR` path are lit at their
vertices, the colours then interpolated over each triangle (Gouraud's first half); objects
on the :data:`~renderer.reflection.materials.FACE_COLOUR` path are lit once per triangle,
with its plane normal at one representative point, the centroid, and the colour held over
it. Which model lights them is their material row's business
(:func:`renderer.reflection.registry.reflect`). All vectors in view space; colours linear
RGB, primary then secondary (separately added specular).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from renderer.jit import njit, prange
from renderer.reflection.materials import FACE_COLOUR, VERTEX_COLOUR
from renderer.reflection.registry import reflect
from renderer.workspace import empty


@njit(cache=True, inline="always")
def face_colour(lit, s):
    """Source triangle ``s``'s flat colour (FACE_COLOUR): primary + secondary RGB of ``lit.face``."""
    return lit.face[s, 0] + lit.face[s, 3], lit.face[s, 1] + lit.face[s, 4], lit.face[s, 2] + lit.face[s, 5]


class LitColours(NamedTuple):
    """vertex (N, 6) per vertex and face (T, 6) per triangle: primary RGB, then secondary RGB.
    Only the rows of objects on the matching path are written; the others are undefined."""

    vertex: np.ndarray
    face: np.ndarray


@njit(cache=True, parallel=True)
def light_vertices(geo, materials, lights, colours):
    """Gouraud's first half (the loop kernel): a lit colour per vertex of every
    VERTEX_COLOUR object into ``colours`` (N, 6), its normal normalised first."""
    for v in prange(geo.verts_view.shape[0]):
        o = geo.vert_object[v]
        if materials.shading_path[o] != VERTEX_COLOUR:
            continue
        nx, ny, nz = geo.normals_view[v, 0], geo.normals_view[v, 1], geo.normals_view[v, 2]
        length = math.sqrt(nx * nx + ny * ny + nz * nz)
        if length > 0.0:
            nx, ny, nz = nx / length, ny / length, nz / length
        lit = reflect((nx, ny, nz), geo.verts_view[v], o, materials, lights)
        for c in range(6):
            colours[v, c] = lit[c]


@njit(cache=True, parallel=True)
def light_faces(geo, materials, lights, colours):
    """Flat shading's colour per triangle of every FACE_COLOUR object (the loop kernel) into
    ``colours`` (T, 6): its unit plane normal (``geo.face_normals``, (v1 − v0) × (v2 − v0)
    normalised), lit at its centroid."""
    verts, triangles = geo.verts_view, geo.triangles
    for t in prange(triangles.shape[0]):
        o = geo.tri_object[t]
        if materials.shading_path[o] != FACE_COLOUR:
            continue
        a, b, c = triangles[t, 0], triangles[t, 1], triangles[t, 2]
        centroid = ((verts[a, 0] + verts[b, 0] + verts[c, 0]) / 3.0, (verts[a, 1] + verts[b, 1] + verts[c, 1]) / 3.0,
                    (verts[a, 2] + verts[b, 2] + verts[c, 2]) / 3.0)
        lit = reflect(geo.face_normals[t], centroid, o, materials, lights)
        for k in range(6):
            colours[t, k] = lit[k]


def lit_colours(geo, materials, lights, ws=None) -> LitColours:
    """Light the vertices and triangles that their objects' paths ask for (the Python
    wrapper); a kernel runs only when some object needs it."""
    colours = LitColours(vertex=empty(ws, "shade.vert_colour", (len(geo.verts_view), 6)),
                         face=empty(ws, "shade.face_colour", (len(geo.triangles), 6)))
    if (materials.shading_path == VERTEX_COLOUR).any():
        light_vertices(geo, materials, lights, colours.vertex)
    if (materials.shading_path == FACE_COLOUR).any():
        light_faces(geo, materials, lights, colours.face)
    return colours
