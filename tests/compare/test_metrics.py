"""Tests for compare/metrics.py: the sRGB → L*a*b* → CIEDE2000 pipeline and the metrics."""
import json
import warnings

import numpy as np
import pytest

from compare.metrics import (
    DIFFERENCE_METHODS,
    compare_frames,
    coverage_masks,
    delta_E_map,
    measure,
    sRGB8_to_Lab,
)
from lab.frame import Frame

with warnings.catch_warnings():
    warnings.filterwarnings("ignore", message='"SciPy" related API features')
    import colour

# Sharma, Wu & Dalal (2005), "The CIEDE2000 color-difference formula: Implementation
# notes, supplementary test data, and mathematical observations", Color Res. Appl.
# 30(1):21-30, Table 1: L*a*b* of both samples and ΔE00 to 4 decimals (kL = kC = kH = 1).
# Pair 14 is left out: its hue difference is exactly 180°, where the result flips between
# 4.8045 and 4.7461 with the last bit of arctan2 (colour-science's own test skips it too).
SHARMA_2005 = [  # (pair, Lab_1, Lab_2, ΔE00)
    (1, (50.0000, 2.6772, -79.7751), (50.0000, 0.0000, -82.7485), 2.0425),
    (2, (50.0000, 3.1571, -77.2803), (50.0000, 0.0000, -82.7485), 2.8615),
    (3, (50.0000, 2.8361, -74.0200), (50.0000, 0.0000, -82.7485), 3.4412),
    (4, (50.0000, -1.3802, -84.2814), (50.0000, 0.0000, -82.7485), 1.0000),
    (5, (50.0000, -1.1848, -84.8006), (50.0000, 0.0000, -82.7485), 1.0000),
    (6, (50.0000, -0.9009, -85.5211), (50.0000, 0.0000, -82.7485), 1.0000),
    (7, (50.0000, 0.0000, 0.0000), (50.0000, -1.0000, 2.0000), 2.3669),
    (8, (50.0000, -1.0000, 2.0000), (50.0000, 0.0000, 0.0000), 2.3669),
    (9, (50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0009), 7.1792),
    (10, (50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0010), 7.1792),
    (11, (50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0011), 7.2195),
    (12, (50.0000, 2.4900, -0.0010), (50.0000, -2.4900, 0.0012), 7.2195),
    (13, (50.0000, -0.0010, 2.4900), (50.0000, 0.0009, -2.4900), 4.8045),
    (15, (50.0000, -0.0010, 2.4900), (50.0000, 0.0011, -2.4900), 4.7461),
    (16, (50.0000, 2.5000, 0.0000), (50.0000, 0.0000, -2.5000), 4.3065),
    (17, (50.0000, 2.5000, 0.0000), (73.0000, 25.0000, -18.0000), 27.1492),
    (18, (50.0000, 2.5000, 0.0000), (61.0000, -5.0000, 29.0000), 22.8977),
    (19, (50.0000, 2.5000, 0.0000), (56.0000, -27.0000, -3.0000), 31.9030),
    (20, (50.0000, 2.5000, 0.0000), (58.0000, 24.0000, 15.0000), 19.4535),
    (21, (50.0000, 2.5000, 0.0000), (50.0000, 3.1736, 0.5854), 1.0000),
    (22, (50.0000, 2.5000, 0.0000), (50.0000, 3.2972, 0.0000), 1.0000),
    (23, (50.0000, 2.5000, 0.0000), (50.0000, 1.8634, 0.5757), 1.0000),
    (24, (50.0000, 2.5000, 0.0000), (50.0000, 3.2592, 0.3350), 1.0000),
    (25, (60.2574, -34.0099, 36.2677), (60.4626, -34.1751, 39.4387), 1.2644),
    (26, (63.0109, -31.0961, -5.8663), (62.8187, -29.7946, -4.0864), 1.2630),
    (27, (61.2901, 3.7196, -5.3901), (61.4292, 2.2480, -4.9620), 1.8731),
    (28, (35.0831, -44.1164, 3.7933), (35.0232, -40.0716, 1.5901), 1.8645),
    (29, (22.7233, 20.0904, -46.6940), (23.0331, 14.9730, -42.5619), 2.0373),
    (30, (36.4612, 47.8580, 18.3852), (36.2715, 50.5065, 21.2231), 1.4146),
    (31, (90.8027, -2.0831, 1.4410), (91.1528, -1.6435, 0.0447), 1.4441),
    (32, (90.9257, -0.5406, -0.9208), (88.6381, -0.8985, -0.7239), 1.5381),
    (33, (6.7747, -0.2908, -2.4247), (5.8714, -0.0985, -2.2286), 0.6377),
    (34, (2.0776, 0.0795, -1.1350), (0.9033, -0.0636, -0.5514), 0.9082),
]


def test_ciede2000_matches_sharma_2005_test_data():
    lab_1 = np.array([row[1] for row in SHARMA_2005])
    lab_2 = np.array([row[2] for row in SHARMA_2005])
    expected = np.array([row[3] for row in SHARMA_2005])
    difference = DIFFERENCE_METHODS["CIE 2000"].difference
    # the table is rounded to 4 decimals, so agree to within half a unit of the last one
    np.testing.assert_allclose(difference(lab_1, lab_2), expected, rtol=0, atol=5e-5)
    np.testing.assert_allclose(difference(lab_2, lab_1), expected, rtol=0, atol=5e-5)


@pytest.mark.parametrize(
    "rgb, lab",
    [  # commonly tabulated sRGB (D65) → CIE L*a*b* (D65) values
        ((255, 255, 255), (100.0, 0.0, 0.0)),
        ((0, 0, 0), (0.0, 0.0, 0.0)),
        ((128, 128, 128), (53.585, 0.0, 0.0)),  # checks the sRGB curve is decoded
        ((255, 0, 0), (53.241, 80.092, 67.203)),  # checks the D65 white point
        ((0, 255, 0), (87.735, -86.183, 83.179)),
        ((0, 0, 255), (32.297, 79.188, -107.860)),
    ],
)
def test_sRGB8_to_Lab_known_values(rgb, lab):
    # 0.05 absorbs the rounding of the sRGB matrix between sources; a wrong white point
    # or a missing sRGB decoding is off by more than 1.
    np.testing.assert_allclose(sRGB8_to_Lab(np.array(rgb, np.uint8)), lab, atol=0.05)


def _frame(rgb, coverage=None):
    rgb = np.asarray(rgb, np.uint8)
    if coverage is None:
        coverage = np.ones(rgb.shape[:2], bool)
    coverage = np.asarray(coverage, bool)
    return Frame(rgb=rgb, depth=np.where(coverage, 0.5, 1.0), coverage=coverage)


def test_identical_images_give_zero_everywhere():
    rng = np.random.default_rng(1)
    rgb = rng.integers(0, 256, (24, 32, 3), dtype=np.uint8)
    coverage = rng.random((24, 32)) < 0.6
    metrics, de = compare_frames(_frame(rgb, coverage), _frame(rgb.copy(), coverage))
    assert de.shape == (24, 32) and not de.any()
    assert all(v == 0.0 for v in metrics["delta_e_2000"].values())
    assert metrics["pixels_over_1"] == 0.0
    assert metrics["coverage_mismatch"] == 0.0
    assert metrics["max_channel_diff"] == 0
    assert metrics["shared_pixels"] == np.count_nonzero(coverage)
    assert metrics["mismatch_pixels"] == 0


def test_single_pixel_change_gives_colour_delta_E():
    a = np.full((4, 5, 3), (200, 120, 40), np.uint8)
    b = a.copy()
    b[2, 3] = (190, 125, 40)
    lab = colour.XYZ_to_Lab(
        colour.sRGB_to_XYZ(np.array([[200, 120, 40], [190, 125, 40]]) / 255),
        colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"],
    )
    expected = float(colour.delta_E(lab[0], lab[1], method="CIE 2000"))
    assert expected > 1  # a visible change, so it counts in pixels_over_1

    metrics, de = compare_frames(_frame(a), _frame(b))
    assert de[2, 3] == pytest.approx(expected, rel=1e-12)
    de[2, 3] = 0
    assert not de.any()
    stats = metrics["delta_e_2000"]
    assert stats["max"] == pytest.approx(expected, rel=1e-12)
    assert stats["mean"] == pytest.approx(expected / 20, rel=1e-12)
    assert stats["median"] == 0.0
    values = [0.0] * 19 + [expected]  # percentiles interpolate linearly (numpy default)
    for key, q in (("p95", 95), ("p99", 99), ("p999", 99.9)):
        assert stats[key] == pytest.approx(np.percentile(values, q), rel=1e-12)
    assert metrics["pixels_over_1"] == pytest.approx(1 / 20)
    assert metrics["max_channel_diff"] == 10


def test_coverage_counts_on_a_hand_made_example():
    cov_a = [[True, True, False],
             [False, True, False]]
    cov_b = [[True, False, False],
             [True, True, False]]
    a = np.zeros((2, 3, 3), np.uint8)
    b = np.zeros((2, 3, 3), np.uint8)
    b[0, 1] = 255  # differs where only ``ours`` has coverage: no ΔE, but a channel diff
    b[1, 2] = 7  # differs where neither has coverage
    ours, ref = _frame(a, cov_a), _frame(b, cov_b)

    shared, mismatch = coverage_masks(ours, ref)
    np.testing.assert_array_equal(shared, [[True, False, False], [False, True, False]])
    np.testing.assert_array_equal(mismatch, [[False, True, False], [True, False, False]])
    metrics, de = compare_frames(ours, ref)
    assert metrics["shared_pixels"] == 2
    assert metrics["mismatch_pixels"] == 2
    assert metrics["coverage_mismatch"] == pytest.approx(2 / 6)
    assert metrics["max_channel_diff"] == 255  # over all pixels, covered or not
    assert not de.any() and metrics["delta_e_2000"]["max"] == 0.0


def test_no_shared_coverage_gives_zeros():
    a = np.zeros((3, 3, 3), np.uint8)
    metrics = measure(_frame(a, np.eye(3)), _frame(a + 9, np.zeros((3, 3))))
    assert metrics["shared_pixels"] == 0
    assert all(v == 0.0 for v in metrics["delta_e_2000"].values())
    assert metrics["pixels_over_1"] == 0.0
    assert metrics["coverage_mismatch"] == pytest.approx(3 / 9)
    assert metrics["max_channel_diff"] == 9


def _brute_force(a, b, method):
    encode = {"CAM16-UCS": lambda xyz: colour.XYZ_to_CAM16UCS(xyz)}.get(
        method, lambda xyz: colour.XYZ_to_Lab(xyz, colour.CCS_ILLUMINANTS[
            "CIE 1931 2 Degree Standard Observer"]["D65"]))
    return colour.delta_E(encode(colour.sRGB_to_XYZ(a / 255)),
                          encode(colour.sRGB_to_XYZ(b / 255)), method=method)


@pytest.mark.parametrize("method", list(DIFFERENCE_METHODS))
@pytest.mark.parametrize("palette", [8, 256])  # few colours (many repeats) / all random
def test_unique_colour_fast_path_equals_brute_force(method, palette):
    rng = np.random.default_rng(palette)
    levels = np.linspace(0, 255, palette).round().astype(np.uint8)
    a = levels[rng.integers(0, palette, (40, 50, 3))]
    b = a.copy()
    changed = rng.random((40, 50)) < 0.3
    b[changed] = levels[rng.integers(0, palette, (np.count_nonzero(changed), 3))]
    fast = delta_E_map(a, b, method)
    assert fast.shape == (40, 50)
    np.testing.assert_allclose(fast, _brute_force(a, b, method), rtol=1e-12, atol=1e-12)


def test_delta_E_map_rejects_bad_input():
    a = np.zeros((2, 2, 3), np.uint8)
    with pytest.raises(TypeError):
        delta_E_map(a / 255, a)
    with pytest.raises(ValueError):
        delta_E_map(a, a[:1])
    with pytest.raises(ValueError):
        delta_E_map(a, a, method="CIE 1994")


def test_metrics_are_json_serialisable_plain_numbers():
    rng = np.random.default_rng(3)
    ours = _frame(rng.integers(0, 256, (8, 9, 3), dtype=np.uint8), rng.random((8, 9)) < 0.7)
    ref = _frame(rng.integers(0, 256, (8, 9, 3), dtype=np.uint8), rng.random((8, 9)) < 0.7)
    metrics = measure(ours, ref)
    assert set(metrics) == {"delta_e_2000", "pixels_over_1", "coverage_mismatch",
                            "max_channel_diff", "shared_pixels", "mismatch_pixels"}
    assert set(metrics["delta_e_2000"]) == {"mean", "median", "p95", "p99", "p999", "max"}
    assert all(type(v) is float for v in metrics["delta_e_2000"].values())
    assert type(metrics["pixels_over_1"]) is float
    assert type(metrics["coverage_mismatch"]) is float
    for key in ("max_channel_diff", "shared_pixels", "mismatch_pixels"):
        assert type(metrics[key]) is int
    assert json.loads(json.dumps(metrics)) == metrics
