"""Properties of the renderer on random valid scenes and random triangle soups (hypothesis).

For every scene: no exception; a frame of the right shapes and dtypes, background and
depth 1.0 exactly where nothing is drawn; no write outside the buffers it was given; a
crop of a larger image is the smaller image; the same bytes every time, after another
scene, and with one thread or two. Profiles and counts: ``tests/conftest.py``.
"""
from __future__ import annotations

import dataclasses

import numba
import numpy as np
from hypothesis import given
from hypothesis import strategies as st

import renderer.pipeline
from renderer import render
from renderer.shading import to_8bit
from renderer.workspace import Workspace

from ..scene_strategies import any_scene



def check_frame(scene, frame):
    width, height = scene.image.size
    assert frame.rgb.dtype == np.uint8 and frame.rgb.shape == (height, width, 3)
    assert frame.coverage.dtype == np.bool_ and frame.coverage.shape == (height, width)
    assert frame.depth.shape == (height, width) and np.isfinite(frame.depth).all()
    empty = ~frame.coverage
    assert (frame.depth[empty] == 1.0).all()
    assert ((frame.depth[frame.coverage] >= 0.0) & (frame.depth[frame.coverage] <= 1.0)).all()
    assert (frame.rgb[empty] == to_8bit(np.asarray(scene.image.background))).all()


@given(any_scene())
def test_renders_a_well_formed_frame(scene):
    """No exception; shapes, dtypes, depth range; background and depth 1.0 wherever nothing was drawn."""
    check_frame(scene, render(scene))


# ------------------------------------------------------------------ writes stay in their buffers
CANARY = 0xA5
PAD = 4096  # bytes of canary before and after every workspace array


class GuardedWorkspace(Workspace):
    """A workspace whose every array sits between two bands of canary bytes, freshly each time."""

    def __init__(self):
        super().__init__()
        self.lent = []

    def array(self, name, shape, dtype=np.float64):
        shape = tuple(int(s) for s in np.atleast_1d(shape))
        nbytes = int(np.prod(shape)) * np.dtype(dtype).itemsize
        raw = np.full(PAD + nbytes + PAD, CANARY, np.uint8)
        self.lent.append((name, raw, nbytes))
        return raw[PAD:PAD + nbytes].view(dtype).reshape(shape)

    def trampled(self):
        """Names of the arrays whose canary bands changed."""
        return [name for name, raw, n in self.lent
                if (raw[:PAD] != CANARY).any() or (raw[PAD + n:] != CANARY).any()]


@given(any_scene())
def test_kernels_never_write_outside_their_buffers(scene):
    """Every scratch array of the pipeline (visibility buffer, clipped triangles, window
    coordinates, …) is lent with canary bytes on both sides; none may change."""
    ws = GuardedWorkspace()
    original = renderer.pipeline.thread_workspace
    renderer.pipeline.thread_workspace = lambda: ws
    try:
        frame = render(scene)
    finally:
        renderer.pipeline.thread_workspace = original
    assert ws.lent and not ws.trampled(), ws.trampled()
    check_frame(scene, frame)


@st.composite
def crops(draw):
    """A parallel-projection scene and a border (a, b) in pixels to add on each side."""
    scene = draw(any_scene())
    cam = dataclasses.replace(scene.camera, parallel=True)
    return dataclasses.replace(scene, camera=cam), draw(st.integers(1, 9)), draw(st.integers(1, 9))


@given(crops())
def test_a_larger_image_contains_the_smaller_one(case):
    """With the pixel size kept (parallel projection, the scale grown with the height), an
    image 2a wider and 2b taller holds the smaller image, pixel for pixel, a and b in:
    nothing is lost or added at the image's edges, and nothing drawn spills over them."""
    scene, a, b = case
    width, height = scene.image.size
    cam = scene.camera
    if cam.clipping_range is None:  # the fitted range does not depend on the image size, but keep it fixed
        from renderer.camera import fit_clipping_range

        cam = dataclasses.replace(cam, clipping_range=fit_clipping_range(cam, scene.world_bounds()))
    small = dataclasses.replace(scene, camera=cam)
    big = dataclasses.replace(small, image=dataclasses.replace(scene.image, size=(width + 2 * a, height + 2 * b)),
                              camera=dataclasses.replace(cam, parallel_scale=cam.parallel_scale * (height + 2 * b)
                                                         / height))
    fs, fb = render(small), render(big)
    inner = (slice(b, b + height), slice(a, a + width))
    mismatch = fs.coverage != fb.coverage[inner]
    assert mismatch.sum() == 0, np.argwhere(mismatch)[:5]
    assert np.abs(fs.rgb.astype(int) - fb.rgb[inner]).max(initial=0) <= 1


# ------------------------------------------------------------------ determinism
def frame_bytes(frame):
    return frame.rgb.tobytes() + frame.depth.tobytes() + frame.coverage.tobytes()


@given(any_scene(), any_scene())
def test_same_scene_same_bytes(scene, other):
    """Twice in a row, after another scene has used the same workspace, and on one thread
    instead of two: the same bytes each time (z-buffer ties included)."""
    first = frame_bytes(render(scene))
    assert frame_bytes(render(scene)) == first
    render(other)
    assert frame_bytes(render(scene)) == first
    threads = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        assert frame_bytes(render(scene)) == first
    finally:
        numba.set_num_threads(threads)


def test_there_are_threads_to_compare():
    """The one-thread comparison means something only with more than one thread."""
    assert numba.config.NUMBA_NUM_THREADS >= 2
