"""Translucent objects (opacity < 1): a fragment list per pixel, shaded and composited.

Opaque objects are drawn first, exactly as without translucency (z-buffer, visibility
buffer, :func:`renderer.shading.shade`). Then the triangles of translucent objects are
scan-converted with the same rules (:func:`renderer.raster.scanline_span`, the top-left
rule, the 24-bit integer depth of :func:`renderer.raster.pixel_fragment`) into a **fragment list**
per pixel: every fragment not behind the opaque surface there (LEQUAL against the opaque
depth), in draw order. Translucent fragments write no depth (neither does VTK's). Two
passes: count the fragments of every pixel, then fill them in at prefix-sum offsets.

Each fragment gets :func:`renderer.shading.fragment_colour` (the same colour an opaque
fragment would get) and alpha = its object's opacity; the list is then composited over
the opaque result ``B`` (the 8-bit colour already in the frame). Modes
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

from renderer.bands import first_row_of_band, raster_bands, shading_bands
from renderer.raster import DEPTH_CLEAR, FILL_RULES, pixel_fragment, row_span, set_up
from renderer.shading import Fragments, ShadingInputs, fragment_colour, unorm8
from renderer.workspace import empty

OIT, DEPTH_PEELING, SORTED = 0, 1, 2
MODES = {"oit": OIT, "depth_peeling": DEPTH_PEELING, "sorted": SORTED}


class FragmentLists(NamedTuple):
    """Every pixel's translucent fragments, in draw order, in flat arrays.

    count (H, W) fragments per pixel; start (H, W) where a pixel's list starts in the flat
    arrays (prefix sums of ``count``); tri (F,) clipped triangle, bary (F, 2) screen-space
    weights of its vertices 1 and 2, z (F,) int32 24-bit integer depth of each fragment;
    longest: the longest list (at least 1), for the compositing scratch; opaque_depth (H, W)
    the opaque integer z-buffer the lists were cut against (:data:`~renderer.raster.DEPTH_CLEAR` where no
    opaque surface is behind).
    """

    count: np.ndarray
    start: np.ndarray
    tri: np.ndarray
    bary: np.ndarray
    z: np.ndarray
    longest: int
    opaque_depth: np.ndarray


@njit(cache=True, parallel=True)
def collect_fragments(setup, n_bands, rule, depth_test, opaque_depth, count, start, frag_tri, frag_bary, frag_z):
    """Scan-convert the translucent triangles of ``setup`` into per-pixel fragment lists
    (the loop kernel).

    First pass, with empty ``frag_*`` arrays: only ``count`` (H, W), the fragments of every
    pixel. Second pass: also write fragment ``j`` of pixel (row, col) at
    ``start[row, col] + j`` of ``frag_tri`` (clipped triangle), ``frag_bary`` (screen-space
    weights of vertices 1 and 2) and ``frag_z`` (24-bit window depth). Bands of rows dealt
    like cards (:mod:`renderer.bands`), in parallel, each drawing every triangle in order
    (as :func:`renderer.raster.rasterize`), so each list is in draw order. A fragment is
    kept where ``z <= opaque_depth`` (or always, without ``depth_test``).
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
                for col in range(first, last + 1):
                    l1, l2, z = pixel_fragment(k, row, col, setup.plane)
                    if z <= opaque_depth[row, col] or not depth_test:
                        if fill:
                            i = start[row, col] + count[row, col]
                            frag_tri[i] = k
                            frag_bary[i, 0] = l1
                            frag_bary[i, 1] = l2
                            frag_z[i] = z
                        count[row, col] += 1


F32_ONE = np.float32(1.0)


HALF_MIN_NORMAL = 2.0 ** -14
HALF_SUBNORMAL_STEP = 2.0 ** 24  # 1 / the fixed step below HALF_MIN_NORMAL
SIGN_BIT = np.int64(-(1 << 31))  # float32's sign bit, as the int32 pattern sees it (sign-extended)


@njit(cache=True, inline="always")
def half(x):
    """``x`` (a float32 value) rounded to the nearest IEEE half float, ties to even, as a
    float32 — what a 16-bit float render target stores. Normal halves keep 11 of float32's
    24 significant bits: the low 13 bits of its pattern are rounded off, ties to even.
    Below 2⁻¹⁴ the step is a fixed 2⁻²⁴ (subnormals). No overflow handling: values here
    stay ≤ 1e3."""
    f = np.float32(x)
    if abs(f) < HALF_MIN_NORMAL:
        return np.float32(np.rint(f * HALF_SUBNORMAL_STEP) / HALF_SUBNORMAL_STEP)
    bits = np.int64(f.view(np.int32))
    sign = bits & SIGN_BIT
    magnitude = bits & ~SIGN_BIT
    magnitude = (magnitude + 0x0FFF + ((magnitude >> 13) & 1)) & ~0x1FFF
    return np.int32(sign | magnitude).view(np.float32)


@njit(cache=True, inline="always")
def mul8(a, b):
    """Two 8-bit unorm values multiplied, as an 8-bit blend unit does: round(a·b/255)."""
    t = np.int64(a) * np.int64(b) + 128
    return (t + (t >> 8)) >> 8


@njit(cache=True, inline="always")
def blend8(src, src_factor, dst, dst_factor):
    """One channel of 8-bit blending: ``src·src_factor + dst·dst_factor`` (all unorm8), saturated."""
    return min(mul8(src, src_factor) + mul8(dst, dst_factor), 255)


@njit(cache=True, inline="always")
def weighted_average(colours, alpha, m, behind, acc, out):
    """``oit``: weighted-average order-independent transparency in VTK's buffers.

    Each fragment (draw order) adds ``α·c`` to a half-float RGB accumulator and ``α`` to a
    half-float weight, and multiplies a half-float transmittance ``T`` by ``1 − α``
    (rounded to half after every step, as the 16-bit float targets store them). The
    result ``C = Σαc / max(Σα, 0.01)`` with coverage ``A = 1 − T`` is converted to 8 bits
    and blended over ``behind``: ``C·A + behind·(1 − A)`` in 8-bit arithmetic.
    """
    acc[:] = 0.0
    weight = np.float32(0.0)
    transmit = F32_ONE
    for j in range(m):
        a = np.float32(alpha[j])
        for c in range(3):
            acc[c] = half(np.float32(acc[c]) + np.float32(colours[j, c]) * a)
        weight = half(weight + a)
        transmit = half((F32_ONE - a) * transmit)
    a8 = unorm8(F32_ONE - transmit)
    for c in range(3):
        out[c] = blend8(unorm8(np.float32(acc[c]) / max(weight, np.float32(0.01))), a8, behind[c], 255 - a8)


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
                    back[c] = min(unorm8(np.float32(colours[b, c]) * a) + mul8(back[c], 255 - a8), 255)
                back[3] = min(a8 + mul8(back[3], 255 - a8), 255)
            far -= 1
        near += 1
        first = False
    t = F32_ONE - np.float32(front[3] / 255.0)
    a8 = unorm8(F32_ONE - t * (F32_ONE - np.float32(back[3] / 255.0)))
    for c in range(3):
        s8 = unorm8(np.float32(front[c] / 255.0) + np.float32(back[c] / 255.0) * t)
        out[c] = min(s8 + mul8(behind[c], 255 - a8), 255)


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
        weighted_average(colours, alpha, m, behind, acc, out)
        return
    depth_order(fragments[:, DEPTH], m, order)
    if mode == DEPTH_PEELING:
        front_to_back(colours, alpha, order, m, behind, opaque_behind, layers[0], layers[1], out)
    else:
        back_to_front(colours, alpha, order, m, behind, acc, out)


@njit(cache=True, parallel=True)
def shade_translucent(frags, lists, mode, geo, materials, textures, lights, lit, n_bands, rgb):
    """Colour every pixel's fragment list and composite it over ``rgb`` (the loop kernel).

    ``frags`` holds the translucent clipped triangles' tables (its tri_index and plane are
    not read); ``lists`` the :class:`FragmentLists`; alpha is each object's
    ``materials.opacity``; ``rgb`` (H, W, 3) uint8 holds the opaque result and receives the composite. Rows are
    independent, dealt out to ``n_bands`` bands (:mod:`renderer.bands`).
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
                    k = lists.tri[i]
                    r, g, b = fragment_colour(k, lists.bary[i, 0], lists.bary[i, 1], frags, geo, materials, textures,
                                              lights, lit)
                    fragments[j, RED], fragments[j, GREEN], fragments[j, BLUE] = r, g, b
                    fragments[j, ALPHA] = materials.opacity[geo.tri_object[frags.clip_source[k]]]
                    fragments[j, DEPTH] = lists.z[i]
                for c in range(3):
                    behind[c] = rgb[row, col, c]
                composite_pixel(mode, fragments, m, behind, lists.opaque_depth[row, col] < DEPTH_CLEAR, out, order, acc,
                                layers)
                for c in range(3):
                    rgb[row, col, c] = out[c]


def fragment_lists(tri_fixed, tri_window, opaque_depth, fill_rule="top-left", depth_test=True, cull_back=False,
                   n_bands=None, ws=None):
    """Rasterise translucent triangles into fragment lists (the Python wrapper), over an
    opaque frame whose z-buffer is ``opaque_depth`` (H, W).

    Returns ``front`` (K,) and the :class:`FragmentLists` (see :func:`collect_fragments`).
    """
    height, width = opaque_depth.shape
    tri_fixed = np.ascontiguousarray(tri_fixed, dtype=np.int64).reshape(-1, 3, 2)
    tri_window = np.ascontiguousarray(tri_window, dtype=np.float64).reshape(-1, 3, 3)
    n_bands = raster_bands(height, n_bands)
    setup = set_up(tri_fixed, tri_window, height, cull_back, ws, "translucency")
    rule = FILL_RULES[fill_rule]
    count = empty(ws, "translucency.count", (height, width), np.int64)
    start = empty(ws, "translucency.start", (height, width), np.int64)
    collect_fragments(setup, n_bands, rule, bool(depth_test), opaque_depth, count, start, np.empty(0, np.int64),
                      np.empty((0, 2)), np.empty(0, np.int32))
    flat = start.reshape(-1)
    flat[0] = 0
    np.cumsum(count.reshape(-1)[:-1], out=flat[1:])
    total = int(flat[-1] + count[-1, -1])
    lists = FragmentLists(count, start, empty(ws, "translucency.frag_tri", total, np.int64),
                          empty(ws, "translucency.frag_bary", (total, 2)), empty(ws, "translucency.frag_z", total, np.int32),
                          max(int(count.max()), 1), opaque_depth)
    if total:
        collect_fragments(setup, n_bands, rule, bool(depth_test), opaque_depth, *lists[:5])
    return setup.front, lists


def draw_translucent(clipped, opaque_depth, rgb, geo, inputs: ShadingInputs, mode="oit", perspective=True,
                     rules=None, ws=None):
    """Draw the translucent clipped triangles over the opaque frame ``rgb`` (window rows, in place).

    ``clipped`` : :class:`renderer.pipeline.ClippedTriangles` of the translucent triangles.
    ``inputs`` : :class:`renderer.shading.ShadingInputs`. ``mode`` : a key of :data:`MODES`.
    ``perspective`` : perspective-correct interpolation. ``rules`` : a
    :class:`renderer.pipeline.RasterRules` (fill rule, depth test, back-face culling; the
    defaults when None). Returns the (H, W) bool mask of pixels that got at least one
    translucent fragment.
    """
    fill_rule, depth_test, cull_back = rules if rules is not None else ("top-left", True, False)
    front, lists = fragment_lists(clipped.tri_fixed, clipped.tri_window, opaque_depth, fill_rule, depth_test,
                                  cull_back, ws=ws)
    frags = Fragments(np.empty((0, 0), np.int32), np.empty((0, 11)), front, np.ascontiguousarray(clipped.tri_clip),
                      np.ascontiguousarray(clipped.clip_bary), np.ascontiguousarray(clipped.clip_source),
                      bool(perspective))
    shade_translucent(frags, lists, MODES[mode], geo, inputs.materials, inputs.textures,
                      inputs.lights, inputs.lit, shading_bands(opaque_depth.shape[0]), rgb)
    return lists.count > 0
