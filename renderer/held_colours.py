"""Stage 7, before the rows: one 8-bit colour per triangle where it cannot change across it.

A triangle lit with its own plane normal (``PIXEL_FACE_NORMAL``, flat shading) by a model
whose colour depends on the normal alone (:func:`renderer.reflection.registry.span_normal_only`:
the vtk model unlit or under a lone headlight) has one colour over all its pixels. The
shading kernel worked it out once per span, at the span's first pixel; a triangle of a
finely divided mesh has a span on every row it covers (a 328k-triangle sphere at 512²:
142k spans of 1.8 pixels), so its colour was worked out again on each. Here it is worked
out once per triangle that won a pixel (:func:`held_colours`), with the same float32
normal and the same span kernel, and the rows copy it (:func:`renderer.shading.shade_rows_lit_spans`).
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit, prange
from renderer.reflection.materials import PIXEL_FACE_NORMAL
from renderer.reflection.registry import light_points, span_normal_only, store_span
from renderer.spans import face_toward_viewer


@njit(cache=True, inline="always")
def held_per_triangle(o, materials, lights):
    """True when object ``o``'s colour is one per triangle: flat (``PIXEL_FACE_NORMAL``) and lit by
    a model whose colour depends on the normal alone."""
    return materials.shading_path[o] == PIXEL_FACE_NORMAL and span_normal_only(o, materials, lights)


@njit(cache=True, parallel=True)
def held_colours(frags, geo, materials, lights, out):
    """The 8-bit colour of every clipped triangle of ``frags`` whose object is
    :func:`held_per_triangle` into ``out`` (K, 3) uint8 (other rows are left as they are):
    its plane normal turned toward the viewer, as float32 (the normal
    :func:`renderer.spans.span_pixel` gives every pixel of a flat triangle), lit by the
    object's span kernel (:func:`renderer.reflection.registry.light_points`) and stored as
    8 bits. The position is not needed (the colour depends on the normal alone) and is 0."""
    count = frags.clip_source.shape[0]
    n_chunks = max(1, min(count, 64))
    for chunk in prange(n_chunks):
        points, colour = np.zeros((6, 1), np.float32), np.empty((3, 1), np.float32)
        for k in range(chunk, count, n_chunks):
            s = frags.clip_source[k]
            o = geo.tri_object[s]
            if not held_per_triangle(o, materials, lights):
                continue
            nx, ny, nz = face_toward_viewer(geo, s)
            points[3, 0], points[4, 0], points[5, 0] = np.float32(nx), np.float32(ny), np.float32(nz)
            light_points(o, materials, lights, points, 0, 1, colour)
            store_span(colour, 1, out[k:k + 1])


def held_colour_table(frags, geo, materials, lights) -> np.ndarray:
    """(K, 3) uint8 (:func:`held_colours`) for the K clipped triangles of ``frags``; the kernel
    runs only when some object is :func:`held_per_triangle`."""
    out = np.zeros((len(frags.clip_source), 3), np.uint8)
    if any(path == PIXEL_FACE_NORMAL for path in materials.shading_path):
        held_colours(frags, geo, materials, lights, out)
    return out
