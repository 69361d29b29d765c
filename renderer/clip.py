"""Stage 4, clip space → clip space: triangles cut to the view volume.

A point (x, y, z, w) in OpenGL clip space is inside the view volume when −w ≤ x ≤ w,
−w ≤ y ≤ w and −w ≤ z ≤ w. Clipping happens *before* the division by w, in homogeneous
coordinates, so a triangle that crosses the near plane keeps the part in front of the
eye and nothing behind the eye can appear (the course's reason for clipping in 4D).

The x and y planes are the viewport's edges, as in the course and as in llvmpipe (Mesa's
software rasteriser clips "with no guardband"). It matters for one reason: the new
corners on the border are snapped to the 1/256-pixel grid (:mod:`renderer.window`) like
any corner, which moves a cut edge by up to 1/512 pixel, and llvmpipe moves it the same
way. A pixel centre exactly on such an edge can change sides (a wide guard band instead
left it to the top-left rule, and VTK then drew one pixel we did not).

Each output vertex carries its barycentric weights with respect to the *source*
triangle, so later stages interpolate the source's attributes (Sutherland–Hodgman
polygon clipping; the clipped polygon is re-triangulated as a fan).

What comes out (:class:`Clipped`) names its triangles rather than copying them: most of
a mesh lies wholly inside the view and is kept as it is, and a copy of each such
triangle's corners and weights would cost some 170 bytes a triangle for nothing; only the
pieces that cutting makes get tables of their own. :func:`clip_triangles` writes every
triangle out, for lessons and tests.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from renderer.jit import njit, prange
from renderer.min_max import larger, smaller

from renderer.workspace import empty, kept

N_PLANES = 6
MAX_POLY = 3 + N_PLANES  # each plane adds at most one vertex to a convex polygon


@njit(cache=True, from_python=False)
def plane_distance(v, plane):
    """Signed distance-like value of clip-space vertex ``v`` to a plane; ≥ 0 is inside.

    Planes: 0 near z ≥ −w, 1 far z ≤ w, 2 right x ≤ w, 3 left x ≥ −w, 4 top y ≤ w,
    5 bottom y ≥ −w.
    """
    x, y, z, w = v[0], v[1], v[2], v[3]
    if plane == 0:
        return z + w
    if plane == 1:
        return w - z
    if plane == 2:
        return w - x
    if plane == 3:
        return w + x
    if plane == 4:
        return w - y
    return w + y


@njit(cache=True, inline="always")
def outcode(verts_clip, i):
    """The planes vertex ``i`` lies outside of, as bits (bit p: plane p of :func:`plane_distance`)."""
    code = 0
    for p in range(N_PLANES):
        if plane_distance(verts_clip[i], p) < 0.0:
            code |= 1 << p
    return code


@njit(cache=True)
def outcodes(verts_clip, codes):
    """:func:`outcode` of every vertex into ``codes`` (N,), for :func:`clip_mesh` given no
    codes (the renderer's own are worked out with the vertices,
    :func:`renderer.transform.transform_vertices`)."""
    for i in range(verts_clip.shape[0]):
        codes[i] = outcode(verts_clip, i)


@njit(cache=True, from_python=False)
def clip_polygon(poly, bary, n, plane, out_poly, out_bary):
    """One Sutherland–Hodgman pass: clip the n-gon ``poly`` against ``plane``.

    Returns the vertex count of the result, written to ``out_poly``/``out_bary``
    (element by element: no temporary arrays).
    """
    m = 0
    for i in range(n):
        j = (i + 1) % n
        di = plane_distance(poly[i], plane)
        dj = plane_distance(poly[j], plane)
        if di >= 0.0:
            for c in range(4):
                out_poly[m, c] = poly[i, c]
            for c in range(3):
                out_bary[m, c] = bary[i, c]
            m += 1
        if (di >= 0.0) != (dj >= 0.0):
            t = di / (di - dj)
            for c in range(4):
                out_poly[m, c] = poly[i, c] + t * (poly[j, c] - poly[i, c])
            for c in range(3):
                out_bary[m, c] = bary[i, c] + t * (bary[j, c] - bary[i, c])
            m += 1
    return m


ALL_PLANES = (1 << N_PLANES) - 1
"""Every plane's bit: what :func:`clip_one` cuts against on the plain path."""


@njit(cache=True, inline="always")
def planes_to_cut(triangles, codes, t, trivial):
    """The planes triangle ``t`` is cut against, as bits: those some corner lies outside of
    (its corners' outcodes or'ed together); ``trivial`` False: all six (:data:`ALL_PLANES`).

    A plane no corner lies outside of is passed by the whole triangle, and so by every
    polygon cut from it (its points are weighted means of the corners): the pass
    (:func:`clip_polygon`) would give the polygon back as it was, vertex for vertex. This is
    the trivial accept plane by plane, and leaves out, as that does, a cut vertex that
    rounding would put outside a plane the corners lie on. A sphere filling the view cuts
    904 triangles (ico5 at 512²) in 70 µs instead of 169 (two threads), the same pieces."""
    if not trivial:
        return np.int64(ALL_PLANES)
    return np.int64(codes[triangles[t, 0]] | codes[triangles[t, 1]] | codes[triangles[t, 2]])


@njit(cache=True, from_python=False)
def clip_one(verts_clip, triangles, t, planes, poly, bary, tmp_poly, tmp_bary):
    """Sutherland–Hodgman on triangle ``t`` against the ``planes`` (bits, :func:`planes_to_cut`),
    in plane order: the vertex count of the clipped polygon (< 3: nothing left), its
    vertices in ``poly`` and weights in ``bary``."""
    n = np.int64(3)  # not the literal 3: clip_polygon would be compiled for it and again for int64
    for v in range(3):
        for c in range(4):
            poly[v, c] = verts_clip[triangles[t, v], c]
        for c in range(3):
            bary[v, c] = 1.0 if c == v else 0.0
    for p in range(N_PLANES):
        if not planes & (1 << p):
            continue
        n = clip_polygon(poly, bary, n, p, tmp_poly, tmp_bary)
        for i in range(n):
            for c in range(4):
                poly[i, c] = tmp_poly[i, c]
            for c in range(3):
                bary[i, c] = tmp_bary[i, c]
        if n < 3:
            return 0
    return n


class Clipped(NamedTuple):
    """Stage 4's output: K triangles in source order, each a source triangle kept whole or a
    piece that clipping cut from one.

    A triangle kept whole (trivially accepted) is not copied: its corners are its source
    triangle's vertices, in order, with weights (1, 0, 0), (0, 1, 0), (0, 0, 1). Only the
    pieces — usually few — get tables of their own.

    source (K,) int32 : the source triangle (row of ``triangles``) of each.
    piece (K,) int32 : −1 for a triangle kept whole, else its row in the piece tables.
    piece_clip (P, 3, 4) : the pieces' clip-space corners.
    piece_bary (P, 3, 3) : each corner's barycentric weights in its source triangle.
    """

    source: np.ndarray
    piece: np.ndarray
    piece_clip: np.ndarray
    piece_bary: np.ndarray


def clip_mesh(verts_clip, triangles, ws=None, trivial=True, codes=None) -> Clipped:
    """Clip triangles given as (N, 4) clip-space vertices and (T, 3) vertex indices (:class:`Clipped`).

    **Trivial reject and accept** (Cohen–Sutherland outcodes, :func:`outcode`): a
    triangle whose three vertices all lie outside one plane is dropped; one whose vertices
    are all inside every plane is kept as it is (no copy); only the others are cut
    (:func:`clip_one`) into pieces. Parallel passes over the triangles — classify by the
    outcodes (:func:`trivial_pass`), count what each straddling one leaves
    (:func:`cut_polygons`, which keeps their polygons), then write at the prefix-sum offsets —
    keep the source order.
    When nothing straddles a plane, the cutting passes are not run (nor compiled); when no
    vertex lies outside any plane, none of the passes is (:func:`all_kept_whole`).

    ws : renderer.workspace.Workspace, optional; the outputs then live in it.
    codes : (N,) uint8, optional; the vertices' outcodes when already known (the pipeline's,
        :func:`renderer.transform.transform_vertices`); else worked out here (:func:`outcodes`).
    trivial : False cuts every triangle against all six planes (the plain path the tests
        compare the trivial accept and reject with: every triangle becomes a piece, with the
        same corners and weights).
    """
    verts_clip = np.ascontiguousarray(verts_clip, dtype=np.float64)
    triangles = np.ascontiguousarray(triangles, dtype=np.int64)
    if codes is None:
        codes = empty(ws, "clip.codes", len(verts_clip), np.uint8)
        outcodes(verts_clip, codes)
    if trivial and not codes.any():  # every vertex inside every plane: every triangle kept whole
        return all_kept_whole(len(triangles), ws)
    counts = empty(ws, "clip.counts", len(triangles), np.uint8)
    cut = empty(ws, "clip.cut", len(triangles), np.bool_)
    trivial_pass(triangles, codes, bool(trivial), counts, cut)
    straddling = np.flatnonzero(cut)
    polygons = Polygons(empty(ws, "clip.polygon", (len(straddling), MAX_POLY, 4)),
                        empty(ws, "clip.polygon_bary", (len(straddling), MAX_POLY, 3)),
                        empty(ws, "clip.polygon_n", len(straddling), np.int64))
    if len(straddling):  # a scene inside the view volume never compiles or runs the cutting
        cut_polygons(verts_clip, triangles, codes, bool(trivial), straddling, counts, cut, *polygons)
    piece_offsets = np.zeros(len(straddling) + 1, np.int64)
    np.cumsum(counts[straddling], out=piece_offsets[1:])
    p = int(piece_offsets[-1])
    at_most = len(triangles) - len(straddling) + p  # every other triangle kept whole, and the pieces
    offsets = empty(ws, "scratch.per_triangle", len(triangles) + 1, np.int64)
    source, piece = empty(ws, "clip.source", at_most, np.int32), empty(ws, "clip.piece", at_most, np.int32)
    k = write_whole(counts, cut, offsets, source, piece)
    out = Clipped(source=source[:k], piece=piece[:k], piece_clip=empty(ws, "clip.piece_clip", (p, 3, 4)),
                  piece_bary=empty(ws, "clip.piece_bary", (p, 3, 3)))
    if p:
        write_pieces(straddling, *polygons, offsets, piece_offsets, *out)
    return out


def all_kept_whole(count: int, ws=None) -> Clipped:
    """:func:`clip_mesh`'s answer when every vertex lies inside every plane (no outcode bit
    set): each of the ``count`` triangles trivially accepted, in source order, no pieces. Its
    tables depend on ``count`` alone, so they are kept in the workspace from frame to frame
    (:func:`renderer.workspace.kept`; callers do not write to them). Without this, classifying
    and listing the triangles one by one took a 1M-triangle scan 4.6 ms a frame at 512² (of
    39), a 270k one 1.2 ms (of 15)."""
    return Clipped(source=kept(ws, "clip.all_sources", count, lambda: np.arange(count, dtype=np.int32)),
                   piece=kept(ws, "clip.no_pieces", count, lambda: np.full(count, -1, np.int32)),
                   piece_clip=empty(ws, "clip.piece_clip", (0, 3, 4)),
                   piece_bary=empty(ws, "clip.piece_bary", (0, 3, 3)))


class Polygons(NamedTuple):
    """The polygons that cutting left of the straddling triangles, row i for the i-th:
    ``poly`` (S, MAX_POLY, 4) clip-space vertices, ``bary`` (S, MAX_POLY, 3) their weights
    in the source triangle, ``n`` (S,) how many (< 3: nothing left)."""

    poly: np.ndarray
    bary: np.ndarray
    n: np.ndarray


@njit(cache=True, parallel=True)
def trivial_pass(triangles, codes, trivial, counts, cut):
    """First pass, from the outcodes alone: a triangle trivially rejected leaves none
    (``counts`` 0), one trivially accepted leaves itself (1); the others straddle a plane
    and are marked in ``cut`` for :func:`cut_polygons` (``trivial`` False: every triangle)."""
    for t in prange(triangles.shape[0]):
        c0, c1, c2 = codes[triangles[t, 0]], codes[triangles[t, 1]], codes[triangles[t, 2]]
        if trivial and c0 & c1 & c2:  # all outside one plane: trivially rejected
            counts[t], cut[t] = 0, False
        elif trivial and (c0 | c1 | c2) == 0:  # all inside every plane: trivially accepted
            counts[t], cut[t] = 1, False
        else:
            counts[t], cut[t] = 0, True


CLIP_CHUNK = 64
"""Straddling triangles a parallel iteration of :func:`cut_polygons` cuts, with one scratch
polygon for them all (not one allocated per triangle)."""


@njit(cache=True, parallel=True)
def cut_polygons(verts_clip, triangles, codes, trivial, straddling, counts, cut, poly, bary, n):
    """Second pass, the ``straddling`` triangles only, :data:`CLIP_CHUNK` at a time: each one
    cut (:func:`clip_one`) against the planes a corner lies outside of (``codes``, the
    vertices' outcodes; ``trivial`` False: all six, :func:`planes_to_cut`), its polygon
    kept in row i of ``poly``, ``bary`` and ``n`` (a :class:`Polygons`) for
    :func:`write_pieces`; how many triangles it leaves into ``counts``, and whether it
    leaves any, into ``cut``."""
    for chunk in prange((straddling.shape[0] + CLIP_CHUNK - 1) // CLIP_CHUNK):
        tmp_poly, tmp_bary = np.empty((MAX_POLY, 4)), np.empty((MAX_POLY, 3))
        for i in range(chunk * CLIP_CHUNK, smaller(chunk * CLIP_CHUNK + CLIP_CHUNK, straddling.shape[0])):
            t = straddling[i]
            n[i] = clip_one(verts_clip, triangles, t, planes_to_cut(triangles, codes, t, trivial), poly[i], bary[i],
                            tmp_poly, tmp_bary)
            counts[t], cut[t] = larger(n[i] - 2, 0), n[i] >= 3


@njit(cache=True)
def write_whole(counts, cut, offsets, source, piece):
    """Third pass, in source order: where each triangle's entries start, ``offsets[t]`` (T + 1,),
    the prefix sums of ``counts`` (the last: how many in all, which this returns), and the
    entry of each triangle kept whole, which names it, no piece. One loop with the sums:
    numpy's ``cumsum`` of a 327,680-triangle sphere's counts alone took 1 ms. The sum is an
    int64 from the start (as plain Python, ``NUMBA_DISABLE_JIT``, a Python 0 plus the uint8
    counts became a uint8 that wrapped at 256)."""
    k = np.int64(0)
    for t in range(counts.shape[0]):
        offsets[t] = k
        if counts[t] and not cut[t]:
            source[k] = t
            piece[k] = -1
        k += counts[t]
    offsets[counts.shape[0]] = k
    return k


@njit(cache=True, parallel=True)
def write_pieces(straddling, poly, bary, n, offsets, piece_offsets, source, piece, piece_clip, piece_bary):
    """Last pass, triangles that were cut: the pieces of source triangle ``t = straddling[i]``
    at ``offsets[t]`` onward (rows ``piece_offsets[i]`` onward of the piece tables), as a fan
    around its polygon's first vertex (row i of ``poly``, ``bary``, ``n``: :func:`cut_polygons`)."""
    for i in prange(straddling.shape[0]):
        t = straddling[i]
        k, p = offsets[t], piece_offsets[i]
        corners, weights = poly[i], bary[i]
        for j in range(1, n[i] - 1):
            for v, at in enumerate((0, j, j + 1)):
                for c in range(4):
                    piece_clip[p, v, c] = corners[at, c]
                for c in range(3):
                    piece_bary[p, v, c] = weights[at, c]
            source[k], piece[k] = t, p
            k += 1
            p += 1


class CornerIndex(NamedTuple):
    """Where triangles' corners are, without writing them out: rows of a vertex table that
    holds the ``n_vertices`` source vertices first and then the pieces' corners, three per
    piece (as :func:`renderer.pipeline.clip_and_map` lays out the window-space table).
    Triangle k is source triangle ``source[k]`` kept whole when ``piece[k]`` < 0 (its
    corners: that triangle's rows of ``triangles`` (T, 3) int64), else piece ``piece[k]``;
    source and piece (K,) int32 (:func:`corner_row`). Triangles given whole, three rows each,
    are pieces 0 … K − 1 after no vertices (:meth:`of_whole`)."""

    source: np.ndarray
    piece: np.ndarray
    triangles: np.ndarray
    n_vertices: int

    @staticmethod
    def of_whole(count: int) -> "CornerIndex":
        """``count`` triangles whose corners are rows 3k, 3k + 1, 3k + 2."""
        return CornerIndex(np.zeros(count, np.int32), np.arange(count, dtype=np.int32), np.empty((0, 3), np.int64), 0)

    def batch(self, a: int, b: int) -> "CornerIndex":
        """Triangles a … b − 1 (views, no copy)."""
        return self._replace(source=self.source[a:b], piece=self.piece[a:b])


@njit(cache=True, inline="always")
def corner_row(corners, k, v):
    """The row of corner ``v`` of triangle ``k`` of a :class:`CornerIndex`."""
    p = corners.piece[k]
    return corners.triangles[corners.source[k], v] if p < 0 else corners.n_vertices + 3 * p + v


@njit(cache=True)
def corner_rows(corners, rows):
    """The rows of each triangle's corners (:class:`CornerIndex` ``corners``) written out into
    ``rows`` (K, 3), for a caller that keeps them (the raster and shading read them through
    :func:`corner_row` as they go)."""
    for k in range(corners.source.shape[0]):
        for v in range(3):
            rows[k, v] = corner_row(corners, k, v)


@njit(cache=True, parallel=True)
def gather_corners(verts_clip, triangles, source, piece, piece_clip, piece_bary, out_clip, out_bary):
    """Each triangle's clip-space corners and their weights, written out into ``out_clip``
    (K, 3, 4) and ``out_bary`` (K, 3, 3): a source triangle's vertices with unit weights, or
    its piece's rows."""
    for k in prange(source.shape[0]):
        p = piece[k]
        for v in range(3):
            if p < 0:
                for c in range(4):
                    out_clip[k, v, c] = verts_clip[triangles[source[k], v], c]
                for c in range(3):
                    out_bary[k, v, c] = 1.0 if c == v else 0.0
            else:
                for c in range(4):
                    out_clip[k, v, c] = piece_clip[p, v, c]
                for c in range(3):
                    out_bary[k, v, c] = piece_bary[p, v, c]


def clipped_corners(clipped: Clipped, verts_clip, triangles, ws=None, name="clip.corners"):
    """The triangles of ``clipped`` written out whole: (K, 3, 4) clip-space corners, (K, 3, 3)
    weights in the source triangle and (K,) int64 source triangles (in workspace ``ws``
    under ``name``)."""
    k = len(clipped.source)
    out_clip, out_bary = empty(ws, f"{name}.clip", (k, 3, 4)), empty(ws, f"{name}.bary", (k, 3, 3))
    gather_corners(np.ascontiguousarray(verts_clip, dtype=np.float64), np.ascontiguousarray(triangles, dtype=np.int64),
                   *clipped, out_clip, out_bary)
    out_source = empty(ws, f"{name}.source", k, np.int64)
    out_source[:] = clipped.source
    return out_clip, out_bary, out_source


@njit(cache=True, parallel=True)
def pick_triangles(source, piece, order, out_source, out_piece):
    """Triangles ``order`` (V,) int64 of a :class:`Clipped`'s ``source`` and ``piece`` tables, in
    that order, into ``out_source`` and ``out_piece`` (V,): :func:`picked`'s loop."""
    for i in prange(order.shape[0]):
        k = order[i]
        out_source[i], out_piece[i] = source[k], piece[k]


def picked(source, piece, order, ws=None, name="clip.picked"):
    """``source[order]`` and ``piece[order]`` (int32; ``order`` int64 rows), in workspace ``ws``
    under ``name``. The winners of a frame, read at scattered rows of tables as long as the
    mesh: numpy's indexing of the 1M-triangle scan's 58k winners at 512² took 0.3 ms a table
    (its checks and its loop, one thread)."""
    out_source = empty(ws, f"{name}.source", len(order), np.int32)
    out_piece = empty(ws, f"{name}.piece", len(order), np.int32)
    if len(order):
        pick_triangles(source, piece, order, out_source, out_piece)
    return out_source, out_piece


def clip_triangles(verts_clip, triangles, ws=None, trivial=True):
    """:func:`clip_mesh`, with every kept triangle written out (for lessons and tests).

    Returns
    -------
    out_clip : (K, 3, 4) clip-space vertices of the kept triangles, in source order.
    out_bary : (K, 3, 3) each vertex's barycentric weights in its source triangle.
    out_source : (K,) int64 index of the source triangle.
    """
    return clipped_corners(clip_mesh(verts_clip, triangles, ws, trivial), verts_clip, triangles, ws)
