"""Tests for compare/images.py: PNGs are written, look sane, and are written atomically."""
import os

import numpy as np
import pytest
from matplotlib.figure import Figure
from PIL import Image

from compare.images import PanelText, delta_e_figure, side_by_side_figure
from compare.metrics import compare_frames, coverage_masks
from lab.frame import Frame

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _scene(w, h, seed=0):
    """Two random frames with partly different coverage, and their comparison."""
    rng = np.random.default_rng(seed)
    frames = []
    for _ in range(2):
        rgb = rng.integers(0, 256, (h, w, 3), dtype=np.uint8)
        coverage = rng.random((h, w)) < 0.8
        frames.append(Frame(rgb, np.where(coverage, 0.5, 1.0), coverage))
    metrics, de = compare_frames(*frames)
    shared, mismatch = coverage_masks(*frames)
    return frames, metrics, de, shared, mismatch


def _read_png(path):
    with open(path, "rb") as f:
        assert f.read(8) == PNG_SIGNATURE
    with Image.open(path) as image:
        return np.asarray(image.convert("RGB"))


def test_delta_e_figure_is_a_sensible_png(tmp_path):
    _, _, de, shared, mismatch = _scene(512, 384)
    delta_e_figure(de, mismatch, tmp_path / "de.png", shared=shared)
    h, w, _ = _read_png(tmp_path / "de.png").shape
    assert 512 < w < 800 and 384 < h < 600  # native size plus colour bar and legend


def test_side_by_side_figure_shows_images_at_native_resolution(tmp_path):
    """Each image appears pixel for pixel (crisp, unscaled), but for the rings around the worst pixels."""
    (ours, ref), metrics, de, shared, mismatch = _scene(300, 200)
    side_by_side_figure(ours.rgb, ref.rgb, de, mismatch, metrics, tmp_path / "s.png",
                        PanelText(title="random"), shared=shared)
    png = _read_png(tmp_path / "s.png")
    assert 3 * 300 < png.shape[1] < 3 * 300 + 300 and 200 < png.shape[0] < 200 + 450
    rows, cols = np.nonzero(np.all(png == ours.rgb[0, 0], axis=-1))
    same = [np.mean(np.all(png[r:r + 200, c:c + 300] == ours.rgb, axis=-1)) for r, c in zip(rows, cols)
            if png[r:r + 200, c:c + 300].shape == ours.rgb.shape]
    assert max(same) > 0.97


def _gradient(h, w):
    """An image whose every pixel is different and none is red: (row, column mod 256, 7 + 50·(column ÷ 256))."""
    r, c = np.mgrid[0:h, 0:w]
    return np.stack([r, c % 256, 7 + 50 * (c // 256)], axis=-1).astype(np.uint8)


def _reddish(block):
    return np.count_nonzero((block[..., 0] > 200) & (block[..., 1] < 90) & (block[..., 2] < 90))


def test_the_worst_pixel_is_ringed_on_all_three_images_and_nowhere_else(tmp_path):
    """One pixel of 300×200 differs: a red ring surrounds it on ours, VTK's and the ΔE map, and no red
    appears elsewhere on the three images."""
    ours = _gradient(200, 300)
    ref = ours.copy()
    ref[50, 120] = (0, 255, 0)
    everywhere = np.ones((200, 300), bool)
    a, b = Frame(ours, np.full((200, 300), 0.5), everywhere), Frame(ref, np.full((200, 300), 0.5), everywhere)
    metrics, de = compare_frames(a, b)
    side_by_side_figure(ours, ref, de, np.zeros((200, 300), bool), metrics, tmp_path / "s.png",
                        PanelText(title="one pixel", settings="model vtk · shading flat", verdict="pass"),
                        shared=everywhere)
    png = _read_png(tmp_path / "s.png")
    rows, cols = np.nonzero(np.all(png == ours[0, 0], axis=-1))  # ours' and VTK's corner pixel
    top, left = rows.min(), cols[rows == rows.min()].min()
    step = 300 + 16  # image width and the gap between panels
    for k in range(3):
        x = left + k * step
        near = png[top + 50 - 10:top + 50 + 11, x + 120 - 10:x + 120 + 11]
        assert _reddish(near) > 20, k
        image = png[top:top + 200, x:x + 300].copy()
        image[50 - 25:50 + 13, 120 - 12:120 + 25] = 0  # the ring and its number
        assert _reddish(image) == 0, k


def test_identical_images_get_no_ring(tmp_path):
    ours = _gradient(60, 80)
    everywhere = np.ones((60, 80), bool)
    frame = Frame(ours, np.full((60, 80), 0.5), everywhere)
    metrics, de = compare_frames(frame, frame)
    side_by_side_figure(ours, ours, de, np.zeros((60, 80), bool), metrics, tmp_path / "s.png", shared=everywhere)
    assert _reddish(_read_png(tmp_path / "s.png")) == 0


def test_small_images_are_enlarged(tmp_path):
    (ours, ref), metrics, de, _, mismatch = _scene(16, 12)
    side_by_side_figure(ours.rgb, ref.rgb, de, mismatch, metrics, tmp_path / "s.png")
    h, w, _ = _read_png(tmp_path / "s.png").shape
    assert w > 3 * 200 and h > 150  # room for titles and the two lines of figures


def _failing_save(self, fp, *args, **kwargs):
    """Stands in for a save that dies half-way, after writing part of the file."""
    fp.write(PNG_SIGNATURE + b"partial")
    raise KeyboardInterrupt("interrupted while saving")


@pytest.mark.parametrize("which", ["delta_e", "side_by_side"])
def test_interrupted_figure_write_leaves_no_partial_file(tmp_path, monkeypatch, which):
    (ours, ref), metrics, de, shared, mismatch = _scene(20, 10)
    monkeypatch.setattr(Figure, "savefig", _failing_save)
    target = tmp_path / "f.png"
    with pytest.raises(KeyboardInterrupt):
        if which == "delta_e":
            delta_e_figure(de, mismatch, target, shared=shared)
        else:
            side_by_side_figure(ours.rgb, ref.rgb, de, mismatch, metrics, target)
    assert not target.exists()
    assert not os.listdir(tmp_path)
