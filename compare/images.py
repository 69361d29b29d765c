"""PNG output for comparisons: raw frames, a ΔE heat map, and a side-by-side panel.

Every file is written atomically (:func:`lab.atomic.atomic_file`): into a temporary file
in the target's directory, then moved over the target with ``os.replace``, so an
interrupted write never leaves a partial PNG behind (an existing target stays untouched).

Figures use matplotlib's object-oriented API (``matplotlib.figure.Figure``), which
renders with the Agg backend without touching pyplot or the process-wide backend, so
this works headless and alongside interactive plotting. Images are drawn at native
pixel resolution (one image pixel = one PNG pixel at ``DPI`` = 100), enlarged by an
integer factor only when they are too small for their labels, always with
``interpolation="nearest"`` so they stay crisp.
"""
from __future__ import annotations

import math
import os

import numpy as np
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from matplotlib.patches import Patch

from lab.atomic import atomic_file

DPI = 100
"""Figure resolution, dots per inch: with it, sizes below are PNG pixels."""
VMAX = 5.0
"""Default top of the ΔE2000 colour scale; larger values are clipped to its colour."""
CMAP = "viridis"
"""Colour map for ΔE: dark and calm near 0, bright yellow at VMAX."""
MISMATCH_COLOUR = (1.0, 0.0, 1.0)  # magenta: not in viridis, so it cannot be misread
BACKGROUND_COLOUR = (0.85, 0.85, 0.85)  # light grey: neither frame has coverage
MIN_PANEL_PX = 256  # small images are enlarged by an integer factor up to this width


def _save_figure(fig: Figure, path: str | os.PathLike) -> None:
    with atomic_file(path) as f:
        fig.savefig(f, format="png", dpi=DPI)


class _PixelCanvas:
    """A figure laid out in PNG pixels, measured from the top-left corner."""

    def __init__(self, width: int, height: int):
        self.width, self.height = width, height
        self.fig = Figure(figsize=(width / DPI, height / DPI), dpi=DPI, facecolor="white")

    def box(self, left: float, top: float, width: float, height: float) -> list[float]:
        """Figure-fraction rectangle [x0, y0, w, h] of a pixel box."""
        return [left / self.width, 1 - (top + height) / self.height,
                width / self.width, height / self.height]

    def axes(self, left: float, top: float, width: float, height: float):
        return self.fig.add_axes(self.box(left, top, width, height))

    def text(self, left: float, top: float, s: str, **kwargs) -> None:
        self.fig.text(left / self.width, 1 - top / self.height, s, va="top", **kwargs)


def _scale(width: int) -> int:
    """Integer enlargement so that a panel is at least MIN_PANEL_PX wide."""
    return max(1, math.ceil(MIN_PANEL_PX / max(width, 1)))


def _show_rgb(ax, rgb: np.ndarray, title: str) -> None:
    ax.imshow(rgb, interpolation="nearest")
    ax.set_title(title, fontsize=11)
    ax.set_axis_off()


def _show_delta_e(ax, cax, de, mismatch, shared, vmax: float, title: str) -> list[Patch]:
    """Draw the ΔE heat map on ``ax`` and its colour bar on ``cax``; return legend."""
    de = np.asarray(de, float)
    mismatch = np.asarray(mismatch, bool)
    if de.shape != mismatch.shape:
        raise ValueError(f"de {de.shape} and mismatch mask {mismatch.shape} differ")
    image = ax.imshow(de, cmap=CMAP, norm=Normalize(0.0, vmax), interpolation="nearest")
    overlay = np.zeros(de.shape + (4,))
    overlay[mismatch] = (*MISMATCH_COLOUR, 1.0)
    legend = [Patch(color=MISMATCH_COLOUR,
                    label=f"coverage differs ({np.count_nonzero(mismatch):,} px)")]
    if shared is not None:
        overlay[~np.asarray(shared, bool) & ~mismatch] = (*BACKGROUND_COLOUR, 1.0)
        legend.append(Patch(color=BACKGROUND_COLOUR, label="no coverage in either"))
    ax.imshow(overlay, interpolation="nearest")
    ax.set_title(title, fontsize=11)
    ax.set_axis_off()

    bar = ax.figure.colorbar(image, cax=cax, extend="max")
    step = 1.0 if vmax <= 10 else 10.0 ** math.floor(math.log10(vmax / 2))
    ticks = [t for t in np.arange(0.0, vmax, step) if t <= vmax - step / 2]
    bar.set_ticks([*ticks, vmax], labels=[f"{t:g}" for t in ticks] + [f"≥{vmax:g}"])
    bar.set_label("ΔE2000 (unitless)", fontsize=10)
    return legend


def _legend_height(panel_width: int) -> int:
    """Pixels taken by the legend row(s) under a ΔE panel of that width."""
    return 28 if panel_width >= 400 else 48


def _legend(canvas: _PixelCanvas, handles: list[Patch], left: int, top: int,
            panel_width: int) -> None:
    """Legend under a ΔE panel: side by side if wide enough, else stacked."""
    canvas.fig.legend(handles=handles, loc="upper left", frameon=False, fontsize=9,
                      ncols=2 if panel_width >= 400 else 1, borderaxespad=0.0,
                      bbox_to_anchor=canvas.box(left, top + 6, panel_width, 0)[:2])


def delta_e_figure(de: np.ndarray, coverage_mismatch_mask: np.ndarray,
                   path: str | os.PathLike, *, shared: np.ndarray | None = None,
                   vmax: float = VMAX, title: str = "ΔE2000 per pixel") -> None:
    """Write a ΔE2000 heat map with a colour bar as PNG, atomically.

    Parameters
    ----------
    de : (H, W) float, ΔE2000 (unitless, 0..~100), e.g. from
        :func:`compare.metrics.compare_frames`. Values above ``vmax`` get the top
        colour; the bar says "≥vmax".
    coverage_mismatch_mask : (H, W) bool, True where exactly one frame has coverage;
        drawn magenta.
    path : target PNG file name.
    shared : (H, W) bool, optional, True where both frames have coverage. Pixels that are
        neither shared nor mismatched (background) are drawn light grey. If None, every
        pixel outside the mismatch mask is drawn from the colour map.
    vmax : top of the colour scale, ΔE2000 (default 5, so that a pass looks calm and
        a failure looks loud).
    title : heading above the map.
    """
    h, w = np.shape(de)
    s = _scale(w)
    iw, ih = w * s, h * s
    left, top, bar_gap, bar_w, right = 16, 36, 14, 18, 80
    canvas = _PixelCanvas(left + iw + bar_gap + bar_w + right,
                          top + ih + _legend_height(iw) + 8)
    ax = canvas.axes(left, top, iw, ih)
    cax = canvas.axes(left + iw + bar_gap, top, bar_w, ih)
    legend = _show_delta_e(ax, cax, de, coverage_mismatch_mask, shared, vmax, title)
    _legend(canvas, legend, left, top + ih, iw)
    _save_figure(canvas.fig, path)


def _percent(fraction: float) -> str:
    if fraction == 0:
        return "0 %"
    return "<0.01 %" if fraction < 1e-4 else f"{100 * fraction:.2f} %"


def metrics_lines(metrics: dict) -> list[str]:
    """The figures of :func:`compare.metrics.measure` as two short lines of text.

    Timings ``"ours_ms"`` and ``"reference_ms"`` (milliseconds) are added when present.
    """
    de = metrics["delta_e_2000"]
    first = (f"ΔE2000 over {metrics['shared_pixels']:,} shared pixels:  "
             f"mean {de['mean']:.3f} · p99 {de['p99']:.3f} · p99.9 {de['p999']:.3f} · "
             f"max {de['max']:.3f} · pixels with ΔE > 1: "
             f"{_percent(metrics['pixels_over_1'])}")
    second = (f"coverage mismatch: {_percent(metrics['coverage_mismatch'])} of all pixels "
              f"({metrics['mismatch_pixels']:,} px) · "
              f"max channel diff: {metrics['max_channel_diff']} / 255")
    for key, name in (("ours_ms", "ours"), ("reference_ms", "reference")):
        if metrics.get(key) is not None:
            second += f" · {name}: {metrics[key]:.1f} ms"
    return [first, second]


def side_by_side_figure(ours_rgb: np.ndarray, ref_rgb: np.ndarray, de: np.ndarray,
                        mismatch_mask: np.ndarray, metrics: dict,
                        path: str | os.PathLike, title: str | None = None, *,
                        shared: np.ndarray | None = None, vmax: float = VMAX,
                        labels: tuple[str, str] = ("scanlab (ours)", "VTK (reference)")) -> None:
    """Write "scanlab (ours)" | "VTK (reference)" | "ΔE2000" as one PNG, atomically.

    ``labels`` renames the two image panels (a lesson may compare two of our renders).

    The figures of ``metrics`` (see :func:`metrics_lines`) are printed underneath.

    Parameters
    ----------
    ours_rgb, ref_rgb : (H, W, 3) uint8, the two renders, row 0 at the top.
    de : (H, W) float, ΔE2000 map (unitless), shown on a 0..``vmax`` scale.
    mismatch_mask : (H, W) bool, True where coverage differs; drawn magenta.
    metrics : dict from :func:`compare.metrics.measure`, optionally with
        ``"ours_ms"`` and ``"reference_ms"`` timings in milliseconds.
    path : target PNG file name.
    title : optional heading above the panels (e.g. the scene name).
    shared : (H, W) bool, optional, True where both frames have coverage; background
        pixels of the ΔE panel are then drawn light grey (see :func:`delta_e_figure`).
    vmax : top of the ΔE2000 colour scale (default 5).
    """
    h, w = np.shape(de)
    if np.shape(ours_rgb) != (h, w, 3) or np.shape(ref_rgb) != (h, w, 3):
        raise ValueError("ours_rgb, ref_rgb and de must have the same height and width")
    s = _scale(w)
    iw, ih = w * s, h * s
    left, gap, bar_gap, bar_w, right = 16, 16, 14, 18, 80
    top = (40 if title else 0) + 32
    text_top = top + ih + _legend_height(iw)
    canvas = _PixelCanvas(left + 3 * iw + 2 * gap + bar_gap + bar_w + right, text_top + 50)
    if title:
        canvas.text(canvas.width / 2, 10, title, ha="center", fontsize=13,
                    fontweight="bold")
    x = [left + i * (iw + gap) for i in range(3)]
    _show_rgb(canvas.axes(x[0], top, iw, ih), ours_rgb, labels[0])
    _show_rgb(canvas.axes(x[1], top, iw, ih), ref_rgb, labels[1])
    legend = _show_delta_e(canvas.axes(x[2], top, iw, ih),
                           canvas.axes(x[2] + iw + bar_gap, top, bar_w, ih),
                           de, mismatch_mask, shared, vmax, "ΔE2000")
    _legend(canvas, legend, x[2], top + ih, iw)
    for i, line in enumerate(metrics_lines(metrics)):
        canvas.text(left, text_top + 22 * i, line, fontsize=10)
    _save_figure(canvas.fig, path)
