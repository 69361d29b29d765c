"""Stage 5, clip → window: perspective division, the viewport (y up), 1/256-pixel snapping and the one y flip."""
import contextlib

import numpy as np
import pytest

from renderer.window import SUBPIXEL, clip_to_window, window_into, window_rows_to_image_rows

from .single_thread import one_thread

W, H = 8, 4  # powers of two: every window position below is exact in binary


def to_window(*verts_clip):
    """Three clip-space vertices (x, y, z, w) of one triangle → (window (3, 3), fixed (3, 2))."""
    tri_window, tri_fixed = clip_to_window(np.array([verts_clip], dtype=np.float64), W, H)
    return tri_window[0], tri_fixed[0]


def at_window(x, y, z=0.0):
    """The clip-space vertex (w = 1) that lands at window (x, y) in a W×H viewport — exact for dyadic x, y."""
    return (x / (W / 2) - 1.0, y / (H / 2) - 1.0, z, 1.0)


def test_ndc_corners_map_to_the_viewport_corners():
    """NDC (−1,−1,−1) → window (0, 0, 0), (1, 1, 1) → (W, H, 1), (0, 0, 0) → (W/2, H/2, ½): y is up, depth 0..1."""
    window, _ = to_window((-1, -1, -1, 1), (1, 1, 1, 1), (0, 0, 0, 1))
    np.testing.assert_array_equal(window, [[0, 0, 0], [W, H, 1], [W / 2, H / 2, 0.5]])


def test_perspective_division_comes_first():
    """Clip (4, 1, 0, 4) is NDC (1, ¼, 0): window (W, 5H/8, ½)."""
    window, _ = to_window((4, 1, 0, 4), (0, 0, 0, 1), (0, 0, 0, 2))
    np.testing.assert_array_equal(window[0], [W, 5 * H / 8, 0.5])


def test_pixel_centres_snap_to_multiples_of_256():
    """Window (i + ½, j + ½), the centre of pixel (i, j), is fixed point (256·i, 256·j)."""
    _, fixed = to_window(at_window(0.5, 0.5), at_window(3.5, 2.5), at_window(7.5, 3.5))
    np.testing.assert_array_equal(fixed, [[0, 0], [3 * 256, 2 * 256], [7 * 256, 3 * 256]])


def test_pixel_corners_sit_half_a_pixel_off_the_lattice():
    """Window (0, 0), a pixel corner, is fixed (−128, −128); (W, H) is (256·W − 128, 256·H − 128)."""
    _, fixed = to_window(at_window(0, 0), at_window(W, H), at_window(1, 1))
    np.testing.assert_array_equal(fixed, [[-128, -128], [256 * W - 128, 256 * H - 128], [128, 128]])


@pytest.mark.parametrize("offset, expected", [
    (1.25, 1), (1.75, 2),     # to the nearest 1/256
    (0.5, 0), (1.5, 2),       # exact halves: to even
    (-0.25, 0), (-0.75, -1),  # below a centre
])
def test_snapping_rounds_to_the_nearest_step_half_to_even(offset, expected):
    """Window x = 2.5 + offset/256 snaps to fixed 512 + round_half_even(offset); the same for y."""
    x = 2.5 + offset / SUBPIXEL
    _, fixed = to_window(at_window(x, x), at_window(0.5, 0.5), at_window(1.5, 0.5))
    assert fixed[0].tolist() == [512 + expected, 512 + expected]


def test_window_keeps_the_unsnapped_position():
    """tri_window holds the exact window position; only tri_fixed is snapped."""
    window, fixed = to_window(at_window(2.5 + 0.3 / 256, 1.0 / 3.0), at_window(0.5, 0.5), at_window(1.5, 0.5))
    assert window[0, 0] == pytest.approx(2.5 + 0.3 / 256, abs=1e-15)
    assert window[0, 1] == pytest.approx(1.0 / 3.0, abs=1e-15)
    assert fixed[0].tolist() == [512, round((1.0 / 3.0 - 0.5) * 256)]


def test_image_rows_are_window_rows_upside_down():
    """window_rows_to_image_rows puts window row H − 1 (the top of the view) at image row 0."""
    window_rows = np.arange(H)[:, None] * np.ones((H, W), int)  # each pixel holds its window row
    image = window_rows_to_image_rows(window_rows)
    assert image.shape == (H, W)
    np.testing.assert_array_equal(image[:, 0], [H - 1 - r for r in range(H)])


def test_many_points_map_to_the_same_bits_on_one_thread_and_on_two():
    """The window mapping runs as a parallel loop over the points: each point on its own, so
    the bits are those of the formula, point by point, on any number of threads."""
    rng = np.random.default_rng(5)
    points = np.column_stack([rng.uniform(-2, 2, (100_000, 3)), rng.uniform(0.5, 3, 100_000)])
    w = points[:, 3]
    x, y = (points[:, 0] / w + 1.0) * (640 / 2.0), (points[:, 1] / w + 1.0) * (480 / 2.0)
    expected_fixed = np.column_stack([np.rint((x - 0.5) * SUBPIXEL), np.rint((y - 0.5) * SUBPIXEL)]).astype(np.int64)
    for threads in (one_thread, contextlib.nullcontext):
        window, fixed, cells = np.empty((100_000, 3)), np.empty((100_000, 2), np.int64), np.empty(100_000, np.int64)
        with threads():
            window_into(points, 640, 480, window, fixed, cells)
        np.testing.assert_array_equal(window, np.column_stack([x, y, (points[:, 2] / w + 1.0) / 2.0]))
        np.testing.assert_array_equal(fixed, expected_fixed)
        np.testing.assert_array_equal(cells, centre_cells_by_formula(expected_fixed))


def centre_cells_by_formula(fixed):
    """:func:`renderer.window.centre_cell` of each row of ``fixed`` (M, 2), written out in numpy:
    per axis 2·⌊v / 256⌋ + (v not a multiple of 256), x in the high 32 bits, y in the low 32."""
    axis = 2 * np.floor_divide(fixed, SUBPIXEL) + (fixed % SUBPIXEL != 0)
    return (axis[:, 0] << 32) | (axis[:, 1] & 0xFFFFFFFF)


def test_centre_cells_are_the_formula_for_vertices_given_whole():
    """Vertex tables made without the window mapping (triangles given whole) get the same
    cells from :func:`renderer.window.centre_cells`, negative coordinates included."""
    from renderer.window import centre_cells

    fixed = np.random.default_rng(3).integers(-4 * SUBPIXEL, 4 * SUBPIXEL, (5000, 2))
    fixed[::3] = fixed[::3] // SUBPIXEL * SUBPIXEL  # on pixel centres
    cells = np.empty(5000, np.int64)
    centre_cells(fixed, cells)
    np.testing.assert_array_equal(cells, centre_cells_by_formula(fixed))
