"""Per-pixel colour difference between two renders, measured with colour-science.

Both renderers write 8-bit sRGB-encoded values (see ``lab/frame.py``). To compare them
the way a person would, every pixel is decoded to CIE XYZ and then to a perceptual space,
where the colour difference ΔE is computed:

- ``"CIE 2000"`` (the default and the one reported by :func:`measure`): CIEDE2000 on
  CIE L*a*b* (D65). Formula and test data: G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000
  color-difference formula: Implementation notes, supplementary test data, and
  mathematical observations", Color Research & Application 30(1), 21-30 (2005),
  doi:10.1002/col.20070. ΔE2000 ≈ 1 is about a just noticeable difference.
- ``"CIE 1976"``: plain Euclidean distance in CIE L*a*b* (ΔE*ab).
- ``"CAM16-UCS"``: Euclidean distance in CAM16-UCS J'a'b' (Li et al. 2017).

colour-science functions used: :func:`colour.sRGB_to_XYZ`, :func:`colour.XYZ_to_Lab`,
:func:`colour.XYZ_to_CAM16UCS` and :func:`colour.delta_E`.

Speed: a render has few distinct colours, so colours are converted once per *unique*
colour and ΔE is computed once per *unique* (colour_a, colour_b) pair, then mapped back
to the pixels (:func:`delta_E_map`). The result is identical to converting every pixel.
"""
from __future__ import annotations

import warnings
from functools import partial
from typing import Callable, NamedTuple

import numpy as np

with warnings.catch_warnings():  # colour warns that SciPy is absent; nothing here needs it
    warnings.filterwarnings("ignore", message='"SciPy" related API features')
    import colour

from lab.frame import Frame

D65_xy = colour.CCS_ILLUMINANTS["CIE 1931 2 Degree Standard Observer"]["D65"]
"""CIE 1931 2° chromaticity (x, y) of illuminant D65, the sRGB white point."""

PERCENTILES = {"median": 50.0, "p95": 95.0, "p99": 99.0, "p999": 99.9}


def _as_rgb8(rgb: np.ndarray) -> np.ndarray:
    rgb = np.asarray(rgb)
    if rgb.dtype != np.uint8 or rgb.shape[-1:] != (3,):
        raise TypeError(f"expected a uint8 (..., 3) array, got {rgb.dtype} {rgb.shape}")
    return rgb


def sRGB8_to_XYZ(rgb: np.ndarray) -> np.ndarray:
    """Decode 8-bit sRGB to CIE XYZ (D65), with ``colour.sRGB_to_XYZ``.

    Parameters
    ----------
    rgb : (..., 3) uint8, sRGB-encoded code values 0..255.

    Returns
    -------
    (..., 3) float64, CIE XYZ with Y in 0..1 (Y = 1 for sRGB white).
    """
    return colour.sRGB_to_XYZ(_as_rgb8(rgb) / 255)


def sRGB8_to_Lab(rgb: np.ndarray) -> np.ndarray:
    """Convert 8-bit sRGB to CIE L*a*b* (reference white D65).

    ``colour.sRGB_to_XYZ`` undoes the sRGB transfer curve (IEC 61966-2-1) and applies the
    sRGB primaries; ``colour.XYZ_to_Lab`` uses the D65 white point, so sRGB white maps to
    L* = 100, a* ≈ b* ≈ 0 (within 0.01: the sRGB matrix is rounded).

    Parameters
    ----------
    rgb : (..., 3) uint8, sRGB-encoded code values 0..255.

    Returns
    -------
    (..., 3) float64, L* in 0..100, a* and b* roughly -128..128.
    """
    return colour.XYZ_to_Lab(sRGB8_to_XYZ(rgb), D65_xy)


def sRGB8_to_CAM16UCS(rgb: np.ndarray) -> np.ndarray:
    """Convert 8-bit sRGB to CAM16-UCS J'a'b' with ``colour.XYZ_to_CAM16UCS``.

    XYZ is passed on the 0..1 scale: colour-science scales it to Y = 100 itself and uses
    the sRGB reference viewing conditions of IEC 61966-2-1 (D65 white at Y = 100,
    64 lx ambient so L_A = 64/π · 0.2 ≈ 4.07 cd/m², Y_b = 20, average surround).

    Parameters
    ----------
    rgb : (..., 3) uint8, sRGB-encoded code values 0..255.

    Returns
    -------
    (..., 3) float64, J' in 0..100, a' and b' roughly -50..50.
    """
    return colour.XYZ_to_CAM16UCS(sRGB8_to_XYZ(rgb))


class DifferenceMethod(NamedTuple):
    """How to measure ΔE: the colour space to convert to, and the distance in it.

    Attributes
    ----------
    encode : uint8 sRGB (N, 3) -> (N, 3) float coordinates in the working space.
    difference : two (N, 3) coordinate arrays -> (N,) float ΔE (unitless, >= 0).
    """

    encode: Callable[[np.ndarray], np.ndarray]
    difference: Callable[[np.ndarray, np.ndarray], np.ndarray]


DIFFERENCE_METHODS: dict[str, DifferenceMethod] = {
    "CIE 2000": DifferenceMethod(sRGB8_to_Lab, partial(colour.delta_E, method="CIE 2000")),
    "CIE 1976": DifferenceMethod(sRGB8_to_Lab, partial(colour.delta_E, method="CIE 1976")),
    "CAM16-UCS": DifferenceMethod(
        sRGB8_to_CAM16UCS, partial(colour.delta_E, method="CAM16-UCS")
    ),
}
"""Colour difference methods by name, as in ``colour.DELTA_E_METHODS``."""


def _pack(rgb: np.ndarray) -> np.ndarray:
    """(..., 3) uint8 -> (...) int64 code 0xRRGGBB."""
    rgb = rgb.astype(np.int64)
    return (rgb[..., 0] << 16) | (rgb[..., 1] << 8) | rgb[..., 2]


def _unpack(code: np.ndarray) -> np.ndarray:
    """(N,) int64 code 0xRRGGBB -> (N, 3) uint8."""
    return np.stack([code >> 16, code >> 8, code], axis=-1).astype(np.uint8)


def delta_E_map(rgb_a: np.ndarray, rgb_b: np.ndarray, method: str = "CIE 2000") -> np.ndarray:
    """Colour difference ΔE between two 8-bit sRGB images, pixel by pixel.

    Each unique colour is converted once and ΔE is computed once per unique
    (colour_a, colour_b) pair; the result equals converting every pixel.

    Parameters
    ----------
    rgb_a, rgb_b : (..., 3) uint8, same shape, sRGB-encoded (e.g. (H, W, 3) images).
    method : a key of :data:`DIFFERENCE_METHODS` ("CIE 2000", "CIE 1976", "CAM16-UCS").

    Returns
    -------
    (...) float64, ΔE per pixel (unitless, 0 for equal colours; ΔE2000 is 0..~100
    for sRGB, ≈ 1 is a just noticeable difference).
    """
    a, b = _as_rgb8(rgb_a), _as_rgb8(rgb_b)
    if a.shape != b.shape:
        raise ValueError(f"image shapes differ: {a.shape} vs {b.shape}")
    if method not in DIFFERENCE_METHODS:
        raise ValueError(f"unknown method {method!r}; choose from {list(DIFFERENCE_METHODS)}")
    encode, difference = DIFFERENCE_METHODS[method]
    n = a[..., 0].size
    if n == 0:
        return np.zeros(a.shape[:-1])
    colours, index = np.unique(
        np.concatenate([_pack(a).ravel(), _pack(b).ravel()]), return_inverse=True
    )
    coords = encode(_unpack(colours))
    pairs, pair_of_pixel = np.unique(index[:n] * len(colours) + index[n:], return_inverse=True)
    de = np.asarray(difference(coords[pairs // len(colours)], coords[pairs % len(colours)]))
    return de.reshape(-1)[pair_of_pixel].reshape(a.shape[:-1])


def coverage_masks(ours: Frame, ref: Frame) -> tuple[np.ndarray, np.ndarray]:
    """Where the two frames are compared, and where their coverage disagrees.

    Returns
    -------
    shared : (H, W) bool, True where both frames have coverage (pixels that get a ΔE).
    mismatch : (H, W) bool, True where exactly one frame has coverage.
    """
    if ours.rgb.shape != ref.rgb.shape or ours.coverage.shape != ref.coverage.shape:
        raise ValueError(f"frame sizes differ: {ours.rgb.shape} vs {ref.rgb.shape}")
    cov_a, cov_b = np.asarray(ours.coverage, bool), np.asarray(ref.coverage, bool)
    return cov_a & cov_b, cov_a != cov_b


def compare_frames(ours: Frame, ref: Frame) -> tuple[dict, np.ndarray]:
    """Compare our render with the reference render.

    Parameters
    ----------
    ours, ref : Frame, same size.

    Returns
    -------
    metrics : dict, JSON-serialisable (plain ``float`` / ``int``):

        - ``"delta_e_2000"``: dict with ``"mean"``, ``"median"``, ``"p95"``, ``"p99"``,
          ``"p999"`` (99.9th percentile) and ``"max"`` of ΔE2000 (unitless, 0..~100) over
          the *shared-coverage* pixels (both frames have coverage); all 0.0 if none.
        - ``"pixels_over_1"``: fraction 0..1 *of the shared-coverage pixels* with
          ΔE2000 > 1 (0.0 if there are none).
        - ``"coverage_mismatch"``: fraction 0..1 *of all pixels* where exactly one frame
          has coverage.
        - ``"max_channel_diff"``: int 0..255, largest absolute difference of any uint8
          channel over *all* pixels (covered or not).
        - ``"shared_pixels"``, ``"mismatch_pixels"``: int pixel counts.

    de_map : (H, W) float64, ΔE2000 per pixel, 0.0 where coverage is not shared.

    Use :func:`coverage_masks` for the matching boolean masks.
    """
    shared, mismatch = coverage_masks(ours, ref)
    de_map = np.zeros(shared.shape)
    de_map[shared] = delta_E_map(ours.rgb[shared], ref.rgb[shared], "CIE 2000")
    de = de_map[shared]
    if de.size:
        stats = {"mean": de.mean(), "max": de.max()}
        stats.update({k: np.percentile(de, q) for k, q in PERCENTILES.items()})
        over_1 = np.count_nonzero(de > 1.0) / de.size
    else:
        stats = dict.fromkeys(["mean", "max", *PERCENTILES], 0.0)
        over_1 = 0.0
    channel_diff = np.abs(ours.rgb.astype(np.int16) - ref.rgb.astype(np.int16))
    metrics = {
        "delta_e_2000": {k: float(stats[k]) for k in ("mean", *PERCENTILES, "max")},
        "pixels_over_1": float(over_1),
        "coverage_mismatch": float(mismatch.mean()) if mismatch.size else 0.0,
        "max_channel_diff": int(channel_diff.max()) if channel_diff.size else 0,
        "shared_pixels": int(np.count_nonzero(shared)),
        "mismatch_pixels": int(np.count_nonzero(mismatch)),
    }
    return metrics, de_map


def measure(ours: Frame, ref: Frame) -> dict:
    """The metrics of :func:`compare_frames` without the ΔE map."""
    return compare_frames(ours, ref)[0]


# The bars and the judge live in compare.verdict; these names stay for the code that reads them here.
from compare.verdict import PARITY_BARS, failed_bars  # noqa: E402,F401
