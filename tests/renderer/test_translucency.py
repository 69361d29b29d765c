"""Translucency: fragment lists per pixel, and compositing by oit, depth_peeling and sorted.

Every expected value is worked out by hand below, in 8-bit steps where the mode keeps
8-bit (or half-float) buffers: ``unorm8(x) = round_half_even(255·x)`` in float32,
``mul8(a, b) = round(a·b/255)`` as a blend unit does. VTK parity of the same modes is in
``tests/compare/test_parity_translucency.py``.
"""
import numpy as np
import pytest

from lab.scene import Camera, Image, Material, RenderSettings, Scene, SceneObject
from lab.matrices import model_matrix
from lab.shapes import quad
from renderer import render
from renderer.raster import DEPTH_CLEAR, DEPTH_MAX
from renderer.translucency import (DEPTH_PEELING, MODES, OIT, SORTED, blend8, composite_pixel, depth_order,
                                   fragment_lists, half, mul8)
from renderer.window import SUBPIXEL

BLUE = (0, 0, 255)


def composite(mode, colours, alphas, depths, behind, opaque_behind=False):
    """One pixel through :func:`composite_pixel`: fragments in draw order, 8-bit ``behind``."""
    m = len(alphas)
    fragments = np.c_[np.array(colours, float), np.array(alphas, float), np.array(depths, float)]
    out = np.empty(3, np.int64)
    composite_pixel(mode, fragments, m, np.array(behind, np.int64), opaque_behind, out, np.empty(m, np.int64),
                    np.empty(3), np.empty((2, 4), np.int64))
    return tuple(int(c) for c in out)


# --------------------------------------------------------------------------- 8-bit and half-float arithmetic
def test_mul8_is_the_rounded_product_over_255():
    """Every pair of 8-bit values: mul8(a, b) = round(a·b/255) (no ties: a·b/255 is never k + ½)."""
    a, b = np.meshgrid(np.arange(256), np.arange(256))
    ours = np.array([[mul8(x, y) for x, y in zip(ra, rb)] for ra, rb in zip(a, b)])
    np.testing.assert_array_equal(ours, np.rint(a * b / 255.0).astype(int))


def test_blend8_saturates_at_255():
    """200·255/255 + 200·255/255 = 400 → 255; 128·128/255 + 127·255/255 = 64 + 127 = 191."""
    assert blend8(200, 255, 200, 255) == 255
    assert blend8(128, 128, 127, 255) == 191


def test_half_rounds_as_a_16_bit_float_target():
    """The OIT accumulators' rounding is IEEE half precision, ties to even."""
    rng = np.random.default_rng(5)
    halves = rng.random(3000).astype(np.float16).astype(np.float32)
    ties = halves + np.spacing(halves.astype(np.float16)).astype(np.float32) / 2  # halfway to the next half
    values = np.concatenate([rng.random(2000) * 4, rng.random(500) * 1e-4, rng.random(500) * 1e3, -rng.random(500),
                             ties, [0.0, 1.0, 2049 / 2048, 1e-7, 2.0 ** -14, 2.0 ** -14 * (1 - 2.0 ** -11)]])
    values = values.astype(np.float32)  # the kernels round float32 sums
    ours = np.array([half(v) for v in values])
    assert np.array_equal(ours, values.astype(np.float16).astype(np.float32))


def test_depth_order_is_nearest_first_and_stable():
    """Depths (0.5, 0.2, 0.5, 0.1): order 3, 1, 0, 2 — the two 0.5s keep their draw order."""
    order = np.empty(4, np.int64)
    depth_order(np.array([0.5, 0.2, 0.5, 0.1]), 4, order)
    assert order.tolist() == [3, 1, 0, 2]


# --------------------------------------------------------------------------- compositing one pixel
@pytest.mark.parametrize("mode, expected", [(OIT, (128, 0, 127)), (DEPTH_PEELING, (128, 0, 127)),
                                            (SORTED, (128, 0, 128))])
def test_one_red_layer_at_half_opacity_over_blue(mode, expected):
    """Red α .5 over blue. sorted, exact: ½·(1, 0, 0) + ½·(0, 0, 1) = (.5, 0, .5) → 127.5 → (128, 0, 128).
    oit: C = ½·red/½ = red, coverage A = 1 − ½ → unorm8 128; red mul8(255, 128) = 128, blue
    mul8(255, 255 − 128) = round(127.5·…) = 127. depth_peeling: front layer red unorm8(½) = 128, alpha
    128; blue behind mul8(255, 127) = 127: the 8-bit blend floors a half step that sorted rounds up."""
    assert composite(mode, [[1, 0, 0]], [0.5], [0.5], BLUE) == expected


@pytest.mark.parametrize("mode, expected", [(OIT, (96, 96, 64)), (DEPTH_PEELING, (128, 64, 63)),
                                            (SORTED, (128, 64, 64))])
@pytest.mark.parametrize("draw_order", ["green first", "red first"])
def test_red_over_green_on_blue(mode, expected, draw_order):
    """Red α .5 in front of green α .5 on blue, in either draw order.
    oit averages, whatever the order: C = (½·red + ½·green)/1 = (.5, .5, 0) → 128; coverage
    1 − ½·½ = .75 → 191; red mul8(128, 191) = 96, green 96, blue mul8(255, 64) = 64.
    sorted, back to front: green over blue (0, .5, .5), red over that (.5, .25, .25) → (128, 64, 64).
    depth_peeling: the same order in 8-bit layers, one LSB below in blue (the parity notes' measurement)."""
    colours, depths = [[0, 1, 0], [1, 0, 0]], [0.6, 0.3]
    if draw_order == "red first":
        colours, depths = colours[::-1], depths[::-1]
    assert composite(mode, colours, [0.5, 0.5], depths, BLUE) == expected


def test_depth_peeling_over_an_opaque_surface_peels_the_front_only_at_first():
    """Over an opaque surface VTK's first peel takes no far fragment, so both layers go through
    the 8-bit front layer: red 128 with coverage 128/255; green weighted by 1 − 128/255 = 127/255:
    255·½·127/255 = 63.5 in real numbers, 63.4999… with float32(128/255), so 63; coverage
    1 − (127/255)·½ → 191.5 → 192, so blue behind keeps 255 − 192 = 63."""
    assert composite(DEPTH_PEELING, [[0, 1, 0], [1, 0, 0]], [0.5, 0.5], [0.6, 0.3], BLUE, True) == (128, 63, 63)
    assert composite(DEPTH_PEELING, [[0, 1, 0], [1, 0, 0]], [0.5, 0.5], [0.6, 0.3], BLUE, False) == (128, 64, 63)


@pytest.mark.parametrize("mode", [OIT, DEPTH_PEELING, SORTED])
def test_opaque_and_invisible_layers(mode):
    """α = 1 hides what is behind: red; α = 0 shows it unchanged: blue."""
    assert composite(mode, [[1, 0, 0]], [1.0], [0.5], BLUE) == (255, 0, 0)
    assert composite(mode, [[1, 0, 0]], [0.0], [0.5], BLUE) == BLUE


def test_sorted_lets_a_highlight_brighter_than_one_shine_through():
    """sorted keeps the lit colour unclamped: 2.0 red at α .5 over black is ½·2 = 1 → 255, not ½ → 128."""
    assert composite(SORTED, [[2.0, 0, 0]], [0.5], [0.5], (0, 0, 0)) == (255, 0, 0)


# --------------------------------------------------------------------------- fragment lists
def triangles(*tris):
    """(fixed, window) arrays for triangles of (x, y, z) vertices in pixel-centre units (see test_raster)."""
    fixed = np.array([[(round(x * SUBPIXEL), round(y * SUBPIXEL)) for x, y, _ in t] for t in tris], np.int64)
    window = np.array([[(x + 0.5, y + 0.5, z) for x, y, z in t] for t in tris], np.float64)
    return fixed, window


# (−0.5, −0.5), (3.5, −0.5), (−0.5, 3.5) in pixel-centre units: the pixel corners (0, 0), (4, 0), (0, 4).
# Centre (i, j) is inside when i + j < 3 (six pixels); on the hypotenuse (i + j = 3), a right edge, it is out.
CORNER = [(-0.5, -0.5), (3.5, -0.5), (-0.5, 3.5)]
INSIDE = np.add.outer(np.arange(4), np.arange(4)) < 3  # [row j, column i]


def test_fragment_lists_count_every_translucent_fragment_in_draw_order():
    """Two copies of the corner triangle at depths .6 then .3 over an empty z-buffer: two fragments in
    each of the six pixels, the first drawn first; starts are the prefix sums of the counts."""
    fixed, window = triangles([(x, y, 0.6) for x, y in CORNER], [(x, y, 0.3) for x, y in CORNER])
    front, lists = fragment_lists(fixed, window, np.full((4, 4), DEPTH_CLEAR, np.int32))
    assert front.tolist() == [True, True]
    np.testing.assert_array_equal(lists.count, np.where(INSIDE, 2, 0))
    np.testing.assert_array_equal(lists.start.reshape(-1), np.concatenate([[0], np.cumsum(lists.count)[:-1]]))
    assert lists.longest == 2
    first = lists.start[0, 0]
    assert lists.tri[first:first + 2].tolist() == [0, 1]
    assert lists.z[first:first + 2].tolist() == [np.floor(0.6 * DEPTH_MAX + 0.5), np.floor(0.3 * DEPTH_MAX + 0.5)]


def test_fragments_behind_the_opaque_surface_are_dropped_unless_the_depth_test_is_off():
    """An opaque surface at depth .4 everywhere: the copy at .6 is behind it, only the one at .3 stays."""
    fixed, window = triangles([(x, y, 0.6) for x, y in CORNER], [(x, y, 0.3) for x, y in CORNER])
    at_04 = np.full((4, 4), np.floor(0.4 * DEPTH_MAX + 0.5), np.int32)  # the 24-bit integer depth of 0.4
    _, lists = fragment_lists(fixed, window, at_04)
    np.testing.assert_array_equal(lists.count, np.where(INSIDE, 1, 0))
    assert set(lists.tri.tolist()) == {1}
    _, everything = fragment_lists(fixed, window, at_04, depth_test=False)
    np.testing.assert_array_equal(everything.count, np.where(INSIDE, 2, 0))


def test_bands_do_not_change_the_lists():
    """One band of rows or four: the same counts, starts and fragments."""
    fixed, window = triangles([(x, y, 0.6) for x, y in CORNER], [(x, y, 0.3) for x, y in CORNER])
    _, one = fragment_lists(fixed, window, np.full((4, 4), DEPTH_CLEAR, np.int32), n_bands=1)
    _, four = fragment_lists(fixed, window, np.full((4, 4), DEPTH_CLEAR, np.int32), n_bands=4)
    for a, b in zip(one, four):
        assert np.array_equal(a, b)


# --------------------------------------------------------------------------- the whole frame
def two_translucent_squares(mode):
    """16×16, parallel view straight down −z: a green square at z = 0 drawn first, a red one in front
    at z = 0.5, both α .5 and unlit (lighting off: Ka·C + Kd·C = C), on a blue background."""
    def square(colour, z):
        return SceneObject(mesh=quad(3.0), model_to_world=model_matrix(translate=(0.0, 0.0, z)),
                           material=Material(color=colour, ambient=0.0, diffuse=1.0, lighting=False, opacity=0.5))
    return Scene(image=Image(size=(16, 16), background=(0.0, 0.0, 1.0)),
                 camera=Camera(position=(0.0, 0.0, 5.0), parallel=True, parallel_scale=1.0), lights=(),
                 objects=(square((0.0, 1.0, 0.0), 0.0), square((1.0, 0.0, 0.0), 0.5)),
                 render=RenderSettings(transparency=mode))


@pytest.mark.parametrize("mode, expected", [("oit", (96, 96, 64)), ("depth_peeling", (128, 64, 63)),
                                            ("sorted", (128, 64, 64))])
def test_a_frame_of_two_translucent_squares(mode, expected):
    """Every pixel of the frame is the hand-composited red-over-green-on-blue of each mode; the
    translucent squares cover it but write no depth."""
    frame = render(two_translucent_squares(mode))
    assert frame.coverage.all() and (frame.depth == 1.0).all()
    assert {tuple(int(c) for c in p) for p in frame.rgb.reshape(-1, 3)} == {expected}
    assert set(MODES) == {"oit", "depth_peeling", "sorted"}
