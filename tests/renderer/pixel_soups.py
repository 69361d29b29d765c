"""Helpers for the tests that draw a soup of small triangles two ways into one visibility
buffer and compare (test_edge_functions.py, test_one_pixel.py).

Not a test file.
"""
from __future__ import annotations

import numpy as np

from renderer.raster import DEPTH_CLEAR, EMPTY
from renderer.window import SUBPIXEL


def window_of(rng, fixed):
    """Window corners (K, 3, 3) for the fixed-point triangles ``fixed`` (K, 3, 2): x, y at the
    same points, random depths, a third of the triangles at one equal depth (ties)."""
    z = np.where(rng.random((len(fixed), 1)) < 0.3, 0.5, rng.uniform(0, 1, (len(fixed), 3)))
    return np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None]], axis=2)


def same_buffer_both_ways(draw, width, height):
    """Call ``draw(first_way, depth, tri_index)`` with True and with False, each on a clear
    (height, width) buffer; assert that both ways leave the same triangle and depth at every
    pixel, and return what the second call returned and its triangle buffer."""
    buffers = []
    for first_way in (True, False):
        depth, tri_index = np.full((height, width), DEPTH_CLEAR, np.int32), np.full((height, width), EMPTY, np.int32)
        drawn = draw(first_way, depth, tri_index)
        buffers.append((depth, tri_index))
    np.testing.assert_array_equal(buffers[0][1], buffers[1][1])
    np.testing.assert_array_equal(buffers[0][0], buffers[1][0])
    return drawn, buffers[1][1]
