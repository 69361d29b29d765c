"""float32 pow, log2 and exp2 for the span shaders (renderer/float32_math.py), against float64; the
half-float rounding of the OIT accumulators, against numpy's float16."""
from __future__ import annotations

import numpy as np
import pytest

from renderer.float32_math import EXP_FLUSH, exp2_f32, half, log2_f32, pow_f32
from renderer.jit import njit
from renderer.reflection.vtk_spans import to8


@njit(cache=False)
def _pow_all(x, p, out):
    for i in range(x.shape[0]):
        out[i] = pow_f32(x[i], p)


@njit(cache=False)
def _log2_exp2_all(x, logs, exps):
    for i in range(x.shape[0]):
        logs[i] = log2_f32(x[i])
        exps[i] = exp2_f32(-x[i] * np.float32(20.0))


@njit(cache=False)
def _to8_all(v, out):
    for i in range(v.shape[0]):
        out[i] = to8(v[i])


@njit(cache=False)
def _half_all(v, out):
    for i in range(v.shape[0]):
        out[i] = half(v[i])


X = np.concatenate([np.geomspace(1e-5, 1.0, 100_001), [1.0, 0.5, 0.25]]).astype(np.float32)


@pytest.mark.parametrize("power", [0.0, 1.0, 2.5, 20.0, 40.0, 128.0])
def test_pow_is_within_2e_5_of_the_exact_power(power):
    """Relative error below 2·10⁻⁵ (exp2 of a float32 product: llvmpipe's accuracy), i.e. under a
    hundredth of an 8-bit step at full scale; x⁰ = 1 exactly."""
    out = np.empty_like(X)
    _pow_all(X, np.float32(power), out)
    exact = X.astype(np.float64) ** power
    relevant = exact > 1e-30
    assert np.all(np.abs(out[relevant] - exact[relevant]) <= 2e-5 * exact[relevant])
    if power == 0.0:
        assert np.all(out == 1.0)


def test_log2_and_exp2_by_their_own_accuracy():
    logs, exps = np.empty_like(X), np.empty_like(X)
    _log2_exp2_all(X, logs, exps)
    np.testing.assert_allclose(logs, np.log2(X.astype(np.float64)), atol=3e-7, rtol=1.2e-7)
    np.testing.assert_allclose(exps, 2.0 ** (-20.0 * X.astype(np.float64)), rtol=2e-6)
    assert log2_f32(np.float32(1.0)) == 0.0 and log2_f32(np.float32(0.25)) == -2.0
    assert exp2_f32(np.float32(0.0)) == 1.0 and exp2_f32(np.float32(-3.0)) == 0.125


@pytest.mark.parametrize("power", [20.0, 40.0, 128.0])
def test_a_power_below_2_to_the_minus_100_is_zero_so_no_product_of_it_is_subnormal(power):
    """Powers that small are flushed to 0: kept, a specular factor near float32's smallest
    normal number makes subnormal products with the material's and the light's colours,
    each a slow microcode assist. Everything at or above 2⁻⁹⁹ is kept."""
    out = np.empty_like(X)
    _pow_all(X, np.float32(power), out)
    exact = X.astype(np.float64) ** power
    assert np.all(out[exact < 2.0 ** -101] == 0.0)
    assert np.all(out[exact > 2.0 ** -99] > 0.0)
    tiny = out[(out > 0.0)].min()
    assert tiny >= 2.0 ** -100.5 and (np.float32(tiny) * np.float32(0.3) * np.float32(2.0 ** -20)) >= np.finfo(np.float32).tiny
    assert exp2_f32(np.float32(EXP_FLUSH - 0.5)) == 0.0 and exp2_f32(EXP_FLUSH) == np.float32(2.0 ** -100)


def test_to8_rounds_half_to_even_as_rint_does():
    v = np.concatenate([np.linspace(-0.1, 1.1, 200_001), (np.arange(256) + 0.5) / 255]).astype(np.float32)
    out = np.empty(len(v), np.uint8)
    _to8_all(v, out)
    np.testing.assert_array_equal(out, np.rint(np.clip(v, 0, 1) * np.float32(255)).astype(np.uint8))


def test_half_rounds_as_a_16_bit_float_target():
    """The OIT accumulators' rounding is IEEE half precision, ties to even, subnormal halves
    included, in a loop LLVM vectorises (numpy's float16 conversion is the reference)."""
    rng = np.random.default_rng(5)
    halves = rng.random(3000).astype(np.float16).astype(np.float32)
    ties = halves + np.spacing(halves.astype(np.float16)).astype(np.float32) / 2  # halfway to the next half
    values = np.concatenate([rng.random(2000) * 4, rng.random(500) * 1e-4, rng.random(500) * 1e3, -rng.random(500),
                             ties, [0.0, 1.0, 2049 / 2048, 1e-7, 2.0 ** -14, 2.0 ** -14 * (1 - 2.0 ** -11),
                                    2.0 ** -25, 3 * 2.0 ** -26, 65504.0]])
    values = values.astype(np.float32)  # the kernels round float32 sums
    ours = np.empty_like(values)
    _half_all(values, ours)
    assert np.array_equal(ours, values.astype(np.float16).astype(np.float32))


def test_half_keeps_every_half_float_exactly():
    """Every finite half float is its own rounding: all 63,488 of them, through float32."""
    every = np.arange(0, 1 << 16, dtype=np.uint16).view(np.float16)
    every = every[np.isfinite(every)].astype(np.float32)
    ours = np.empty_like(every)
    _half_all(every, ours)
    assert np.array_equal(ours.view(np.uint32), every.view(np.uint32))


@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_unorm8_gives_the_bits_of_a_clamp_in_float64_for_either_width(dtype):
    """unorm8 clamps after making its value float32; the bytes are those of the clamp in
    float64 first (the framebuffer's rule), at the ends, just inside and outside them, at
    the half-way points of the 8-bit steps and on random values."""
    from renderer.float32_math import unorm8

    @njit
    def each(values, out):
        for i in range(values.shape[0]):
            out[i] = unorm8(values[i])

    steps = (np.arange(256) + 0.5) / 255.0
    values = np.concatenate([[0.0, -0.0, 1.0, -1e-50, 1e-50, -0.3, 1.7, 1e30, -1e30, np.nextafter(1.0, 2.0),
                              np.nextafter(1.0, 0.0)], steps, np.nextafter(steps, 0.0), np.nextafter(steps, 1.0),
                             np.random.default_rng(5).uniform(-0.2, 1.2, 2000)]).astype(dtype)
    out = np.empty(len(values), np.uint8)
    each(values, out)
    clamped64 = np.clip(values.astype(np.float64), 0.0, 1.0)
    expected = np.rint(clamped64.astype(np.float32) * np.float32(255.0)).astype(np.uint8)
    assert np.array_equal(out, expected)
