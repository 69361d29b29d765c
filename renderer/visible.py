"""Between stages 6 and 7: the triangles that won a pixel, renumbered for shading.

After the visibility pass each covered pixel names the one triangle it shows; most of a
large mesh's triangles win no pixel at all (hidden, or too small to cover a pixel
centre). Shading reads tables of the triangles' corners, weights and set-up: made for the
winners only, they stay as long as the image has pixels, however many triangles the
scene has. The winners keep their draw order, so a pixel's triangle number changes but
not which triangle it is, nor which pixels show the same one.

Three passes (:func:`visible_triangles`): mark every triangle some pixel shows, number the
marked ones in draw order (one pass over the triangles), then rewrite the pixels. With
numpy's masks and fancy indexing instead, a 1024² frame of a 328k-triangle sphere spent
7.8 ms here.
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.raster import EMPTY
from renderer.workspace import empty


@njit(cache=True)
def over_shown(tri_index, number, renumber):
    """Every covered pixel of ``tri_index`` (H, W): ``renumber`` False marks its triangle
    (``number[k] = 1``); True rewrites the pixel as its triangle's number ``number[k]``. (One
    kernel for both passes: one compiled, not two.) One thread: rows in parallel gained
    nothing at 512² and 0.1 ms a pass at 1024² (ico7, igea-1m, 2 threads, in one process),
    and cost a cold start 0.4 s of compile."""
    for row in range(tri_index.shape[0]):
        for col in range(tri_index.shape[1]):
            k = tri_index[row, col]
            if k != EMPTY:
                if renumber:
                    tri_index[row, col] = number[k]
                else:
                    number[k] = 1


@njit(cache=True)
def number_marked(number, ids):
    """The marked triangles (``number[k]`` = 1) numbered 0, 1, … in draw order, in place,
    and listed in ``ids`` (as long as ``number``); returns how many."""
    count = 0
    for k in range(number.shape[0]):
        if number[k]:
            number[k] = count
            ids[count] = k
            count += 1
    return count


def visible_triangles(tri_index: np.ndarray, count: int, ws=None) -> np.ndarray:
    """The triangles (of ``count``) that some pixel of ``tri_index`` (H, W) int32 shows, in
    draw order, as an index array (V,) int64; ``tri_index`` is renumbered in place to count
    them 0 … V − 1 (:data:`renderer.raster.EMPTY` stays where no triangle is).

    >>> tri_index = np.array([[7, -1], [2, 7]], np.int32)
    >>> visible_triangles(tri_index, 9).tolist(), tri_index.tolist()
    ([2, 7], [[1, -1], [0, 1]])
    """
    number = empty(ws, "scratch.per_triangle", count, np.int64)  # shared with the clipper's offsets
    number[:] = 0
    over_shown(tri_index, number, False)
    ids = empty(ws, "visible.ids", count, np.int64)  # a list as long as the triangles: reused, not faulted in anew
    shown = number_marked(number, ids)
    over_shown(tri_index, number, True)
    return ids[:shown].copy()  # not a view of the workspace
