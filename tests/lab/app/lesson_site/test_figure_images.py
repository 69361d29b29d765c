"""lab/app/lesson_site/figure_images.py: text-free figure images in the comparison run's colours."""
from __future__ import annotations

import numpy as np
from PIL import Image

from lab.frame import Frame
from lab.app.lesson_site.figure_images import colour_bar_stops, depth_grey, heat_map, write_figure_images
from lab.app.lesson_site.measurement import Measurement


def test_the_heat_map_uses_viridis_magenta_and_grey():
    values = np.array([[0.0, 5.0, 9.0, 0.0]])
    shared = np.array([[True, True, True, False]])
    mismatch = np.array([[False, False, False, True]])
    rgb = heat_map(values, 5.0, mismatch, shared)
    assert rgb[0, 0].tolist() == [68, 1, 84]          # viridis at 0
    assert rgb[0, 1].tolist() == rgb[0, 2].tolist() == [253, 231, 37]  # at and above vmax
    assert rgb[0, 3].tolist() == [255, 0, 255]        # one renderer only
    assert heat_map(values, 5.0, ~shared & False, shared)[0, 3].tolist() == [217, 217, 217]  # neither


def test_the_colour_bar_runs_from_dark_to_yellow():
    stops = colour_bar_stops()
    assert stops[0] == "#440154" and stops[-1] == "#fde725" and len(stops) == 11


def test_depth_is_grey_near_bright_and_black_where_nothing_is():
    depth = np.array([[0.2, 0.6, 1.0]])
    grey = depth_grey(depth, np.array([[True, True, False]]), 0.2, 0.6)
    assert grey[0, :, 0].tolist() == [255, 55, 0]


def test_the_images_are_written_at_native_size(tmp_path):
    rgb = np.zeros((4, 6, 3), np.uint8)
    frame = Frame(rgb=rgb, depth=np.full((4, 6), 0.5), coverage=np.ones((4, 6), bool))
    m = Measurement(frame, frame, np.zeros((4, 6)), np.ones((4, 6), bool), np.zeros((4, 6), bool), {})
    names = write_figure_images(m, tmp_path, depth=True)
    assert names == ["ours.png", "vtk.png", "delta_e.png", "depth-ours.png", "depth-vtk.png", "depth-diff.png"]
    assert all(Image.open(tmp_path / n).size == (6, 4) for n in names)
