"""Narrow triangles by edge functions: the same pixels, depths and ties as a division per edge
and row, in one group of vector lanes that never leaves the row."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from renderer.edge_functions import fill_narrow_rows, lanes_start, owns_ties
from renderer.fill_rules import FILL_RULES, TOP_LEFT
from renderer.jit import njit
from renderer.raster import fill_row, set_up
from renderer.spans import LANES
from renderer.window import SUBPIXEL

from .pixel_soups import same_buffer_both_ways, window_of


@njit
def start_of(f, width):
    return lanes_start(f, width)


@pytest.mark.parametrize("x0, x1, width, expected", [
    (0, 7, 20, (0, 8)),              # eight columns: one group from the first
    (0, 8, 20, (-1, 0)),             # nine: too wide
    (3, 4, 20, (3, 8)),              # two columns: still whole lanes
    (15, 19, 20, (12, 8)),           # at the row's end the group moves left
    (-30, 5, 20, (0, 8)),            # off the left edge: only the columns in the image count
    (17, 60, 20, (12, 8)),           # off the right edge likewise
    (2, 4, 7, (-1, 0)),              # an image narrower than the lanes
])
def test_the_group_of_lanes_holds_the_triangles_columns_in_the_image(x0, x1, width, expected):
    """Corners on the pixel centres of columns x0 … x1: a box of up to eight columns in the
    image is one group, starting at its first column or moved left to end at the row's end."""
    f = np.array([[x0, 0], [x1, 0], [x0, 5]], np.int64) * SUBPIXEL
    assert start_of(f, width) == expected


def test_a_box_between_pixel_centres_has_no_lanes_to_fill():
    """A triangle between two columns of centres covers none: its group has no lanes."""
    f = np.array([[SUBPIXEL + 10, 0], [SUBPIXEL + 200, 0], [SUBPIXEL + 10, 5 * SUBPIXEL]], np.int64)
    start, lanes = start_of(f, 20)
    assert start >= 0 and lanes == 0


@njit
def owns_of(dx, dy, top_left):
    return owns_ties(dx, dy, top_left)


def test_left_and_bottom_edges_own_their_ties_under_the_top_left_rule():
    """Counter-clockwise, y up: a left edge runs down, a bottom edge runs right."""
    assert owns_of(0, -5, True) and owns_of(3, -5, True) and owns_of(5, 0, True)
    assert not owns_of(0, 5, True) and not owns_of(-5, 0, True)
    assert owns_of(0, 5, False) and owns_of(-5, 0, False) and not owns_of(0, -5, False) and not owns_of(5, 0, False)


@njit
def draw_narrow_ones(setup, rule, depth_test, by_lanes, depth, tri_index):
    """Draw, in order, every triangle of ``setup`` that fits one group of lanes, by edge
    functions (``by_lanes``) or by one division per edge and row; how many were drawn."""
    drawn = 0
    for k in range(setup.ccw.shape[0]):
        columns = lanes_start(setup.ccw[k], depth.shape[1])
        if columns[0] < 0 or setup.rows[k, 0] > setup.rows[k, 1]:
            continue
        drawn += 1
        lo, hi = setup.rows[k, 0], setup.rows[k, 1]
        if by_lanes:
            fill_narrow_rows(setup.ccw[k], columns, lo, hi, setup.plane[k], np.int32(k), rule == TOP_LEFT,
                             depth_test, depth, tri_index)
        else:
            for row in range(lo, hi + 1):
                fill_row(k, row, setup, rule, depth_test, 0, depth, tri_index)
    return drawn


def narrow_triangles(rng, n, width, height):
    """Triangles at most eight columns wide: corners on pixel centres (edges through centres,
    horizontal edges), on quarter pixels, anywhere, and hanging over the image's sides."""
    out = []
    for k in range(n):
        x = rng.integers(-4, width, 1)[0] * SUBPIXEL
        y = rng.integers(-2, height, 1)[0] * SUBPIXEL
        kind = k % 4
        if kind == 0:
            f = rng.integers(0, 8, (3, 2)) * SUBPIXEL
            if rng.random() < 0.5:  # a horizontal edge, bottom or top
                f[1, 1] = f[0, 1]
        elif kind == 1:
            f = rng.integers(0, 29, (3, 2)) * (SUBPIXEL // 4)
        elif kind == 2:
            f = rng.integers(0, 7 * SUBPIXEL + SUBPIXEL - 1, (3, 2))
        else:  # tall: more rows than a block
            f = np.array([[0, 0], [rng.integers(0, 8 * SUBPIXEL), rng.integers(10, 40) * SUBPIXEL],
                          [rng.integers(0, 8 * SUBPIXEL), rng.integers(0, 40) * SUBPIXEL]])
        out.append(f + [x, y])
    return np.array(out, np.int64)


@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("depth_test", [True, False])
@pytest.mark.parametrize("width", [LANES, 13, 37])
def test_narrow_triangles_by_edge_functions_fill_what_a_division_per_row_fills(rule, depth_test, width):
    """800 narrow triangles drawn together, front and back faces, over one another at random
    depths and at equal ones (ties go to the later triangle): the same depth and triangle at
    every pixel as the spans found by division, on images as wide as the lanes and wider."""
    height = 41
    rng = np.random.default_rng(width)
    fixed = narrow_triangles(rng, 800, width, height)
    setup = set_up(fixed, window_of(rng, fixed), height, False)
    drawn, tri_index = same_buffer_both_ways(
        lambda by_lanes, depth, tri_index: draw_narrow_ones(setup, FILL_RULES[rule], depth_test, by_lanes, depth,
                                                            tri_index), width, height)
    assert drawn > 500 and len(np.unique(tri_index)) > 60  # the sample really draws, and overdraws


_NARROW_AS_PYTHON = """
import numba
import numpy as np
assert numba.config.DISABLE_JIT
from renderer.edge_functions import fill_narrow_rows, lanes_start
from renderer.raster import scanline_span
from renderer.window import SUBPIXEL
for width in (3, 8, 13):
    for x0 in range(-3, width + 2):
        for x1 in range(x0 + 1, x0 + 9):
            f = np.array([[x0, 0], [x1, 0], [x0, 2]], np.int64) * SUBPIXEL
            columns = lanes_start(f, width)
            if columns[0] < 0:
                continue
            depth, tri_index = np.full((3, width), 1 << 23, np.int32), np.zeros((3, width), np.int32)
            plane = np.array([0, 0, 0, 0, 0, 0, 0.0, 0.0, 0.25, 0.0, 0.0])
            fill_narrow_rows(f, columns, 0, 2, plane, np.int32(1), True, True, depth, tri_index)
            for row in range(3):
                first, last = scanline_span(f, row)
                assert tri_index[row].tolist() == [int(first <= c <= last) for c in range(width)], (width, x0, x1)
"""


def test_no_lane_reads_or_writes_outside_the_row():
    """A lane outside the triangle writes back what it read, so its values cannot show a lane
    past the row's end: run as plain Python (NUMBA_DISABLE_JIT=1), where any index past the
    row raises, every narrow box at every place on rows narrower than, as wide as and wider
    than the lanes fills exactly its columns."""
    repo = Path(__file__).resolve().parents[2]
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PYTHONPATH=os.pathsep.join([str(repo), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", _NARROW_AS_PYTHON], cwd=repo, env=env, capture_output=True,
                          text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-3000:]
