"""Between raster and shading: the triangles that won a pixel, renumbered in draw order."""
import numpy as np
import pytest

from renderer.raster import EMPTY
from renderer.visible import visible_triangles


def test_the_winners_keep_their_order_and_pixels_keep_their_triangle():
    """Triangles 2 and 7 of 9 won pixels: they become 0 and 1, empty pixels stay empty."""
    tri_index = np.array([[7, EMPTY, 7], [2, 2, EMPTY]], np.int32)
    ids = visible_triangles(tri_index, 9)
    assert ids.tolist() == [2, 7]
    assert tri_index.tolist() == [[1, EMPTY, 1], [0, 0, EMPTY]]


def test_an_empty_image_has_no_winners():
    tri_index = np.full((3, 4), EMPTY, np.int32)
    assert visible_triangles(tri_index, 5).tolist() == []
    assert (tri_index == EMPTY).all()


@pytest.mark.parametrize("seed", range(3))
def test_renumbering_is_a_bijection_that_keeps_order(seed):
    """Random visibility buffers: each pixel names the same triangle through the winners'
    list, the winners are exactly the triangles on screen, sorted, and pixels showing the
    same triangle still show the same number (the spans of shading are unchanged)."""
    rng = np.random.default_rng(seed)
    before = rng.integers(-1, 5000, (61, 97)).astype(np.int32)
    before[rng.uniform(size=before.shape) < 0.3] = EMPTY
    after = before.copy()
    ids = visible_triangles(after, 5000)
    assert ids.tolist() == sorted(set(before[before >= 0].tolist()))
    np.testing.assert_array_equal(after == EMPTY, before == EMPTY)
    np.testing.assert_array_equal(ids[after[after >= 0]], before[before >= 0])
    np.testing.assert_array_equal(after[:, 1:] == after[:, :-1], before[:, 1:] == before[:, :-1])
