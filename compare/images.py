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

A side-by-side panel explains itself: the settings that made it and the verdict are
printed above the images, the worst pixels (:mod:`compare.worst`) are ringed on all three
images, and a row underneath zooms into the worst one (ours, the reference and ΔE, 9×9
pixels) with its coordinates and channel values. Figures carry no timings, so the same
inputs give the same bytes (a figure kept in git does not change when it is made again).
"""
from __future__ import annotations

import math
import os
import textwrap
from contextlib import nullcontext
from typing import NamedTuple

import matplotlib
import numpy as np
from matplotlib.colors import Normalize
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Patch, Rectangle

from compare.worst import INSET, pixel_report, window, worst_pixels
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


MARKS = 5
"""How many of the worst pixels are ringed on a panel."""
MARK_COLOUR = (1.0, 0.1, 0.1)  # the rings: red with a white halo, visible on any colour
INSET_ZOOM = 12  # PNG pixels per image pixel in the zoomed inset
CHAR_PX = 7.2  # width of a wide-ish character at font size 10 (DejaVu Sans), for wrapping lines


def save_figure(fig: Figure, path) -> None:
    """Write ``fig`` as PNG to a path (atomically) or to a binary file object (``io.BytesIO``)."""
    with nullcontext(path) if hasattr(path, "write") else atomic_file(path) as f:
        fig.savefig(f, format="png", dpi=DPI)


class PixelCanvas:
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


def enlargement(width: int) -> int:
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


def _legend(canvas: PixelCanvas, handles: list[Patch], left: int, top: int,
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
    s = enlargement(w)
    iw, ih = w * s, h * s
    left, top, bar_gap, bar_w, right = 16, 36, 14, 18, 80
    canvas = PixelCanvas(left + iw + bar_gap + bar_w + right,
                          top + ih + _legend_height(iw) + 8)
    ax = canvas.axes(left, top, iw, ih)
    cax = canvas.axes(left + iw + bar_gap, top, bar_w, ih)
    legend = _show_delta_e(ax, cax, de, coverage_mismatch_mask, shared, vmax, title)
    _legend(canvas, legend, left, top + ih, iw)
    save_figure(canvas.fig, path)


def _percent(fraction: float) -> str:
    if fraction == 0:
        return "0 %"
    return "<0.01 %" if fraction < 1e-4 else f"{100 * fraction:.2f} %"


def metrics_lines(metrics: dict) -> list[str]:
    """The figures of :func:`compare.metrics.measure` as two short lines of text.

    Timings are left out on purpose: a figure must be the same bytes every time it is made.
    """
    de = metrics["delta_e_2000"]
    first = (f"ΔE2000 over {metrics['shared_pixels']:,} shared pixels:  "
             f"mean {de['mean']:.3f} · p99 {de['p99']:.3f} · p99.9 {de['p999']:.3f} · "
             f"max {de['max']:.3f} · pixels with ΔE > 1: "
             f"{_percent(metrics['pixels_over_1'])}")
    second = (f"coverage mismatch: {_percent(metrics['coverage_mismatch'])} of all pixels "
              f"({metrics['mismatch_pixels']:,} px) · "
              f"max channel diff: {metrics['max_channel_diff']} / 255")
    return [first, second]


def _wrap(text: str, width_px: float) -> list[str]:
    return textwrap.wrap(text, max(20, int(width_px / CHAR_PX))) or [""]


def _mark(ax, marks: list[tuple[int, int]], scale: int) -> None:
    """Ring each marked pixel (row, col) on an image axes; the worst gets a thicker ring and "1"."""
    radius = 7.0 / scale  # about 7 PNG pixels, in image pixels
    for i, (r, c) in enumerate(marks):
        for colour, width in (((1, 1, 1), 3.2 if i == 0 else 2.4), (MARK_COLOUR, 1.6 if i == 0 else 1.0)):
            ax.add_patch(Circle((c, r), radius, fill=False, edgecolor=colour, linewidth=width))
        ax.text(c + 1.3 * radius, r - 1.1 * radius, str(i + 1), color=MARK_COLOUR, fontsize=8, fontweight="bold",
                ha="left", va="bottom")


def _inset(canvas: "PixelCanvas", left: float, top: float, block: np.ndarray, title: str, **imshow) -> None:
    """One zoomed block with its centre pixel outlined."""
    side = INSET * INSET_ZOOM
    ax = canvas.axes(left, top, side, side)
    ax.imshow(block, interpolation="nearest", **imshow)
    half = INSET // 2
    ax.add_patch(Rectangle((half - 0.5, half - 0.5), 1, 1, fill=False, edgecolor=MARK_COLOUR, linewidth=2))
    ax.set_xticks(np.arange(-0.5, INSET, 1.0), labels=[])
    ax.set_yticks(np.arange(-0.5, INSET, 1.0), labels=[])
    ax.tick_params(length=0)
    ax.grid(True, color=(0.5, 0.5, 0.5), linewidth=0.4)
    ax.set_title(title, fontsize=9)


class PanelText(NamedTuple):
    """The words on a side-by-side panel: ``title`` above it, the ``verdict`` line (green
    for "pass" and "fails as meant", red otherwise), the ``settings`` that made the images,
    and the ``labels`` of the two image panels (a lesson may compare two of our renders)."""

    title: str | None = None
    labels: tuple[str, str] = ("scanlab (ours)", "VTK (reference)")
    settings: str | None = None
    verdict: str | None = None


class _Zoomed(NamedTuple):
    """What the zoomed row reads: both images, ΔE, the coverage mismatch and, when known,
    each side's coverage (ours, reference)."""

    ours_rgb: np.ndarray
    ref_rgb: np.ndarray
    de: np.ndarray
    mismatch: np.ndarray
    coverage: tuple | None


INSET_ROW_PX = 40 + 22 + INSET * INSET_ZOOM + 8
"""Height of the row that zooms into the worst pixel: caption, inset titles, insets."""


def _inset_row(canvas: PixelCanvas, left: float, top: float, zoomed: _Zoomed, marks, labels, vmax: float) -> None:
    """Caption and three 9×9 zooms (ours, reference, ΔE) around the worst pixel, marks[0]."""
    ours_rgb, ref_rgb, de, mismatch, coverage = zoomed
    if not marks:
        canvas.text(left, top, "worst pixel: none, the two images are identical", fontsize=10)
        return
    r, c = marks[0]
    if coverage is None:  # which side drew a mismatched pixel is unknown
        both = ~mismatch
        cov_a, cov_b = both | mismatch, both
    else:
        cov_a, cov_b = (np.asarray(cv, bool) for cv in coverage)
    report = pixel_report(ours_rgb, ref_rgb, de, cov_a, cov_b, r, c)
    if coverage is None and mismatch[r, c]:
        report = report._replace(coverage="differs")
    canvas.text(left, top, "worst pixel, ringed 1 (x = column, y = row from the top):", fontsize=10)
    canvas.text(left, top + 18, report.caption((labels[0], labels[1])), fontsize=10, family="monospace")
    step, inset_top = INSET * INSET_ZOOM + 36, top + 40 + 22
    for i, (rgb, title) in enumerate(((ours_rgb, labels[0]), (ref_rgb, labels[1]))):
        short = title.split(" (")[0]  # "scanlab (ours)" → "scanlab": an inset is narrow
        short = short if len(short) <= 17 else short[:16] + "…"
        _inset(canvas, left + i * step, inset_top, window(rgb, r, c, fill=128).astype(np.uint8), short)
    missing = np.isnan(window(np.asarray(de, float), r, c))  # off the image
    block = window(np.asarray(de, float), r, c, fill=0.0)
    colours = matplotlib.colormaps[CMAP](Normalize(0.0, vmax)(block))
    colours[window(~(cov_a | cov_b), r, c, fill=True).astype(bool)] = (*BACKGROUND_COLOUR, 1.0)
    colours[window(np.asarray(mismatch, bool), r, c, fill=False).astype(bool)] = (*MISMATCH_COLOUR, 1.0)
    colours[missing] = (0.5, 0.5, 0.5, 1.0)
    _inset(canvas, left + 2 * step, inset_top, colours, "ΔE2000")


def side_by_side_figure(ours_rgb: np.ndarray, ref_rgb: np.ndarray, de: np.ndarray,
                        mismatch_mask: np.ndarray, metrics: dict, path, text: PanelText = PanelText(), *,
                        shared: np.ndarray | None = None, vmax: float = VMAX,
                        coverage: tuple[np.ndarray, np.ndarray] | None = None) -> None:
    """Write "scanlab (ours)" | "VTK (reference)" | "ΔE2000" as one PNG, atomically.

    Above the images: ``title``, the ``verdict`` line (green for "pass" and "fails as
    meant", red otherwise) and the ``settings`` that made the images. On the images: the
    worst pixels ringed (:func:`compare.worst.worst_pixels`, at most :data:`MARKS`).
    Underneath: the figures of ``metrics`` (:func:`metrics_lines`, no timings), then the
    worst pixel zoomed, 9×9 pixels of each image and of ΔE, with its coordinates and
    both colours.

    Parameters
    ----------
    ours_rgb, ref_rgb : (H, W, 3) uint8, the two renders, row 0 at the top.
    de : (H, W) float, ΔE2000 map (unitless), shown on a 0..``vmax`` scale.
    mismatch_mask : (H, W) bool, True where coverage differs; drawn magenta.
    metrics : dict from :func:`compare.metrics.measure`.
    path : target PNG file name, or a binary file object (e.g. ``io.BytesIO``).
    text : :class:`PanelText`: the title above the panels (e.g. the scene name), the
        verdict line, the settings line and the labels of the two image panels.
    shared : (H, W) bool, optional, True where both frames have coverage; background
        pixels of the ΔE panel are then drawn light grey (see :func:`delta_e_figure`).
    vmax : top of the ΔE2000 colour scale (default 5).
    coverage : (ours, reference) (H, W) bool coverage, to say which side drew a pixel
        where coverage differs; by default worked out from ``shared`` and the mask.
    """
    title, labels, settings, verdict = text
    h, w = np.shape(de)
    if np.shape(ours_rgb) != (h, w, 3) or np.shape(ref_rgb) != (h, w, 3):
        raise ValueError("ours_rgb, ref_rgb and de must have the same height and width")
    mismatch = np.asarray(mismatch_mask, bool)
    s = enlargement(w)
    iw, ih = w * s, h * s
    left, gap, bar_gap, bar_w, right = 16, 16, 14, 18, 80
    width = left + 3 * iw + 2 * gap + bar_gap + bar_w + right
    head = []  # (text, style) lines above the images
    if title:
        head.append((title, dict(fontsize=13, fontweight="bold")))
    if verdict:
        ok = verdict.startswith(("pass", "fails as meant"))
        head += [(line, dict(fontsize=11, fontweight="bold", color=(0.0, 0.45, 0.0) if ok else (0.8, 0.0, 0.0)))
                 for line in _wrap(verdict, width - 2 * left)]
    if settings:
        head += [(line, dict(fontsize=10, color=(0.25, 0.25, 0.25))) for line in _wrap(settings, width - 2 * left)]
    top = 10 + sum(24 if st.get("fontsize") == 13 else 18 for _, st in head) + 32
    text_top = top + ih + _legend_height(iw)
    marks = worst_pixels(de, mismatch, MARKS)
    canvas = PixelCanvas(width, text_top + 50 + (INSET_ROW_PX if marks else 30))
    y = 10
    for line, style in head:
        canvas.text(left, y, line, **style)
        y += 24 if style.get("fontsize") == 13 else 18
    x = [left + i * (iw + gap) for i in range(3)]
    ax_ours, ax_ref = canvas.axes(x[0], top, iw, ih), canvas.axes(x[1], top, iw, ih)
    _show_rgb(ax_ours, ours_rgb, labels[0])
    _show_rgb(ax_ref, ref_rgb, labels[1])
    ax_de = canvas.axes(x[2], top, iw, ih)
    legend = _show_delta_e(ax_de, canvas.axes(x[2] + iw + bar_gap, top, bar_w, ih),
                           de, mismatch, shared, vmax, "ΔE2000")
    for ax in (ax_ours, ax_ref, ax_de):
        _mark(ax, marks, s)
        ax.set_xlim(-0.5, w - 0.5)
        ax.set_ylim(h - 0.5, -0.5)
    _legend(canvas, legend, x[2], top + ih, iw)
    for i, line in enumerate(metrics_lines(metrics)):
        canvas.text(left, text_top + 22 * i, line, fontsize=10)
    _inset_row(canvas, left, text_top + 50, _Zoomed(ours_rgb, ref_rgb, de, mismatch, coverage), marks, labels, vmax)
    save_figure(canvas.fig, path)
