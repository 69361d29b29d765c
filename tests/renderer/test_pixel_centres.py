"""Which pixel centres a triangle's box holds: triangles that can cover none get no rows at set-up.

Coordinates are the window's fixed-point grid (y up, 1/256 pixel, pixel centre (i, j) at
(256·i, 256·j)). The set-up is :func:`renderer.raster.set_up`; what it drops must be what
drawing would have drawn nothing of, so the buffers stay the same bytes.
"""
import numpy as np
import pytest

from renderer.raster import depth_plane, rasterize_triangles, set_up, weights_plane
from renderer.window import SUBPIXEL


def ceil_centre(v):
    """The first pixel centre index at or above fixed-point ``v`` (numpy, any shape)."""
    return -(-v // SUBPIXEL)


def sub_pixel_soup(rng, n, size, reach=3 * SUBPIXEL // 4):
    """``n`` triangles whose corners lie within ``reach`` (fixed point) of a point of a
    ``size`` × ``size`` image, with window depths: about a pixel across or less, boxes
    holding no pixel centre, one, two or four; a third have a corner on a centre, so that
    centres fall on edges."""
    corner = rng.integers(0, size * SUBPIXEL, (n, 1, 2))
    fixed = corner + rng.integers(-reach, reach, (n, 3, 2))
    fixed[::3, 0] = (fixed[::3, 0] // SUBPIXEL) * SUBPIXEL
    window = np.concatenate([fixed / SUBPIXEL + 0.5, rng.uniform(0, 1, (n, 3, 1))], axis=2)
    return fixed.astype(np.int64), window


def signed_areas(fixed):
    """Twice each triangle's signed area, (K,) from (K, 3, 2)."""
    (x0, y0), (x1, y1), (x2, y2) = fixed.transpose(1, 2, 0)
    return (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0)


def test_a_triangle_whose_box_holds_no_pixel_centre_is_set_up_only_as_far_as_it_is_read():
    """A triangle whose box holds no pixel centre — it lies between two rows of centres, or
    between two columns — gets its facing, rows (none) and weights' plane (translucent spans
    read it), not its counter-clockwise corners or depth plane, which only drawing reads;
    every other triangle with an area gets all of them, as set up one by one."""
    rng = np.random.default_rng(21)
    corner = rng.integers(0, 30 * SUBPIXEL, (600, 1, 2))
    fixed = (corner + rng.integers(-SUBPIXEL, SUBPIXEL, (600, 3, 2))).astype(np.int64)  # about a pixel across
    window = np.concatenate([fixed / SUBPIXEL + 0.5, rng.uniform(0, 1, (600, 3, 1))], axis=2)
    setup = set_up(fixed, window, 30, False)
    has_rows = setup.rows[:, 0] <= setup.rows[:, 1]
    a_row = np.maximum(ceil_centre(fixed[:, :, 1].min(1)), 0) <= np.minimum(fixed[:, :, 1].max(1) // SUBPIXEL, 29)
    a_column = ceil_centre(fixed[:, :, 0].min(1)) <= fixed[:, :, 0].max(1) // SUBPIXEL
    np.testing.assert_array_equal(has_rows, a_row & a_column & (signed_areas(fixed) != 0))
    assert 50 < has_rows.sum() < 550 and (a_row & ~a_column).sum() > 50
    flat_window = window.reshape(-1, 3)
    for k in range(len(fixed)):
        plane = np.zeros(11)
        weights_plane(flat_window, 3 * k, 3 * k + 1, 3 * k + 2, plane)
        depth_plane(flat_window, 3 * k, 3 * k + 1, 3 * k + 2, plane[6:])
        assert setup.plane[k, :6].tobytes() == plane[:6].tobytes(), k
        if has_rows[k]:
            assert setup.plane[k, 6:].tobytes() == plane[6:].tobytes(), k
            clockwise = signed_areas(fixed[k:k + 1])[0] < 0
            assert (setup.ccw[k] == (fixed[k, [0, 2, 1]] if clockwise else fixed[k])).all(), k


def test_a_lone_pixel_centre_outside_the_triangle_drops_it_at_set_up():
    """With the lone-centre test, a triangle whose box holds one pixel centre (on one of the
    image's rows; the triangle with an area) gets no rows exactly when the centre lies
    strictly outside one of its edges (an edge function of the wrong sign; a centre on an
    edge is kept, for the fill rule to decide when drawing), and every such triangle
    drawn alone covers no pixel. Without the test each keeps its row; a triangle whose box
    holds more centres, or none, gets the same rows either way."""
    fixed, window = sub_pixel_soup(np.random.default_rng(5), 3000, 20)
    tested, plain = set_up(fixed, window, 20, False, lone_test=True), set_up(fixed, window, 20, False)
    columns = fixed[:, :, 0].max(1) // SUBPIXEL - ceil_centre(fixed[:, :, 0].min(1)) + 1
    rows = fixed[:, :, 1].max(1) // SUBPIXEL - ceil_centre(fixed[:, :, 1].min(1)) + 1
    area = signed_areas(fixed)
    col, row = ceil_centre(fixed.min(1)).T  # the box's first centre
    lone = (columns == 1) & (rows == 1) & (area != 0) & (row >= 0) & (row < 20)
    x, y = col * SUBPIXEL, row * SUBPIXEL
    outside = np.zeros(len(fixed), bool)
    for e in range(3):
        (xa, ya), (xb, yb) = fixed[:, e].T, fixed[:, (e + 1) % 3].T
        outside |= ((xb - xa) * (y - ya) - (yb - ya) * (x - xa)) * np.sign(area) < 0
    kept = tested.rows[:, 0] <= tested.rows[:, 1]
    assert (plain.rows[lone, 0] <= plain.rows[lone, 1]).all()
    np.testing.assert_array_equal(kept[lone], ~outside[lone])
    np.testing.assert_array_equal(kept[~lone], plain.rows[~lone, 0] <= plain.rows[~lone, 1])
    dropped = np.flatnonzero(lone & ~kept)
    assert len(dropped) > 300 and (lone & kept).sum() > 300 and (~lone & (columns * rows > 1)).sum() > 500
    for k in dropped[:200]:
        assert (rasterize_triangles(fixed[k:k + 1], window[k:k + 1], 22, 20)[1] < 0).all(), k


@pytest.mark.parametrize("fill_rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("cull_back", [False, True])
def test_batches_after_a_batch_finer_than_the_pixels_test_lone_centres_and_draw_the_same(fill_rule, cull_back):
    """A batch's set-up tests its triangles' lone pixel centres when the batch before it
    spanned fewer than LONE_ROWS rows a triangle; the first batch never does. Whatever it
    drops, the buffers are those of one pass over every triangle (both fill rules, with and
    without back-face culling)."""
    from unittest import mock

    import renderer.raster as raster
    from renderer.pixel_centres import LONE_ROWS
    fixed, window = sub_pixel_soup(np.random.default_rng(8), 4000, 24, SUBPIXEL // 2)
    tests = []

    def set_up_corners(*args, lone_test=False, **kwargs):
        tests.append(lone_test)
        return set_up_plain(*args, lone_test=lone_test, **kwargs)

    set_up_plain = raster.set_up_corners
    one_pass = raster.rasterize_visibility(raster.whole_triangles(fixed, window), 24, 24, fill_rule,
                                           cull_back=cull_back, batch=None)
    with mock.patch.object(raster, "set_up_corners", set_up_corners):
        batches = raster.rasterize_visibility(raster.whole_triangles(fixed, window), 24, 24, fill_rule,
                                              cull_back=cull_back, batch=1000)
    assert tests == [False, True, True, True]
    assert raster.mean_rows(raster.set_up(fixed, window, 24, cull_back)) < LONE_ROWS
    several = (fixed.max(1) // SUBPIXEL - ceil_centre(fixed.min(1)) >= 1).any(1)
    assert several.sum() > 100  # boxes of two or four centres, which the lone test leaves alone
    assert (one_pass.tri_index >= 0).sum() > 100
    np.testing.assert_array_equal(batches.tri_index, one_pass.tri_index)
    np.testing.assert_array_equal(batches.depth, one_pass.depth)


def test_the_corners_centre_cells_tell_a_box_without_pixel_centres():
    """From the three corners' centre cells alone (:func:`renderer.window.centre_cell`),
    :func:`renderer.pixel_centres.box_misses_centres` is True exactly when the box holds no
    column or no row of pixel centres, as the coordinates say: corners on a centre, just
    either side of one, far apart, and at negative coordinates (the floor of a negative
    fixed-point value)."""
    from renderer.pixel_centres import box_misses_centres
    from renderer.window import centre_cells

    rng = np.random.default_rng(13)
    fixed, _ = sub_pixel_soup(rng, 4000, 8)
    fixed[::4] -= 5 * SUBPIXEL  # a quarter of them at negative coordinates
    fixed[1::5, :, 1] = fixed[1::5, :1, 1] + rng.integers(-1, 2, (len(fixed[1::5]), 3))  # within a step of one y
    cells = np.empty(3 * len(fixed), np.int64)
    centre_cells(fixed.reshape(-1, 2), cells)
    cells = cells.reshape(-1, 3)
    no_column = ceil_centre(fixed[:, :, 0].min(1)) > fixed[:, :, 0].max(1) // SUBPIXEL
    no_row = ceil_centre(fixed[:, :, 1].min(1)) > fixed[:, :, 1].max(1) // SUBPIXEL
    got = np.array([box_misses_centres(*c) for c in cells])
    np.testing.assert_array_equal(got, no_column | no_row)
    assert 500 < got.sum() < 3500 and (no_column & ~no_row).sum() > 100 and (no_row & ~no_column).sum() > 100


@pytest.mark.parametrize("fill_rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("cull_back", [False, True])
def test_triangles_dropped_by_their_cells_draw_nothing_and_the_rest_set_up_alike(fill_rule, cull_back):
    """The raster's set-up drops a triangle whose box holds no pixel centre from its corners'
    cells before working out anything else (:data:`renderer.raster.DROP_EMPTY_BOXES`): every
    triangle it drops gets no rows without them either, every other gets the same rows,
    facing, planes and counter-clockwise corners, and the visibility buffers are the bytes
    of a set-up without cells (both fill rules, with and without back-face culling)."""
    from unittest import mock

    import renderer.raster as raster
    from renderer.window import NO_CELLS

    fixed, window = sub_pixel_soup(np.random.default_rng(17), 4000, 24, SUBPIXEL // 2)
    whole = raster.whole_triangles(fixed, window)
    with_cells = raster.set_up_corners(whole.corners, whole.vertices, 24, cull_back, lone_test=True)
    plain = raster.set_up(fixed, window, 24, cull_back, lone_test=True)
    drawn = plain.rows[:, 0] <= plain.rows[:, 1]
    np.testing.assert_array_equal(with_cells.rows[:, 0] <= with_cells.rows[:, 1], drawn)
    np.testing.assert_array_equal(with_cells.rows[drawn], plain.rows[drawn])
    np.testing.assert_array_equal(with_cells.front[drawn], plain.front[drawn])
    np.testing.assert_array_equal(with_cells.plane[drawn], plain.plane[drawn])
    np.testing.assert_array_equal(with_cells.ccw[drawn], plain.ccw[drawn])
    np.testing.assert_array_equal(with_cells.row_sums, plain.row_sums)
    dropped = ~with_cells.front & ~drawn & plain.front  # dropped by the cells, facing the viewer
    assert dropped.sum() > 500 and drawn.sum() > 500
    cells = raster.rasterize_visibility(whole, 24, 24, fill_rule, cull_back=cull_back, batch=1000)
    no_cells = whole._replace(cells=NO_CELLS)
    with mock.patch.object(raster, "DROP_EMPTY_BOXES", 0):
        reference = raster.rasterize_visibility(no_cells, 24, 24, fill_rule, cull_back=cull_back, batch=1000)
    np.testing.assert_array_equal(cells.tri_index, reference.tri_index)
    np.testing.assert_array_equal(cells.depth, reference.depth)
