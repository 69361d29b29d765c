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

The textbook models (``model = "opengl" | "classic"``, :mod:`renderer.textbook_lighting`)
light per triangle (flat, at the centroid), per vertex with the colours interpolated
(gouraud) or per pixel with the interpolated normal (phong); their normals are used as
given, never flipped.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from renderer.jit import njit, prange

from renderer.lighting import vtk_lighting
from renderer.textbook_lighting import textbook_lighting
from renderer.texture import sample


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


ROW_DECKS = 64
"""Parallel loops over rows deal them out like cards: row r goes to deck r mod 64, and the
decks are shared among the threads. Every thread then gets rows from all over the image;
in contiguous blocks, a floor filling the lower half landed on one thread and the sky on
the other (measured: 1 thread 12.7 ms, 2 threads 11.5 ms on ``near-plane``)."""


@njit(cache=True)
def face_normals(verts, triangles, out):
    """:func:`plane_normal` of every triangle (T, 3) of ``verts`` into ``out`` (T, 3), once
    per frame: flat shading reads its triangle's, instead of working it out at every pixel."""
    for t in range(triangles.shape[0]):
        plane_normal(verts[triangles[t, 0]], verts[triangles[t, 1]], verts[triangles[t, 2]], out[t])


# How an object is shaded (ObjectTable.kind), chosen once per object in renderer.pipeline.
VTK_FLAT, VTK_SMOOTH, FACE_COLOUR, VERTEX_COLOUR, TEXTBOOK_PIXEL = 0, 1, 2, 3, 4


class Fragments(NamedTuple):
    """The visibility buffer and the clipped triangles it points into (window rows, y up).

    tri_index (H, W) clipped triangle per pixel (−1 = empty); bary (H, W, 2) its
    screen-space weights of vertices 1 and 2; front (K,); tri_clip (K, 3, 4); clip_bary
    (K, 3, 3) weights in the source triangle; clip_source (K,) source triangle.
    """

    tri_index: np.ndarray
    bary: np.ndarray
    front: np.ndarray
    tri_clip: np.ndarray
    clip_bary: np.ndarray
    clip_source: np.ndarray


class ObjectTable(NamedTuple):
    """Per-object shading data (index = object) and the scene-wide light-model values.

    kind : VTK_FLAT … TEXTBOOK_PIXEL. model : 0 vtk, 1 opengl, 2 classic.
    complexity : VTK light complexity (0 when the object's lighting is off).
    amb, dif, spe (O, 3), power (O,): see :func:`renderer.pipeline.object_table`.
    global_ambient, ambient_light (3,), local_viewer, separate_specular: from the scene's
    ``[render]``.
    textured, tex_offset, tex_width, tex_height, tex_filter, tex_wrap (O,) and texels
    (Σ H·W, 3) uint8: the objects' textures (see :func:`renderer.pipeline.texture_table`).
    """

    kind: np.ndarray
    model: np.ndarray
    complexity: np.ndarray
    amb: np.ndarray
    dif: np.ndarray
    spe: np.ndarray
    power: np.ndarray
    global_ambient: np.ndarray
    ambient_light: np.ndarray
    local_viewer: bool
    separate_specular: bool
    textured: np.ndarray
    tex_offset: np.ndarray
    tex_width: np.ndarray
    tex_height: np.ndarray
    tex_filter: np.ndarray
    tex_wrap: np.ndarray
    texels: np.ndarray


@njit(cache=True, inline="always")
def interpolate(w, a, i0, i1, i2, out, first=0):
    """out = w0·a[i0] + w1·a[i1] + w2·a[i2] over columns ``first .. first + 2`` of ``a``."""
    for c in range(3):
        out[c] = w[0] * a[i0, first + c] + w[1] * a[i1, first + c] + w[2] * a[i2, first + c]


@njit(cache=True, inline="always")
def normalise(n):
    length = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
    if length > 0.0:
        for c in range(3):
            n[c] /= length


@njit(cache=True, inline="always")
def fragment_colour(frags, k, l1, l2, geo, objs, lights, vert_colour, face_colour, parallel_camera, perspective,
                    w, n, p, tex, spec, out):
    """The linear colour of one fragment of clipped triangle ``k`` with screen-space weights
    ``l1, l2`` (of its vertices 1 and 2) into ``out``; ``w, n, p, tex, spec`` are (3,) scratch.

    Per object kind: VTK's per-fragment lighting with the plane normal (VTK_FLAT) or the
    interpolated normal (VTK_SMOOTH); a lit colour per triangle (FACE_COLOUR) or
    interpolated from lit vertices (VERTEX_COLOUR, Gouraud); the textbook model per
    pixel with the interpolated normal (TEXTBOOK_PIXEL, Phong). Only the clipped-triangle
    tables of ``frags`` (front, tri_clip, clip_bary, clip_source) are read.
    """
    tris, verts = geo.triangles, geo.verts_view
    fragment_weights(k, l1, l2, frags.tri_clip, frags.clip_bary, perspective, w)
    s = frags.clip_source[k]
    o = geo.tri_object[s]
    i0, i1, i2 = tris[s, 0], tris[s, 1], tris[s, 2]
    kind = objs.kind[o]
    for c in range(3):
        spec[c] = 0.0
    if kind == FACE_COLOUR:
        for c in range(3):
            out[c] = face_colour[s, c]
            spec[c] = face_colour[s, 3 + c]
    elif kind == VERTEX_COLOUR:
        interpolate(w, vert_colour, i0, i1, i2, out)
        interpolate(w, vert_colour, i0, i1, i2, spec, 3)
    else:
        interpolate(w, verts, i0, i1, i2, p)
        if kind == VTK_FLAT:
            for c in range(3):
                n[c] = geo.face_normals[s, c]
            if (n[2] < 0.0) if parallel_camera else (n[0] * p[0] + n[1] * p[1] + n[2] * p[2] > 0.0):
                for c in range(3):
                    n[c] = -n[c]
        else:
            interpolate(w, geo.normals_view, i0, i1, i2, n)
            normalise(n)
            if kind == VTK_SMOOTH and not frags.front[k]:
                for c in range(3):
                    n[c] = -n[c]
        if kind == TEXTBOOK_PIXEL:
            textbook_lighting(objs.model[o], n, p, objs.amb[o], objs.dif[o], objs.spe[o], objs.power[o],
                              objs.global_ambient, objs.local_viewer, objs.separate_specular, objs.ambient_light,
                              lights, out, spec)
        else:
            vtk_lighting(n, p, objs.complexity[o], objs.amb[o], objs.dif[o], objs.spe[o], objs.power[o],
                         lights, out)
    if objs.textured[o]:  # the texture multiplies the lit colour (VTK, GL_MODULATE) ...
        ts = w[0] * geo.tcoords[i0, 0] + w[1] * geo.tcoords[i1, 0] + w[2] * geo.tcoords[i2, 0]
        tt = w[0] * geo.tcoords[i0, 1] + w[1] * geo.tcoords[i1, 1] + w[2] * geo.tcoords[i2, 1]
        sample(objs.texels, objs.tex_offset[o], objs.tex_width[o], objs.tex_height[o], objs.tex_filter[o],
               objs.tex_wrap[o], ts, tt, tex)
        for c in range(3):
            out[c] *= tex[c]
    for c in range(3):  # ... and the separate specular colour (zero unless asked for) comes after it
        out[c] += spec[c]


@njit(cache=True, parallel=True)
def shade(frags, geo, objs, lights, vert_colour, face_colour, parallel_camera, perspective, background, rgb):
    """Colour every covered pixel and store 8-bit RGB (the loop kernel).

    Each covered pixel gets :func:`fragment_colour` of its visible fragment.
    Rows are independent and each pixel is written once, so a parallel loop gives the
    same bytes as a serial one. Rows are dealt out like cards (:data:`ROW_DECKS`).
    ``background`` is the 8-bit clear colour.
    """
    height, width = frags.tri_index.shape
    n_decks = min(height, ROW_DECKS)
    for deck in prange(n_decks):
        w = np.empty(3)
        n = np.empty(3)
        p = np.empty(3)
        out = np.empty(3)
        tex = np.empty(3)
        spec = np.empty(3)
        for row in range(deck, height, n_decks):
            for col in range(width):
                k = frags.tri_index[row, col]
                if k < 0:
                    for c in range(3):
                        rgb[row, col, c] = background[c]
                    continue
                fragment_colour(frags, k, frags.bary[row, col, 0], frags.bary[row, col, 1], geo, objs, lights,
                                vert_colour, face_colour, parallel_camera, perspective, w, n, p, tex, spec, out)
                for c in range(3):
                    rgb[row, col, c] = unorm8(out[c])
