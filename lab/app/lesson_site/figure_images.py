"""The pictures of a lesson figure, written without any text in them.

Words on a page are translated; words burnt into a PNG are not. So the figure images
here carry no labels: the panel titles, the colour bar's ticks and the legend are HTML
around them, in the page's language (:mod:`lab.app.lesson_site.figure`). The colours are those
of the comparison run's panels (:mod:`compare.images`: viridis from 0 to ``VMAX``,
magenta where only one renderer drew, light grey where neither did), so a student who
has seen ``scanlab compare``'s output reads these the same way.

Images are written at their native size, one pixel per pixel, and the bytes depend only
on the arrays (Pillow's PNG writer, no time stamps).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib import colormaps

from compare.images import BACKGROUND_COLOUR, CMAP, MISMATCH_COLOUR, VMAX
from lab.png import write_png

DEPTH_VMAX_LSB = 8.0
"""Top of the depth-difference scale, in steps of a 24-bit depth buffer (1/2²⁴)."""


def _rgb8(colour) -> np.ndarray:
    return np.round(np.asarray(colour) * 255).astype(np.uint8)


def heat_map(values: np.ndarray, vmax: float, mismatch: np.ndarray, shared: np.ndarray) -> np.ndarray:
    """(H, W, 3) uint8: ``values`` 0..vmax through :data:`compare.images.CMAP` (clipped above),
    magenta where ``mismatch``, light grey where neither ``shared`` nor ``mismatch``."""
    lut = _rgb8(colormaps[CMAP](np.linspace(0.0, 1.0, 256))[:, :3])
    index = np.clip(np.round(np.asarray(values, float) / vmax * 255), 0, 255).astype(np.int64)
    rgb = lut[index]
    rgb[~shared & ~mismatch] = _rgb8(BACKGROUND_COLOUR)
    rgb[mismatch] = _rgb8(MISMATCH_COLOUR)
    return rgb


def colour_bar_stops(n: int = 11) -> list[str]:
    """CSS colour stops of the heat map's scale, bottom (0) to top (vmax): ``#rrggbb`` strings."""
    rgb = _rgb8(colormaps[CMAP](np.linspace(0.0, 1.0, n))[:, :3])
    return ["#%02x%02x%02x" % tuple(int(v) for v in c) for c in rgb]


def depth_grey(depth: np.ndarray, coverage: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Window depth (0 near .. 1 far) as grey, near bright: ``lo``..``hi`` spans white..dark grey,
    uncovered pixels black."""
    t = np.clip((np.asarray(depth) - lo) / max(hi - lo, 1e-12), 0.0, 1.0)
    grey = np.round(255 - 200 * t).astype(np.uint8)
    grey[~coverage] = 0
    return np.repeat(grey[..., None], 3, axis=2)


def write_figure_images(m, folder: Path, depth: bool = False) -> list[str]:
    """Write a :class:`lab.app.lesson_site.measurement.Measurement` as PNGs into ``folder``; return their names.

    ``ours.png`` and ``vtk.png`` (the two frames), ``delta_e.png`` (ΔE2000 heat map on
    0..``VMAX``); with ``depth``, also ``depth-ours.png``, ``depth-vtk.png`` (both on one
    grey scale, the range of the depths either drew) and ``depth-diff.png`` (|Δdepth| in
    24-bit steps on 0..``DEPTH_VMAX_LSB``).
    """
    names = {"ours.png": m.ours.rgb, "vtk.png": m.ref.rgb, "delta_e.png": heat_map(m.de, VMAX, m.mismatch, m.shared)}
    if depth:
        covered = m.ours.coverage | m.ref.coverage
        both = np.concatenate([m.ours.depth[m.ours.coverage], m.ref.depth[m.ref.coverage]])
        lo, hi = (float(both.min()), float(both.max())) if both.size else (0.0, 1.0)
        names["depth-ours.png"] = depth_grey(m.ours.depth, m.ours.coverage, lo, hi)
        names["depth-vtk.png"] = depth_grey(m.ref.depth, m.ref.coverage, lo, hi)
        steps = np.abs(m.ours.depth - m.ref.depth) * float(1 << 24)
        names["depth-diff.png"] = heat_map(steps, DEPTH_VMAX_LSB, m.mismatch, m.shared & covered)
    for name, rgb in names.items():
        write_png(folder / name, rgb)
    return list(names)


def depth_metrics(m) -> dict:
    """Depth agreement where both drew: largest and 99.9th-percentile |Δdepth| in 24-bit steps."""
    steps = np.abs(m.ours.depth - m.ref.depth)[m.shared] * float(1 << 24)
    if not steps.size:
        return {"max_lsb": 0.0, "p999_lsb": 0.0}
    return {"max_lsb": float(steps.max()), "p999_lsb": float(np.percentile(steps, 99.9))}
