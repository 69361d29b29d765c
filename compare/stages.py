"""The stages before the colours, compared: depth buffers, triangle IDs, the clipped wireframe.

Our side comes from :func:`renderer.render_stages` (the z-buffer, which triangle won each
pixel, the clipped triangles in window space); VTK's depth is its z-buffer read back from
the same render that gave its colours (:func:`compare.reference.read_frame`).

Depth is compared in steps of the 24-bit depth buffer: window depth d in 0..1 is stored
as round(d · (2²⁴ − 1)), and both sides keep exactly that (ours rounds to it in
:mod:`renderer.raster`; VTK's float read-back is k / (2²⁴ − 1)). Only pixels that both
z-buffers cover are compared (coverage is measured apart, in ``metrics.json``); a pixel
only translucent surfaces cover has no depth on either side.

:func:`stages_figure` writes ``stages.png``: ours | VTK | their difference in steps on
the first row; the triangle-ID image and the clipped triangles as a wireframe over our
image, back faces marked, on the second.
"""
from __future__ import annotations

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.colors import ListedColormap, Normalize
from matplotlib.patches import Patch

from compare.images import BACKGROUND_COLOUR, PixelCanvas, enlargement, save_figure

DEPTH_STEPS = (1 << 24) - 1
"""Largest value of a 24-bit depth buffer: window depth d is stored as round(d · DEPTH_STEPS)."""
STAGE_FILES = ("stages.png",)
"""The files :func:`write_stages` adds to a comparison's folder."""
FRONT_COLOUR = (0.1, 0.35, 0.9)
BACK_COLOUR = (0.9, 0.1, 0.1)


def depth_steps(depth: np.ndarray) -> np.ndarray:
    """Window depth (0..1) → int64 steps of the 24-bit depth buffer."""
    return np.rint(np.asarray(depth, float) * DEPTH_STEPS).astype(np.int64)


def depth_metrics(ours_depth: np.ndarray, ref_depth: np.ndarray) -> dict:
    """How far two z-buffers are apart, in 24-bit steps, where both hold a surface.

    Parameters
    ----------
    ours_depth, ref_depth : (H, W) window depth 0..1, 1.0 where empty.

    Returns
    -------
    dict (the ``depth`` of ``metrics.json``): ``max_steps`` (int, largest |difference| in
    steps), ``p99_steps`` (99th percentile of |difference|, steps), ``pixels_over_1_step``
    (int, pixels more than one step apart),
    ``over_1_step`` (that count as a fraction 0..1 of the compared pixels, 0.0 when
    none) and ``compared_pixels`` (int, pixels both z-buffers cover).
    """
    a, b = depth_steps(ours_depth), depth_steps(ref_depth)
    both = (a < DEPTH_STEPS) & (b < DEPTH_STEPS)
    diff = np.abs(a - b)[both]
    over = int(np.count_nonzero(diff > 1))
    return {"max_steps": int(diff.max()) if diff.size else 0,
            "p99_steps": float(np.percentile(diff, 99)) if diff.size else 0.0, "pixels_over_1_step": over,
            "over_1_step": over / diff.size if diff.size else 0.0, "compared_pixels": int(diff.size)}


def depth_difference(ours_depth: np.ndarray, ref_depth: np.ndarray) -> np.ma.MaskedArray:
    """(H, W) ours − VTK in 24-bit steps, masked where either z-buffer is empty."""
    a, b = depth_steps(ours_depth), depth_steps(ref_depth)
    return np.ma.masked_array(a - b, mask=(a >= DEPTH_STEPS) | (b >= DEPTH_STEPS))


def _depth_grey(depth: np.ndarray, lo: float, hi: float) -> np.ndarray:
    """Depth as an RGB image: nearest white, farthest dark grey, empty light grey."""
    d = np.asarray(depth, float)
    t = np.clip((d - lo) / max(hi - lo, 1e-12), 0.0, 1.0)
    grey = 1.0 - 0.85 * t
    rgb = np.repeat(grey[..., None], 3, axis=2)
    rgb[d >= 1.0] = BACKGROUND_COLOUR
    return rgb


def triangle_colours(ids: np.ndarray) -> np.ndarray:
    """A colour per triangle ID that tells neighbours apart: hue stepped by the golden
    ratio, two lightness levels; (H, W) IDs → (H, W, 3) floats, light grey where −1."""
    import colorsys

    ids = np.asarray(ids)
    table_size = int(ids.max()) + 1 if ids.size and ids.max() >= 0 else 1
    hues = (np.arange(table_size) * 0.6180339887498949) % 1.0
    table = np.array([colorsys.hls_to_rgb(h, 0.45 if i % 2 else 0.65, 0.7) for i, h in enumerate(hues)])
    out = table[np.maximum(ids, 0)]
    out[ids < 0] = BACKGROUND_COLOUR
    return out


def _image_axes(canvas, left, top, w, h, s, title):
    ax = canvas.axes(left, top, w * s, h * s)
    ax.set_title(title, fontsize=11)
    ax.set_axis_off()
    ax.set_xlim(-0.5, w - 0.5)
    ax.set_ylim(h - 0.5, -0.5)
    return ax


def _wireframe(ax, stages, height: int, culling: bool) -> tuple[int, int]:
    """Every clipped triangle's edges over the image (window y flipped to image rows);
    back faces red (dashed when culled). Returns (front, back) counts."""
    tri = stages.tri_window[:, :, :2].copy()
    tri[:, :, 0] -= 0.5  # window x → image column of the pixel centre
    tri[:, :, 1] = height - tri[:, :, 1] - 0.5  # window y (up) → image row (down): the one flip, for drawing
    closed = np.concatenate([tri, tri[:, :1]], axis=1)
    front = np.asarray(stages.front, bool)
    if culling:  # the culled ones are the point: drawn boldly, dashed
        ax.add_collection(LineCollection(closed[~front], colors=[BACK_COLOUR], linewidths=0.9, linestyles="dashed"))
    else:  # drawn, but mostly hidden behind front faces: faint, underneath
        ax.add_collection(LineCollection(closed[~front], colors=[(*BACK_COLOUR, 0.35)], linewidths=0.3))
    ax.add_collection(LineCollection(closed[front], colors=[FRONT_COLOUR], linewidths=0.4))
    return int(front.sum()), int((~front).sum())


def stages_figure(ours, stages, ref, path, title: str | None = None, culling: bool = False) -> dict:
    """Write ``stages.png`` (see the module docstring); return :func:`depth_metrics`.

    Parameters
    ----------
    ours, ref : :class:`lab.frame.Frame`, our frame and VTK's (same size).
    stages : :class:`renderer.Stages` of our frame.
    path : PNG file name (written atomically) or a binary file object.
    title : heading (e.g. the scene name).
    culling : whether back faces were culled (``[render] cull_backfaces``).
    """
    h, w = ours.depth.shape
    s = enlargement(w)
    iw, ih = w * s, h * s
    left, gap, bar_w, right = 16, 16, 18, 70
    top = (36 if title else 8) + 28
    row_h = ih + 74
    canvas = PixelCanvas(left + 3 * iw + 2 * gap + 14 + bar_w + right, top + 2 * row_h + 30)
    if title:
        canvas.text(left, 10, title, fontsize=13, fontweight="bold")
    m = depth_metrics(ours.depth, ref.depth)
    covered = np.concatenate([ours.depth[ours.depth < 1], ref.depth[ref.depth < 1]])
    lo, hi = (float(covered.min()), float(covered.max())) if covered.size else (0.0, 1.0)
    x = [left + i * (iw + gap) for i in range(3)]
    for i, (frame, name) in enumerate(((ours, "scanlab z-buffer"), (ref, "VTK z-buffer (read back)"))):
        _image_axes(canvas, x[i], top, w, h, s, name).imshow(_depth_grey(frame.depth, lo, hi),
                                                              interpolation="nearest")
    diff = depth_difference(ours.depth, ref.depth)
    limit = max(2, m["max_steps"])
    cmap = ListedColormap(_diverging(2 * limit + 1)).with_extremes(bad=BACKGROUND_COLOUR)
    ax = _image_axes(canvas, x[2], top, w, h, s, "ours − VTK, 24-bit steps")
    image = ax.imshow(diff, cmap=cmap, norm=Normalize(-limit - 0.5, limit + 0.5), interpolation="nearest")
    bar = canvas.fig.colorbar(image, cax=canvas.axes(x[2] + iw + 14, top, bar_w, ih))
    bar.set_ticks(sorted({-limit, 0, limit} | ({-1, 1} if limit <= 4 else set())))
    canvas.text(left, top + ih + 14,
                f"depth as 24-bit steps: nearest white, farthest dark (window depth {lo:.6f} … {hi:.6f}); "
                f"compared where both cover: {m['compared_pixels']:,} px", fontsize=10)
    canvas.text(left, top + ih + 34,
                f"largest difference {m['max_steps']} step(s), 99th percentile {m['p99_steps']:g}; more than one step apart: "
                f"{m['pixels_over_1_step']:,} px ({100 * m['over_1_step']:.3f} %)", fontsize=10)

    top2 = top + row_h + 10
    ids = stages.triangle
    n_source = len(stages.geometry.triangles)
    ax = _image_axes(canvas, x[0], top2, w, h, s, "triangle ID (which triangle won each pixel)")
    ax.imshow(triangle_colours(ids), interpolation="nearest")
    ax = _image_axes(canvas, x[1], top2, w, h, s, "clipped triangles over our image")
    ax.imshow((0.35 * ours.rgb + 0.65 * 255).astype(np.uint8), interpolation="nearest")
    n_front, n_back = _wireframe(ax, stages, h, culling)
    back = "back faces (clockwise on screen), culled" if culling else "back faces (clockwise on screen), drawn"
    canvas.fig.legend(handles=[Patch(color=FRONT_COLOUR, label=f"front faces: {n_front:,}"),
                               Patch(color=BACK_COLOUR, label=f"{back}: {n_back:,}")],
                      loc="upper left", frameon=False, fontsize=9,
                      bbox_to_anchor=canvas.box(x[2], top2 + 24, iw, 0)[:2])
    drawn = len(np.unique(ids[ids >= 0]))
    canvas.text(x[2], top2 + 80, f"{n_source:,} triangles in the scene\n{len(stages.tri_window):,} after "
                f"clipping\n{drawn:,} visible in the opaque pass", fontsize=10)
    canvas.text(left, top2 + ih + 14, "wireframe: the triangles after clipping at the view volume, in window "
                "space; a triangle cut by a plane becomes several", fontsize=10)
    save_figure(canvas.fig, path)
    return m


def _diverging(n: int) -> np.ndarray:
    """n colours from blue (ours nearer) through white (equal) to red (ours farther)."""
    t = np.linspace(-1.0, 1.0, n)[:, None]
    white, blue, red = np.ones(3), np.array([0.15, 0.3, 0.85]), np.array([0.85, 0.15, 0.1])
    return np.where(t < 0, white + (-t) * (blue - white), white + t * (red - white))
