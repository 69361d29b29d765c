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
from lab.mesh import Mesh
from lab.scene import Material
from renderer import render
from renderer.camera import clipping_range, view_to_clip, world_to_view
from renderer.pipeline import transform_scene
from renderer.raster import DEPTH_MAX
from renderer.shading import to_8bit
from renderer.workspace import Workspace

from ..scene_strategies import any_scene
from .single_thread import one_thread



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


def triangle_ids(scene):
    """The scene with every triangle its own unlit object whose colour is its number
    (k + 1 in base 255 over R, G, B), drawn in the same order: its image says which
    triangle is visible at each pixel."""
    objects = []
    for obj in scene.objects:
        for tri in obj.mesh.triangles:
            k = len(objects) + 1
            colour = tuple(((k // 255 ** c) % 255) / 255.0 for c in range(3))
            objects.append(dataclasses.replace(obj, mesh=Mesh(obj.mesh.points, tri[None]), texture=None,
                                               material=Material(color=colour, ambient=0.0, diffuse=1.0,
                                                                 lighting=False)))
    return dataclasses.replace(scene, objects=tuple(objects))


def edge_distance(scene, pixels):
    """For each pixel (image row, column) in ``pixels`` (M, 2), the distance in pixels
    from its centre to the nearest line a triangle's edge may lie on: the projected edges,
    and the lines where the triangle is cut by the near and far planes. Lines are joins of
    homogeneous window points (X, Y, W), so a corner behind the eye still gives the
    right line."""
    width, height = scene.image.size
    cam = scene.camera
    geo = transform_scene(scene, world_to_view(cam),
                          view_to_clip(cam, width / height, clipping_range(cam, scene.world_bounds())))
    c = geo.verts_clip[geo.triangles]  # (T, 3, 4)
    p = np.stack([(c[..., 0] + c[..., 3]) * width / 2, (c[..., 1] + c[..., 3]) * height / 2, c[..., 3]], axis=-1)
    nxt = [1, 2, 0]
    lines = [np.cross(p, p[:, nxt]).reshape(-1, 3)]
    for d in (c[..., 2] + c[..., 3], c[..., 3] - c[..., 2]):  # near, far: ≥ 0 inside
        cross = (d > 0) != (d[:, nxt] > 0)
        t = np.where(cross, d / np.where(cross, d - d[:, nxt], 1.0), 0.0)
        q = p + t[..., None] * (p[:, nxt] - p)  # where each edge meets the plane (rows with cross)
        for i, j in ((0, 1), (1, 2), (0, 2)):
            both = cross[:, i] & cross[:, j]
            lines.append(np.cross(q[both, i], q[both, j]))
    lines = np.concatenate(lines)
    norm = np.hypot(lines[:, 0], lines[:, 1])
    lines = lines[norm > 0] / norm[norm > 0, None]
    x = pixels[:, 1] + 0.5
    y = height - 1 - pixels[:, 0] + 0.5  # window rows are y up
    return np.abs(x[:, None] * lines[:, 0] + y[:, None] * lines[:, 1] + lines[:, 2]).min(axis=1, initial=np.inf)


@given(crops())
def test_a_larger_image_contains_the_smaller_one(case):
    """With the pixel size kept (parallel projection, the scale grown with the height), an
    image 2a wider and 2b taller holds the smaller image, pixel for pixel, a and b in:
    nothing is lost or added at the image's edges, and nothing drawn spills over them.

    Where the two differ, it is for one of three reasons, and the test checks which:

    - a pixel centre within 1/256 pixel of a triangle's edge, or of the line where the
      near or far plane cuts it: a triangle cut at the border gets new corners snapped
      to the 1/256 grid, which moves its edges there by up to 1/512 pixel (as llvmpipe
      does; :mod:`renderer.clip`), and the larger image cuts it elsewhere or not at all.
      Coverage, or which triangle shows, may then differ;
    - a depth tie (a shared edge of two intersecting triangles, coincident ones): the
      z-buffer's winner rests on the last bit of each depth, so either may show, and the
      stored depths agree within two 24-bit steps;
    - a surface lying on the near or far plane (a fitted clipping range touches the
      scene's bounds): whether it is kept rests on the last bit, and what shows has a
      depth within two 24-bit steps of 0 or 1.

    Wherever the same triangle shows in both, colours agree within 1."""
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
    same = (render(triangle_ids(small)).rgb == render(triangle_ids(big)).rgb[inner]).all(axis=-1)
    assert np.abs(fs.rgb.astype(int) - fb.rgb[inner])[same].max(initial=0) <= 1
    differ = np.argwhere(~same)  # another triangle, or background on one side only
    near_edge = edge_distance(small, differ) < 1 / 256
    step = 2 / DEPTH_MAX
    depth_s, depth_b, cover_s, cover_b = fs.depth, fb.depth[inner], fs.coverage, fb.coverage[inner]
    tie = cover_s & cover_b & (np.abs(depth_s - depth_b) <= step)
    at_planes = ((cover_s & ((depth_s <= step) | (depth_s >= 1.0 - step)))
                 | (cover_b & ((depth_b <= step) | (depth_b >= 1.0 - step))))
    unexplained = differ[~near_edge & ~(tie | at_planes)[tuple(differ.T)]]
    assert len(unexplained) == 0, unexplained[:5]


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
    with one_thread():
        assert frame_bytes(render(scene)) == first


def test_there_are_threads_to_compare():
    """The one-thread comparison means something only with more than one thread."""
    assert numba.config.NUMBA_NUM_THREADS >= 2
