"""The ``oit`` mode's buffers: what a weighted-average order-independent transparency keeps per pixel.

VTK's default translucency (:mod:`renderer.translucency`, mode ``oit``) sums every fragment
of a pixel into 16-bit float render targets — ``Σαr, Σαg, Σαb``, the weight ``Σα`` and the
transmittance ``Π(1 − α)`` — in draw order, each step rounded to half as the targets store
it (:func:`oit_add`); then resolves them over the opaque 8-bit frame: ``C = Σαc / max(Σα,
0.01)``, coverage ``A = 1 − Π(1 − α)``, ``A·C + (1 − A)·B`` in an 8-bit blend unit
(:func:`oit_resolve`, :func:`blend8`). Here the targets are five float32 planes of
half-float values (:data:`SUM_R` …), a strip of rows at a time: cleared
(:func:`clear_oit_rows`), a run of fragments added (:func:`add_run_to_oit`), each row resolved
(:func:`resolve_oit_row`).
"""
from __future__ import annotations

import numpy as np

from renderer.float32_math import half, unorm8
from renderer.jit import njit
from renderer.min_max import larger, smaller
from renderer.spans import round_up_to_lanes

F32_ZERO = np.float32(0.0)
F32_ONE = np.float32(1.0)


@njit(cache=True, inline="always")
def mul8(a, b):
    """Two 8-bit unorm values multiplied, as an 8-bit blend unit does: round(a·b/255)."""
    t = np.int64(a) * np.int64(b) + 128
    return (t + (t >> 8)) >> 8


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
"""The ``oit`` buffers as :func:`shade_fragments` keeps them: five (H, W) float32 planes
holding half-float values, the sums Σαr, Σαg, Σαb, the weight Σα and the transmittance
Π(1 − α). Each strip's rows are cleared to no fragment yet (:func:`clear_oit_rows`) before its
triangles are drawn, so adding a fragment is the same sum for a pixel's first one as for the rest."""


@njit(cache=True, inline="always")
def clear_oit_rows(sums, lo, hi):
    """Rows ``lo … hi`` of the ``oit`` buffers ``sums`` (5, H, W) as a pixel without fragments
    holds them: zero sums and weight, transmittance 1."""
    for row in range(lo, hi + 1):
        for c in range(TRANSMIT):
            sums[c, row, :] = F32_ZERO
        sums[TRANSMIT, row, :] = F32_ONE


@njit(cache=True, inline="always")
def add_to_sum(total, colour, first, c0, count, lanes, a):
    """One channel of a run (:func:`add_run_to_oit`): ``total[c0 + i] += α·colour[first + i]``
    rounded to half (:func:`oit_add`'s step), for ``i < count`` of ``lanes`` lanes (the
    others keep their values). Two arrays in the loop, so the vectoriser's run-time overlap
    test is one comparison and its vector body runs from eight lanes on."""
    for i in range(lanes):
        p, j = np.uint64(c0 + i), np.uint64(first + i)  # unsigned: no wrap-around, the loop vectorises
        old = total[p]
        new = half(old + colour[j] * a)
        total[p] = new if i < count else old


@njit(cache=True, inline="always")
def scale_and_add(total, c0, count, lanes, scale, offset):
    """The weight's or the transmittance's step for a run (:func:`add_run_to_oit`):
    ``total[c0 + i] = half(total[c0 + i]·scale + offset)`` for ``i < count`` of ``lanes`` lanes
    (the others keep their values). The weight is ``scale`` 1, ``offset`` α (x·1 is x); the
    transmittance ``scale`` 1 − α, ``offset`` 0 (a product of values ≥ 0 is never −0, so
    adding 0 changes no bit): :func:`oit_add`'s bits."""
    for i in range(lanes):
        p = np.uint64(c0 + i)  # unsigned: no wrap-around, the loop vectorises
        old = total[p]
        new = half(old * scale + offset)
        total[p] = new if i < count else old


@njit(cache=True, from_python=False, refcounts=False)
def add_run_to_oit(colour, first, a, row, c0, count, seen, sums):
    """A run's ``count`` fragments (linear colours: columns ``first`` … of ``colour`` (3, N)
    float32, alpha ``a``; pixels ``c0`` … of ``row``) added to the pixels' ``oit`` buffers
    ``sums`` (5, H, W) (:func:`oit_add`'s five steps) and counted in ``seen`` (H, W).

    One loop a buffer, over whole vector lanes (:data:`~renderer.spans.LANES`; the pixels
    past the run keep their values) where the row and ``colour`` have room for them, else
    over the run alone: the same bits as :func:`oit_add` a fragment at a time. In one loop
    over the six buffers, LLVM's test that they do not overlap took 40-odd comparisons and
    it kept the vector body for runs of 112 fragments or more: a translucent-three run (6 to
    30 pixels) went through the scalar loop. Measured alone, ns a fragment, one loop → one
    a buffer in lanes: runs of about 6 pixels 7.4–9.3 → 5.1, 12: 5.3 → 3.3, 30: 3.9 → 2.2,
    100: 3.5 → 1.5. Compiled on its own, without reference counts (the row views cost
    nothing to take)."""
    lanes = round_up_to_lanes(count)
    if c0 + lanes > seen.shape[1] or first + lanes > colour.shape[1]:
        lanes = count
    add_to_sum(sums[SUM_R, row], colour[0], first, c0, count, lanes, a)
    add_to_sum(sums[SUM_G, row], colour[1], first, c0, count, lanes, a)
    add_to_sum(sums[SUM_B, row], colour[2], first, c0, count, lanes, a)
    scale_and_add(sums[WEIGHT, row], c0, count, lanes, F32_ONE, a)  # Σα + α
    scale_and_add(sums[TRANSMIT, row], c0, count, lanes, F32_ONE - a, F32_ZERO)  # T·(1 − α)
    seen_row = seen[row]
    for i in range(lanes):
        p = np.uint64(c0 + i)
        seen_row[p] += 1 if i < count else 0


@njit(cache=True, inline="always")
def resolve_oit_row(sums, seen, row, rgb, eight):
    """Every pixel of ``row`` that got a fragment: its ``oit`` buffers over ``rgb`` (as :func:`oit_resolve`).
    First every pixel's 8-bit colour and coverage (:func:`oit_colour8`) into ``eight`` (4, ≥ W) uint8, no
    branch, 8 lanes at a time (a pixel without fragments holds clear buffers, :func:`clear_oit_rows`); then
    those with a fragment blended over ``rgb``. In one loop this ran scalar: 14 % of a translucent-three frame."""
    for col in range(seen.shape[1]):
        j = np.uint64(col)  # unsigned: no wrap-around, the loop vectorises
        eight[0, j], eight[1, j], eight[2, j], eight[3, j] = oit_colour8(
            sums[SUM_R, row, j], sums[SUM_G, row, j], sums[SUM_B, row, j], sums[WEIGHT, row, j],
            sums[TRANSMIT, row, j])
    for col in range(seen.shape[1]):
        if seen[row, col] > 0:
            rgb[row, col, 0], rgb[row, col, 1], rgb[row, col, 2] = oit_over(
                eight[0, col], eight[1, col], eight[2, col], eight[3, col], rgb[row, col, 0], rgb[row, col, 1],
                rgb[row, col, 2])
