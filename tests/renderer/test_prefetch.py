"""Prefetch is a hint: it is in the machine code, and it changes no value."""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.prefetch import prefetch_row


@njit
def sum_rows_read_ahead(table, order, out):
    for k in range(order.shape[0]):
        if k + 4 < order.shape[0]:
            prefetch_row(table, order[k + 4])
        out[k] = table[order[k]].sum()


@njit
def first_of_rows_read_ahead(values, order, out):
    for k in range(order.shape[0]):
        if k + 4 < order.shape[0]:
            prefetch_row(values, order[k + 4])
        out[k] = values[order[k]]


def test_reading_ahead_changes_no_value_of_a_table_of_rows_or_of_a_list():
    rng = np.random.default_rng(3)
    table, order = rng.random((5000, 3)), rng.integers(0, 5000, 2000)
    out = np.empty(2000)
    sum_rows_read_ahead(table, order, out)
    np.testing.assert_array_equal(out, table[order].sum(axis=1))
    values = rng.integers(0, 9, 5000)
    first = np.empty(2000, np.int64)
    first_of_rows_read_ahead(values, order, first)
    np.testing.assert_array_equal(first, values[order])


def test_the_hint_is_in_the_machine_code():
    """The kernel's LLVM code calls ``llvm.prefetch`` (the hint was not dropped on the way)."""
    table, order = np.zeros((10, 3)), np.arange(10)
    sum_rows_read_ahead(table, order, np.empty(10))
    code = "\n".join(sum_rows_read_ahead.inspect_llvm().values())
    assert "llvm.prefetch" in code
