"""Stage 7, before the rows: one 8-bit colour per triangle where it cannot change across it.

A triangle lit with its own plane normal (``PIXEL_FACE_NORMAL``, flat shading) by a model
whose colour depends on the normal alone (:func:`renderer.reflection.registry.span_normal_only`:
the vtk model unlit or under a lone headlight) has one colour over all its pixels. The
shading kernel worked it out once per span, at the span's first pixel; a triangle of a
finely divided mesh has a span on every row it covers (a 328k-triangle sphere at 512²:
142k spans of 1.8 pixels), so its colour was worked out again on each. Here it is worked
out once per triangle that won a pixel (:func:`held_colours`), with the same float32
normal and the same span kernel, and the rows copy it (:func:`renderer.shading.shade_rows_lit_spans`).
A ``FACE_COLOUR`` triangle (flat under the opengl or classic model) holds its lit colour
(:mod:`renderer.lit_colours`) in the same table.

A frame whose every object is held (:func:`all_held`: flat shading under a headlight, the
demo's icosphere, Menger sponges) needs nothing more: :func:`paint_rows` copies each pixel's
colour from the table, with no walk along spans and no lighting code compiled (a fresh
process drawing the level-5 icosphere skips the 7 s the span-lighting kernel takes to compile).
"""
from __future__ import annotations

import numpy as np

from renderer.float32_math import unorm8
from renderer.jit import njit, prange
from renderer.lit_colours import face_colour
from renderer.min_max import larger
from renderer.prefetch import prefetch_row
from renderer.raster import EMPTY
from renderer.reflection.materials import FACE_COLOUR, PIXEL_FACE_NORMAL, any_face_colour
from renderer.reflection.registry import light_points, span_normal_only, spans_normal_only, store_span
from renderer.spans import AHEAD_CORNERS, AHEAD_SOURCE, F0, corners_toward_viewer
from renderer.workspace import empty


@njit(cache=True, inline="always")
def held_per_triangle(o, materials, lights):
    """True when object ``o``'s colour is one per triangle: flat (``PIXEL_FACE_NORMAL``) and lit by
    a model whose colour depends on the normal alone."""
    return materials.shading_path[o] == PIXEL_FACE_NORMAL and span_normal_only(o, materials, lights)


def holds_per_triangle(o, materials, lights) -> bool:
    """:func:`held_per_triangle` in Python (for choosing kernels before shading)."""
    return materials.shading_path[o] == PIXEL_FACE_NORMAL and spans_normal_only(o, materials, lights)


def all_held(materials, lights) -> bool:
    """True when every object's triangles are held (:func:`held_per_triangle`, or
    ``FACE_COLOUR``), for objects that :func:`renderer.shading.span_covers` (the same rule in
    Python, for choosing :func:`paint_rows`)."""
    return all(path == FACE_COLOUR or holds_per_triangle(o, materials, lights)
               for o, path in enumerate(materials.shading_path))


@njit(cache=True)
def held_colours(frags, geo, materials, lights, points, colour, stored, out):
    """The 8-bit colour of every clipped triangle of ``frags`` whose object is
    :func:`held_per_triangle` into ``out`` (K, 3) uint8 (other rows are left as they are):
    its plane normal turned toward the viewer, as float32 (the normal
    :func:`renderer.spans.span_pixel` gives every pixel of a flat triangle), lit by the
    object's span kernel and stored as 8 bits. The normal is worked out here from the
    triangle's corners (:func:`renderer.spans.corners_toward_viewer`, the bits of the frame's
    table of plane normals), so a frame painted from held colours alone makes no such table
    (:func:`renderer.pipeline.normals_of_shown`).
    An object's triangles are lit together, as one run of points (``points`` (6, ≥ K),
    ``colour`` (3, ≥ K) float32 and ``stored`` (≥ K, 3) uint8 scratch): one call, whose loop
    runs 8 triangles at a time. The positions are not needed (the colour depends on the
    normal alone) and are 0.

    The winners come in the order the image shows them, so the rows read for each are at
    random over the mesh's tables: the rows of the triangle :data:`~renderer.spans.AHEAD_SOURCE`
    on (its object and corners) and the three corners of the one
    :data:`~renderer.spans.AHEAD_CORNERS` on are asked for ahead (:mod:`renderer.prefetch`). Measured, the kernel alone
    on its frame's input, this against no reading ahead: ico7-flat 0.88–0.95 of the time at
    512², 0.93 at 1024², menger4 at 512² 0.87. Written out in the loop: as a function of the
    frame's tables, inlined or not, it took 3–5 times as long (reference counts)."""
    count = frags.clip_source.shape[0]
    for o in range(materials.shading_path.shape[0]):
        if not held_per_triangle(o, materials, lights):
            continue
        n = 0
        for k in range(count):
            if k + AHEAD_SOURCE < count:  # read ahead, written out here: a call would count references to the tables
                ahead = frags.clip_source[k + AHEAD_SOURCE]
                prefetch_row(geo.triangles, ahead)
                prefetch_row(geo.tri_object, ahead)
            if k + AHEAD_CORNERS < count:
                near = frags.clip_source[k + AHEAD_CORNERS]
                prefetch_row(geo.verts_view, geo.triangles[near, 0])
                prefetch_row(geo.verts_view, geo.triangles[near, 1])
                prefetch_row(geo.verts_view, geo.triangles[near, 2])
            s = frags.clip_source[k]
            if geo.tri_object[s] == o:
                nx, ny, nz = corners_toward_viewer(geo, s)
                points[0, n], points[1, n], points[2, n] = F0, F0, F0
                points[3, n], points[4, n], points[5, n] = np.float32(nx), np.float32(ny), np.float32(nz)
                n += 1
        light_points(o, materials, lights, points, 0, n, colour)
        store_span(colour, n, stored)
        n = 0
        for k in range(count):
            if geo.tri_object[frags.clip_source[k]] == o:
                out[k, 0], out[k, 1], out[k, 2] = stored[n, 0], stored[n, 1], stored[n, 2]
                n += 1


@njit(cache=True)
def face_colours(frags, geo, materials, lit, out):
    """The 8-bit colour of every clipped triangle of ``frags`` whose object is ``FACE_COLOUR``
    (flat under the opengl or classic model) into ``out`` (K, 3): its source triangle's lit
    colour, primary + secondary (``lit.face``). A kernel of its own, run only when such an
    object is in the frame: inside :func:`held_colours` it cost every flat frame 0.3 s of
    compile on a cold start."""
    for k in range(frags.clip_source.shape[0]):
        s = frags.clip_source[k]
        if materials.shading_path[geo.tri_object[s]] == FACE_COLOUR:
            r, g, b = face_colour(lit, s)
            out[k, 0], out[k, 1], out[k, 2] = unorm8(r), unorm8(g), unorm8(b)


def held_colour_table(frags, geo, materials, lights, lit, ws=None) -> np.ndarray:
    """(K, 3) uint8 for the K clipped triangles of ``frags``: :func:`held_colours` where some
    object is :func:`held_per_triangle`, :func:`face_colours` where some is ``FACE_COLOUR``;
    each kernel runs only when its kind is in the frame. Scratch in workspace ``ws``."""
    count = len(frags.clip_source)
    out = np.zeros((count, 3), np.uint8)
    if any(holds_per_triangle(o, materials, lights) for o in range(len(materials.shading_path))):
        held_colours(frags, geo, materials, lights, empty(ws, "held.points", (6, max(count, 1)), np.float32),
                     empty(ws, "held.colour", (3, max(count, 1)), np.float32),
                     empty(ws, "held.stored", (max(count, 1), 3), np.uint8), out)
    if any_face_colour(materials):
        face_colours(frags, geo, materials, lit, out)
    return out


@njit(cache=True, parallel=True)
def paint_rows(tri_index, held, background, n_bands, rgb):
    """Shading of a frame whose every object is held (:func:`all_held`): each pixel of
    ``rgb`` (H, W, 3) uint8, C-contiguous, gets its triangle's row of ``held`` (K, 3) uint8,
    an empty one the 8-bit ``background``. The bytes of
    :func:`renderer.shading.shade_rows_lit_spans`, which copies the same rows along spans.
    Rows are dealt to ``n_bands`` bands as there (:mod:`renderer.bands`); each pixel is
    written once.

    The colours are first packed a triangle to one integer (:func:`packed_colours`), so a
    pixel's colour is one read, chosen without a branch, and its three bytes go out through
    the row seen as one line of bytes (byte 3·col + c): LLVM vectorises the loop, a gather
    and a store of three interleaved bytes. Measured, the kernel alone on its frame's input:
    ico5-flat at 1024², one thread 1.65 → 0.62 ms, two 0.96 → 0.47; menger3 at 512², two
    threads 0.23 → 0.14 (the loop before: a branch and three byte stores a pixel)."""
    height, width = tri_index.shape
    colours, empty_colour = packed_colours(held), pack_colour(background[0], background[1], background[2])
    for band in prange(n_bands):
        for row in range(band, height, n_bands):
            paint_row(tri_index[row], colours, empty_colour, rgb[row].reshape(-1))


@njit(cache=True, inline="always")
def pack_colour(r, g, b):
    """Three 8-bit values as one uint32: r in bits 0–7, g in 8–15, b in 16–23."""
    return np.uint32(r) | (np.uint32(g) << np.uint32(8)) | (np.uint32(b) << np.uint32(16))


@njit(cache=True, inline="always")
def packed_colours(held):
    """(K,) uint32: each row of ``held`` (K, 3) uint8 packed (:func:`pack_colour`); a table of
    one entry for none (never read: no pixel names a triangle)."""
    out = np.empty(larger(held.shape[0], 1), np.uint32)
    out[0] = 0
    for k in range(held.shape[0]):
        out[k] = pack_colour(held[k, 0], held[k, 1], held[k, 2])
    return out


@njit(cache=True, inline="always")
def paint_row(triangles, colours, empty_colour, row_bytes):
    """One row: pixel ``col`` showing triangle ``triangles[col]`` gets ``colours`` of it
    (:func:`packed_colours`), an empty one ``empty_colour``, unpacked into bytes 3·col … 3·col + 2
    of ``row_bytes`` (3W,) uint8."""
    for col in range(triangles.shape[0]):
        k = triangles[col]
        j = np.uint64(col)  # unsigned: no wrap-around for a negative index, which keeps a loop scalar
        # the index is a valid one for an empty pixel too: the loop in lanes reads every lane, then chooses
        v = colours[np.uint64(k if k != EMPTY else 0)] if k != EMPTY else empty_colour
        row_bytes[3 * j] = np.uint8(v & np.uint32(255))
        row_bytes[3 * j + 1] = np.uint8((v >> np.uint32(8)) & np.uint32(255))
        row_bytes[3 * j + 2] = np.uint8((v >> np.uint32(16)) & np.uint32(255))
