"""Prefetch: ask the processor to start loading a table's row that a loop will read a few
iterations later (LLVM's ``llvm.prefetch``: a hint, no load, no fault, no effect on any value).

Loops that walk the triangles that won a pixel in the order the image shows them
(:mod:`renderer.visible`) read the mesh's tables at random: each triangle's corners, then
their positions and normals, two cache misses one after the other. Asking for the rows a
few triangles ahead lets those misses overlap with the work on the triangles in between.
"""
from __future__ import annotations

import numba
from llvmlite import ir
from numba.core import cgutils, types
from numba.extending import intrinsic


def _prefetch_row(typingctx, table, row):
    """The intrinsic behind :func:`prefetch_row`."""
    if not isinstance(table, types.Array) or not isinstance(row, types.Integer):
        return None

    def codegen(context, builder, sig, args):
        table_type, row_type = sig.args
        array = context.make_array(table_type)(context, builder, args[0])
        index = [context.cast(builder, args[1], row_type, types.intp)]
        index += [context.get_constant(types.intp, 0)] * (table_type.ndim - 1)
        first = cgutils.get_item_pointer2(context, builder, array.data, cgutils.unpack_tuple(builder, array.shape),
                                          cgutils.unpack_tuple(builder, array.strides), table_type.layout, index,
                                          wraparound=False, boundscheck=False)
        byte_pointer = builder.bitcast(first, ir.IntType(8).as_pointer())
        i32 = ir.IntType(32)
        hint = cgutils.get_or_insert_function(
            builder.module, ir.FunctionType(ir.VoidType(), [byte_pointer.type, i32, i32, i32]), "llvm.prefetch.p0")
        builder.call(hint, [byte_pointer, i32(0), i32(3), i32(1)])  # read, keep in all cache levels, data
        return context.get_dummy_value()

    return types.void(table, row), codegen


if numba.config.DISABLE_JIT:
    def prefetch_row(table, row):
        """Nothing (kernels run as Python)."""
else:
    prefetch_row = intrinsic(_prefetch_row)
    prefetch_row.__doc__ = """Start loading the first element of row ``row`` of ``table`` (an array of
    any dimensions, C order) into the caches; a hint, nothing is read or changed. Call it
    for a row a few iterations ahead, inside the table (the caller checks the bound)."""
