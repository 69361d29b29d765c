"""Translucent objects (opacity < 1): their fragments lit in runs and composited in draw order.

Opaque objects are drawn first, exactly as without translucency (z-buffer, visibility
buffer, :func:`renderer.shading.shade`). Then the triangles of translucent objects are
scan-converted with the same rules (:func:`renderer.raster.scanline_span`, the top-left
rule, the 24-bit integer depth of :func:`renderer.raster.pixel_depth`): every fragment
not behind the opaque surface there (LEQUAL against the opaque depth) counts, in draw
order. Translucent fragments write no depth (neither does VTK's).

Each fragment gets the linear colour an opaque fragment would get before its 8-bit store,
lit in runs of one triangle along a row (:mod:`renderer.fragment_spans`: VTK's model in
float32, as VTK's shaders compute), and alpha = its object's opacity; the fragments are
composited over the opaque result ``B`` (the 8-bit colour already in the frame). ``oit``
needs no order but draw order, so each fragment is added to the pixel's buffers as it is
drawn (:func:`shade_fragments`); the other modes sort, so their fragments are first
gathered into a **fragment list** per pixel (:func:`fragment_lists`: count, then fill at
prefix-sum offsets) and composited pixel by pixel (:func:`composite_lists`). Modes
(``[render] transparency``):

- ``oit``: weighted-average order-independent transparency (VTK's default),
  ``C = Σαᵢcᵢ / max(Σαᵢ, 0.01)``, ``A = 1 − Π(1−αᵢ)``, result ``A·C + (1−A)·B``.
  No sorting: exact for one layer, an approximation for more.
- ``depth_peeling``: the fragments front to back (by depth, ties in draw order), each
  peeled layer added under the ones in front: ``acc += T·αᵢcᵢ``, ``T ·= 1−αᵢ``, result
  ``acc + T·B`` (VTK's ``enable_depth_peeling``, peeled until nothing is left).
- ``sorted``: the same fragments back to front, each blended *over* what is behind it,
  the transmitted light ``Lt = Kt·Iq + (1−Kt)·Ip`` with ``Kt = 1−αᵢ``, ``Iq`` behind and
  ``Ip = cᵢ`` — the course's formula. Equal to depth peeling up to rounding.

Precision is part of the algorithm: the sums above are kept in the buffers a GPU
pipeline keeps them in, measured against VTK on Mesa (see :func:`weighted_average`,
:func:`front_to_back`, :func:`back_to_front`): half floats for the OIT accumulators,
8-bit layers for depth peeling, an 8-bit framebuffer for ``sorted``. Composited in
float64 and rounded once, the same formulas differ from VTK by 1–2 grey levels on a
tenth to a third of the translucent pixels.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from renderer.jit import njit, prange
from renderer.min_max import larger, smaller

from renderer.bands import first_row_of_band, one_band_at_a_time, raster_bands, shading_bands
from renderer.fragment_spans import batch_points, light_batch, lit_in_batches, span_linear_colours
from renderer.oit_buffers import (F32_ONE, OIT_VALUES, add_run_to_oit, clear_oit_strip, mul8, oit_add, oit_resolve,
                                  resolve_oit_row, resolve_scratch)
from renderer.edge_walk import edge_walk, split_at_middle, walk_on, walked_columns
from renderer.fill_rules import FILL_RULES, TOP_LEFT
from renderer.raster import DEPTH_CLEAR, WALK_ROWS, pixel_depth, row_depth, row_span, set_up
from renderer.reflection.materials import PIXEL_FACE_NORMAL
from renderer.shading import ShadingInputs, fragments, span_scratch, unorm8, with_span_table
from renderer.spans import LANES, whole_lanes
from renderer.workspace import empty

OIT, DEPTH_PEELING, SORTED = 0, 1, 2
MODES = {"oit": OIT, "depth_peeling": DEPTH_PEELING, "sorted": SORTED}


class FragmentLists(NamedTuple):
    """Every pixel's translucent fragments, in draw order, in flat compact arrays.

    count (H, W) fragments per pixel; start (H, W) where a pixel's list starts in the flat
    arrays (prefix sums of ``count``); tri (F,) int32 clipped triangle and z (F,) int32
    24-bit integer depth of each fragment; longest: the longest list (at least 1), for the
    compositing scratch; opaque_depth (H, W) the opaque integer z-buffer the lists were cut
    against (:data:`~renderer.raster.DEPTH_CLEAR` where no opaque surface is behind). The
    fragments' colours are a separate (F, 3) float32 array (:func:`shade_fragments`).
    """

    count: np.ndarray
    start: np.ndarray
    tri: np.ndarray
    z: np.ndarray
    longest: int
    opaque_depth: np.ndarray


@njit(cache=True, parallel=True)
def collect_fragments(setup, n_bands, rule, depth_test, opaque_depth, count, start, frag_tri, frag_z):
    """Scan-convert the translucent triangles of ``setup`` into per-pixel fragment lists
    (the loop kernel).

    First pass, with empty ``frag_*`` arrays: only ``count`` (H, W), the fragments of every
    pixel. Second pass: also write fragment ``j`` of pixel (row, col) at
    ``start[row, col] + j`` of ``frag_tri`` (clipped triangle) and ``frag_z`` (24-bit
    window depth). Bands of rows dealt like cards (:mod:`renderer.bands`), in parallel,
    each drawing every triangle in order (as :func:`renderer.raster.rasterize`), so each
    list is in draw order. A fragment is kept where ``z <= opaque_depth`` (or always,
    without ``depth_test``).
    """
    height, width = count.shape
    fill = frag_tri.shape[0] > 0
    for b in prange(n_bands):
        for row in range(b, height, n_bands):
            for col in range(width):
                count[row, col] = 0
        for k in range(setup.ccw.shape[0]):
            for row in range(first_row_of_band(setup.rows[k, 0], b, n_bands), setup.rows[k, 1] + 1, n_bands):
                first, last = row_span(k, row, setup.ccw, width, rule)
                z_row = row_depth(k, row, setup.plane)
                for col in range(first, last + 1):
                    z = pixel_depth(k, z_row, col, setup.plane)
                    if not depth_test or z <= opaque_depth[row, col]:  # without the test, the buffer unread
                        if fill:
                            i = start[row, col] + count[row, col]
                            frag_tri[i] = k
                            frag_z[i] = z
                        count[row, col] += 1


@njit(cache=True, inline="always")
def weighted_average(colours, alpha, m, behind, out):
    """``oit``: weighted-average order-independent transparency in VTK's buffers: the ``m``
    fragments in draw order through :func:`oit_add`, then :func:`oit_resolve` over ``behind``."""
    sum_r = sum_g = sum_b = weight = np.float32(0.0)
    transmit = F32_ONE
    for j in range(m):
        sum_r, sum_g, sum_b, weight, transmit = oit_add(sum_r, sum_g, sum_b, weight, transmit,
                                                        np.float32(colours[j, 0]), np.float32(colours[j, 1]),
                                                        np.float32(colours[j, 2]), np.float32(alpha[j]))
    oit_resolve(sum_r, sum_g, sum_b, weight, transmit, behind, out)


@njit(cache=True, inline="always")
def front_to_back(colours, alpha, order, m, behind, opaque_behind, front, back, out):
    """``depth_peeling``: exact front-to-back compositing in VTK's dual depth peeling buffers.

    Each peel takes the nearest remaining fragment *and* the farthest one. The nearest is
    added under the 8-bit front layer (``F += T·α·c``, ``T`` its transmittance, stored
    as 8 bits after each peel); the farthest, premultiplied and rounded to 8 bits, is
    blended over the 8-bit back layer (``B = αc + (1 − α)·B``). At the end the back layer
    goes under the front one, and the sum over ``behind``: ``F + T·B`` then
    ``+ (1 − A)·behind``.

    With an opaque surface behind (``opaque_behind``) the first peel's far end is that
    surface's depth (the peeler starts from the opaque depth buffer), so it takes no
    translucent fragment: the first peel is front only.
    """
    front[:] = 0  # rgb, and 1 − T, as 8-bit unorm
    back[:] = 0   # premultiplied rgb, and alpha
    near, far = 0, m - 1
    first = True
    while near <= far:
        f = order[near]
        a = np.float32(alpha[f])
        t = F32_ONE - np.float32(front[3] / 255.0)
        for c in range(3):
            front[c] = unorm8(t * a * np.float32(colours[f, c]) + np.float32(front[c] / 255.0))
        front[3] = unorm8(F32_ONE - t * (F32_ONE - a))
        if far > near and not (first and opaque_behind):
            b = order[far]
            a = np.float32(alpha[b])
            a8 = unorm8(a)
            if a8 > 0:
                for c in range(3):
                    back[c] = smaller(unorm8(np.float32(colours[b, c]) * a) + mul8(back[c], 255 - a8), 255)
                back[3] = smaller(a8 + mul8(back[3], 255 - a8), 255)
            far -= 1
        near += 1
        first = False
    t = F32_ONE - np.float32(front[3] / 255.0)
    a8 = unorm8(F32_ONE - t * (F32_ONE - np.float32(back[3] / 255.0)))
    for c in range(3):
        s8 = unorm8(np.float32(front[c] / 255.0) + np.float32(back[c] / 255.0) * t)
        out[c] = smaller(s8 + mul8(behind[c], 255 - a8), 255)


@njit(cache=True, inline="always")
def back_to_front(colours, alpha, order, m, behind, lt, out):
    """``sorted``: the fragments back to front, each blended *over* the colour behind it:
    ``Lt = Kt·Iq + (1 − Kt)·Ip`` with ``Kt = 1 − α``, ``Iq`` the light from behind and
    ``Ip`` the fragment's own (its lit colour, not clamped: a highlight brighter than 1
    still shows through a layer in front). Exact arithmetic in ``lt`` (3,), rounded to 8
    bits once."""
    for c in range(3):
        lt[c] = behind[c] / 255.0
    for j in range(m - 1, -1, -1):
        f = order[j]
        kt = 1.0 - alpha[f]
        for c in range(3):
            lt[c] = kt * lt[c] + (1.0 - kt) * colours[f, c]
    for c in range(3):
        out[c] = unorm8(lt[c])


@njit(cache=True, inline="always")
def depth_order(z, m, order):
    """``order[:m]``: fragment indices nearest first (insertion sort; stable, so equal depths
    stay in draw order)."""
    for j in range(m):
        order[j] = j
        i = j
        while i > 0 and z[order[i - 1]] > z[order[i]]:
            order[i - 1], order[i] = order[i], order[i - 1]
            i -= 1


RED, GREEN, BLUE, ALPHA, DEPTH = range(5)
"""The columns of a pixel's fragment list as :func:`composite_pixel` reads it: linear RGB
0..1, alpha (the object's opacity) and window depth."""


@njit(cache=True, inline="always")
def composite_pixel(mode, fragments, m, behind, opaque_behind, out, order, acc, layers):
    """Composite the ``m`` fragments of one pixel (``fragments`` (M, 5): r, g, b, alpha and
    window depth, in draw order) over the 8-bit colour ``behind`` (of an opaque surface if
    ``opaque_behind``, else the background) into the 8-bit ``out``, by ``mode``
    (:data:`OIT`, :data:`DEPTH_PEELING` or :data:`SORTED`).
    Scratch: ``order`` (M,) int, ``acc`` (3,) float, ``layers`` (2, 4) int (front, back)."""
    colours, alpha = fragments[:, RED:ALPHA], fragments[:, ALPHA]
    if mode == OIT:
        weighted_average(colours, alpha, m, behind, out)
        return
    depth_order(fragments[:, DEPTH], m, order)
    if mode == DEPTH_PEELING:
        front_to_back(colours, alpha, order, m, behind, opaque_behind, layers[0], layers[1], out)
    else:
        back_to_front(colours, alpha, order, m, behind, acc, out)


STRIP_ROWS = 16
"""Rows of a strip, the unit of work of :func:`shade_fragments`: every triangle is drawn over
one strip before the next, so the strip's buffers stay in the cache while its layers
arrive (measured: dealing single rows, each pixel's buffers came back from memory for
each of its layers)."""


@njit(cache=True, inline="always")
def batch_scratch(width):
    """Scratch for a triangle's runs on one strip of an image ``width`` pixels wide (at most one
    fragment a pixel): their points (6, N) and linear colours (3, N) float32
    (:func:`renderer.fragment_spans.batch_points`), and each run's (row, first column,
    pixels) (N, 3) int64, N = :data:`STRIP_ROWS` · (2 · width + :data:`~renderer.spans.LANES`).
    Each run's points are padded to whole vector lanes (:func:`renderer.spans.whole_lanes`:
    a run of c ≥ 4 pixels takes at most c + 7 points), and runs on a row are parted by at
    least one pixel behind the opaque surface, so a row takes at most 8 points for every 5
    of its pixels (runs of 4 between gaps of 1), plus 4 for a run at its end."""
    n = STRIP_ROWS * (2 * larger(width, 1) + LANES)
    return np.empty((6, n), np.float32), np.empty((3, n), np.float32), np.empty((n, 3), np.int64)


@njit(cache=True, inline="always")
def emit_run(colour, first, a, row, c0, count, seen_row, start, colours, buffers):
    """A lit run's fragments (pixels ``c0 … c0 + count − 1`` of ``row``, linear colours from
    column ``first`` of ``colour`` (3, N) float32, alpha ``a``) to where
    :func:`shade_fragments` sends them, counted in ``seen_row`` (W,) int32, the row's counts:
    with ``colours`` (F, 3) not empty, each pixel's next place in its fragment list
    (``start``, and the count so far); else the row's ``oit`` buffers ``buffers`` (W, 5)
    (:func:`add_run_to_oit`)."""
    if colours.shape[0] > 0:
        for i in range(count):
            j = start[row, c0 + i] + seen_row[c0 + i]
            colours[j, 0], colours[j, 1], colours[j, 2] = colour[0, first + i], colour[1, first + i], colour[2, first + i]
            seen_row[c0 + i] += 1
    else:
        add_run_to_oit(colour, first, a, c0, count, seen_row, buffers)


@njit(cache=True, inline="always")
def cover_row(seen_row, covered_row):
    """A resolved row's coverage: ``covered_row`` (W,) bool True where ``seen_row`` (W,) int32
    counted a fragment; the counts then cleared for the strip's next row there."""
    for col in range(seen_row.shape[0]):
        covered_row[col] = seen_row[col] > 0
        seen_row[col] = 0


@njit(cache=True, inline="always")
def widen(touched, r, c0, count):
    """Row ``r`` of a strip's ``touched`` (rows, 2) columns, first and last, widened to take
    in a run of ``count`` pixels from column ``c0``."""
    touched[r, 0] = smaller(touched[r, 0], c0)
    touched[r, 1] = larger(touched[r, 1], c0 + count - 1)


@njit(cache=True, inline="always")
def nearest_in_row(opaque_depth, row):
    """The least (nearest) opaque depth on ``row`` of ``opaque_depth`` (H, W) int32:
    :data:`~renderer.raster.DEPTH_CLEAR` on a row with no opaque surface."""
    nearest = DEPTH_CLEAR
    for col in range(opaque_depth.shape[1]):
        nearest = smaller(nearest, opaque_depth[row, col])
    return nearest


@njit(cache=True, inline="always")
def span_in_front(k, z_row, first, last, plane, nearest):
    """True when every fragment of triangle ``k``'s span ``first … last`` on a row passes the
    depth test against that row's opaque surface, whose nearest depth is ``nearest``
    (:func:`nearest_in_row`): the span's depth is linear along the row, so its largest is
    at one end (:func:`~renderer.raster.pixel_depth`, monotonic), and LEQUAL against the
    row's nearest opaque depth passes at every pixel if it passes there. The span is then
    one run, found with two depths instead of one a pixel (a translucent object in front
    of everything opaque, or with nothing opaque on the row: every span)."""
    if first > last:
        return True
    far = larger(pixel_depth(k, z_row, first, plane), pixel_depth(k, z_row, last, plane))
    return far <= nearest


class RunRules(NamedTuple):
    """How :func:`shade_fragments` draws: strips of :data:`STRIP_ROWS` rows dealt to
    ``n_bands`` bands, the fill ``rule`` (a :data:`renderer.raster.FILL_RULES` code),
    ``depth_test`` against the opaque z-buffer, ``spans`` (False: runs of one pixel)."""

    n_bands: int
    rule: int
    depth_test: bool
    spans: bool


class RunTargets(NamedTuple):
    """What :func:`shade_fragments` reads and writes (window rows): ``opaque_depth`` (H, W)
    the opaque z-buffer; ``seen`` int32 each pixel's fragments so far, (H, W) with lists to
    fill, else (bands · :data:`STRIP_ROWS`, W), the rows of each band's strip (counts that
    stay in the cache, cleared as each row is resolved); ``start`` (H, W) int64 and
    ``colours`` (F, 3) float32 the fragment lists to fill (``colours`` empty: none); ``sums``
    (bands, :data:`STRIP_ROWS`, W, 5) float32 the ``oit`` buffers of each band's strip
    (:mod:`renderer.oit_buffers`; W is 0 with lists to fill); ``rgb`` (H, W, 3) uint8;
    ``covered`` (H, W) bool, for ``oit``, which pixels got a fragment (written as each row is
    resolved; (0, 0) with lists to fill)."""

    opaque_depth: np.ndarray
    seen: np.ndarray
    start: np.ndarray
    colours: np.ndarray
    sums: np.ndarray
    rgb: np.ndarray
    covered: np.ndarray


@njit(cache=True, parallel=True)
def shade_fragments(setup, frags, geo, materials, textures, lights, lit, how, into):
    """Scan-convert the translucent triangles and light their fragments in runs (the loop kernel).

    The same fragments as :func:`collect_fragments`, in the same order: bands of rows in
    parallel, each drawing every triangle in order. Along a triangle's span on a row, each
    run of neighbouring fragments in front of the opaque surface is lit in one go
    (:func:`renderer.fragment_spans.span_linear_colours`; ``how`` a :class:`RunRules`;
    ``into`` a :class:`RunTargets`); for an object that
    :func:`renderer.fragment_spans.lit_in_batches`, all the triangle's runs on the strip's
    rows are interpolated first and lit in one loop, then sent on run by run (:func:`emit_run`). ``seen`` counts each pixel's fragments so far. Then:

    - with ``colours`` (F, 3) float32 not empty: fragment ``j`` of pixel (row, col) gets
      its colour at ``start[row, col] + j`` (the lists of :func:`fragment_lists`);
    - else (``oit``): each fragment is added straight to the pixel's ``oit`` buffers
      ``sums`` (one strip a band, :mod:`renderer.oit_buffers`; :func:`oit_add`, in draw
      order as the lists would give it), and when a band has drawn every triangle over a
      strip, its rows are composited over ``rgb`` (:func:`oit_resolve`) and their coverage
      written into ``covered`` (:func:`cover_row`) — no lists, no second pass.
    """
    opaque_depth, seen, start = into.opaque_depth, into.seen, into.start
    colours, sums, rgb, covered = into.colours, into.sums, into.rgb, into.covered
    n_bands, rule, depth_test, spans = how.n_bands, how.rule, how.depth_test, how.spans
    height, width = opaque_depth.shape
    fill = colours.shape[0] > 0
    n_strips = (height + STRIP_ROWS - 1) // STRIP_ROWS
    for b in prange(n_bands):
        inputs = (materials, textures, lights, lit)  # made inside the parallel loop: numba passes no tuple into it
        scratch = span_scratch(width)  # a run's points, linear colours and texture coordinates
        colour = scratch[1]
        run_points, run_colours, runs = batch_scratch(width)  # a triangle's runs on a strip
        resolving = resolve_scratch(width)  # a row's oit values and colours (resolve_oit_row)
        nearest = np.empty(STRIP_ROWS, np.int32)  # the nearest opaque depth of each of the strip's rows
        touched = np.empty((STRIP_ROWS, 2), np.int64)  # the first and last column each row's runs touched
        counted = b * STRIP_ROWS  # without lists, the first of the band's rows of ``seen``
        if not fill:
            clear_oit_strip(sums[b])  # then each row clears what it touched when it is resolved
            seen[counted:counted + STRIP_ROWS] = 0  # and its counts, all of them
        for strip in range(b, n_strips, n_bands):
            lo, hi = strip * STRIP_ROWS, smaller(strip * STRIP_ROWS + STRIP_ROWS, height) - 1
            if fill:
                counted = lo  # with lists, ``seen`` has every row of the image
                for row in range(lo, hi + 1):
                    for col in range(width):
                        seen[row, col] = 0
            for row in range(lo, hi + 1):
                nearest[row - lo] = nearest_in_row(opaque_depth, row) if depth_test else DEPTH_CLEAR
            touched[:, 0], touched[:, 1] = width, -1
            for k in range(setup.ccw.shape[0]):
                if setup.rows[k, 0] > hi or setup.rows[k, 1] < lo:  # not on this strip
                    continue
                o = geo.tri_object[frags.clip_source[k]]
                a = np.float32(materials.opacity[o])
                batched = spans and lit_in_batches(o, materials, textures, lights)
                face = materials.shading_path[o] == PIXEL_FACE_NORMAL
                n_runs = n_points = 0
                r0, r1 = larger(setup.rows[k, 0], lo), smaller(setup.rows[k, 1], hi)
                walking = r1 - r0 >= WALK_ROWS - 1  # the edges walked (no division a row), as the raster's fill_rows
                f, top_left = setup.ccw[k], rule == TOP_LEFT
                long_walk = short_walk = (0, 0, 0, 1, 0, 0)
                split, high_edge = r1 + 1, 0
                if walking:
                    long_edge, low_edge, high_edge, split, r0, r1 = split_at_middle(f, r0, r1, top_left)
                    long_walk = edge_walk(f, long_edge, r0, 1, top_left)
                    short_walk = edge_walk(f, low_edge if r0 < split else high_edge, r0, 1, top_left)
                for row in range(r0, r1 + 1):
                    if not walking:
                        first, last = row_span(k, row, setup.ccw, width, rule)
                    else:
                        if row == split and row > r0:  # the middle corner passed: the high edge from here
                            short_walk = edge_walk(f, high_edge, row, 1, top_left)
                        first, last = walked_columns(long_walk, short_walk, top_left, width)
                        long_walk, short_walk = walk_on(long_walk), walk_on(short_walk)
                    z_row = row_depth(k, row, setup.plane)
                    whole = spans and (not depth_test or span_in_front(k, z_row, first, last, setup.plane,
                                                                       nearest[row - lo]))
                    col = first
                    while col <= last:
                        c0 = col
                        if whole:  # one run, no test a pixel
                            col = last + 1
                        while col <= last and (not depth_test
                                               or pixel_depth(k, z_row, col, setup.plane) <= opaque_depth[row, col]):
                            col += 1
                            if not spans:
                                break
                        if col == c0:  # behind the opaque surface
                            col += 1
                            continue
                        if batched:  # lit with the triangle's other runs on this strip, below
                            lanes = whole_lanes(col - c0)  # no scalar tail in the loops over the batch
                            batch_points(k, row, c0, lanes, frags, geo, face, run_points, n_points)
                            runs[n_runs, 0], runs[n_runs, 1], runs[n_runs, 2] = row, c0, col - c0
                            n_runs, n_points = n_runs + 1, n_points + lanes
                            continue
                        span_linear_colours(k, row, c0, col - c0, frags, geo, inputs, scratch)
                        emit_run(colour, 0, a, row, c0, col - c0, seen[counted + row - lo], start, colours,
                                 sums[b, row - lo])
                        widen(touched, row - lo, c0, col - c0)
                if n_runs:
                    light_batch(o, materials, lights, run_points, n_points, run_colours)
                    first = 0
                    for r in range(n_runs):
                        row, c0, count = runs[r, 0], runs[r, 1], runs[r, 2]
                        emit_run(run_colours, first, a, row, c0, count, seen[counted + row - lo], start, colours,
                                 sums[b, row - lo])
                        widen(touched, row - lo, c0, count)
                        first += whole_lanes(count)
            if not fill:
                for row in range(lo, hi + 1):
                    resolve_oit_row(sums[b, row - lo], rgb[row], resolving, touched[row - lo, 0], touched[row - lo, 1])
                    cover_row(seen[counted + row - lo], covered[row])


@njit(cache=True, parallel=True)
def composite_lists(lists, colours, alphas, mode, n_bands, rgb):
    """Composite every pixel's fragment list over ``rgb`` (the loop kernel): ``colours``
    (F, 3) float32 the fragments' linear colours, ``alphas`` (K,) each clipped triangle's
    opacity; ``rgb`` (H, W, 3) uint8 holds the opaque result and receives the composite
    (:func:`composite_pixel`, by ``mode``). Rows are independent, dealt out to ``n_bands``
    bands (:mod:`renderer.bands`).
    """
    height, width = lists.count.shape
    for band in prange(n_bands):
        fragments = np.empty((lists.longest, 5))
        behind = np.empty(3, np.int64)
        out = np.empty(3, np.int64)
        order = np.empty(lists.longest, np.int64)
        acc = np.empty(3)
        layers = np.empty((2, 4), np.int64)
        for row in range(band, height, n_bands):
            for col in range(width):
                m = lists.count[row, col]
                if m == 0:
                    continue
                for j in range(m):
                    i = lists.start[row, col] + j
                    fragments[j, RED], fragments[j, GREEN], fragments[j, BLUE] = colours[i, 0], colours[i, 1], colours[i, 2]
                    fragments[j, ALPHA] = alphas[lists.tri[i]]
                    fragments[j, DEPTH] = lists.z[i]
                for c in range(3):
                    behind[c] = rgb[row, col, c]
                composite_pixel(mode, fragments, m, behind, lists.opaque_depth[row, col] < DEPTH_CLEAR, out, order, acc,
                                layers)
                for c in range(3):
                    rgb[row, col, c] = out[c]


def collect_lists(setup, opaque_depth, rule, depth_test, n_bands, ws=None) -> FragmentLists:
    """The :class:`FragmentLists` of set-up triangles ``setup`` over the opaque z-buffer
    ``opaque_depth`` (H, W): :func:`collect_fragments` twice, counts then fragments at their
    prefix-sum offsets."""
    height, width = opaque_depth.shape
    count = empty(ws, "translucency.count", (height, width), np.int32)
    start = empty(ws, "translucency.start", (height, width), np.int64)
    with one_band_at_a_time():
        collect_fragments(setup, n_bands, rule, bool(depth_test), opaque_depth, count, start, np.empty(0, np.int32),
                          np.empty(0, np.int32))
    flat = start.reshape(-1)
    flat[0] = 0
    np.cumsum(count.reshape(-1)[:-1], out=flat[1:])
    total = int(flat[-1] + count[-1, -1])
    lists = FragmentLists(count, start, empty(ws, "translucency.frag_tri", total, np.int32),
                          empty(ws, "translucency.frag_z", total, np.int32), max(int(count.max()), 1), opaque_depth)
    if total:
        with one_band_at_a_time():
            collect_fragments(setup, n_bands, rule, bool(depth_test), opaque_depth, count, start, lists.tri, lists.z)
    return lists


def fragment_lists(tri_fixed, tri_window, opaque_depth, fill_rule="top-left", depth_test=True, cull_back=False,
                   n_bands=None, ws=None):
    """Rasterise translucent triangles into fragment lists (the Python wrapper), over an
    opaque frame whose z-buffer is ``opaque_depth`` (H, W).

    Returns the triangles' :class:`~renderer.raster.TriangleSetup` and the
    :class:`FragmentLists` (see :func:`collect_fragments`).
    """
    tri_fixed = np.ascontiguousarray(tri_fixed, dtype=np.int64).reshape(-1, 3, 2)
    tri_window = np.ascontiguousarray(tri_window, dtype=np.float64).reshape(-1, 3, 3)
    height = opaque_depth.shape[0]
    setup = set_up(tri_fixed, tri_window, height, cull_back, ws, "translucency")
    return setup, collect_lists(setup, opaque_depth, FILL_RULES[fill_rule], depth_test, raster_bands(height, n_bands),
                                ws)


def reads_opaque_depth(mode: str, spans: bool) -> bool:
    """Whether :func:`draw_translucent` reads ``opaque_depth`` even without a depth test: the
    fragment lists' compositing does (whether an opaque surface lies behind a pixel,
    :func:`composite_pixel`); ``oit`` summed as the fragments are drawn (``spans``) does not."""
    return not (MODES[mode] == OIT and spans)


def draw_translucent(clipped, opaque_depth, rgb, geo, inputs: ShadingInputs, mode="oit", perspective=True,
                     rules=None, ws=None, spans=True):
    """Draw the translucent clipped triangles over the opaque frame ``rgb`` (window rows, in place).

    ``clipped`` : :class:`renderer.pipeline.ClippedTriangles` of the translucent triangles.
    ``inputs`` : :class:`renderer.shading.ShadingInputs`. ``mode`` : a key of :data:`MODES`.
    ``perspective`` : perspective-correct interpolation. ``rules`` : a
    :class:`renderer.pipeline.RasterRules` (fill rule, depth test, back-face culling; the
    defaults when None). ``spans`` : light fragments in runs and, for ``oit``, sum them as
    they are drawn (the fast path); False: fragment lists for every mode, lit one pixel at
    a time (the plain path the tests compare with: the same bytes). Returns the (H, W)
    bool mask of pixels that got at least one translucent fragment. Without a depth test,
    the ``oit`` fast path reads only ``opaque_depth``'s shape (:func:`reads_opaque_depth`).
    """
    fill_rule, depth_test, cull_back = rules if rules is not None else ("top-left", True, False)
    height, width = opaque_depth.shape
    rule, n_bands = FILL_RULES[fill_rule], raster_bands(height)
    tri_fixed = np.ascontiguousarray(clipped.tri_fixed, dtype=np.int64).reshape(-1, 3, 2)
    tri_window = np.ascontiguousarray(clipped.tri_window, dtype=np.float64).reshape(-1, 3, 3)
    setup = set_up(tri_fixed, tri_window, height, cull_back, ws, "translucency")
    corners = [np.ascontiguousarray(t) for t in (clipped.tri_clip, clipped.clip_bary, clipped.clip_source)]
    frags = with_span_table(fragments(np.empty((0, 0), np.int32), setup.plane, setup.front, *corners, perspective),
                            geo, ws, "translucency", textured=bool(inputs.textures.textured.any()))
    strip_bands = raster_bands((height + STRIP_ROWS - 1) // STRIP_ROWS)
    shading = (setup, frags, geo, inputs.materials, inputs.textures, inputs.lights, inputs.lit,
               RunRules(strip_bands, rule, bool(depth_test), bool(spans)))
    if not reads_opaque_depth(mode, spans):  # oit, summed as the fragments are drawn
        covered = np.empty((height, width), np.bool_)  # every row written as it is resolved
        with one_band_at_a_time():
            shade_fragments(*shading, RunTargets(opaque_depth,
                                                 empty(ws, "translucency.strip_seen", (strip_bands * STRIP_ROWS, width),
                                                       np.int32),
                                                 np.empty((1, 1), np.int64), np.empty((0, 3), np.float32),
                                                 empty(ws, "translucency.sums", (strip_bands, STRIP_ROWS, width, OIT_VALUES),
                                                       np.float32), rgb, covered))
        return covered
    lists = collect_lists(setup, opaque_depth, rule, depth_test, n_bands, ws)
    colours = empty(ws, "translucency.colours", (len(lists.tri), 3), np.float32)
    with one_band_at_a_time():
        if len(colours):
            shade_fragments(*shading, RunTargets(opaque_depth, empty(ws, "translucency.seen", (height, width), np.int32),
                                                 lists.start, colours,
                                                 np.empty((strip_bands, STRIP_ROWS, 0, OIT_VALUES), np.float32),
                                                 rgb, np.empty((0, 0), np.bool_)))
        alphas = inputs.materials.opacity[geo.tri_object[frags.clip_source]]
        composite_lists(lists, colours, alphas, MODES[mode], shading_bands(height), rgb)
    return lists.count > 0
