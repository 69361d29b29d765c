"""The edge walk (renderer/edge_walk.py): each row's span by stepping the edges, the same
columns as one division per edge and row (renderer.raster.scanline_span)."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.edge_walk import column_bound, edge_walk, split_at_middle, walk_on, walked_columns
from renderer.fill_rules import FILL_RULES
from renderer.raster import row_span
from renderer.window import SUBPIXEL


def _divided_bound(f, e, row, top_left):
    """Edge ``e``'s column bound on ``row`` by one division, as scanline_span works it out: a
    left edge's first column, a right edge's last column + 1."""
    (xa, ya), (xb, yb) = f[e], f[(e + 1) % 3]
    dx, dy, y = xb - xa, yb - ya, row * SUBPIXEL
    if dy < 0:
        num, den = -dy * xa - dx * (y - ya), -dy * SUBPIXEL
        return -(-num // den) if top_left else num // den + 1
    num, den = dy * xa + dx * (y - ya), dy * SUBPIXEL
    return -(-num // den) if top_left else num // den + 1


def _cases(seed, n):
    """Tall thin triangles, flat-bottomed and flat-topped ones, and random ones with corners on
    the subpixel grid or on pixel centres (ties), counter-clockwise, none without area."""
    rng = np.random.default_rng(seed)
    cases = [np.array([[0, 0], [3 * SUBPIXEL + 17, 2000 * SUBPIXEL + 5], [-SUBPIXEL + 3, 1999 * SUBPIXEL]]),
             np.array([[0, 0], [40 * SUBPIXEL, 0], [13 * SUBPIXEL, 30 * SUBPIXEL]]),      # horizontal bottom edge
             np.array([[0, 30 * SUBPIXEL], [13 * SUBPIXEL, 0], [40 * SUBPIXEL, 30 * SUBPIXEL]])]  # horizontal top edge
    cases += [rng.integers(-60 * SUBPIXEL, 60 * SUBPIXEL, (3, 2)) // rng.choice([1, SUBPIXEL]) * rng.choice([1, SUBPIXEL])
              for _ in range(n)]
    for f in cases:
        area = (f[1, 0] - f[0, 0]) * (f[2, 1] - f[0, 1]) - (f[2, 0] - f[0, 0]) * (f[1, 1] - f[0, 1])
        if area != 0:
            yield np.ascontiguousarray(f if area > 0 else f[[0, 2, 1]], dtype=np.int64)


@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
def test_two_edges_split_at_the_middle_corner_bound_every_row_as_the_three_do(rule):
    """The course's split (the long edge on one side; below the middle corner the low edge,
    from it up the high edge, on the other), both walked, gives every row of the triangle the
    columns one division per edge and row gives: the third edge never narrows a row, and a
    horizontal edge's row is kept or dropped by the fill rule, whichever corner it starts from."""
    top_left = rule == "top-left"
    checked = flat = 0
    for f in _cases(11, 200):
        lo, hi = -(-int(f[:, 1].min()) // SUBPIXEL), int(f[:, 1].max()) // SUBPIXEL
        for rotation in range(3):  # the same triangle from each corner: the split must not care
            g = np.ascontiguousarray(np.roll(f, rotation, axis=0))
            long_edge, low_edge, high_edge, split, a, b = split_at_middle(g, lo, hi, top_left)
            long_walk, walked = edge_walk(g, long_edge, a, 1, top_left), {}
            for row in range(a, b + 1):
                short = edge_walk(g, low_edge if row < split else high_edge, row, 1, top_left)
                walked[row] = walked_columns(long_walk, short, top_left, 1 << 20)
                long_walk = walk_on(long_walk)
            for row in range(lo, hi + 1):
                first, last = row_span(0, row, g[None], 1 << 20, FILL_RULES[rule])
                expected = (first, last) if first <= last else None
                got = walked.get(row, (1, 0))
                assert (got if got[0] <= got[1] else None) == expected, f"triangle {g.tolist()} row {row}"
                checked += expected is not None
        flat += len(set(f[:, 1].tolist())) == 2
    assert checked > 10000 and flat >= 2


@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("stride", [1, 3])
def test_walking_an_edge_gives_every_row_the_column_of_dividing_for_it(rule, stride):
    """The edge walk (x stepped by Δx/Δy a row, the fraction kept as a remainder) finds the
    same column bound as one division per edge and row, on every ``stride``-th row: on tall
    thin triangles whose edges cross thousands of rows, and with corners on pixel centres
    (ties), also on rows beyond the edge's ends."""
    top_left = rule == "top-left"
    checked = 0
    for f in _cases(7, 60):
        lo, hi = int(f[:, 1].min()) // SUBPIXEL - 2, -(-int(f[:, 1].max()) // SUBPIXEL) + 2
        for e in range(3):
            if f[(e + 1) % 3, 1] == f[e, 1]:
                continue  # a horizontal edge is never walked (split_at_middle)
            walk = edge_walk(f, e, lo, stride, top_left)
            for row in range(lo, hi + 1, stride):
                assert column_bound(walk, top_left) == _divided_bound(f, e, row, top_left), f"{f.tolist()} edge {e}"
                walk = walk_on(walk)
                checked += 1
    assert checked > 9000 // stride
