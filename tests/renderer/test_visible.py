"""Between raster and shading: the triangles that won a pixel, renumbered in the order the rows show them."""
import numpy as np
import pytest

from renderer.raster import EMPTY
from renderer.visible import HELD_PIXELS_PER_TRIANGLE, PIXELS_PER_TRIANGLE, number_in_sight, renumbering_pays, visible_triangles
from renderer.workspace import Workspace


def test_the_winners_are_numbered_as_the_rows_first_show_them():
    """Triangles 7, 2 and 4 of 9 won pixels: row 0 shows 7 first, then row 1 shows 2 and 4,
    so they become 0, 1 and 2; empty pixels stay empty."""
    tri_index = np.array([[EMPTY, 7, 7], [2, 7, 4]], np.int32)
    ids = visible_triangles(tri_index, 9)
    assert ids.tolist() == [7, 2, 4]
    assert tri_index.tolist() == [[EMPTY, 0, 0], [1, 0, 2]]


def test_an_empty_image_has_no_winners():
    tri_index = np.full((3, 4), EMPTY, np.int32)
    assert visible_triangles(tri_index, 5).tolist() == []
    assert (tri_index == EMPTY).all()


@pytest.mark.parametrize("seed", range(3))
def test_renumbering_is_a_bijection_in_the_order_of_first_sight(seed):
    """Random visibility buffers: each pixel names the same triangle through the winners'
    list, the winners are exactly the triangles on screen, each listed where the rows first
    show it, and pixels showing the same triangle still show the same number (the spans of
    shading are unchanged)."""
    rng = np.random.default_rng(seed)
    before = rng.integers(-1, 5000, (61, 97)).astype(np.int32)
    before[rng.uniform(size=before.shape) < 0.3] = EMPTY
    after = before.copy()
    ids = visible_triangles(after, 5000)
    shown = before[before >= 0]
    assert ids.tolist() == shown[np.sort(np.unique(shown, return_index=True)[1])].tolist()
    np.testing.assert_array_equal(after == EMPTY, before == EMPTY)
    np.testing.assert_array_equal(ids[after[after >= 0]], before[before >= 0])
    np.testing.assert_array_equal(after[:, 1:] == after[:, :-1], before[:, 1:] == before[:, :-1])


def test_numbering_puts_back_the_zeros_it_was_given_so_a_workspace_table_serves_the_next_frame():
    """:func:`number_in_sight` is handed an all-zero table and leaves it all zero; frames of
    other buffers through one workspace are numbered as each would be alone."""
    rng = np.random.default_rng(7)
    number, ids = np.zeros(300, np.int32), np.empty(300, np.int64)
    tri_index = rng.integers(-1, 300, (20, 30)).astype(np.int32)
    assert number_in_sight(tri_index, number, ids) > 0
    assert not number.any()
    ws = Workspace()
    for count in (300, 120, 300, 500):
        before = rng.integers(-1, count, (17, 23)).astype(np.int32)
        alone, reused = before.copy(), before.copy()
        np.testing.assert_array_equal(visible_triangles(reused, count, ws), visible_triangles(alone, count))
        np.testing.assert_array_equal(reused, alone)


def test_winners_are_renumbered_when_the_triangles_are_many_for_the_pixels():
    """Fewer than PIXELS_PER_TRIANGLE pixels a triangle: renumbered (a 20,480-triangle sphere
    at 512²); as many or more: the raster's numbers kept (the same sphere at 1024², a
    4,096-triangle cylinder at 512²)."""
    assert PIXELS_PER_TRIANGLE == 32
    assert renumbering_pays(20480, 512, 512)
    assert not renumbering_pays(20480, 1024, 1024)
    assert not renumbering_pays(4096, 512, 512)
    assert renumbering_pays(512 * 512 // 32 + 1, 512, 512) and not renumbering_pays(512 * 512 // 32, 512, 512)


def test_a_frame_painted_from_held_colours_renumbers_only_for_more_triangles():
    """Held colours (flat under a headlight) cost a colour and a normal a triangle when not
    renumbered: renumbered below HELD_PIXELS_PER_TRIANGLE pixels a triangle (the level-3
    sponge, 36,096 triangles, at 512²), not above (the 20,480-triangle sphere at 512², the
    sponge at 1024²)."""
    assert HELD_PIXELS_PER_TRIANGLE == 10
    assert renumbering_pays(36096, 512, 512, held=True)
    assert not renumbering_pays(20480, 512, 512, held=True) and renumbering_pays(20480, 512, 512)
    assert not renumbering_pays(36096, 1024, 1024, held=True) and renumbering_pays(36096, 1024, 1024)
    assert renumbering_pays(512 * 512 // 10 + 1, 512, 512, held=True)
    assert not renumbering_pays(512 * 512 // 10, 512, 512, held=True)
