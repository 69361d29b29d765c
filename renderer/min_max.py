"""``min`` and ``max`` of two numbers for the kernels, and :func:`clamp`.

numba's builtin ``min``/``max`` are an overload: each pair of argument types used anywhere
compiles a small function of its own before the first frame (a cold start of the level-5
icosphere compiled 18 of them, 0.5 s of its CPU). :func:`smaller` and :func:`larger` are
intrinsics instead: one compare and one select written straight into the kernel that
uses them, nothing compiled of their own. (A Python ``b if b < a else a``, inlined, also
compiles nothing of its own, but its branches made the kernels' own compile slower by
more than it saved: a cold start 12.5 → 13.0 s of CPU.)

They give what the builtins give, bit for bit: the two values are brought to one type as
numba brings them (int64 and float64 give float64, int32 and int64 give int64), and the
first argument is kept unless the second is strictly smaller (:func:`smaller`) or larger
(:func:`larger`), as Python's ``min(a, b)``/``max(a, b)`` do (a NaN first argument is kept,
``max(0.0, -0.0)`` is ``0.0``). Three values: ``smaller(smaller(a, b), c)``, the builtin's
left-to-right order. Under ``NUMBA_DISABLE_JIT`` (kernels run as Python) they are the builtins.
"""
from __future__ import annotations

import operator

import numba
from numba.core import types
from numba.core.typing import signature
from numba.extending import intrinsic

from renderer.jit import njit


def compare_and_select(compare):
    """An intrinsic of two numbers: the second if ``compare(second, first)``, else the first,
    both first brought to their common type."""

    def minmax(typingctx, a, b):
        common = typingctx.unify_types(a, b)
        if not isinstance(common, (types.Number, types.Boolean)):
            return None

        def codegen(context, builder, sig, args):
            first = context.cast(builder, args[0], a, common)
            second = context.cast(builder, args[1], b, common)
            test = context.get_function(compare, signature(types.boolean, common, common))
            return builder.select(test(builder, (second, first)), second, first)

        return signature(common, a, b), codegen

    return minmax


if numba.config.DISABLE_JIT:
    smaller, larger = min, max
else:
    smaller = intrinsic(compare_and_select(operator.lt))
    larger = intrinsic(compare_and_select(operator.gt))


@njit(cache=True, inline="always")
def clamp(x, lo, hi):
    """``min(max(x, lo), hi)``: ``x`` brought into [lo, hi] (a NaN ``x`` stays NaN)."""
    return smaller(larger(x, lo), hi)
