"""The edge walk (renderer/edge_walk.py): each row's span by stepping the edges, the same
columns as one division per edge and row (renderer.raster.scanline_span)."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.edge_walk import edge_walk, walk_on, walk_span
from renderer.raster import FILL_RULES, row_span
from renderer.window import SUBPIXEL


def _walked_spans(f, lo, hi, stride, rule, width):
    """Every ``stride``-th row's span from ``lo`` to ``hi`` by walking the edges, and by one division per edge and row."""
    top_left = rule == FILL_RULES["top-left"]
    walks = tuple(edge_walk(f, e, lo, stride, top_left) for e in range(3))
    walked, divided = [], []
    for row in range(lo, hi + 1, stride):
        walked.append(walk_span(walks, row, top_left, width))
        divided.append(row_span(0, row, f[None], width, rule))
        walks = tuple(walk_on(w) for w in walks)
    empty = [(1, 0) if a > b else (a, b) for a, b in divided]
    return [(1, 0) if a > b else (a, b) for a, b in walked], empty


@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("stride", [1, 3])
def test_walking_the_edges_gives_every_row_the_span_of_dividing_for_it(rule, stride):
    """The edge walk (x stepped by Δx/Δy a row, the fraction kept as a remainder) finds the
    same columns as one division per edge and row: on tall thin triangles whose edges cross
    thousands of rows, with horizontal edges and with corners on pixel centres (ties)."""
    rng = np.random.default_rng(7)
    cases = [np.array([[0, 0], [3 * SUBPIXEL + 17, 2000 * SUBPIXEL + 5], [-SUBPIXEL + 3, 1999 * SUBPIXEL]]),
             np.array([[0, 0], [40 * SUBPIXEL, 0], [13 * SUBPIXEL, 30 * SUBPIXEL]]),      # horizontal bottom edge
             np.array([[0, 30 * SUBPIXEL], [13 * SUBPIXEL, 0], [40 * SUBPIXEL, 30 * SUBPIXEL]])]  # horizontal top edge
    cases += [rng.integers(-60 * SUBPIXEL, 60 * SUBPIXEL, (3, 2)) // rng.choice([1, SUBPIXEL]) * rng.choice([1, SUBPIXEL])
              for _ in range(60)]
    checked = 0
    for f in cases:
        area = (f[1, 0] - f[0, 0]) * (f[2, 1] - f[0, 1]) - (f[2, 0] - f[0, 0]) * (f[1, 1] - f[0, 1])
        if area == 0:
            continue
        f = np.ascontiguousarray(f if area > 0 else f[[0, 2, 1]], dtype=np.int64)
        lo, hi = int(f[:, 1].min()) // SUBPIXEL - 2, -(-int(f[:, 1].max()) // SUBPIXEL) + 2
        walked, divided = _walked_spans(f, lo, hi, stride, FILL_RULES[rule], 1 << 20)
        assert walked == divided, f"triangle {f.tolist()}"
        checked += sum(a <= b for a, b in divided)
    assert checked > 3000 // stride
