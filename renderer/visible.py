"""Between stages 6 and 7: the triangles that won a pixel, renumbered for shading.

After the visibility pass each covered pixel names the one triangle it shows; most of a
large mesh's triangles win no pixel at all (hidden, or too small to cover a pixel
centre). Shading reads tables of the triangles' corners, weights and set-up: made for the
winners only, they stay as long as the image has pixels, however many triangles the
scene has. A pixel's triangle number changes but not which triangle it is, nor which
pixels show the same one.

The winners are numbered **in the order the image's rows first show them**
(:func:`number_in_sight`), not in draw order: shading walks the rows in order, so the
table rows it reads one span after another are neighbours in memory, and the rows of a
triangle met again on the next scanline are still in the cache. In draw order a
328k-triangle sphere's tables (34 MB at 1024²) were read at random, a cache miss per span:
its shading took 33.4 ms a frame, 25.1 in this order (one thread). The numbering is one pass
over the pixels (a triangle's number is known when it is first seen), where marking,
numbering in draw order and rewriting took three.

The pass is serial and costs about a nanosecond a pixel; a table row for a triangle that
shows nothing costs more, but only once per triangle. So a scene with few triangles for its
pixels keeps the raster's numbers and gets a table row for every triangle
(:func:`renumbering_pays`); the bytes are the same either way.
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.raster import EMPTY
from renderer.workspace import empty, zeros


@njit(cache=True)
def number_in_sight(tri_index, number, ids):
    """Number the triangles of ``tri_index`` (H, W) in the order the rows first show them
    (rows from the first, each from its first column), and rewrite each covered pixel as
    its triangle's number, in one pass: a triangle's number is known when it is first seen.
    ``number`` (int32, all 0 on entry) keeps one more than each triangle's number (0: not
    shown yet; read at random, so int32, half the cache lines of int64: the kernel alone on
    its frame's buffer, the 1M-triangle scan at 1024² 2.16 → 1.26 ms, other scenes 0.92–1.01),
    ``ids`` the triangles in that order. Returns how many, with ``number`` all 0 again (the
    shown triangles' entries put back: a frame shows few of a large mesh's triangles, and
    filling a 672,768-triangle table with zeros took 0.7 ms a frame)."""
    count = 0
    for row in range(tri_index.shape[0]):
        for col in range(tri_index.shape[1]):
            k = tri_index[row, col]
            if k != EMPTY:
                if number[k] == 0:
                    ids[count] = k
                    count += 1
                    number[k] = count
                tri_index[row, col] = number[k] - 1
    for i in range(count):
        number[ids[i]] = 0
    return count


PIXELS_PER_TRIANGLE = 32
"""The fewest pixels per triangle for which the winners are renumbered (:func:`renumbering_pays`).
Measured, frames alternating in one process, 41 pairs each, ratio of frame times without
renumbering to with it: the 1,024-segment cylinder (4,096 triangles) 0.97 at 512², 0.93 at
1024²; the textured sphere (5,120) 1.02 and 0.96; ico5 (20,480) 1.05 at 512² (12.8 pixels a
triangle: renumbered) and 0.98 at 1024² (51)."""

HELD_PIXELS_PER_TRIANGLE = 10
""":data:`PIXELS_PER_TRIANGLE` for a frame painted from colours held per triangle
(:data:`renderer.shading.HELD`: flat under a headlight). Its tables are a colour and a plane
normal a triangle, worked out for every triangle when they are not renumbered, so
renumbering pays only for more triangles. Measured, frames alternating in one process, 40
pairs, frame time without renumbering / with it: ico5-flat at 512² (12.8 pixels a triangle)
0.95; the level-3 sponge (36,096 triangles) 1.03 at 512² (7.3), 0.96 at 1024² (29); the
level-7 icosphere 1.11 and 1.03 (0.8 and 3.2), the level-4 sponge 1.15 and 1.21 (0.4, 1.6)."""


def renumbering_pays(count: int, height: int, width: int, held: bool = False) -> bool:
    """Whether to renumber the winners of ``count`` triangles on an image ``height`` × ``width``
    (:func:`visible_triangles`): when it has fewer than :data:`PIXELS_PER_TRIANGLE` pixels
    for each triangle (:data:`HELD_PIXELS_PER_TRIANGLE` for a frame painted from ``held``
    colours). Otherwise the pass over the pixels costs more than the table rows of the
    triangles that won none; shading then reads the raster's numbers as they are."""
    return count * (HELD_PIXELS_PER_TRIANGLE if held else PIXELS_PER_TRIANGLE) > height * width


def visible_triangles(tri_index: np.ndarray, count: int, ws=None) -> np.ndarray:
    """The triangles (of ``count``) that some pixel of ``tri_index`` (H, W) int32 shows, in
    the order the image's rows first show them, as an index array (V,) int64; ``tri_index``
    is renumbered in place to count them 0 … V − 1 (:data:`renderer.raster.EMPTY` stays
    where no triangle is).

    >>> tri_index = np.array([[7, -1], [2, 7]], np.int32)
    >>> visible_triangles(tri_index, 9).tolist(), tri_index.tolist()
    ([7, 2], [[0, -1], [1, 0]])
    """
    number = zeros(ws, "visible.number", count, np.int32)  # kept all 0 between frames (number_in_sight puts the zeros back)
    ids = empty(ws, "visible.ids", count, np.int64)  # a list as long as the triangles: reused, not faulted in anew
    shown = number_in_sight(tri_index, number, ids)
    return ids[:shown].copy()  # not a view of the workspace
