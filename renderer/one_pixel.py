"""Triangles that can cover one pixel at most: the inside test and the depth test at that one centre.

On a mesh finer than the pixels (the 1M-triangle Igea scan at 512²: 126,446 of the 128,213
triangles the set-up leaves with rows), a triangle's box holds one pixel centre: one row
(:func:`renderer.pixel_centres.centre_rows`) and one column of centres. Drawn by its edge
functions in a group of vector lanes (:func:`renderer.edge_functions.fill_narrow_rows`),
such a triangle pays for eight pixels' depths and stores; here it is tested at its one
centre: its three edge functions there, with the same top-left rule
(:func:`renderer.edge_functions.edge_function`'s bars), and, when inside, the depth test of
:func:`renderer.visibility_buffer.fill_columns` on that pixel, the same expression for the
depth. So it chooses the same pixel, the same depth and the same winner as the lanes.

The raster's band kernel takes this path only in a batch finer than the pixels
(:data:`renderer.raster.FINE_BATCH`): where one triangle in two or more has a box of one
centre and the rest do not, the branch between the two paths is taken at random, and it
cost more than the lanes it saved (the 1M scan at 1024², where 409,719 of 833,669 drawn
triangles hold one centre: the raster 1.01–1.02 of its time).

Coordinates: the window's fixed-point grid (y up, 1/256 pixel, pixel centre (i, j) at
(256·i, 256·j)); rows are window rows.
"""
from __future__ import annotations

import numpy as np

from renderer.edge_functions import edge_function
from renderer.jit import njit
from renderer.min_max import larger, smaller
from renderer.visibility_buffer import depth_bits, nearer_or_later
from renderer.window import SUBPIXEL_BITS

NOT_ONE_COLUMN = -2
""":func:`one_column`'s answer for a box with more than one column of pixel centres."""

OUTSIDE_IMAGE = -1
""":func:`one_column`'s answer for a box whose one column of centres lies outside the image."""


@njit(cache=True, inline="always")
def one_column(f, width):
    """The one column of pixel centres in the box of the counter-clockwise fixed-point
    triangle ``f`` (3, 2), in an image ``width`` wide: ⌈x_min / 256⌉ when it equals
    ⌊x_max / 256⌋; :data:`OUTSIDE_IMAGE` when that column is not in the image (nothing to
    draw); :data:`NOT_ONE_COLUMN` when the box holds more columns (or none)."""
    x_min = smaller(smaller(f[0, 0], f[1, 0]), f[2, 0])
    x_max = larger(larger(f[0, 0], f[1, 0]), f[2, 0])
    col = -((-x_min) >> SUBPIXEL_BITS)
    if col != x_max >> SUBPIXEL_BITS:
        return NOT_ONE_COLUMN
    return col if 0 <= col < width else OUTSIDE_IMAGE


@njit(cache=True, inline="always")
def fill_one_centre(f, row, col, plane, kk, top_left, depth_test, depth, tri_index):
    """Pixel (row, col) for the counter-clockwise fixed-point triangle ``f`` (3, 2), numbered
    ``kk`` in the visibility buffer, whose set-up row is ``plane`` (11,)
    (:class:`renderer.raster.TriangleSetup`): when the centre is inside all three edges
    (``top_left``: the top-left rule, else the bottom-right one), it takes the triangle's depth
    and number if the depth test passes (:func:`renderer.visibility_buffer.nearer_or_later`;
    always without ``depth_test``). The pixel is written either way, with its old values
    where the triangle does not take it, as :func:`renderer.visibility_buffer.fill_columns`
    writes one pixel: no branch on the depth test."""
    e0, _, _, bar0 = edge_function(f, 0, col, row, top_left)
    e1, _, _, bar1 = edge_function(f, 1, col, row, top_left)
    e2, _, _, bar2 = edge_function(f, 2, col, row, top_left)
    if not ((e0 > bar0) & (e1 > bar1) & (e2 > bar2)):
        return
    z_row = plane[8] + plane[10] * (row + 0.5 - plane[7])  # renderer.raster.row_depth
    z = depth_bits(z_row + plane[9] * (col + 0.5 - plane[6]))  # renderer.raster.pixel_depth
    at = np.uint64(col)
    depth_row, index_row = depth[row], tri_index[row]
    old_z, old_k = depth_row[at], index_row[at]
    takes = nearer_or_later(z, kk, old_z, old_k) | (not depth_test)
    depth_row[at] = z if takes else old_z
    index_row[at] = kk if takes else old_k
