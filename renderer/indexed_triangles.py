"""Triangles as rows of vertex tables: what the raster's set-up reads (:mod:`renderer.raster`).

The pipeline's triangles name their corners among the rows of the window-space vertex
tables (:class:`~renderer.clip.CornerIndex`), shared vertices once; triangles given whole,
in the textbook's per-triangle tables, are laid out the same way (:func:`whole_triangles`).
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

from renderer.clip import CornerIndex
from renderer.window import NO_CELLS, WindowVertices, centre_cells


class IndexedTriangles(NamedTuple):
    """Triangles as rows of vertex tables: ``corners`` (:class:`~renderer.clip.CornerIndex`)
    says where the triangles' corners are in ``fixed`` (M, 2) int64, x and y on the
    1/256-pixel grid, ``window`` (M, 3), window space (:mod:`renderer.window`), and
    ``cells`` (M,) int64, the vertices' centre cells (:func:`renderer.window.centre_cell`;
    the set-up drops a triangle whose box holds no pixel centre from them, :data:`renderer.raster.DROP_EMPTY_BOXES`)."""

    corners: CornerIndex
    fixed: np.ndarray
    window: np.ndarray
    cells: np.ndarray

    @property
    def vertices(self) -> WindowVertices:
        """The vertex tables, as the set-up reads them."""
        return WindowVertices(self.fixed, self.window, self.cells)

    @property
    def count(self) -> int:
        """How many triangles."""
        return len(self.corners.source)


def whole_triangles(tri_fixed: np.ndarray, tri_window: np.ndarray, with_cells: bool = True) -> IndexedTriangles:
    """Per-triangle tables (K, 3, 2) and (K, 3, 3) as :class:`IndexedTriangles`: triangle k's
    corners on rows 3k, 3k + 1, 3k + 2 of their vertex tables (3K, 2) and (3K, 3), with their
    centre cells unless ``with_cells`` is False (then :data:`~renderer.window.NO_CELLS`)."""
    tri_fixed = np.ascontiguousarray(tri_fixed, dtype=np.int64).reshape(-1, 3, 2)
    tri_window = np.ascontiguousarray(tri_window, dtype=np.float64).reshape(-1, 3, 3)
    if len(tri_fixed) != len(tri_window):
        raise ValueError("tri_fixed and tri_window must hold the same triangles")
    fixed = tri_fixed.reshape(-1, 2)
    cells = np.empty(len(fixed), np.int64) if with_cells else NO_CELLS
    if with_cells and len(fixed):
        centre_cells(fixed, cells)
    return IndexedTriangles(CornerIndex.of_whole(len(tri_fixed)), fixed, tri_window.reshape(-1, 3), cells)
