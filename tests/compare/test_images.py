"""Tests for compare/images.py: PNGs are written, look sane, and are written atomically."""
import os

import numpy as np
import pytest
from matplotlib.figure import Figure
from PIL import Image

from compare.images import delta_e_figure, side_by_side_figure
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
    (ours, ref), metrics, de, shared, mismatch = _scene(300, 200)
    metrics.update(ours_ms=12.5, reference_ms=80.0)
    side_by_side_figure(ours.rgb, ref.rgb, de, mismatch, metrics, tmp_path / "s.png",
                        title="random", shared=shared)
    png = _read_png(tmp_path / "s.png")
    assert 3 * 300 < png.shape[1] < 3 * 300 + 300 and 200 < png.shape[0] < 200 + 250
    # our random image appears pixel for pixel somewhere in the figure: crisp, unscaled
    rows, cols = np.nonzero(np.all(png == ours.rgb[0, 0], axis=-1))
    assert any(np.array_equal(png[r:r + 200, c:c + 300], ours.rgb) for r, c in zip(rows, cols))


def test_small_images_are_enlarged_and_timings_are_optional(tmp_path):
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
