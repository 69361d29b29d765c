"""A frame: its size, and a depth given as an array or as a function run on first read."""
import numpy as np

from lab.frame import Frame


def frame_of(depth):
    return Frame(np.zeros((2, 3, 3), np.uint8), depth, np.zeros((2, 3), bool))


def test_a_frame_knows_its_size_as_width_then_height():
    assert frame_of(np.ones((2, 3))).size == (3, 2)


def test_a_depth_array_is_kept_as_given():
    depth = np.full((2, 3), 0.5)
    assert frame_of(depth).depth is depth


def test_a_depth_function_runs_once_on_first_read_and_never_when_unread():
    calls = []

    def make():
        calls.append(1)
        return np.full((2, 3), 0.25)

    unread, read = frame_of(make), frame_of(make)
    assert calls == [] and unread.rgb.shape == (2, 3, 3)
    first = read.depth
    assert read.depth is first and calls == [1] and float(first[0, 0]) == 0.25
