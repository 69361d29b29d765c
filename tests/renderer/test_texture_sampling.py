"""Texture sampling: which texel nearest picks, how linear blends, how repeat and clamp wrap."""
import numpy as np

from renderer.texture_sampling import CLAMP, LINEAR, NEAREST, REPEAT, sample

# a 2×2 8-bit texture, rows from the bottom: texel (0,0) = [10, 20, 30], (1,0) = [110, 120, 130], …
TEX = np.array([[10, 20, 30], [110, 120, 130], [210, 220, 230], [50, 60, 70]], dtype=np.uint8)


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
