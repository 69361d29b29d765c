"""The fill rules (renderer/fill_rules.py): two numbers, one per rule, found by the names
scenes and options give them; and what each means where two triangles share an edge
through pixel centres: every such centre drawn once, by the edge's owner under the rule."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.fill_rules import BOTTOM_RIGHT, FILL_RULES, TOP_LEFT
from renderer.raster import rasterize_triangles
from renderer.window import SUBPIXEL


def test_each_rule_s_name_finds_its_own_number():
    assert FILL_RULES == {"top-left": TOP_LEFT, "bottom-right": BOTTOM_RIGHT}
    assert TOP_LEFT != BOTTOM_RIGHT


def square_in_two(n):
    """A square of corners on the pixel centres (0, 0) … (n, n) (window coordinates, y up) cut
    along its diagonal, both counter-clockwise: triangle 0 below the diagonal, which is its
    left edge (running down, from (n, n) to (0, 0)); triangle 1 above it, its right edge."""
    corners = np.array([[(0, 0), (n, 0), (n, n)], [(0, 0), (n, n), (0, n)]], np.int64) * SUBPIXEL
    window = np.concatenate([corners / SUBPIXEL + 0.5, np.full((2, 3, 1), 0.5)], axis=2)
    return corners, window


@pytest.mark.parametrize("rule, owner", [("top-left", 0), ("bottom-right", 1)])
def test_a_shared_edge_s_centres_go_to_one_triangle_chosen_by_the_rule(rule, owner):
    """The diagonal's centres (i, i) lie on both triangles; drawn with the depth test off (the
    later triangle would win any pixel both drew), each goes to the triangle whose edge the
    rule makes the owner: the lower one's left edge under top-left, the upper one's right
    edge under bottom-right."""
    n = 6
    corners, window = square_in_two(n)
    _, tri_index, _, _ = rasterize_triangles(corners, window, n + 2, n + 2, fill_rule=rule, depth_test=False)
    diagonal = tri_index[np.arange(1, n), np.arange(1, n)]
    assert diagonal.tolist() == [owner] * (n - 1)
