"""Triangles as rows of vertex tables (renderer/indexed_triangles.py): triangles given whole
are laid out three rows each, their corners where the set-up looks for them, with their
centre cells when asked; tables of different triangles are refused."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.clip import corner_row
from renderer.indexed_triangles import IndexedTriangles, whole_triangles
from renderer.jit import njit
from renderer.window import NO_CELLS, centre_cell


@njit(cache=False)
def corner_rows_of(corners, count):
    out = np.empty((count, 3), np.int64)
    for k in range(count):
        for v in range(3):
            out[k, v] = corner_row(corners, k, v)
    return out


def test_triangle_k_s_corners_are_rows_3k_to_3k_plus_2_of_its_tables():
    rng = np.random.default_rng(2)
    fixed = rng.integers(-600, 3000, (5, 3, 2))
    window = rng.uniform(0, 12, (5, 3, 3))
    whole = whole_triangles(fixed, window)
    assert isinstance(whole, IndexedTriangles) and whole.count == 5
    rows = corner_rows_of(whole.corners, 5)
    np.testing.assert_array_equal(rows, np.arange(15).reshape(5, 3))
    np.testing.assert_array_equal(whole.fixed[rows], fixed)
    np.testing.assert_array_equal(whole.window[rows], window)
    assert whole.vertices.fixed is whole.fixed


def test_centre_cells_come_with_the_vertices_unless_left_out():
    fixed = np.array([[[0, 0], [300, 10], [-5, 700]]])
    window = np.zeros((1, 3, 3))
    cells = whole_triangles(fixed, window).cells
    assert cells.tolist() == [centre_cell(x, y) for x, y in fixed[0]]
    assert whole_triangles(fixed, window, with_cells=False).cells is NO_CELLS


def test_tables_of_different_triangles_are_refused():
    with pytest.raises(ValueError, match="same triangles"):
        whole_triangles(np.zeros((2, 3, 2)), np.zeros((3, 3, 3)))
