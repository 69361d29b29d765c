"""Between stages 6 and 7: the triangles that won a pixel, renumbered for shading.

After the visibility pass each covered pixel names the one triangle it shows; most of a
large mesh's triangles win no pixel at all (hidden, or too small to cover a pixel
centre). Shading reads tables of the triangles' corners, weights and set-up: made for the
winners only, they stay as long as the image has pixels, however many triangles the
scene has. The winners keep their draw order, so a pixel's triangle number changes but
not which triangle it is, nor which pixels show the same one.
"""
from __future__ import annotations

import numpy as np

from renderer.raster import EMPTY
from renderer.workspace import empty


def visible_triangles(tri_index: np.ndarray, count: int, ws=None) -> np.ndarray:
    """The triangles (of ``count``) that some pixel of ``tri_index`` (H, W) int32 shows, in
    draw order, as an index array (V,); ``tri_index`` is renumbered in place to count them
    0 … V − 1 (:data:`renderer.raster.EMPTY` stays where no triangle is).

    >>> tri_index = np.array([[7, -1], [2, 7]], np.int32)
    >>> visible_triangles(tri_index, 9).tolist(), tri_index.tolist()
    ([2, 7], [[1, -1], [0, 1]])
    """
    covered = tri_index != EMPTY
    shown = tri_index[covered]
    number = empty(ws, "scratch.per_triangle", count, np.int64)  # shared with the clipper's offsets
    number[:] = 0
    number[shown] = 1
    ids = np.flatnonzero(number)
    number[ids] = np.arange(len(ids))
    tri_index[covered] = number[shown]
    return ids
