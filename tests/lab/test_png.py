"""lab/png.py: PNGs round-trip, refuse what is not 8-bit RGB, and are written atomically."""
import io
import os

import numpy as np
import pytest
from PIL import Image

from lab.png import png_bytes, write_png

PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def _read_png(path):
    with open(path, "rb") as f:
        assert f.read(8) == PNG_SIGNATURE
    with Image.open(path) as image:
        return np.asarray(image.convert("RGB"))


def _failing_save(self, fp, *args, **kwargs):
    """Stands in for a save that dies half-way, after writing part of the file."""
    fp.write(PNG_SIGNATURE + b"partial")
    raise KeyboardInterrupt("interrupted while saving")


def test_write_png_round_trips(tmp_path):
    rgb = np.random.default_rng(0).integers(0, 256, (7, 11, 3), dtype=np.uint8)
    write_png(tmp_path / "a.png", rgb)
    np.testing.assert_array_equal(_read_png(tmp_path / "a.png"), rgb)
    assert os.listdir(tmp_path) == ["a.png"]


def test_write_png_rejects_float_images(tmp_path):
    with pytest.raises(TypeError):
        write_png(tmp_path / "a.png", np.zeros((2, 2, 3)))
    assert not os.listdir(tmp_path)


@pytest.mark.parametrize("existing", [False, True])
def test_interrupted_png_write_leaves_no_partial_file(tmp_path, monkeypatch, existing):
    target = tmp_path / "a.png"
    if existing:
        target.write_bytes(b"old")
    monkeypatch.setattr(Image.Image, "save", _failing_save)
    with pytest.raises(KeyboardInterrupt):
        write_png(target, np.zeros((4, 4, 3), np.uint8))
    assert os.listdir(tmp_path) == (["a.png"] if existing else [])  # no temp file left
    if existing:
        assert target.read_bytes() == b"old"


@pytest.mark.parametrize("level", [0, 1, 9])
def test_png_bytes_are_the_same_image_at_any_compression(level):
    rgb = np.random.default_rng(1).integers(0, 256, (5, 9, 3), dtype=np.uint8)
    data = png_bytes(rgb, level)
    assert data.startswith(PNG_SIGNATURE)
    with Image.open(io.BytesIO(data)) as image:
        np.testing.assert_array_equal(np.asarray(image.convert("RGB")), rgb)
    with pytest.raises(TypeError):
        png_bytes(rgb.astype(float), level)
