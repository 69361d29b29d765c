"""Stage 6, the scanline fill: exact coverage in 1/256-pixel fixed point, the top-left rule, and the LEQUAL z-buffer.

Coordinates in these tests are given in *pixel-centre units*: vertex (i, j) sits exactly on
the centre of pixel (i, j), i.e. at window (i + 0.5, j + 0.5), fixed point (256·i, 256·j).
Window y is up, so in the pictures below the top line is the highest window row. A centre
exactly on an edge belongs to the triangle when the edge is a left edge or a bottom edge.
"""
import numpy as np
import pytest

from renderer.raster import DEPTH_MAX, rasterize_triangles
from renderer.window import SUBPIXEL


# --------------------------------------------------------------------------- helpers
def triangles(*tris, z=0.5):
    """(fixed, window) arrays for triangles whose vertices are (x, y) or (x, y, z) in pixel-centre units."""
    fixed, window = [], []
    for tri in tris:
        f = [(round(v[0] * SUBPIXEL), round(v[1] * SUBPIXEL)) for v in tri]
        fixed.append(f)
        window.append([(fx / SUBPIXEL + 0.5, fy / SUBPIXEL + 0.5, v[2] if len(v) > 2 else z) for (fx, fy), v in zip(f, tri)])
    return np.array(fixed, np.int64).reshape(-1, 3, 2), np.array(window, np.float64).reshape(-1, 3, 3)


def raster(tris, width, height, z=0.5):
    """Rasterise the triangles together: (depth, tri_index, bary, front), window rows (y up)."""
    return rasterize_triangles(*triangles(*tris, z=z), width, height)


def coverage(tri, width, height):
    """Boolean (H, W) coverage of one triangle, window rows."""
    return raster([tri], width, height)[1] >= 0


def picture(text):
    """A drawn expectation: one line per window row, the *top* line is the highest row; '.' is empty."""
    lines = [line.strip() for line in text.strip().splitlines()]
    return np.array([list(line) for line in lines[::-1]])


def as_picture(tri_index):
    """tri_index (window rows) drawn like :func:`picture` ('.' empty, else the triangle's index)."""
    return np.where(tri_index < 0, ".", tri_index.astype(str))


def owns(e, dx, dy):
    """The tie rule on one edge: E > 0 inside; E = 0 counts for a left edge (dy < 0) or a bottom edge (dy = 0, dx > 0)."""
    return e > 0 or (e == 0 and (dy < 0 or (dy == 0 and dx > 0)))


def inside_ccw_polygon(poly_fixed, x, y):
    """Exact point-in-convex-polygon (CCW, fixed point) with the same tie rule on every edge."""
    n = len(poly_fixed)
    for a in range(n):
        (xa, ya), (xb, yb) = poly_fixed[a], poly_fixed[(a + 1) % n]
        dx, dy = xb - xa, yb - ya
        if not owns(dx * (y - ya) - dy * (x - xa), dx, dy):
            return False
    return True


def reference_coverage(f, width, height):
    """The slow reference: bounding box, exact integer edge functions, the top-left tie rule."""
    f = [(int(x), int(y)) for x, y in f]
    out = np.zeros((height, width), bool)
    area = (f[1][0] - f[0][0]) * (f[2][1] - f[0][1]) - (f[2][0] - f[0][0]) * (f[1][1] - f[0][1])
    if area == 0:
        return out
    if area < 0:
        f = [f[0], f[2], f[1]]
    xs, ys = [p[0] for p in f], [p[1] for p in f]
    col0, col1 = max(0, -(-min(xs) // SUBPIXEL)), min(width - 1, max(xs) // SUBPIXEL)
    row0, row1 = max(0, -(-min(ys) // SUBPIXEL)), min(height - 1, max(ys) // SUBPIXEL)
    for row in range(row0, row1 + 1):
        for col in range(col0, col1 + 1):
            out[row, col] = inside_ccw_polygon(f, col * SUBPIXEL, row * SUBPIXEL)
    return out


def fan_draw_counts(centre, rim, width, height):
    """Rasterise each triangle (centre, rim[k], rim[k+1]) on its own; how many times each pixel was drawn."""
    counts = np.zeros((height, width), int)
    for k in range(len(rim)):
        counts += coverage((centre, rim[k], rim[(k + 1) % len(rim)]), width, height)
    return counts


def polygon_expectation(rim, width, height):
    """Pixels the convex polygon ``rim`` (CCW, pixel-centre units) owns under the tie rule."""
    poly = [(round(x * SUBPIXEL), round(y * SUBPIXEL)) for x, y in rim]
    return np.array([[inside_ccw_polygon(poly, col * SUBPIXEL, row * SUBPIXEL) for col in range(width)]
                     for row in range(height)])


# --------------------------------------------------------------------------- hand-computed rasters
def test_right_triangle_on_pixel_centres():
    """(1,1), (5,1), (1,5): left and bottom legs are in, the hypotenuse (a right edge) is out — 10 pixels."""
    expected = picture("""
        .......
        .......
        .#.....
        .##....
        .###...
        .####..
        .......
    """) == "#"
    cov = coverage([(1, 1), (5, 1), (1, 5)], 7, 7)
    np.testing.assert_array_equal(cov, expected)
    assert cov.sum() == 10


def test_triangle_with_no_centre_on_an_edge():
    """(−0.25,−0.25), (5.75,−0.25), (−0.25,5.75): exactly the centres with i, j ≥ 0 and i + j ≤ 5 — 21 pixels."""
    cov = coverage([(-0.25, -0.25), (5.75, -0.25), (-0.25, 5.75)], 7, 7)
    rows, cols = np.mgrid[0:7, 0:7]
    np.testing.assert_array_equal(cov, rows + cols <= 5)
    assert cov.sum() == 21


def test_centre_on_a_left_edge_is_in():
    """(2,0) → (6,4) → (2,8): the vertical edge x = 2 runs downward, a left edge, so centre (2,4) is drawn."""
    cov = coverage([(2, 0), (6, 4), (2, 8)], 9, 9)
    assert cov[4, 2]
    assert not cov[4, 1]
    assert cov[1:8, 2].all()  # the whole edge, between the vertices


def test_centre_on_a_right_edge_is_out():
    """(6,0) → (6,8) → (2,4): the vertical edge x = 6 runs upward, a right edge, so centre (6,4) is not drawn."""
    cov = coverage([(6, 0), (6, 8), (2, 4)], 9, 9)
    assert not cov[4, 6]
    assert cov[4, 5]
    assert not cov[:, 6].any()


def test_centre_on_a_bottom_edge_is_in():
    """(0,2) → (8,2) → (4,6): the horizontal edge y = 2 runs in +x, the bottom edge (y up), so centre (4,2) is drawn."""
    cov = coverage([(0, 2), (8, 2), (4, 6)], 9, 9)
    assert cov[2, 4]
    assert not cov[1, 4]
    assert cov[2, 0:8].all() and not cov[2, 8]  # the far end is on the right edge


def test_centre_on_a_top_edge_is_out():
    """(4,0) → (8,6) → (0,6): the horizontal edge y = 6 runs in −x, the top edge (y up), so centre (4,6) is not drawn."""
    cov = coverage([(4, 0), (8, 6), (0, 6)], 9, 9)
    assert not cov[6, 4]
    assert cov[5, 4]
    assert not cov[6].any()


def test_square_split_along_the_rising_diagonal():
    """Square (1,1)–(7,7) split by (1,1)–(7,7): the diagonal's centres go to the lower-right triangle (its left edge)."""
    _, tri_index, _, _ = raster([[(1, 1), (7, 1), (7, 7)], [(1, 1), (7, 7), (1, 7)]], 8, 8)
    expected = picture("""
        ........
        .111110.
        .111100.
        .111000.
        .110000.
        .100000.
        .000000.
        ........
    """)
    np.testing.assert_array_equal(as_picture(tri_index), expected)


def test_square_split_along_the_falling_diagonal():
    """Square (1,1)–(7,7) split by (7,1)–(1,7): the diagonal's centres go to the upper-right triangle (its left edge)."""
    _, tri_index, _, _ = raster([[(1, 1), (7, 1), (1, 7)], [(7, 1), (7, 7), (1, 7)]], 8, 8)
    expected = picture("""
        ........
        .011111.
        .001111.
        .000111.
        .000011.
        .000001.
        .000000.
        ........
    """)
    np.testing.assert_array_equal(as_picture(tri_index), expected)


@pytest.mark.parametrize("first_diagonal", [True, False])
def test_shared_diagonal_is_drawn_exactly_once(first_diagonal):
    """Each triangle drawn on its own: every pixel of the half-open square [1,7)² is drawn by exactly one of them."""
    if first_diagonal:
        pair = [[(1, 1), (7, 1), (7, 7)], [(1, 1), (7, 7), (1, 7)]]
    else:
        pair = [[(1, 1), (7, 1), (1, 7)], [(7, 1), (7, 7), (1, 7)]]
    counts = sum(coverage(t, 8, 8).astype(int) for t in pair)
    expected = np.zeros((8, 8), int)
    expected[1:7, 1:7] = 1
    np.testing.assert_array_equal(counts, expected)


def test_eight_triangle_fan_fills_a_square_exactly_once():
    """8 triangles around centre (8,8) with rim on the square (3..13)²: pixels [3,13)² drawn once each, nothing else."""
    rim = [(13, 8), (13, 13), (8, 13), (3, 13), (3, 8), (3, 3), (8, 3), (13, 3)]
    counts = fan_draw_counts((8, 8), rim, 17, 17)
    expected = np.zeros((17, 17), int)
    expected[3:13, 3:13] = 1
    np.testing.assert_array_equal(counts, expected)
    assert counts[8, 8] == 1  # the shared centre vertex


def test_twelve_triangle_fan_draws_every_pixel_once():
    """12 triangles around (8,8), every spoke through pixel centres: drawn once inside the rim, never twice, never outside."""
    offsets = [(6, 0), (6, 4), (4, 6), (0, 6), (-4, 6), (-6, 4), (-6, 0), (-6, -4), (-4, -6), (0, -6), (4, -6), (6, -4)]
    rim = [(8 + dx, 8 + dy) for dx, dy in offsets]
    counts = fan_draw_counts((8, 8), rim, 17, 17)
    assert counts.max() == 1
    np.testing.assert_array_equal(counts == 1, polygon_expectation(rim, 17, 17))
    assert counts[5:12, 5:12].all()  # well inside the rim: every pixel drawn
    assert counts[8, 8] == 1  # the shared centre vertex
    # rim vertices on pixel centres: the leftmost (2,8) and lowest (8,2) are drawn, the rightmost and highest are not
    assert counts[8, 2] == 1 and counts[2, 8] == 1 and counts[8, 14] == 0 and counts[14, 8] == 0


@pytest.mark.parametrize("seed", range(4))
def test_fan_with_sub_pixel_vertices_draws_every_pixel_once(seed):
    """A 16-triangle fan with a random sub-pixel centre and rim: the pixels of the rim polygon are drawn exactly once."""
    rng = np.random.default_rng(seed)
    centre = (12 + rng.integers(-256, 257) / 256, 12 + rng.integers(-256, 257) / 256)
    angles = np.sort(rng.uniform(0, 2 * np.pi, 16))
    angles = angles[np.diff(np.append(angles, angles[0] + 2 * np.pi)) > 0.05]
    rim = [(round((12 + 10 * np.cos(a)) * 256) / 256, round((12 + 10 * np.sin(a)) * 256) / 256) for a in angles]
    for k in range(len(rim)):  # a valid fan: every triangle counter-clockwise, the rim convex
        for a, b, c in ((centre, rim[k], rim[(k + 1) % len(rim)]), (rim[k - 1], rim[k], rim[(k + 1) % len(rim)])):
            assert (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) > 0
    counts = fan_draw_counts(centre, rim, 25, 25)
    assert counts.max() == 1
    np.testing.assert_array_equal(counts == 1, polygon_expectation(rim, 25, 25))


def test_clockwise_twin_covers_the_same_pixels_and_is_a_back_face():
    """A clockwise triangle draws exactly the pixels of its counter-clockwise twin (ties included) and reports front=False."""
    ccw = [(1, 1), (5, 1), (1, 5)]
    cw = [(1, 1), (1, 5), (5, 1)]
    _, index_ccw, _, front_ccw = raster([ccw], 7, 7)
    _, index_cw, _, front_cw = raster([cw], 7, 7)
    np.testing.assert_array_equal(index_cw >= 0, index_ccw >= 0)
    assert front_ccw.tolist() == [True] and front_cw.tolist() == [False]


def test_clockwise_triangle_keeps_the_weights_in_source_order():
    """Weights are of the given vertices 1 and 2 whatever the winding: centre (2,1) of (0,0),(4,0),(0,4) has (1/2, 1/4)."""
    _, _, bary_ccw, _ = raster([[(0, 0), (4, 0), (0, 4)]], 6, 6)
    _, _, bary_cw, _ = raster([[(0, 0), (0, 4), (4, 0)]], 6, 6)
    np.testing.assert_allclose(bary_ccw[1, 2], [0.5, 0.25])  # centre (2,1): l1 = 2/4, l2 = 1/4
    np.testing.assert_allclose(bary_cw[1, 2], [0.25, 0.5])


@pytest.mark.parametrize("tri", [
    [(1, 1), (3, 3), (5, 5)],          # collinear through pixel centres
    [(0, 2), (3, 2), (6, 2)],          # along a row of centres
    [(2, 2), (2, 2), (5, 1)],          # a repeated vertex
    [(1, 1), (4, 1.001), (7, 1.0014)],  # not collinear, but collinear after snapping to 1/256
], ids=["diagonal", "horizontal", "repeated-vertex", "snaps-to-a-line"])
def test_zero_area_triangle_draws_nothing(tri):
    """A triangle of zero area in fixed point covers no pixel, even where its points lie on pixel centres."""
    f, _ = triangles(tri)
    assert (f[0, 1, 0] - f[0, 0, 0]) * (f[0, 2, 1] - f[0, 0, 1]) == (f[0, 2, 0] - f[0, 0, 0]) * (f[0, 1, 1] - f[0, 0, 1])
    assert not coverage(tri, 8, 8).any()


def test_pixels_off_the_buffer_are_clipped_away():
    """A triangle hanging over every side of a 6×4 buffer covers all of it and touches nothing outside."""
    depth, tri_index, _, _ = raster([[(-100, -100), (300, -100), (-100, 300)]], 6, 4)
    assert tri_index.shape == (4, 6) and (tri_index == 0).all()


def test_triangle_entirely_off_screen_draws_nothing():
    """A triangle left of, right of, below or above the buffer covers no pixel."""
    for tri in ([(-9, 1), (-1, 1), (-5, 5)], [(6, 1), (12, 1), (9, 5)], [(1, -9), (5, -9), (3, -1)],
                [(1, 4), (5, 4), (3, 9)]):
        assert not coverage(tri, 6, 4).any()


# --------------------------------------------------------------------------- depth
def test_depth_is_rounded_to_24_bits():
    """A constant depth 0.25 is stored as round(0.25·(2²⁴−1)) / (2²⁴−1); empty pixels stay 1.0."""
    depth, tri_index, _, _ = raster([[(0, 0), (4, 0), (0, 4)]], 6, 6, z=0.25)
    assert np.all(depth[tri_index >= 0] == np.floor(0.25 * DEPTH_MAX + 0.5) / DEPTH_MAX)
    assert np.all(depth[tri_index < 0] == 1.0)


def test_depth_is_interpolated_linearly_in_the_window():
    """z = 0.1 at (0,0), 0.3 at (4,0), 0.9 at (0,4): at centre (1,2) z = 0.1 + 0.2·(1/4) + 0.8·(2/4) = 0.55."""
    depth, _, _, _ = raster([[(0, 0, 0.1), (4, 0, 0.3), (0, 4, 0.9)]], 6, 6)
    assert depth[2, 1] == np.floor(0.55 * DEPTH_MAX + 0.5) / DEPTH_MAX


def test_equal_depth_the_later_triangle_wins():
    """LEQUAL: two triangles at the same depth, drawn in order 0 then 1 — triangle 1 is kept wherever they overlap."""
    tri = [(0, 0), (6, 0), (0, 6)]
    _, tri_index, _, _ = raster([tri, tri], 8, 8)
    assert set(np.unique(tri_index).tolist()) == {-1, 1}


@pytest.mark.parametrize("order", [(1, 2, 0), (2, 0, 1), (0, 2, 1), (2, 1, 0)])
def test_coincident_triangles_tie_whatever_their_corner_order(order):
    """The same sloped triangle listed with its corners in another order has bit-identical
    depths, so at every pixel the later one wins. Corners on pixel centres with depths
    0.5, 0.25 and 1.0 put many centres exactly on a 24-bit rounding tie, where a plane set
    up from each triangle's own first corner rounds either way (1 pixel in 13 here)."""
    tri = [(7, 24, 1.0), (21, 9, 0.0), (14, 14, 0.5)]
    other = [tri[i] for i in order]
    depth, tri_index, _, _ = raster([tri, other], 24, 24)
    assert set(np.unique(tri_index).tolist()) == {-1, 1}
    alone = raster([other], 24, 24)[0]
    assert (depth == alone).all()


def test_depths_equal_after_24_bit_rounding_count_as_equal():
    """Depths 0.5 and 0.5 + 1e−9 round to the same 24-bit value, so the later (slightly farther) triangle still wins."""
    _, tri_index, _, _ = raster([[(0, 0, 0.5), (6, 0, 0.5), (0, 6, 0.5)], [(0, 0, 0.5 + 1e-9), (6, 0, 0.5 + 1e-9),
                                                                          (0, 6, 0.5 + 1e-9)]], 8, 8)
    assert set(np.unique(tri_index).tolist()) == {-1, 1}


@pytest.mark.parametrize("order", [(0.25, 0.75), (0.75, 0.25)])
def test_the_nearer_triangle_wins(order):
    """Otherwise the smaller window depth wins, whatever the drawing order."""
    a, b = order
    tri = [(0, 0), (6, 0), (0, 6)]
    depth, tri_index, _, _ = raster([[(*v, a) for v in tri], [(*v, b) for v in tri]], 8, 8)
    nearer = 0 if a < b else 1
    assert set(np.unique(tri_index).tolist()) == {-1, nearer}
    assert np.all(depth[tri_index >= 0] == np.floor(0.25 * DEPTH_MAX + 0.5) / DEPTH_MAX)


def test_overlapping_triangles_at_different_depths_interleave_by_depth():
    """A tilted triangle through a flat one: each pixel shows whichever is nearer there."""
    flat = [(0, 0, 0.5), (8, 0, 0.5), (0, 8, 0.5)]
    tilted = [(0, 0, 0.0), (8, 0, 1.0), (0, 8, 0.0)]  # z = x/8: nearer than 0.5 left of x = 4
    depth, tri_index, _, _ = raster([flat, tilted], 9, 9)
    cols = np.broadcast_to(np.arange(9), (9, 9))
    covered = tri_index >= 0
    assert np.all(tri_index[covered & (cols < 4)] == 1)
    assert np.all(tri_index[covered & (cols > 4)] == 0)
    assert np.all(tri_index[covered & (cols == 4)] == 1)  # equal depth there: the later one


def test_z_buffer_keeps_the_nearest_and_among_equals_the_last():
    """80 overlapping triangles drawn together: each pixel keeps the least 24-bit depth any of them has there, the last one on ties."""
    width, height = 37, 29
    rng = np.random.default_rng(11)
    fixed = np.concatenate([rng.integers(-3, 40, (40, 3, 2)) * SUBPIXEL,
                            rng.integers(-3 * SUBPIXEL, 40 * SUBPIXEL, (40, 3, 2))])
    z = np.where(rng.random((80, 1)) < 0.5, rng.choice([0.25, 0.5], (80, 1)), rng.uniform(0, 1, (80, 3)))
    window = np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None] * np.ones((80, 3, 1))], axis=2)
    depth, tri_index, _, _ = rasterize_triangles(fixed, window, width, height)
    alone = np.full((80, height, width), np.inf)  # each triangle's own depth where it covers
    for k in range(80):
        d, idx, _, _ = rasterize_triangles(fixed[k:k + 1], window[k:k + 1], width, height)
        alone[k][idx == 0] = d[idx == 0]
    best = alone.min(axis=0)
    last_best = 79 - np.argmax((alone == best)[::-1], axis=0)
    covered = np.isfinite(best)
    np.testing.assert_array_equal(tri_index, np.where(covered, last_best, -1))
    np.testing.assert_array_equal(depth, np.where(covered, best, 1.0))
    assert (np.sum(alone == best, axis=0) > 1).sum() > 50  # many pixels really are ties


@pytest.mark.parametrize("batch", [1, 7, 79])
@pytest.mark.parametrize("depth_test", [True, False])
def test_drawing_in_batches_fills_the_buffer_one_pass_fills(batch, depth_test):
    """The 80 overlapping triangles (ties included) drawn ``batch`` at a time, each batch set up
    and filled over what the ones before it left: the depth and triangle of every pixel are
    those of one pass over all of them, z-buffer on or off."""
    from renderer.raster import rasterize_visibility
    from renderer.indexed_triangles import whole_triangles

    width, height = 37, 29
    rng = np.random.default_rng(11)
    fixed = rng.integers(-3 * SUBPIXEL, 40 * SUBPIXEL, (80, 3, 2))
    z = np.where(rng.random((80, 1)) < 0.5, rng.choice([0.25, 0.5], (80, 1)), rng.uniform(0, 1, (80, 3)))
    window = np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None] * np.ones((80, 3, 1))], axis=2)
    one_pass = rasterize_visibility(whole_triangles(fixed, window), width, height, depth_test=depth_test, batch=None)
    batches = rasterize_visibility(whole_triangles(fixed, window), width, height, depth_test=depth_test, batch=batch)
    assert len(np.unique(one_pass.tri_index)) > 40
    np.testing.assert_array_equal(batches.tri_index, one_pass.tri_index)
    np.testing.assert_array_equal(batches.depth, one_pass.depth)


def test_the_bottom_right_option_hands_ties_to_the_other_edges():
    """fill_rule="bottom-right" (the lessons' deliberately wrong rule) owns right and top edges instead of left and bottom."""
    f, w = triangles([(1, 1), (5, 1), (1, 5)])
    _, tri_index, _, _ = rasterize_triangles(f, w, 7, 7, fill_rule="bottom-right")
    expected = picture("""
        .......
        .......
        ..#....
        ..##...
        ..###..
        .......
        .......
    """) == "#"
    np.testing.assert_array_equal(tri_index >= 0, expected)


# --------------------------------------------------------------------------- against a slow reference
def random_triangles(rng, n, width, height):
    """Fixed-point triangles of every kind: on pixel centres, on 1/4 pixels, arbitrary, off-screen, slivers, huge."""
    out = []
    for k in range(n):
        kind = k % 6
        if kind == 0:    # on pixel centres: many centres exactly on edges and vertices
            f = rng.integers(-3, max(width, height) + 3, (3, 2)) * SUBPIXEL
        elif kind == 1:  # on quarter pixels
            f = rng.integers(-12, 4 * max(width, height) + 12, (3, 2)) * (SUBPIXEL // 4)
        elif kind == 2:  # arbitrary sub-pixel positions around the buffer
            f = rng.integers(-10 * SUBPIXEL, (max(width, height) + 10) * SUBPIXEL, (3, 2))
        elif kind == 3:  # entirely or mostly off-screen
            f = rng.integers(-60 * SUBPIXEL, 60 * SUBPIXEL, (3, 2)) + rng.choice([-1, 1], 2) * 50 * SUBPIXEL
        elif kind == 4:  # slivers: a long edge and a vertex close to it
            a, b = rng.integers(-5 * SUBPIXEL, (width + 5) * SUBPIXEL, (2, 2))
            c = (a + b) // 2 + rng.integers(-200, 201, 2)
            f = np.array([a, b, c])
        else:            # huge: vertices up to 100 000 pixels away
            f = rng.integers(-100_000 * SUBPIXEL, 100_000 * SUBPIXEL, (3, 2))
        out.append(f)
    return np.array(out, np.int64)


def test_matches_a_slow_reference_rasteriser_on_random_triangles():
    """Pixel for pixel, rasterize_triangles agrees with a bounding-box, integer edge-function rasteriser on 240 triangles."""
    width, height = 37, 29
    fixed = random_triangles(np.random.default_rng(20240611), 240, width, height)
    window = np.concatenate([fixed / SUBPIXEL + 0.5, np.full(fixed.shape[:2] + (1,), 0.5)], axis=2)
    n_ties = drawn = 0
    for f, w in zip(fixed, window):
        _, tri_index, _, front = rasterize_triangles(f[None], w[None], width, height)
        expected = reference_coverage(f, width, height)
        np.testing.assert_array_equal(tri_index >= 0, expected, err_msg=f"triangle {f.tolist()}")
        area = (f[1, 0] - f[0, 0]) * (f[2, 1] - f[0, 1]) - (f[2, 0] - f[0, 0]) * (f[1, 1] - f[0, 1])
        assert front[0] == (area > 0)
        drawn += expected.any()
        n_ties += _count_centres_on_edges(f, width, height)
    assert drawn > 120 and n_ties > 100  # the sample really exercises coverage and the tie rule


def _count_centres_on_edges(f, width, height):
    rows, cols = np.mgrid[0:height, 0:width] * SUBPIXEL
    hits = np.zeros((height, width), bool)
    for a in range(3):
        (xa, ya), (xb, yb) = f[a], f[(a + 1) % 3]
        e = (xb - xa) * (rows - ya) - (yb - ya) * (cols - xa)
        within = ((cols - xa) * (cols - xb) <= 0) & ((rows - ya) * (rows - yb) <= 0)
        hits |= (e == 0) & within
    return int(hits.sum())


def test_huge_triangles_are_exact_far_from_their_vertices():
    """A triangle with vertices 100 000 pixels away still puts its edge exactly through the expected centres."""
    # the lower-right half of a 200 000-pixel square: its diagonal y = x runs down-left, a left edge → centres on it are in
    tri = [(-100_000, -100_000), (100_000, -100_000), (100_000, 100_000)]
    cov = coverage(tri, 10, 10)
    rows, cols = np.mgrid[0:10, 0:10]
    np.testing.assert_array_equal(cov, rows <= cols)


def test_integer_z_buffer_matches_a_float_z_buffer_on_overlapping_triangles():
    """The integer 24-bit z-buffer (the fast path) against the plain one: every triangle's depth
    rounded to 24 bits in float64, compared LEQUAL, drawn in order. Constant depths a hair
    either side of a half step (0.499 and 0.501 of a step: one rounds down, one up), depths
    equal only after rounding (the later triangle wins), nearer and farther ones, overlapping
    in every order."""
    width, height = 23, 19
    rng = np.random.default_rng(7)
    fixed = random_triangles(rng, 120, width, height)
    fixed = fixed[[k % 6 in (0, 1, 2, 4) for k in range(len(fixed))]]  # none covers the whole buffer
    step = 1.0 / DEPTH_MAX
    levels = np.array([1000.499, 1000.501, 1000.2, 1000.7, 1001.0, 999.9, 1000.5 - 1e-4, 1002.3, 1001.5]) * step
    z = rng.choice(levels, len(fixed))
    window = np.concatenate([fixed / SUBPIXEL + 0.5, np.repeat(z[:, None, None], 3, axis=1)], axis=2)
    depth, tri_index, _, _ = rasterize_triangles(fixed, window, width, height)

    zbuf = np.full((height, width), DEPTH_MAX, np.int64)
    index = np.full((height, width), -1)
    for t, (f, zt) in enumerate(zip(fixed, z)):
        q = int(np.floor(zt * DEPTH_MAX + 0.5))
        win = reference_coverage(f, width, height) & (q <= zbuf)
        zbuf[win], index[win] = q, t
    # both sides of the half step are seen: 1000.499 steps round to 1000, 1000.501 to 1001
    assert (index >= 0).mean() > 0.3 and {1000, 1001} <= set(np.unique(zbuf[index >= 0]).tolist())
    np.testing.assert_array_equal(tri_index, index)
    np.testing.assert_array_equal(depth, zbuf / DEPTH_MAX)


@pytest.mark.parametrize("tall", [False, True], ids=["dividing", "walking"])
@pytest.mark.parametrize("batch", [None, 7, 1])
@pytest.mark.parametrize("n_bands", [1, 3])
def test_the_frame_coverage_is_the_finished_buffer_compared(tall, batch, n_bands):
    """Coverage tri_index ≠ EMPTY, as numpy writes it from the finished buffer: written by
    each band after the last batch only, on every row (the empty ones, and the last block
    cut short: 3 bands of 16- or 64-row blocks over 71 rows), by the dividing and the walking
    kernel; the depth of empty pixels is the clear value, window depth 1.0."""
    from renderer.raster import EMPTY, depth_to_window, rasterize_visibility
    from renderer.indexed_triangles import whole_triangles

    width, height = 23, 71
    rng = np.random.default_rng(4)
    if tall:  # every triangle spans the image's height: the walking kernel draws them
        fixed = rng.integers(-2 * SUBPIXEL, 24 * SUBPIXEL, (40, 3, 2))
        fixed[:, 0, 1], fixed[:, 1, 1] = -SUBPIXEL, 72 * SUBPIXEL
    else:  # small ones in the lower half only
        centres = rng.integers(0, [24 * SUBPIXEL, 30 * SUBPIXEL], (40, 1, 2))
        fixed = centres + rng.integers(-2 * SUBPIXEL, 2 * SUBPIXEL, (40, 3, 2))
    window = np.concatenate([fixed / SUBPIXEL + 0.5, rng.uniform(0, 1, (40, 3, 1))], axis=2)
    vis = rasterize_visibility(whole_triangles(fixed, window), width, height, n_bands=n_bands, batch=batch)
    covered_rows = (vis.tri_index != EMPTY).any(axis=1)
    assert covered_rows.any() and (tall or not covered_rows.all())
    np.testing.assert_array_equal(vis.covered, vis.tri_index != EMPTY)
    assert (depth_to_window(vis.depth)[vis.tri_index == EMPTY] == 1.0).all()


def test_an_empty_scene_has_an_empty_frame_depth_and_coverage():
    """No triangles: one pass clears the buffer and finishes it, depth 1.0 and nothing covered."""
    from renderer.raster import depth_to_window, rasterize_visibility
    from renderer.indexed_triangles import whole_triangles

    vis = rasterize_visibility(whole_triangles(np.zeros((0, 3, 2), np.int64), np.zeros((0, 3, 3))), 9, 5)
    assert (depth_to_window(vis.depth) == 1.0).all() and not vis.covered.any()
# --------------------------------------------------------------------------- the walking kernel
def test_tall_thin_triangles_are_drawn_as_the_reference_draws_them():
    """Triangles tall enough to be walked (the fast path of fill_rows), beside short ones that
    are divided row by row, cover exactly the reference rasteriser's pixels."""
    width, height = 23, 90
    fixed = np.array([[[2 * SUBPIXEL + 40, -SUBPIXEL], [5 * SUBPIXEL + 3, 95 * SUBPIXEL], [3 * SUBPIXEL, 88 * SUBPIXEL + 200]],
                      [[20 * SUBPIXEL, 10 * SUBPIXEL], [8 * SUBPIXEL + 77, 80 * SUBPIXEL + 1], [9 * SUBPIXEL, 3 * SUBPIXEL]],
                      [[10 * SUBPIXEL, 40 * SUBPIXEL], [14 * SUBPIXEL, 41 * SUBPIXEL + 30], [11 * SUBPIXEL, 42 * SUBPIXEL + 99]]],
                     np.int64)
    for f in fixed:
        w = np.concatenate([f / SUBPIXEL + 0.5, np.full((3, 1), 0.5)], axis=1)
        _, tri_index, _, _ = rasterize_triangles(f[None], w[None], width, height)
        expected = reference_coverage(f, width, height)
        assert expected.any()
        np.testing.assert_array_equal(tri_index >= 0, expected, err_msg=f"triangle {f.tolist()}")


@pytest.mark.parametrize("rule", ["top-left", "bottom-right"])
@pytest.mark.parametrize("depth_test", [True, False])
def test_the_walking_kernel_fills_the_buffers_the_dividing_one_fills(rule, depth_test):
    """rasterize_walking (spans by edge walks) and rasterize (a division per edge and row) on
    the same set-up: 240 triangles of every kind (ties, slivers, huge, off-screen) and 40 tall
    thin ones over them, drawn together so that depth ties and overdraw count: the same
    depth and triangle at every pixel. mean_rows sends the tall batch to the walking kernel."""
    from renderer.bands import raster_bands
    from renderer.hidden_back_faces import NO_TILES
    from renderer.fill_rules import FILL_RULES
    from renderer.raster import (DEPTH_CLEAR, EMPTY, FIRST_BATCH, LAST_BATCH, TALL_ROWS, mean_rows, rasterize,
                                 rasterize_walking, set_up)
    width, height = 37, 90
    rng = np.random.default_rng(5)
    small = random_triangles(rng, 240, width, height)
    x = rng.integers(0, width * SUBPIXEL, (40, 1))
    tall = np.stack([np.concatenate([x, rng.integers(-3 * SUBPIXEL, 5 * SUBPIXEL, (40, 1))], 1),
                     np.concatenate([x + rng.integers(1, 3 * SUBPIXEL, (40, 1)), rng.integers(80, 95, (40, 1)) * SUBPIXEL
                                     + rng.integers(0, 2, (40, 1)) * 77], 1),
                     np.concatenate([x + rng.integers(-SUBPIXEL, SUBPIXEL, (40, 1)), rng.integers(30, 60, (40, 1)) * SUBPIXEL], 1)],
                    axis=1)
    fixed = np.concatenate([small, tall]).astype(np.int64)
    z = np.where(rng.random((len(fixed), 1)) < 0.5, 0.5, rng.uniform(0, 1, (len(fixed), 3)))
    z[len(small):] = np.where(rng.random((40, 1)) < 0.5, 0.1, rng.uniform(0, 0.2, (40, 3)))  # in front, ties among them
    window = np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None] * np.ones((len(fixed), 3, 1))], axis=2)
    setup = set_up(fixed, window, height, False, n_bands=raster_bands(height, 3))
    buffers = []
    for kernel in (rasterize, rasterize_walking):
        depth, tri_index = np.empty((height, width), np.int32), np.empty((height, width), np.int32)
        covered = np.empty((height, width), np.bool_)
        kernel(setup, FILL_RULES[rule], depth_test, 0, FIRST_BATCH | LAST_BATCH, depth,
               tri_index, covered, NO_TILES)
        buffers.append((depth, tri_index))
    np.testing.assert_array_equal(buffers[1][1], buffers[0][1])
    np.testing.assert_array_equal(buffers[1][0], buffers[0][0])
    assert len(np.unique(buffers[0][1][buffers[0][1] >= len(small)])) > 30  # the tall ones really show
    assert (buffers[0][1] != EMPTY).mean() > 0.5 and (buffers[0][0] < DEPTH_CLEAR).any()
    assert mean_rows(set_up(tall, window[len(small):], height, False)) >= TALL_ROWS
    assert mean_rows(set_up(small[:1] * 0, window[:1], height, False)) < TALL_ROWS
    rows = set_up(tall, window[len(small):], height, False).rows
    assert (rows[:, 1] - rows[:, 0] + 1).mean() >= TALL_ROWS


_SET_UP_WITH_A_COLD_CACHE = """
import numpy as np
from renderer.raster import SETUP_CHUNK, set_up, set_up_range
from renderer.window import SUBPIXEL
rng = np.random.default_rng(8)
fixed = rng.integers(0, 20 * SUBPIXEL, (int(SETUP_CHUNK) + 5, 3, 2))
window = np.concatenate([fixed / SUBPIXEL + 0.5, rng.uniform(0, 1, (len(fixed), 3, 1))], axis=2)
setup = set_up(fixed, window, 20, False)
assert (setup.rows[:, 0] <= setup.rows[:, 1]).any()
print(len(set_up_range.signatures))
"""


def test_the_set_up_of_a_chunk_is_compiled_once(tmp_path):
    """setup_triangles calls set_up_range from its parallel loop, which numba types twice (the
    loop, then the loop body as a function of its own): the chunk's bounds have one type in
    both, so the set-up is compiled once, not twice (0.7 s of a cold start). In a process of
    its own with an empty kernel cache: a kernel loaded from the cache compiles nothing."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    repo = Path(__file__).resolve().parents[2]
    env = dict(os.environ, SCANLAB_KERNEL_CACHE=str(tmp_path),
               PYTHONPATH=os.pathsep.join([str(repo), os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", _SET_UP_WITH_A_COLD_CACHE], cwd=repo, env=env, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    assert done.stdout.split()[-1] == "1"


@pytest.mark.parametrize("cull_back", [False, True])
def test_the_mean_rows_of_a_batch_are_the_exact_mean_its_set_up_summed_chunk_by_chunk(cull_back):
    """:func:`mean_rows` (which chooses a batch's kernel) is the mean over every triangle of
    the rows it spans, clamped to the image, a triangle that draws nothing (no area, culled)
    counting none: the set-up sums them per chunk of SETUP_CHUNK triangles as it goes."""
    from renderer.raster import SETUP_CHUNK, mean_rows, set_up
    rng = np.random.default_rng(12)
    width, height = 40, 60
    fixed = random_triangles(rng, 2 * int(SETUP_CHUNK) + 77, width, height).astype(np.int64)
    fixed[:50] = fixed[:50, :1]  # no area
    window = np.concatenate([fixed / SUBPIXEL + 0.5, rng.uniform(0, 1, (len(fixed), 3, 1))], axis=2)
    setup = set_up(fixed, window, height, cull_back)
    spans = np.maximum(setup.rows[:, 1] - setup.rows[:, 0] + 1, 0)
    assert len(setup.row_sums) == 3 and setup.row_sums.tolist() == [
        int(spans[a:a + int(SETUP_CHUNK)].sum()) for a in range(0, len(spans), int(SETUP_CHUNK))]
    assert mean_rows(setup) == pytest.approx(spans.mean(), rel=1e-12) and spans[:50].sum() == 0
    assert (setup.rows[:, 1] <= height - 1).all() and spans.max() > 10
    assert mean_rows(set_up(fixed[:0], window[:0], height, cull_back)) == 0.0


@pytest.mark.parametrize("depth_test", [True, False])
def test_no_triangles_leave_the_buffer_a_culled_triangle_leaves(depth_test):
    """A frame with nothing to draw (a scene of translucent objects only) gets the clear buffer
    without running the kernels: the same depth, triangles and coverage as the kernels leave
    when their only triangle is a culled back face."""
    from renderer.raster import rasterize_visibility
    from renderer.indexed_triangles import whole_triangles

    fixed, window = triangles([(1, 1), (1, 5), (5, 1)])  # clockwise: a back face
    culled = rasterize_visibility(whole_triangles(fixed, window), 9, 7, depth_test=depth_test, cull_back=True)
    nothing = rasterize_visibility(whole_triangles(fixed[:0], window[:0]), 9, 7, depth_test=depth_test)
    np.testing.assert_array_equal(nothing.depth, culled.depth)
    np.testing.assert_array_equal(nothing.tri_index, culled.tri_index)
    np.testing.assert_array_equal(nothing.covered, culled.covered)
    assert not culled.covered.any() and nothing.depth.dtype == culled.depth.dtype


def test_the_raster_set_up_leaves_the_weights_plane_unwritten_and_works_out_the_rest_the_same():
    """With ``weights=False`` (:data:`renderer.raster.DROP_WEIGHTS`, the opaque raster's set-up)
    the first six columns of ``plane`` keep what was there (here NaN), and the facing, rows,
    counter-clockwise corners and depth plane of every triangle that draws are those of the
    set-up that works the weights out; triangles of every kind, with no area among them."""
    from renderer.raster import set_up_corners
    from renderer.indexed_triangles import whole_triangles
    from renderer.workspace import Workspace

    rng = np.random.default_rng(21)
    width, height = 40, 60
    fixed = random_triangles(rng, 600, width, height).astype(np.int64)
    fixed[:30] = fixed[:30, :1]  # no area
    window = np.concatenate([fixed / SUBPIXEL + 0.5, rng.uniform(0, 1, (len(fixed), 3, 1))], axis=2)
    whole = whole_triangles(fixed, window, with_cells=False)
    ws = Workspace()
    set_up_corners(whole.corners, whole.vertices, height, False, ws, "lean", weights=False)
    ws.array("lean.plane", (len(fixed), 11))[:] = np.nan
    lean = set_up_corners(whole.corners, whole.vertices, height, False, ws, "lean", weights=False)
    full = set_up_corners(whole.corners, whole.vertices, height, False, None, "full", weights=True)
    draws = full.rows[:, 0] <= full.rows[:, 1]
    assert np.isnan(lean.plane[:, :6]).all() and np.isfinite(full.plane[:, :6]).all()
    assert 100 < draws.sum() < len(fixed) - 30
    np.testing.assert_array_equal(lean.rows, full.rows)
    np.testing.assert_array_equal(lean.front, full.front)
    np.testing.assert_array_equal(lean.ccw[draws], full.ccw[draws])
    np.testing.assert_array_equal(lean.plane[draws, 6:], full.plane[draws, 6:])


@pytest.mark.parametrize("batch", [None, 7])
def test_the_raster_fills_the_same_buffer_with_and_without_the_weights_plane(monkeypatch, batch):
    """:data:`renderer.raster.WEIGHTS_IN_RASTER` (the plain path: every triangle's weights
    worked out in the set-up) and without: the same depth, triangles and coverage, z-buffer
    ties, tall triangles for the walking kernel and no-area ones among them; the set-up's
    tables start poisoned, as a workspace's may hold anything."""
    import renderer.raster as raster
    from renderer.indexed_triangles import whole_triangles

    rng = np.random.default_rng(22)
    width, height = 37, 29
    fixed = random_triangles(rng, 240, width, height).astype(np.int64)
    fixed[:10] = fixed[:10, :1]
    z = np.where(rng.random((240, 1)) < 0.5, 0.5, rng.uniform(0, 1, (240, 3)))
    window = np.concatenate([fixed / SUBPIXEL + 0.5, z[..., None] * np.ones((240, 3, 1))], axis=2)
    def poisoned(ws, name, shape, dtype=np.float64):  # what an earlier frame may have left
        return np.full(shape, np.nan if np.dtype(dtype).kind == "f" else 3, dtype)

    monkeypatch.setattr(raster, "empty", poisoned)
    buffers = {}
    for weights in (True, False):
        monkeypatch.setattr(raster, "WEIGHTS_IN_RASTER", weights)
        buffers[weights] = raster.rasterize_visibility(whole_triangles(fixed, window), width, height, batch=batch,
                                                       backs_last=True)
    assert len(np.unique(buffers[False].tri_index)) > 20
    for name in ("depth", "tri_index", "covered"):
        np.testing.assert_array_equal(getattr(buffers[False], name), getattr(buffers[True], name))


def test_a_frames_whole_batches_are_set_up_into_one_set_of_tables_and_its_last_short_one_into_its_own():
    """rasterize_visibility makes the set-up tables of a whole batch once a frame
    (:func:`renderer.raster.setup_tables`) and sets up every whole batch into them; a shorter
    last batch gets tables of its own length (its chunks are all the raster reads): the
    buffer of one pass either way (checked by the batch test above)."""
    from unittest import mock
    import renderer.raster as raster

    fixed, window = triangles(*[[(0, 0), (4, 0), (0, 4)]] * 10)
    given = []
    set_up_plain = raster.set_up_corners

    def set_up_corners(*args, tables=None, **kwargs):
        given.append(tables)
        return set_up_plain(*args, tables=tables, **kwargs)

    with mock.patch.object(raster, "set_up_corners", set_up_corners):
        raster.rasterize_visibility(raster.whole_triangles(fixed, window), 8, 8, batch=4)
    assert [t is None for t in given] == [False, False, True]
    assert given[0] is given[1] and len(given[0].rows) == 4


def test_a_frames_set_up_runs_in_the_bands_hand_out_one_iteration_at_a_time():
    """The raster enters :func:`renderer.bands.one_band_at_a_time` once a frame, its batches'
    set-up included: numba hands the set-up's chunks out one at a time, as the bands
    (measured quicker on the big meshes than a block around each batch's fill)."""
    from unittest import mock
    import numba
    import renderer.raster as raster
    from renderer.bands import BAND_CHUNK

    fixed, window = triangles(*[[(0, 0), (4, 0), (0, 4)]] * 10)
    chunk_sizes = []
    setup_plain = raster.setup_triangles

    def setup_triangles(*args):
        chunk_sizes.append(numba.get_parallel_chunksize())
        return setup_plain(*args)

    with mock.patch.object(raster, "setup_triangles", setup_triangles):
        raster.rasterize_visibility(raster.whole_triangles(fixed, window), 8, 8, batch=4)
    assert chunk_sizes == [BAND_CHUNK] * 3 and numba.get_parallel_chunksize() != BAND_CHUNK
