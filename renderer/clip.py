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
from renderer.jit import njit

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


@njit(cache=True)
def clip_polygon(poly, bary, n, plane, out_poly, out_bary):
    """One Sutherland–Hodgman pass: clip the n-gon ``poly`` against ``plane``.

    Returns the vertex count of the result, written to ``out_poly``/``out_bary``.
    """
    m = 0
    for i in range(n):
        j = (i + 1) % n
        di = plane_distance(poly[i], plane)
        dj = plane_distance(poly[j], plane)
        if di >= 0.0:
            out_poly[m] = poly[i]
            out_bary[m] = bary[i]
            m += 1
        if (di >= 0.0) != (dj >= 0.0):
            t = di / (di - dj)
            out_poly[m] = poly[i] + t * (poly[j] - poly[i])
            out_bary[m] = bary[i] + t * (bary[j] - bary[i])
            m += 1
    return m


def clip_triangles(verts_clip, triangles, ws=None):
    """Clip triangles given as (N, 4) clip-space vertices and (T, 3) vertex indices.

    Parameters
    ----------
    ws : renderer.workspace.Workspace, optional; the outputs then live in it.

    Returns
    -------
    out_clip : (K, 3, 4) clip-space vertices of the kept triangles, in source order.
    out_bary : (K, 3, 3) each vertex's barycentric weights in its source triangle.
    out_source : (K,) index of the source triangle.
    """
    verts_clip = np.ascontiguousarray(verts_clip, dtype=np.float64)
    triangles = np.ascontiguousarray(triangles, dtype=np.int64)
    cap = len(triangles) + 16
    while True:
        out_clip = empty(ws, "clip.clip", (cap, 3, 4))
        out_bary = empty(ws, "clip.bary", (cap, 3, 3))
        out_source = empty(ws, "clip.source", cap, np.int64)
        k = clip_into(verts_clip, triangles, out_clip, out_bary, out_source)
        if k >= 0:
            return out_clip[:k], out_bary[:k], out_source[:k]
        cap *= 2  # more pieces than room: try again with twice the room


@njit(cache=True)
def clip_into(verts_clip, triangles, out_clip, out_bary, out_source):
    """The loop kernel of :func:`clip_triangles`; returns the piece count, −1 if out of room."""
    t_count = triangles.shape[0]
    cap = out_clip.shape[0]
    poly = np.empty((MAX_POLY, 4))
    bary = np.empty((MAX_POLY, 3))
    tmp_poly = np.empty((MAX_POLY, 4))
    tmp_bary = np.empty((MAX_POLY, 3))
    k = 0
    for t in range(t_count):
        n = 3
        for v in range(3):
            for c in range(4):
                poly[v, c] = verts_clip[triangles[t, v], c]
            for c in range(3):
                bary[v, c] = 1.0 if c == v else 0.0
        inside_all = True
        for v in range(3):
            for p in range(N_PLANES):
                if plane_distance(poly[v], p) < 0.0:
                    inside_all = False
        if not inside_all:
            for p in range(N_PLANES):
                n = clip_polygon(poly, bary, n, p, tmp_poly, tmp_bary)
                poly[:n] = tmp_poly[:n]
                bary[:n] = tmp_bary[:n]
                if n < 3:
                    break
        if n < 3:
            continue
        if k + n - 2 > cap:
            return -1
        for i in range(1, n - 1):
            for c in range(4):
                out_clip[k, 0, c], out_clip[k, 1, c], out_clip[k, 2, c] = poly[0, c], poly[i, c], poly[i + 1, c]
            for c in range(3):
                out_bary[k, 0, c], out_bary[k, 1, c], out_bary[k, 2, c] = bary[0, c], bary[i, c], bary[i + 1, c]
            out_source[k] = t
            k += 1
    return k
