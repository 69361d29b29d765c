"""renderer/coverage.py: one triangle's pixel mask is exactly what the scanline fill draws for it."""
import numpy as np
import pytest

from renderer.coverage import triangle_coverage, window_to_fixed
from renderer.raster import rasterize_triangles
from renderer.window import clip_to_window

W, H = 16, 12


def drawn_by_the_renderer(tri_window_xy, width=W, height=H):
    """Coverage of one triangle through the full stage 5 → 6 path: clip space at w = 1, window, raster."""
    xy = np.asarray(tri_window_xy, np.float64)
    clip = np.zeros((1, 3, 4))
    clip[0, :, 0] = xy[:, 0] / (width / 2) - 1.0
    clip[0, :, 1] = xy[:, 1] / (height / 2) - 1.0
    clip[0, :, 3] = 1.0
    window, fixed = clip_to_window(clip, width, height)
    return rasterize_triangles(fixed, window, width, height)[1] >= 0


def test_a_right_triangle_on_pixel_corners_takes_its_bottom_left_pixel_only():
    """(0,0), (2,0), (0,2): centre (0.5, 0.5) is inside; (1.5, 0.5) and (0.5, 1.5) lie on the hypotenuse, a right edge."""
    assert triangle_coverage((0, 0), (2, 0), (0, 2), 2, 2).tolist() == [[True, False], [False, False]]


def test_both_windings_cover_the_same_pixels():
    a = triangle_coverage((1, 1), (9, 2), (4, 8), W, H)
    b = triangle_coverage((1, 1), (4, 8), (9, 2), W, H)
    assert a.any() and (a == b).all()


def test_a_zero_area_triangle_covers_nothing():
    assert not triangle_coverage((1.5, 1.5), (5.5, 5.5), (9.5, 9.5), W, H).any()


def test_the_wrong_rule_takes_the_other_ties():
    """Bottom-right hands the hypotenuse's centres to the triangle and drops the left and bottom ones."""
    assert triangle_coverage((0, 0), (2, 0), (0, 2), 2, 2, "bottom-right").tolist() == [[True, True], [True, False]]


def test_snapping_is_the_window_stage_s_rounding():
    rng = np.random.default_rng(3)
    xy = rng.uniform(0, 16, (200, 2))
    clip = np.zeros((200, 3, 4))
    clip[:, 0, 0] = xy[:, 0] / (W / 2) - 1.0
    clip[:, 0, 1] = xy[:, 1] / (H / 2) - 1.0
    clip[:, :, 3] = 1.0
    _, fixed = clip_to_window(clip, W, H)
    window = np.stack([(clip[:, 0, 0] + 1) * W / 2, (clip[:, 0, 1] + 1) * H / 2], axis=1)
    assert (window_to_fixed(window) == fixed[:, 0]).all()


@pytest.mark.parametrize("seed", range(4))
def test_every_triangle_is_what_the_scanline_fill_draws(seed):
    """Random triangles, half of them with corners on pixel centres (ties on every edge), some off screen."""
    rng = np.random.default_rng(seed)
    for k in range(60):
        if k % 2:
            tri = rng.integers(-3, 18, (3, 2)) + 0.5
        else:
            tri = rng.uniform(-4, 20, (3, 2))
        assert (triangle_coverage(*tri, W, H) == drawn_by_the_renderer(tri)).all(), tri
