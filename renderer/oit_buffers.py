"""The ``oit`` mode's buffers: what a weighted-average order-independent transparency keeps per pixel.

VTK's default translucency (:mod:`renderer.translucency`, mode ``oit``) sums every fragment
of a pixel into 16-bit float render targets — ``Σαr, Σαg, Σαb``, the weight ``Σα`` and the
transmittance ``Π(1 − α)`` — in draw order, each step rounded to half as the targets store
it (:func:`oit_add`); then resolves them over the opaque 8-bit frame: ``C = Σαc / max(Σα,
0.01)``, coverage ``A = 1 − Π(1 − α)``, ``A·C + (1 − A)·B`` in an 8-bit blend unit
(:func:`oit_resolve`, :func:`blend8`). Here the targets are five float32 values of
half-float value a pixel, side by side (:data:`SUM_R` …), in a buffer of one strip of rows
a band: cleared once (:func:`clear_oit_strip`), a run of fragments added
(:func:`add_run_to_oit`), each row resolved and its touched pixels cleared again
(:func:`resolve_oit_row`).
"""
from __future__ import annotations

import numpy as np

from renderer.float32_math import half, unorm8
from renderer.jit import njit
from renderer.min_max import larger, smaller

F32_ZERO = np.float32(0.0)
F32_ONE = np.float32(1.0)


@njit(cache=True, inline="always")
def mul8(a, b):
    """Two 8-bit unorm values multiplied, as an 8-bit blend unit does: round(a·b/255).

    In int32 (a·b + 128 ≤ 65,153): a loop over bytes then works 16 lanes to a vector
    register, where int64 products took it to scalar code."""
    t = np.int32(a) * np.int32(b) + np.int32(128)
    return (t + (t >> np.int32(8))) >> np.int32(8)


@njit(cache=True, inline="always")
def blend8(src, src_factor, dst, dst_factor):
    """One channel of 8-bit blending: ``src·src_factor + dst·dst_factor`` (all unorm8), saturated."""
    return smaller(mul8(src, src_factor) + mul8(dst, dst_factor), 255)


@njit(cache=True, inline="always")
def oit_add(sum_r, sum_g, sum_b, weight, transmit, r, g, b, a):
    """One fragment (float32 linear colour ``r, g, b``, alpha ``a``) added to the ``oit``
    buffers: ``α·c`` to the half-float RGB sum, ``α`` to the half-float weight, and the
    half-float transmittance multiplied by ``1 − α``, each rounded to half after the step
    as the 16-bit float targets store them. Returns the five new values (float32)."""
    return (half(sum_r + r * a), half(sum_g + g * a), half(sum_b + b * a), half(weight + a),
            half((F32_ONE - a) * transmit))


@njit(cache=True, inline="always")
def oit_resolve(sum_r, sum_g, sum_b, weight, transmit, behind, out):
    """The ``oit`` buffers of one pixel composited over the 8-bit ``behind`` into the 8-bit
    ``out``: ``C = Σαc / max(Σα, 0.01)`` with coverage ``A = 1 − T``, ``C`` converted to 8 bits
    (:func:`oit_colour8`) and blended ``C·A + behind·(1 − A)`` in 8-bit arithmetic."""
    r8, g8, b8, a8 = oit_colour8(sum_r, sum_g, sum_b, weight, transmit)
    out[0], out[1], out[2] = oit_over(r8, g8, b8, a8, behind[0], behind[1], behind[2])


@njit(cache=True, inline="always")
def oit_colour8(sum_r, sum_g, sum_b, weight, transmit):
    """One pixel's ``oit`` buffers as 8 bits ``(r, g, b, a)``: ``Σαc / max(Σα, 0.01)``, coverage ``1 − T`` (0 if clear)."""
    w = larger(weight, np.float32(0.01))
    return unorm8(sum_r / w), unorm8(sum_g / w), unorm8(sum_b / w), unorm8(F32_ONE - transmit)


@njit(cache=True, inline="always")
def oit_over(r8, g8, b8, a8, r, g, b):
    """The 8-bit ``oit`` colour ``(r8, g8, b8)``, coverage ``a8``, over the 8-bit ``(r, g, b)`` (:func:`blend8`)."""
    return blend8(r8, a8, r, 255 - a8), blend8(g8, a8, g, 255 - a8), blend8(b8, a8, b, 255 - a8)


SUM_R, SUM_G, SUM_B, WEIGHT, TRANSMIT = range(5)
"""The ``oit`` buffers of a pixel as :func:`shade_fragments` keeps them: five float32 values
holding half floats, side by side (a strip (rows, W, 5) for a strip of rows: the pixels of
a row one after another, each pixel's five values together), the sums Σαr, Σαg, Σαb, the
weight Σα and the transmittance Π(1 − α). A strip holds no fragment yet when its
triangles are drawn (:func:`clear_oit_strip`, then each resolved row cleared again,
:func:`resolve_oit_row`), so adding a fragment is the same sum for a pixel's first one as
for the rest."""

OIT_VALUES = 5
"""Values of a pixel's ``oit`` buffers (:data:`SUM_R` … :data:`TRANSMIT`)."""


@njit(cache=True, inline="always")
def clear_oit_strip(strip):
    """The ``oit`` buffers ``strip`` (rows, W, 5) as pixels without fragments hold them: zero
    sums and weight, transmittance 1."""
    for row in range(strip.shape[0]):
        for col in range(strip.shape[1]):
            for c in range(TRANSMIT):
                strip[row, col, c] = F32_ZERO
            strip[row, col, TRANSMIT] = F32_ONE


@njit(cache=True, inline="always")
def add_run_to_oit(colour, first, a, c0, count, seen_row, buffers):
    """A run's ``count`` fragments (linear colours: columns ``first`` … of ``colour`` (3, N)
    float32, alpha ``a``; pixels ``c0`` … of one row) added to the pixels' ``oit`` buffers
    ``buffers`` (W, 5), the row's in a strip (:func:`oit_add`'s five steps, the same bits),
    and counted in ``seen_row`` (W,).

    A pixel's five values lie together, so a fragment reads and writes one short stretch of
    memory. Measured alone on runs of 4 to 19 pixels, ns a fragment: five planes (one loop a
    plane, in whole vector lanes) 7.3, together 3.5; in a translucent-three frame the five
    planes took 15 ns a fragment. The five values are read first, summed, then written:
    with the reads and writes apart, LLVM's straight-line vectoriser (:mod:`renderer.jit`)
    makes the four sums one packed add and one packed rounding to half (1.7 ns a fragment
    alone, against 2.5 for four scalar read-add-round-write steps)."""
    t = F32_ONE - a
    for i in range(count):
        p, j = np.uint64(c0 + i), np.uint64(first + i)  # unsigned: no wrap-around
        v = buffers[p]
        r, g, b = colour[0, j], colour[1, j], colour[2, j]
        sum_r, sum_g, sum_b, weight, transmit = v[SUM_R], v[SUM_G], v[SUM_B], v[WEIGHT], v[TRANSMIT]
        sum_r, sum_g, sum_b, weight = half(sum_r + r * a), half(sum_g + g * a), half(sum_b + b * a), half(weight + a)
        transmit = half(transmit * t)  # (1 − α)·T: a product, commutative, the same bits
        v[SUM_R], v[SUM_G], v[SUM_B], v[WEIGHT], v[TRANSMIT] = sum_r, sum_g, sum_b, weight, transmit
        seen_row[p] += 1


@njit(cache=True, inline="always")
def resolve_scratch(width):
    """Scratch for :func:`resolve_oit_row` on rows of ``width`` pixels: the five values in
    planes (5, W) float32, the 8-bit colour and coverage in planes (4, W) uint8, and the
    colour and coverage again laid out as the frame's bytes (2, 3·W) uint8."""
    return (np.empty((OIT_VALUES, width), np.float32), np.empty((4, width), np.uint8),
            np.empty((2, 3 * width), np.uint8))


@njit(cache=True, inline="always")
def resolve_oit_row(buffers, rgb_row, scratch, first, last):
    """The pixels ``first … last`` of a row (the columns its runs touched; none when ``first
    > last``): their ``oit`` buffers (``buffers`` (W, 5), the row's in a strip) over
    ``rgb_row`` (W, 3) uint8 (as :func:`oit_resolve`); the buffers then cleared
    (:func:`clear_oit_strip`'s values), so the strip is clear for the next one without a
    pass over all its pixels. ``scratch``: :func:`resolve_scratch`.

    Every pixel of the stretch is blended, with a fragment or not: clear buffers give colour
    0 and coverage 0, and ``blend8(0, 0, v, 255)`` is ``v`` for every 8-bit ``v``, so a pixel
    without a fragment keeps its bytes, and the blend runs without a branch. Four loops,
    each LLVM turns into vector code or plain moves: the five values out to planes (the
    buffers cleared on the way), the 8-bit colour and coverage from the planes
    (:func:`oit_colour8`, 16 lanes), those laid out as the frame's bytes (r, g, b of a
    pixel together), and the blend over the row's bytes, one byte a lane (:func:`blend8`).
    Measured alone on rows of 400 touched pixels, a quarter of them without a fragment:
    4.3 ns a pixel, against 9.2 for one loop over pixels with a branch (scalar code: the
    five values lie side by side, and the frame's three bytes too)."""
    planes, eight, bytewise = scratch
    for col in range(first, last + 1):
        j = np.uint64(col)  # unsigned: no wrap-around
        for c in range(OIT_VALUES):
            planes[c, j] = buffers[j, c]
        for c in range(TRANSMIT):
            buffers[j, c] = F32_ZERO
        buffers[j, TRANSMIT] = F32_ONE
    for col in range(first, last + 1):
        j = np.uint64(col)
        eight[0, j], eight[1, j], eight[2, j], eight[3, j] = oit_colour8(
            planes[SUM_R, j], planes[SUM_G, j], planes[SUM_B, j], planes[WEIGHT, j], planes[TRANSMIT, j])
    three = np.uint64(3)
    for col in range(first, last + 1):
        j = np.uint64(col)
        for c in range(3):
            bytewise[0, three * j + np.uint64(c)] = eight[c, j]
            bytewise[1, three * j + np.uint64(c)] = eight[3, j]
    row_bytes = rgb_row.reshape(rgb_row.size)
    for q in range(3 * first, 3 * last + 3):
        p = np.uint64(q)
        a8 = np.int32(bytewise[1, p])
        row_bytes[p] = blend8(bytewise[0, p], a8, row_bytes[p], np.int32(255) - a8)
