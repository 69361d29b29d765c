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
"""
from __future__ import annotations

import numpy as np
from renderer.jit import njit, prange

from renderer.workspace import empty

N_PLANES = 6
MAX_POLY = 3 + N_PLANES  # each plane adds at most one vertex to a convex polygon


@njit(cache=True)
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


@njit(cache=True, parallel=True)
def outcodes(verts_clip, codes):
    """:func:`outcode` of every vertex into ``codes`` (N,) (the loop kernel)."""
    for i in prange(verts_clip.shape[0]):
        codes[i] = outcode(verts_clip, i)


@njit(cache=True)
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


@njit(cache=True)
def clip_one(verts_clip, triangles, t, poly, bary, tmp_poly, tmp_bary):
    """Sutherland–Hodgman on triangle ``t`` against all six planes: the vertex count of the
    clipped polygon (< 3: nothing left), its vertices in ``poly`` and weights in ``bary``."""
    n = 3
    for v in range(3):
        for c in range(4):
            poly[v, c] = verts_clip[triangles[t, v], c]
        for c in range(3):
            bary[v, c] = 1.0 if c == v else 0.0
    for p in range(N_PLANES):
        n = clip_polygon(poly, bary, n, p, tmp_poly, tmp_bary)
        for i in range(n):
            for c in range(4):
                poly[i, c] = tmp_poly[i, c]
            for c in range(3):
                bary[i, c] = tmp_bary[i, c]
        if n < 3:
            return 0
    return n


def clip_triangles(verts_clip, triangles, ws=None, trivial=True):
    """Clip triangles given as (N, 4) clip-space vertices and (T, 3) vertex indices.

    **Trivial reject and accept** (Cohen–Sutherland outcodes, :func:`outcode`): a
    triangle whose three vertices all lie outside one plane is dropped; one whose vertices
    are all inside every plane is kept as it is; only the others are cut
    (:func:`clip_one`). Two parallel passes over the triangles — count the pieces, then
    write them at their prefix-sum offsets — keep the source order.

    Parameters
    ----------
    ws : renderer.workspace.Workspace, optional; the outputs then live in it.
    trivial : False cuts every triangle against all six planes (the plain path the tests
        compare the trivial accept and reject with: the same output).

    Returns
    -------
    out_clip : (K, 3, 4) clip-space vertices of the kept triangles, in source order.
    out_bary : (K, 3, 3) each vertex's barycentric weights in its source triangle.
    out_source : (K,) index of the source triangle.
    """
    verts_clip = np.ascontiguousarray(verts_clip, dtype=np.float64)
    triangles = np.ascontiguousarray(triangles, dtype=np.int64)
    codes = empty(ws, "clip.codes", len(verts_clip), np.int64)
    outcodes(verts_clip, codes)
    counts = empty(ws, "clip.counts", len(triangles) + 1, np.int64)
    count_pieces(verts_clip, triangles, codes, bool(trivial), counts[1:])
    counts[0] = 0
    offsets = np.cumsum(counts, out=counts)
    k = int(offsets[-1])
    out_clip = empty(ws, "clip.clip", (k, 3, 4))
    out_bary = empty(ws, "clip.bary", (k, 3, 3))
    out_source = empty(ws, "clip.source", k, np.int64)
    write_pieces(verts_clip, triangles, codes, bool(trivial), offsets, out_clip, out_bary, out_source)
    return out_clip, out_bary, out_source


@njit(cache=True, parallel=True)
def count_pieces(verts_clip, triangles, codes, trivial, counts):
    """First pass: how many triangles each source triangle leaves after clipping, into ``counts``
    (``trivial`` False: no trivial accept or reject, every triangle is cut)."""
    for t in prange(triangles.shape[0]):
        c0, c1, c2 = codes[triangles[t, 0]], codes[triangles[t, 1]], codes[triangles[t, 2]]
        if trivial and c0 & c1 & c2:  # all outside one plane: trivially rejected
            counts[t] = 0
        elif trivial and (c0 | c1 | c2) == 0:  # all inside every plane: trivially accepted
            counts[t] = 1
        else:
            poly, bary = np.empty((MAX_POLY, 4)), np.empty((MAX_POLY, 3))
            n = clip_one(verts_clip, triangles, t, poly, bary, np.empty((MAX_POLY, 4)), np.empty((MAX_POLY, 3)))
            counts[t] = max(n - 2, 0)


@njit(cache=True, parallel=True)
def write_pieces(verts_clip, triangles, codes, trivial, offsets, out_clip, out_bary, out_source):
    """Second pass: the pieces of source triangle ``t`` at ``offsets[t]`` onward, as a fan
    around the clipped polygon's first vertex; trivially accepted triangles copied whole."""
    for t in prange(triangles.shape[0]):
        k = offsets[t]
        if offsets[t + 1] == k:
            continue
        c0, c1, c2 = codes[triangles[t, 0]], codes[triangles[t, 1]], codes[triangles[t, 2]]
        if trivial and (c0 | c1 | c2) == 0:
            for v in range(3):
                for c in range(4):
                    out_clip[k, v, c] = verts_clip[triangles[t, v], c]
                for c in range(3):
                    out_bary[k, v, c] = 1.0 if c == v else 0.0
            out_source[k] = t
            continue
        poly, bary = np.empty((MAX_POLY, 4)), np.empty((MAX_POLY, 3))
        n = clip_one(verts_clip, triangles, t, poly, bary, np.empty((MAX_POLY, 4)), np.empty((MAX_POLY, 3)))
        for i in range(1, n - 1):
            for c in range(4):
                out_clip[k, 0, c], out_clip[k, 1, c], out_clip[k, 2, c] = poly[0, c], poly[i, c], poly[i + 1, c]
            for c in range(3):
                out_bary[k, 0, c], out_bary[k, 1, c], out_bary[k, 2, c] = bary[0, c], bary[i, c], bary[i + 1, c]
            out_source[k] = t
            k += 1
