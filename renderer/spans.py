"""Spans: one triangle's run of visible pixels on one row, interpolated in float32, 8+ lanes at a time.

Shading (:mod:`renderer.shading`) walks each row of the visibility buffer in **spans**,
the runs of neighbouring pixels that show the same triangle. Everything constant along a
span is worked out once, in float64, and handed to the per-pixel code as float32
constants (:func:`span_setup`): where the triangle's weights stand and how they step per
pixel, its clipped vertices' positions and normals. A model's span kernel
(:mod:`renderer.reflection.vtk_spans`) then runs one loop over the span's pixels —
interpolate (:func:`span_pixel`), light, store 8 bits — in float32 and without calls or
early exits, which LLVM turns into SIMD code: llvmpipe shades 8 float32 lanes at a time,
and VTK's shaders compute in float32 too.

Interpolation (perspective-correct, as :func:`renderer.shading.fragment_weights`): the
screen-space weights ``l0, l1, l2`` of the clipped triangle are affine along the row,
``l_i = L_i + B_i·x`` with x the pixel's column counted from the triangle's **anchor
column** (the pixel column of its first vertex), so a pixel gets the same bits whichever
span it is shaded in; divided by the vertices' clip w they stay affine, ``b_i = l_i/w_i``;
an attribute is ``(Σ b_i·A_i) / Σ b_i`` with ``A_i`` the clipped vertex's attribute (the
source vertices' attributes mixed by its clipping weights). Screen-linear interpolation
takes ``w_i = 1``. Texture coordinates too (:func:`span_tcoords`), in a textured frame
whose span table carries its corners' (s, t).

**Span table.** Everything a span's set-up reads that does not depend on the row is
gathered once a frame per clipped triangle, in the order ``tri_index`` numbers them (for the
lean path, the order the rows first show them: :mod:`renderer.visible`), into :class:`SpanTable`
(:func:`span_table`): two rows of two tables instead of a chain of lookups (clipped
triangle → source triangle → its vertices → their positions and normals), each of which
missed the cache on a large mesh, where a triangle has one or two spans. The values are
the same bits as working them out span by span (the same float64 expressions, the same
casts to float32); read from the clipped corners (:func:`span_table_of_corners`), a
triangle kept whole takes its vertices' values without mixing them by weights of 1 and 0:
the same numbers, up to the sign of a zero.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from renderer.clip import corner_row
from renderer.jit import njit, prange
from renderer.plane_normals import corners_normal
from renderer.prefetch import prefetch_row
from renderer.window import signed_area_corners, window_edges

F0, F1 = np.float32(0.0), np.float32(1.0)
CORNERS, TEXTURED_CORNERS = 22, 28
"""Columns of the span corners (:class:`SpanTable`): every frame's 22, and a textured frame's
28 (then the clipped vertices' texture coordinates)."""


class SpanTable(NamedTuple):
    """Per clipped triangle ``k`` (as ``tri_index`` numbers them), what each of its spans starts
    from (:func:`span_table`).

    weights (K, 11) float64: ``anchor, px, y0, e1x, e1y, e2x, e2y, inv_a2, iw0, iw1, iw2`` —
    the anchor column (floor of the first vertex's x), the anchor pixel's centre counted
    from that vertex, its y, the two edge vectors and one over twice the signed area
    (:func:`table_weights`), one over each clipped vertex's clip w (1 when screen-linear);
    corners (K, 22) float32, or (K, 28) in a textured frame (:data:`CORNERS`, :data:`TEXTURED_CORNERS`): the
    clipped vertices' view-space positions (9), their unnormalised normals (9), the plane
    normal turned toward the viewer (3, zeros when the frame has no face normals), 1 on a
    front face, −1 on a back face, and the clipped vertices' texture coordinates
    (s0, t0, s1, t1, s2, t2: :func:`span_texture_corners`);
    object (K,) int64: the object the triangle belongs to.
    """

    weights: np.ndarray
    corners: np.ndarray
    object: np.ndarray


@njit(cache=True, parallel=True)
def span_table(plane, front, tri_clip, clip_bary, clip_source, perspective, geo, weights, corners, objects):
    """Fill :class:`SpanTable`'s ``weights``, ``corners`` and ``objects`` for every clipped
    triangle of written-out tables (:class:`renderer.shading.Fragments`' ``plane``, ``front``,
    ``tri_clip``, ``clip_bary``, ``clip_source``); each row is written by its own iteration
    (the same bytes on any number of threads)."""
    for k in prange(plane.shape[0]):
        edges = (plane[k, 0], plane[k, 1], plane[k, 2], plane[k, 3], plane[k, 4], plane[k, 5])
        w = (tri_clip[k, 0, 3], tri_clip[k, 1, 3], tri_clip[k, 2, 3]) if perspective else (1.0, 1.0, 1.0)
        mix = ((clip_bary[k, 0, 0], clip_bary[k, 0, 1], clip_bary[k, 0, 2]),
               (clip_bary[k, 1, 0], clip_bary[k, 1, 1], clip_bary[k, 1, 2]),
               (clip_bary[k, 2, 0], clip_bary[k, 2, 1], clip_bary[k, 2, 2]))
        table_row(k, clip_source[k], edges, w, front[k], geo, weights, corners, objects)
        mixed_corners(k, clip_source[k], mix, geo, corners)


class CornerTables(NamedTuple):
    """Clipped triangles as clipping and the window mapping left them, not written out: the
    fields of a :class:`renderer.clip.CornerIndex` (``source``, ``piece``, ``triangles``,
    ``n_vertices``: where each one's corners are, :func:`renderer.clip.corner_row`), the
    pieces' clip-space corners ``piece_clip`` (P, 3, 4) and weights in their source triangle
    ``piece_bary`` (P, 3, 3) (:class:`renderer.clip.Clipped`), the scene's ``verts_clip`` (N, 4),
    and the rows in window space, ``window`` (M, 3) and ``fixed`` (M, 2) int64. Flat, not a
    CornerIndex inside: numba passes no tuple inside a tuple into a parallel loop."""

    source: np.ndarray
    piece: np.ndarray
    triangles: np.ndarray
    n_vertices: int
    piece_clip: np.ndarray
    piece_bary: np.ndarray
    verts_clip: np.ndarray
    window: np.ndarray
    fixed: np.ndarray


@njit(cache=True, parallel=True)
def span_table_of_corners(clipped, perspective, geo, weights, corners, objects):
    """:func:`span_table` read straight from ``clipped`` (:class:`CornerTables`): each triangle's
    weights' plane and facing from its corners' window rows (as
    :func:`renderer.raster.weight_planes` works them out), its corners' clip w and weights
    from the scene's vertices (unit weights) or its piece (as
    :func:`renderer.clip.gather_corners` writes them out) — the same bits (a triangle kept
    whole: its vertices' values, :func:`source_corners`), without writing those tables out
    and reading them back (a 270k-triangle scan at 512²: 6 ms a frame). The
    rows of the triangles a few iterations on are asked for ahead (:func:`read_ahead`)."""
    fixed, count = clipped.fixed, clipped.source.shape[0]
    for k in prange(count):
        read_ahead(k, count, clipped, geo)
        i0, i1, i2 = corner_row(clipped, k, 0), corner_row(clipped, k, 1), corner_row(clipped, k, 2)
        s, p = clipped.source[k], clipped.piece[k]
        if p < 0:  # kept whole: its corner rows are its vertices
            w = (clipped.verts_clip[i0, 3], clipped.verts_clip[i1, 3], clipped.verts_clip[i2, 3])
            source_corners(k, s, geo, corners)
        else:
            c, b = clipped.piece_clip, clipped.piece_bary
            w = (c[p, 0, 3], c[p, 1, 3], c[p, 2, 3])
            mix = ((b[p, 0, 0], b[p, 0, 1], b[p, 0, 2]), (b[p, 1, 0], b[p, 1, 1], b[p, 1, 2]),
                   (b[p, 2, 0], b[p, 2, 1], b[p, 2, 2]))
            mixed_corners(k, s, mix, geo, corners)
        edges, front = window_edges(clipped.window, i0, i1, i2), signed_area_corners(fixed, i0, i1, i2) > 0
        table_row(k, s, edges, w if perspective else (1.0, 1.0, 1.0), front, geo, weights, corners, objects)


AHEAD_SOURCE, AHEAD_CORNERS = 16, 8
"""How many triangles ahead :func:`read_ahead` asks for a triangle's own rows, and for its
corners' rows (these need the triangle's corners, asked for earlier). Measured, the span
table alone on its frame's input, in one process, this against no reading ahead:
igea-270k at 512² 0.68–0.75 of the time on one thread, 0.85–0.94 on two; ico7-phong at
1024², two threads, 0.81–0.84 (8 and 4 ahead, or 32 and 16, were no better)."""


@njit(cache=True, inline="always")
def read_ahead(k, count, clipped, geo):
    """Ask for the rows :func:`table_row` will read for clipped triangle ``k`` +
    :data:`AHEAD_SOURCE` (its source triangle's corners, object and plane normal) and for the
    corners of triangle ``k`` + :data:`AHEAD_CORNERS`, kept whole (positions, normals, clip
    and window rows): the winners come in the order the image shows them, so these are reads
    at random over the mesh's tables (:mod:`renderer.prefetch`)."""
    if k + AHEAD_SOURCE < count:
        s = clipped.source[k + AHEAD_SOURCE]
        prefetch_row(geo.triangles, s)
        prefetch_row(geo.tri_object, s)
        if geo.face_normals.shape[0] > 0:
            prefetch_row(geo.face_normals, s)
    if k + AHEAD_CORNERS < count and clipped.piece[k + AHEAD_CORNERS] < 0:
        s = clipped.source[k + AHEAD_CORNERS]
        for v in range(3):
            i = geo.triangles[s, v]
            prefetch_row(geo.verts_view, i)
            prefetch_row(geo.normals_view, i)
            prefetch_row(clipped.verts_clip, i)
            prefetch_row(clipped.window, i)
            prefetch_row(clipped.fixed, i)


@njit(cache=True, inline="always")
def table_row(k, s, edges, w, front, geo, weights, corners, objects):
    """Row ``k`` of the span table (``weights``, ``corners``, ``objects``) for a clipped triangle
    of source triangle ``s``, but for its corners' values (:func:`source_corners`,
    :func:`mixed_corners`): ``edges`` its weights' plane (x0, y0, e1x, e1y, e2x, e2y,
    :func:`renderer.raster.weights_plane`), ``w`` its corners' clip w (1 when screen-linear),
    ``front`` its facing. (The tables come one by one, not as a tuple: numba loses writes made
    through a tuple's arrays inside ``prange``, numba issues #5872, #7135.)"""
    x0, y0, e1x, e1y, e2x, e2y = edges
    anchor = np.floor(x0)
    weights[k, 0], weights[k, 1], weights[k, 2] = anchor, anchor + 0.5 - x0, y0
    weights[k, 3], weights[k, 4], weights[k, 5], weights[k, 6] = e1x, e1y, e2x, e2y
    weights[k, 7] = 1.0 / (e1x * e2y - e2x * e1y)
    weights[k, 8], weights[k, 9], weights[k, 10] = 1.0 / w[0], 1.0 / w[1], 1.0 / w[2]
    fx, fy, fz = face_toward_viewer(geo, s) if geo.face_normals.shape[0] > 0 else (0.0, 0.0, 0.0)
    corners[k, 18], corners[k, 19], corners[k, 20] = np.float32(fx), np.float32(fy), np.float32(fz)
    corners[k, 21] = F1 if front else -F1
    objects[k] = geo.tri_object[s]


@njit(cache=True, inline="always")
def mixed_corners(k, s, mix, geo, corners):
    """The corners' values in row ``k`` of the span table's ``corners``: positions, normals and,
    in a textured frame, texture coordinates of source triangle ``s``'s vertices mixed by each
    corner's weights ``mix`` (three rows of three, :func:`mixed_vertex`)."""
    i0, i1, i2 = geo.triangles[s, 0], geo.triangles[s, 1], geo.triangles[s, 2]
    for i in range(3):
        p = mixed_vertex(geo.verts_view, mix[i], i0, i1, i2)
        n = mixed_vertex(geo.normals_view, mix[i], i0, i1, i2)
        for c in range(3):
            corners[k, 3 * i + c], corners[k, 9 + 3 * i + c] = p[c], n[c]
    if corners.shape[1] == TEXTURED_CORNERS:
        for i in range(3):
            st = mixed_vertex(geo.tcoords, mix[i], i0, i1, i2)
            corners[k, 22 + 2 * i], corners[k, 23 + 2 * i] = st[0], st[1]


@njit(cache=True, inline="always")
def source_corners(k, s, geo, corners):
    """:func:`mixed_corners` of a triangle kept whole, whose corners are source triangle ``s``'s
    vertices: their values as they are, as float32 (:func:`vertex_values`), without the mix's
    products by weights of 1 and 0, which give the same numbers up to the sign of a zero (the
    span table alone: 0.82–0.89 of its time, docs/performance.md)."""
    for i in range(3):
        v = geo.triangles[s, i]
        p, n = vertex_values(geo.verts_view, v), vertex_values(geo.normals_view, v)
        for c in range(3):
            corners[k, 3 * i + c], corners[k, 9 + 3 * i + c] = p[c], n[c]
    if corners.shape[1] == TEXTURED_CORNERS:
        for i in range(3):
            st = vertex_values(geo.tcoords, geo.triangles[s, i])
            corners[k, 22 + 2 * i], corners[k, 23 + 2 * i] = st[0], st[1]


@njit(cache=True, inline="always")
def table_weights(t, k, row, c0):
    """Float64 ``(L0, B0, L1, B1, L2, B2, x)`` from the span table's ``weights`` ``t``: clipped
    triangle ``k``'s weights of its three vertices on ``row`` at its anchor column and their
    step per pixel to the right, each divided by its vertex's clip w (times 1 when
    screen-linear); ``x`` is the span's first pixel ``c0`` counted from the anchor."""
    anchor, px, y0 = t[k, 0], t[k, 1], t[k, 2]
    e1x, e1y, e2x, e2y, inv_a2 = t[k, 3], t[k, 4], t[k, 5], t[k, 6], t[k, 7]
    py = row + 0.5 - y0
    l1, l2 = (px * e2y - e2x * py) * inv_a2, (e1x * py - px * e1y) * inv_a2
    b1, b2 = e2y * inv_a2, -e1y * inv_a2
    l0, b0 = 1.0 - l1 - l2, -b1 - b2
    w0, w1, w2 = t[k, 8], t[k, 9], t[k, 10]
    return l0 * w0, b0 * w0, l1 * w1, b1 * w1, l2 * w2, b2 * w2, c0 - anchor


@njit(cache=True, inline="always")
def clipped_vertex(values, k, i, cb, i0, i1, i2):
    """``values`` (per source vertex, 3 columns) at vertex ``i`` of clipped triangle ``k``, as
    float32: its clipping weights ``cb[k, i]`` mix the source triangle's three vertices."""
    return mixed_vertex(values, (cb[k, i, 0], cb[k, i, 1], cb[k, i, 2]), i0, i1, i2)


@njit(cache=True, inline="always")
def mixed_vertex(values, mix, i0, i1, i2):
    """``values`` (per source vertex, 3 columns; or 2, texture coordinates) mixed by the
    weights ``mix`` of the source triangle's vertices ``i0, i1, i2``, as float32 (a clipped
    corner's value)."""
    w0, w1, w2 = mix
    s0 = np.float32(w0 * values[i0, 0] + w1 * values[i1, 0] + w2 * values[i2, 0])
    s1 = np.float32(w0 * values[i0, 1] + w1 * values[i1, 1] + w2 * values[i2, 1])
    if values.shape[1] == 2:
        return s0, s1, F0
    return s0, s1, np.float32(w0 * values[i0, 2] + w1 * values[i1, 2] + w2 * values[i2, 2])


@njit(cache=True, inline="always")
def vertex_values(values, i):
    """Row ``i`` of ``values`` (per source vertex, 3 columns; or 2, texture coordinates, then a
    third 0) as float32: a corner that is that vertex (:func:`source_corners`)."""
    if values.shape[1] == 2:
        return np.float32(values[i, 0]), np.float32(values[i, 1]), F0
    return np.float32(values[i, 0]), np.float32(values[i, 1]), np.float32(values[i, 2])


@njit(cache=True, inline="always")
def face_toward_viewer(geo, s):
    """Source triangle ``s``'s unit plane normal turned toward the viewer: perspective,
    so that n·P ≤ 0 at its first vertex P (the sign of n·P is the same over the whole
    plane); parallel, so that n.z ≥ 0. One decision per triangle."""
    return toward_viewer(geo, s, geo.face_normals[s, 0], geo.face_normals[s, 1], geo.face_normals[s, 2])


@njit(cache=True, inline="always")
def corners_toward_viewer(geo, s):
    """:func:`face_toward_viewer` with the plane normal worked out from the triangle's corners
    (:func:`renderer.plane_normals.corners_normal`, the same bits), for a frame that made no
    table of plane normals."""
    nx, ny, nz = corners_normal(geo.verts_view, geo.triangles, s)
    return toward_viewer(geo, s, nx, ny, nz)


@njit(cache=True, inline="always")
def toward_viewer(geo, s, nx, ny, nz):
    """Source triangle ``s``'s unit plane normal ``(nx, ny, nz)``, negated if it points away from
    the viewer (:func:`face_toward_viewer`)."""
    if geo.parallel:
        away = nz < 0.0
    else:
        p = geo.verts_view[geo.triangles[s, 0]]
        away = nx * p[0] + ny * p[1] + nz * p[2] > 0.0
    return (-nx, -ny, -nz) if away else (nx, ny, nz)


@njit(cache=True, inline="always")
def span_setup(k, row, c0, frags, geo, face):
    """The float32 constants of clipped triangle ``k``'s span on ``row`` from column ``c0``:
    ``(weights, positions, normals, face_normal, sign)``, read from the frame's span table
    (``frags.span_weights`` and ``frags.span_corners``, :class:`SpanTable`).

    weights: (L0, B0, L1, B1, L2, B2, x) (:func:`table_weights`, x the first pixel's
    offset from the anchor); positions and normals: the clipped vertices' view-space
    positions and (unnormalised) normals, 9 values each; ``face``: use the triangle's own
    plane normal turned toward the viewer (``face_normal``) instead of interpolating;
    sign: −1 on a back face (two-sided lighting), else 1.
    """
    L0, B0, L1, B1, L2, B2, x = table_weights(frags.span_weights, k, row, c0)
    weights = (np.float32(L0), np.float32(B0), np.float32(L1), np.float32(B1), np.float32(L2), np.float32(B2),
               np.float32(x))
    c = frags.span_corners
    pa, pb, pc = (c[k, 0], c[k, 1], c[k, 2]), (c[k, 3], c[k, 4], c[k, 5]), (c[k, 6], c[k, 7], c[k, 8])
    if face:
        na = nb = nc = (F0, F0, F0)
        face_normal = (c[k, 18], c[k, 19], c[k, 20])
    else:
        na, nb, nc = (c[k, 9], c[k, 10], c[k, 11]), (c[k, 12], c[k, 13], c[k, 14]), (c[k, 15], c[k, 16], c[k, 17])
        face_normal = (F0, F0, F0)
    sign = F1 if face else c[k, 21]
    return weights, (pa, pb, pc), (na, nb, nc), face_normal, sign


@njit(cache=True, inline="always")
def span_weights_at(weights, i):
    """Pixel ``i`` of the span (0 = its first): its three corners' weights ``(w0, w1, w2)``
    (each already divided by its clip w), float32: an attribute there is
    ``(w0·A0 + w1·A1 + w2·A2) / (w0 + w1 + w2)``."""
    fl0, fb0, fl1, fb1, fl2, fb2, first = weights
    x = first + np.float32(np.int32(i))  # from int32: eight lanes convert in one instruction (int64: one by one)
    return fl0 + fb0 * x, fl1 + fb1 * x, fl2 + fb2 * x


@njit(cache=True, inline="always")
def span_pixel(consts, i, face):
    """Pixel ``i`` of the span (0 = its first): view-space position ``(px, py, pz)`` and unit
    normal ``(nx, ny, nz)`` on the viewer's side, float32 (see the module docstring): its
    sums (:func:`pixel_sums`) finished (:func:`finished_point`)."""
    return finished_point(pixel_sums(consts, i, face), face)


@njit(cache=True, inline="always")
def pixel_sums(consts, i, face):
    """The first half of :func:`span_pixel`, without a division or a root: pixel ``i``'s
    weighted sums of the corners' positions and normals (``w0·A0 + w1·A1 + w2·A2``), the sum
    of its weights and the span's sign (the plane normal toward the viewer and 1 with
    ``face``), float32: ``(sx, sy, sz, snx, sny, snz, w, sign)``."""
    weights, positions, normals, face_normal, sign = consts
    w0, w1, w2 = span_weights_at(weights, i)
    a, b, c = positions
    sx = w0 * a[0] + w1 * b[0] + w2 * c[0]
    sy = w0 * a[1] + w1 * b[1] + w2 * c[1]
    sz = w0 * a[2] + w1 * b[2] + w2 * c[2]
    if face:
        return sx, sy, sz, face_normal[0], face_normal[1], face_normal[2], w0 + w1 + w2, sign
    a, b, c = normals
    snx = w0 * a[0] + w1 * b[0] + w2 * c[0]
    sny = w0 * a[1] + w1 * b[1] + w2 * c[1]
    snz = w0 * a[2] + w1 * b[2] + w2 * c[2]
    return sx, sy, sz, snx, sny, snz, w0 + w1 + w2, sign


@njit(cache=True, inline="always")
def finished_point(sums, face):
    """The second half of :func:`span_pixel`: :func:`pixel_sums` divided by the weights' sum
    (perspective-correct), the normal made unit and turned by the sign (with ``face``, the
    plane normal as it is)."""
    sx, sy, sz, snx, sny, snz, w, sign = sums
    inv = F1 / w
    px, py, pz = sx * inv, sy * inv, sz * inv
    if face:
        return px, py, pz, snx, sny, snz
    nx, ny, nz = snx * inv, sny * inv, snz * inv
    length = np.sqrt(nx * nx + ny * ny + nz * nz)
    scale = sign / length if length > F0 else sign
    return px, py, pz, nx * scale, ny * scale, nz * scale


LANES = 8
"""32-bit values (float32 colours, int32 depths) in one of the vector registers the span loops
run in (AVX2's 256 bits)."""


@njit(cache=True, inline="always")
def round_up_to_lanes(count):
    """``count`` rounded up to a multiple of :data:`LANES`."""
    return (count + LANES - 1) & -LANES


@njit(cache=True, inline="always")
def whole_lanes(count):
    """``count`` rounded up to a multiple of :data:`LANES` when it fills half a vector register
    or more: a loop over that many pixels then runs in vector steps alone, with no scalar
    tail. A shorter count is kept (a thin triangle's span of a pixel or two is not worth a
    vector register's eight: padding those made the 1,024-segment cylinder slower)."""
    return round_up_to_lanes(count) if count >= LANES // 2 else count


@njit(cache=True, inline="always")
def span_points(consts, face, count, points, at):
    """The span's first ``count`` pixels (:func:`span_pixel`) into columns ``at`` … ``at +
    count − 1`` of ``points`` (6, W) float32: rows x, y, z of the view-space position, then
    nx, ny, nz of the unit normal. (Whole rows and an offset, not a slice of columns: numba
    reads a slice of columns through its strides, and the loops then do not vectorise.)"""
    for i in range(count):
        px, py, pz, nx, ny, nz = span_pixel(consts, i, face)
        j = np.uint64(at + i)  # unsigned: no wrap-around for a negative index, which keeps a loop scalar
        points[0, j], points[1, j], points[2, j] = px, py, pz
        points[3, j], points[4, j], points[5, j] = nx, ny, nz


@njit(cache=True, inline="always")
def span_point_sums(consts, face, count, points, at):
    """The span's first ``count`` pixels' :func:`pixel_sums` into columns ``at`` … ``at + count
    − 1`` of ``points`` (8, W) float32 (rows sx, sy, sz, snx, sny, snz, w, sign), for
    :func:`finish_points` to finish over a whole run: a span of a pixel or two then pays no
    division and no root in scalar code."""
    for i in range(count):
        sx, sy, sz, snx, sny, snz, w, sign = pixel_sums(consts, i, face)
        j = np.uint64(at + i)
        points[0, j], points[1, j], points[2, j], points[3, j] = sx, sy, sz, snx
        points[4, j], points[5, j], points[6, j], points[7, j] = sny, snz, w, sign


@njit(cache=True, inline="always")
def finish_points(points, at, count, face):
    """Columns ``at`` … ``at + count − 1`` of ``points`` (8, W) float32, sums written by
    :func:`span_point_sums`, made points (:func:`finished_point`) in place: rows x, y, z of
    the view-space position, then nx, ny, nz of the unit normal (rows 6 and 7 left as they
    are). One loop over the run, which LLVM vectorises: the same bits as :func:`span_points`."""
    for i in range(count):
        j = np.uint64(at + i)
        px, py, pz, nx, ny, nz = finished_point((points[0, j], points[1, j], points[2, j], points[3, j], points[4, j],
                                                 points[5, j], points[6, j], points[7, j]), face)
        points[0, j], points[1, j], points[2, j] = px, py, pz
        points[3, j], points[4, j], points[5, j] = nx, ny, nz


@njit(cache=True, inline="always")
def span_texture_corners(k, frags):
    """Clipped triangle ``k``'s corners' texture coordinates, float32, from a textured frame's
    span table: ``(s0, t0, s1, t1, s2, t2)`` (flat: numba's parallel loops mistake the
    shapes of nested tuples unpacked)."""
    c = frags.span_corners
    return c[k, 22], c[k, 23], c[k, 24], c[k, 25], c[k, 26], c[k, 27]


@njit(cache=True, inline="always")
def span_tcoord(weights, corners, i):
    """Pixel ``i``'s texture coordinates ``(s, t)``, float32, interpolated as positions are
    (:func:`span_weights_at`; ``weights`` from :func:`span_setup`, ``corners`` from
    :func:`span_texture_corners`), as llvmpipe interpolates them, in float32."""
    w0, w1, w2 = span_weights_at(weights, i)
    inv = F1 / (w0 + w1 + w2)
    s0, t0, s1, t1, s2, t2 = corners
    return (w0 * s0 + w1 * s1 + w2 * s2) * inv, (w0 * t0 + w1 * t1 + w2 * t2) * inv


@njit(cache=True, inline="always")
def span_tcoords(consts, corners, count, st, at):
    """The span's first ``count`` pixels' texture coordinates (:func:`span_tcoord`) into columns
    ``at`` … ``at + count − 1`` of ``st`` (2, W) float32."""
    for i in range(count):
        s, t = span_tcoord(consts[0], corners, i)
        j = np.uint64(at + i)
        st[0, j], st[1, j] = s, t


@njit(cache=True, inline="always")
def span_textured_points(consts, corners, face, count, points, st, at):
    """:func:`span_points` and :func:`span_tcoords` in one loop (the same bits as each alone)."""
    for i in range(count):
        px, py, pz, nx, ny, nz = span_pixel(consts, i, face)
        s, t = span_tcoord(consts[0], corners, i)
        j = np.uint64(at + i)
        points[0, j], points[1, j], points[2, j] = px, py, pz
        points[3, j], points[4, j], points[5, j] = nx, ny, nz
        st[0, j], st[1, j] = s, t
