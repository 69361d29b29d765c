"""Texture sampling: which texel nearest picks, how linear blends, how repeat and clamp wrap;
a span's loop gives what one fragment at a time gives."""
import numpy as np
import pytest

from renderer.texture_sampling import (CLAMP, LINEAR, NEAREST, REPEAT, UNIT32, Textures, channels, lanes_of,
                                       modulate_texels, pack_texels, packed_texels, sample, texel_scratch)

from .texture_filters import by_definition

# a 2×2 8-bit texture, rows from the bottom: texel (0,0) = [10, 20, 30], (1,0) = [110, 120, 130], …
TEX = pack_texels(np.array([[10, 20, 30], [110, 120, 130], [210, 220, 230], [50, 60, 70]], dtype=np.uint8))


def at(s, t, filt=NEAREST, wrap=REPEAT):
    return np.rint(np.array(sample(TEX, 0, 2, 2, filt, wrap, s, t)) * 255).astype(int).tolist()


def test_nearest_picks_the_texel_containing_the_point():
    """Nearest: texel (⌊s·W⌋, ⌊t·H⌋), rows counted from the bottom."""
    assert at(0.25, 0.25) == [10, 20, 30]
    assert at(0.75, 0.25) == [110, 120, 130]
    assert at(0.25, 0.75) == [210, 220, 230]
    assert at(0.999, 0.999) == [50, 60, 70]


def test_repeat_wraps_and_clamp_holds_the_edge():
    """s = 1.25 repeats to 0.25; clamped it stays on the last column."""
    assert at(1.25, 0.25) == at(0.25, 0.25)
    assert at(-0.75, 0.25) == at(0.25, 0.25)
    assert at(1.25, 0.25, wrap=CLAMP) == at(0.75, 0.25)
    assert at(-3.0, 0.25, wrap=CLAMP) == at(0.25, 0.25)


def test_linear_at_a_texel_centre_is_that_texel_and_halfway_is_the_mean():
    """Linear: at a texel centre the texel itself; midway between two centres their mean (8-bit lerp, rounded)."""
    assert at(0.25, 0.25, LINEAR, CLAMP) == [10, 20, 30]
    assert at(0.5, 0.25, LINEAR, CLAMP) == [60, 70, 80]
    assert at(0.5, 0.5, LINEAR, CLAMP) == [95, 105, 115]


def test_linear_repeat_blends_across_the_wrap():
    """With repeat, the point between the last and first column blends both (s = 0 lies midway)."""
    assert at(0.0, 0.25, LINEAR, REPEAT) == [60, 70, 80]
    assert at(0.0, 0.25, LINEAR, CLAMP) == [10, 20, 30]


# --------------------------------------------------------------------------- the span's loop and the lanes
def coordinates(size, rng):
    """Along one axis of a texture ``size`` texels long: texel edges i/size and centres over
    three periods, the linear filter's weight steps (i + ½ + k/256)/size, a float step either
    side of each edge, and random values from −3 to 4 (both wraps at work)."""
    edges = np.arange(-size, 2 * size + 1) / size
    steps = ((np.arange(-size, 2 * size)[:, None] + 0.5 + np.array([0, 1, 127, 128, 255]) / 256) / size).ravel()
    return np.concatenate([edges, edges + 0.5 / size, steps, np.nextafter(edges, -np.inf),
                           np.nextafter(edges, np.inf), rng.uniform(-3, 4, 400)])


def points(width, height, seed=0):
    """(s, t): every value of :func:`coordinates` on each axis, paired at random."""
    rng = np.random.default_rng(seed)
    s, t = coordinates(width, rng), coordinates(height, rng)
    n = max(len(s), len(t))
    return rng.permutation(np.resize(s, n)), rng.permutation(np.resize(t, n))


SIZES = [(16, 8), (3, 5), (1, 1)]
FILTERS = [(f, w, size) for f in (NEAREST, LINEAR) for w in (REPEAT, CLAMP) for size in SIZES]


@pytest.mark.parametrize("filt, wrap, size", FILTERS, ids=[f"{'nearest linear'.split()[f]}-{'repeat clamp'.split()[w]}-"
                                                            f"{s[0]}x{s[1]}" for f, w, s in FILTERS])
def test_sample_is_the_filter_as_defined_inside_outside_and_on_texel_edges(filt, wrap, size):
    """Nearest and linear, repeat and clamp, on textures of 16×8, 3×5 and 1×1 texels (every
    index of a 1-texel texture wraps): :func:`sample` gives the plainly written filter at random
    points, at texel edges and centres, at the linear weights' 1/256 steps and one float either
    side of an edge."""
    width, height = size
    texels = np.random.default_rng(5).integers(0, 256, (width * height, 3)).astype(np.uint8)
    lanes = pack_texels(texels)
    for s, t in zip(*points(width, height)):
        got = np.rint(np.array(sample(lanes, 0, width, height, filt, wrap, s, t)) * 255).astype(int).tolist()
        assert got == by_definition(texels, width, height, filt, wrap, s, t), (s, t)


@pytest.mark.parametrize("filt, wrap, size", FILTERS, ids=[f"{'nearest linear'.split()[f]}-{'repeat clamp'.split()[w]}-"
                                                            f"{s[0]}x{s[1]}" for f, w, s in FILTERS])
def test_a_span_is_modulated_by_exactly_the_values_sample_gives(filt, wrap, size):
    """The span's loop (filter and wrap chosen once, :func:`modulate_texels`) multiplies each
    pixel's colour by float32 of what :func:`sample` gives there, bit for bit: on coordinates
    inside, outside and on texel edges; on a span whose texels all lie inside the texture
    (the linear filter's loop without wrapping); and on that span with one pixel outside. A
    second texture after the first (``offset``) is read where it starts."""
    width, height = size
    rng = np.random.default_rng(9)
    first = rng.integers(0, 256, (7, 3)).astype(np.uint8)  # another object's texture before this one
    texels = rng.integers(0, 256, (width * height, 3)).astype(np.uint8)
    lanes = pack_texels(np.concatenate([first, texels]))
    textures = Textures(np.array([True, True]), np.array([0, 7]), np.array([7, width]), np.array([1, height]),
                        np.array([NEAREST, filt]), np.array([REPEAT, wrap]), lanes)
    s, t = points(width, height, seed=1)
    inner = [(0.5 + 2 * rng.random(len(s)) * (size - 1.5) / 2) / size if size > 1 else np.zeros(len(s))
             for size in (width, height)]  # every pixel's four texels inside the texture
    for s, t in ((s, t), inner, (np.append(inner[0], s[0]), np.append(inner[1], t[0]))):
        st = np.stack([s, t]).astype(np.float32)  # a span's coordinates are float32
        start = rng.uniform(0.2, 1.5, (3, len(s))).astype(np.float32)
        colour = start.copy()
        at = 5  # the span's coordinates from column 5 of a row's scratch on
        row_st = np.concatenate([np.full((2, at), np.nan, np.float32), st], axis=1)
        modulate_texels(textures, 1, row_st, at, len(s), colour, texel_scratch.py_func(at + len(s)))
        expected = start * np.array([sample(lanes, 7, width, height, filt, wrap, a, b) for a, b in st.T],
                                    np.float32).T
        np.testing.assert_array_equal(colour, expected)


def test_a_texel_is_packed_in_one_word_and_read_into_lanes_sixteen_bits_apart():
    """Stored: r, g, b in bits 0, 8, 16 of a 32-bit word (4 bytes a texel); read: widened
    into 16-bit lanes (r, b, g from the lowest), which give back r, g and b."""
    packed = pack_texels(np.array([[1, 2, 3], [255, 128, 0]], np.uint8))
    assert packed.dtype == np.uint32 and packed.tolist() == [1 + (2 << 8) + (3 << 16), 255 + (128 << 8)]
    assert int(lanes_of(packed[0])) == 1 + (3 << 16) + (2 << 32)
    assert [int(v) for v in channels(lanes_of(packed[1]))] == [255, 128, 0]


def test_a_textures_packed_texels_are_worked_out_once():
    from lab.texture import Texture

    tex = Texture(np.random.default_rng(2).random((4, 6, 3)))
    assert packed_texels(tex) is packed_texels(tex)
    np.testing.assert_array_equal(packed_texels(tex), pack_texels(tex.texels_8bit))


def test_an_8_bit_value_divided_by_255_in_float32_is_the_looked_up_unit_value():
    """The vector blend (``blend_texels``) divides in float32 where the scalar paths look the
    value up: the same float32 for every 8-bit value."""
    values = np.arange(256)
    np.testing.assert_array_equal(values.astype(np.float32) / np.float32(255.0), UNIT32)
