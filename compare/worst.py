"""The worst pixels of a comparison: where to look first, and what is there.

Conventions: images in image rows (row 0 at the top), pixels named (row, col); a pixel's
*x* is its column and its *y* its row from the top, as in an image viewer.

Ranking (:func:`worst_pixels`): a pixel drawn by one renderer only (coverage mismatch)
is worse than any colour difference, since it breaks the strictest bar; among shared
pixels a larger ΔE2000 is worse; ties go to the first pixel in reading order (row by
row), so the choice is the same every run. Pixels with ΔE2000 = 0 are never "worst".
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np

INSET = 9
"""Side of the zoomed inset around the worst pixel, in image pixels (odd: it has a centre)."""
SPACING = 24
"""Marked pixels lie at least this many pixels apart (in x or y), so their rings do not pile up."""
CANDIDATES = 4096
"""Pixels considered for the marks, worst first (more than enough to find a few far apart)."""


def worst_pixels(de: np.ndarray, mismatch: np.ndarray, n: int = 5, spacing: int = SPACING) -> list[tuple[int, int]]:
    """Up to ``n`` worst pixels as (row, col), worst first, at least ``spacing`` apart.

    Parameters
    ----------
    de : (H, W) float, ΔE2000 per pixel (0 where coverage is not shared).
    mismatch : (H, W) bool, True where exactly one renderer drew.
    n : how many to return at most.
    spacing : a pixel is skipped when one already chosen lies within ``spacing`` pixels
        in both x and y.

    Returns [] when the two images agree exactly (no mismatch, ΔE2000 0 everywhere).
    """
    de = np.asarray(de, float)
    score = np.where(np.asarray(mismatch, bool), np.inf, de).ravel()
    candidates = np.flatnonzero(score > 0)
    if candidates.size > CANDIDATES:
        keep = np.argpartition(-score[candidates], CANDIDATES - 1)[:CANDIDATES]
        candidates = candidates[keep]
    order = candidates[np.lexsort((candidates, -score[candidates]))]  # worst first, then reading order
    chosen: list[tuple[int, int]] = []
    width = de.shape[1]
    for flat in order:
        r, c = divmod(int(flat), width)
        if all(abs(r - r0) >= spacing or abs(c - c0) >= spacing for r0, c0 in chosen):
            chosen.append((r, c))
            if len(chosen) == n:
                break
    return chosen


def window(image: np.ndarray, row: int, col: int, size: int = INSET, fill=np.nan) -> np.ndarray:
    """The ``size``×``size`` block of ``image`` centred on (row, col), padded with ``fill``
    where it runs off the image; keeps trailing axes (an RGB image gives (size, size, 3))."""
    image = np.asarray(image)
    half = size // 2
    dtype = np.result_type(image.dtype, np.asarray(fill).dtype)
    out = np.full((size, size) + image.shape[2:], fill, dtype=dtype)
    r0, c0 = row - half, col - half
    rs, re = max(r0, 0), min(r0 + size, image.shape[0])
    cs, ce = max(c0, 0), min(c0 + size, image.shape[1])
    out[rs - r0:re - r0, cs - c0:ce - c0] = image[rs:re, cs:ce]
    return out


class PixelReport(NamedTuple):
    """What both renderers put at one pixel (row, col; image rows)."""

    row: int
    col: int
    ours: tuple[int, int, int]
    reference: tuple[int, int, int]
    delta_e: float
    coverage: str
    """"shared", "ours only", "reference only" or "differs" (one side only, not known which)."""

    def caption(self, names: tuple[str, str] = ("ours", "VTK")) -> str:
        """One line: where the pixel is and what each side holds there."""
        where = f"x {self.col}, y {self.row}"
        a, b = names
        if self.coverage == "shared":
            return f"{where}: {a} {self.ours}, {b} {self.reference}, ΔE2000 {self.delta_e:.2f}"
        if self.coverage == "differs":
            return f"{where}: coverage differs, one side drew here ({a} {self.ours}, {b} {self.reference})"
        drew = a if self.coverage == "ours only" else b
        return f"{where}: coverage differs, only {drew} drew here ({a} {self.ours}, {b} {self.reference})"


def pixel_report(ours_rgb, ref_rgb, de, ours_coverage, ref_coverage, row: int, col: int) -> PixelReport:
    """The two colours (8-bit), ΔE2000 and coverage at (row, col)."""
    a, b = bool(ours_coverage[row, col]), bool(ref_coverage[row, col])
    coverage = "shared" if a == b else ("ours only" if a else "reference only")
    return PixelReport(row, col, tuple(int(v) for v in ours_rgb[row, col]), tuple(int(v) for v in ref_rgb[row, col]),
                       float(de[row, col]), coverage)
