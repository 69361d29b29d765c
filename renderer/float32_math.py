"""float32 ``pow``, ``log2`` and ``exp2`` for the span shaders, written so LLVM can vectorise them;
:func:`unorm8`, a linear value to the framebuffer's 8 bits; and :func:`half`, a float32 rounded
to a 16-bit float as a half-float render target stores it.

VTK's fragment shaders run in float32 on llvmpipe, 8 lanes at a time, and llvmpipe
evaluates GLSL's ``pow(x, y)`` as ``exp2(y·log2(x))`` with polynomials. The library
``pow`` is a function call per pixel that no loop vectoriser can widen; these are
straight-line float32 arithmetic, integer bit operations and one division, so a loop
over a span of pixels becomes SIMD code. Every operation is IEEE float32 with no
reassociation, so a lane of a vectorised loop gives the same bits as the scalar code.

Accuracy (``tests/renderer/test_float32_math.py``): ``pow_f32(x, p)`` is within 4 float32
ulps of the exact power for x in [1e-5, 1] and p in [0, 128] — far below the 1/255 step
of the 8-bit output. Powers below 2⁻¹⁰⁰ are 0 (:data:`EXP_FLUSH`), so no product of
them is a subnormal float, which the processor handles slowly.
"""
from __future__ import annotations

import numba
import numpy as np
from llvmlite import ir
from numba.core import types
from numba.core.typing import signature
from numba.extending import intrinsic

from renderer.jit import njit
from renderer.min_max import clamp

F0, F1, F2 = np.float32(0.0), np.float32(1.0), np.float32(2.0)
HALF = np.float32(0.5)
SQRT2 = np.float32(1.4142135)
LN2 = np.float32(0.6931472)
INV_LN2 = np.float32(1.442695)
# ln(m) = 2·atanh(s), s = (m − 1)/(m + 1): 2·(s + s³/3 + s⁵/5 + s⁷/7 + s⁹/9)
C3, C5, C7, C9 = np.float32(1.0 / 3.0), np.float32(1.0 / 5.0), np.float32(1.0 / 7.0), np.float32(1.0 / 9.0)
# 2^f = e^t, t = f·ln 2 ∈ [0, 0.694): Taylor to t⁹ (so 2^0 is exactly 1)
E2, E3, E4, E5, E6, E7, E8, E9 = (np.float32(1.0 / 2.0), np.float32(1.0 / 6.0), np.float32(1.0 / 24.0),
                                  np.float32(1.0 / 120.0), np.float32(1.0 / 720.0), np.float32(1.0 / 5040.0),
                                  np.float32(1.0 / 40320.0), np.float32(1.0 / 362880.0))
EXP_MIN, EXP_MAX = np.float32(-126.0), np.float32(127.0)
EXP_FLUSH = np.float32(-100.0)
"""``exp2_f32`` of anything below this is 0 (2⁻¹⁰⁰ ≈ 8·10⁻³¹, a hundred thousand times
below float32's smallest normal number, 2⁻¹²⁶). A specular factor that small is zero to every 8-bit and
half-float store, but kept, its products with a material's and a light's colour fall
below the normal range, and every multiply that makes or reads a subnormal float takes
a microcode assist: measured, 25 ns a pixel instead of 4.7 in the span kernel
(``vtk_light_kernel``, a highlight of power 20 where ``r·v`` is at its floor 10⁻⁵).
llvmpipe runs with subnormals flushed to zero, so the same products are zero there too."""
MANTISSA = np.int32(0x007FFFFF)
ONE_BITS = np.int32(0x3F800000)


@njit(cache=True, inline="always")
def log2_f32(x):
    """log₂ of a positive normal float32 ``x``: exponent from the bits, the mantissa m
    brought into [√½, √2) and ln(m) from its atanh series."""
    bits = np.float32(x).view(np.int32)
    e = np.float32((bits >> 23) - 127)
    m = np.int32((bits & MANTISSA) | ONE_BITS).view(np.float32)  # [1, 2)
    big = m > SQRT2
    m = m * HALF if big else m
    e = e + F1 if big else e
    s = (m - F1) / (m + F1)
    s2 = s * s
    ln_m = F2 * s * (F1 + s2 * (C3 + s2 * (C5 + s2 * (C7 + s2 * C9))))
    return e + ln_m * INV_LN2


@njit(cache=True, inline="always")
def exp2_f32(y):
    """2^y for float32 ``y``: 0 below :data:`EXP_FLUSH`, else clamped to at most 2¹²⁷; the
    integer part goes into the exponent bits, the fraction through a polynomial (exact at
    integers). No subnormal result, and no branch: a loop of them vectorises."""
    flushed = np.float32(y) < EXP_FLUSH
    y = clamp(np.float32(y), EXP_MIN, EXP_MAX)
    i = np.floor(y)
    t = (y - i) * LN2
    p = F1 + t * (F1 + t * (E2 + t * (E3 + t * (E4 + t * (E5 + t * (E6 + t * (E7 + t * (E8 + t * E9))))))))
    scale = np.int32((np.int32(i) + 127) << 23).view(np.float32)
    return F0 if flushed else p * scale


@njit(cache=True, inline="always")
def pow_f32(x, p):
    """x^p for float32 ``x`` > 0 (normal) and ``p`` ≥ 0, as ``exp2(p·log2(x))``; x^0 = 1."""
    return exp2_f32(np.float32(p) * log2_f32(x))


@njit(cache=True, inline="always")
def unorm8(c):
    """Linear 0..1 → the framebuffer's 8 bits: ``round_half_even(clamp(c, 0, 1)·255)`` in float32.

    ``c`` is made float32 before the clamp, not after: 0 and 1 are exact in both widths and
    rounding to float32 keeps the order, so the bits are those of a clamp in float64 (a NaN
    stays NaN either way), and a float32 ``c`` is not widened to float64 and back (four
    conversions a pixel in the scalar loop of :func:`renderer.oit_buffers.resolve_oit_row`)."""
    f = clamp(np.float32(c), F0, F1) * np.float32(255.0)
    return np.uint8(np.rint(f))


def round_to_half(typingctx, x):
    """The intrinsic behind :func:`half`: LLVM's ``fptrunc`` to ``half`` and ``fpext`` back."""
    if x != types.float32:
        return None

    def codegen(context, builder, sig, args):
        return builder.fpext(builder.fptrunc(args[0], ir.HalfType()), ir.FloatType())

    return signature(types.float32, types.float32), codegen


if numba.config.DISABLE_JIT:
    def half(x):
        """``x`` rounded to a half float (kernels run as Python: numpy's float16)."""
        return np.float32(np.float16(x))
else:
    half = intrinsic(round_to_half)
    half.__doc__ = """``x`` (float32) rounded to the nearest IEEE half float, ties to even, as a float32:
    what a 16-bit float render target stores (the ``oit`` accumulators of
    :mod:`renderer.translucency`). LLVM's ``fptrunc`` to ``half`` is IEEE round-to-nearest-even,
    subnormal halves included, and becomes the processor's own conversion (x86's F16C
    ``vcvtps2ph``/``vcvtph2ps``, a vector of 8 at a time in a vectorised loop; without F16C, a
    library call). The bit-twiddling rounding it replaced took 14 instructions a value and
    kept a run of about 12 ``oit`` fragments at 8.3 ns a fragment (measured, 4.4 with this).
    Above 65504 it gives infinity; the sums here stay ≤ 1e3."""
