"""Stages 2–3, world → view → clip: the U-V-N frame, the projections, and VTK's clipping-range fit."""
import math
import os

import numpy as np
import pytest

from lab.scene import Camera
from renderer.camera import (NEAR_CLIPPING_PLANE_TOLERANCE, fit_clipping_range, uvn_frame, view_to_clip,
                             world_to_view)

OBLIQUE = Camera(position=(3.0, 2.0, 4.0), focal_point=(0.2, 0.1, -0.3), view_up=(0.1, 1.0, 0.2), view_angle=40.0)
PERSPECTIVE_CAMERAS = [
    Camera(position=(0.0, 0.0, 5.0)),
    OBLIQUE,
    Camera(position=(0.0, 0.0, 0.3)),  # inside the box: near falls back to the tolerance
    Camera(position=(0.0, 0.0, 100.0), view_angle=10.0),  # far away: the minimum gap widens the range
]
PARALLEL_CAMERAS = [
    Camera(position=(1.0, 5.0, 2.0), parallel=True, parallel_scale=1.7),
    Camera(position=(0.0, 0.0, 5.0), parallel=True, parallel_scale=0.5),
]
BOUNDS = [(-0.5, 0.5, -0.5, 0.5, -0.5, 0.5), (-1.0, 2.0, -0.3, 0.7, -2.0, 1.0), (10.0, 10.1, 0.0, 0.1, 0.0, 0.1)]


def to_view(camera, point):
    return (np.append(np.asarray(point, dtype=np.float64), 1.0) @ world_to_view(camera))[:3]


def to_ndc(clip_row):
    return clip_row[:3] / clip_row[3]


def vtk_matrix(m):
    return np.array([[m.GetElement(i, j) for j in range(4)] for i in range(4)])


def vtk_camera(vtk, camera, cam=None):
    """Copy a scene camera onto a vtkCamera (clipping range last)."""
    c = cam if cam is not None else vtk.vtkCamera()
    c.SetPosition(*camera.position)
    c.SetFocalPoint(*camera.focal_point)
    c.SetViewUp(*camera.view_up)
    c.SetViewAngle(camera.view_angle)
    c.SetParallelProjection(camera.parallel)
    c.SetParallelScale(camera.parallel_scale)
    if camera.clipping_range is not None:
        c.SetClippingRange(*camera.clipping_range)
    return c


@pytest.fixture(scope="module")
def vtk():
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import vtk as vtk_module

    return vtk_module


# --------------------------------------------------------------------------- the U-V-N frame
def test_uvn_frame_of_the_default_view_is_the_identity():
    """Eye (0,0,5), focal point origin, up +y: U = x, V = y, N = z."""
    np.testing.assert_allclose(uvn_frame((0, 0, 5), (0, 0, 0), (0, 1, 0)), np.eye(3), atol=1e-15)


def test_uvn_frame_looking_down_minus_x():
    """Eye (3,0,0) looking at the origin, up +y: N = (1,0,0), U = up × N = (0,0,−1), V = N × U = (0,1,0)."""
    u, v, n = uvn_frame((3, 0, 0), (0, 0, 0), (0, 1, 0))
    np.testing.assert_allclose(n, [1, 0, 0], atol=1e-15)
    np.testing.assert_allclose(u, [0, 0, -1], atol=1e-15)
    np.testing.assert_allclose(v, [0, 1, 0], atol=1e-15)


def test_uvn_frame_with_a_slanted_view_up():
    """A view-up not perpendicular to N only picks the plane: eye (0,0,5), up (0,1,1) still gives U = x, V = y."""
    np.testing.assert_allclose(uvn_frame((0, 0, 5), (0, 0, 0), (0, 1, 1)), np.eye(3), atol=1e-15)


@pytest.mark.parametrize("camera", PERSPECTIVE_CAMERAS + PARALLEL_CAMERAS)
def test_uvn_frame_is_orthonormal_and_right_handed(camera):
    """U, V, N are unit, mutually perpendicular, and U × V = N."""
    u, v, n = frame = uvn_frame(camera.position, camera.focal_point, camera.view_up)
    np.testing.assert_allclose(frame @ frame.T, np.eye(3), atol=1e-14)
    np.testing.assert_allclose(np.cross(u, v), n, atol=1e-14)
    assert np.linalg.det(frame) == pytest.approx(1.0)


def test_uvn_frame_has_the_bits_of_numpys_cross_and_norm():
    """The frame, worked out component by component, is bit for bit the one np.cross and
    np.linalg.norm give, for 2,000 random cameras (view-up given as ints, floats or an array)."""
    rng = np.random.default_rng(11)
    for k in range(2000):
        position, focal = rng.normal(0, 10, 3), rng.normal(0, 1, 3)
        up = rng.integers(-3, 4, 3).tolist() if k % 3 == 0 else (tuple(rng.normal(0, 1, 3)) if k % 3 == 1
                                                                 else rng.normal(0, 1, 3))
        if np.allclose(np.cross(up, position - focal), 0):
            continue
        n = np.subtract(position, focal).astype(np.float64)
        n /= np.linalg.norm(n)
        u = np.cross(up, n)
        u /= np.linalg.norm(u)
        expected = np.array([u, np.cross(n, u), n])
        assert uvn_frame(position, focal, up).tobytes() == expected.tobytes(), (position, focal, up)


# --------------------------------------------------------------------------- world → view
@pytest.mark.parametrize("camera", PERSPECTIVE_CAMERAS + PARALLEL_CAMERAS)
def test_world_to_view_puts_the_eye_at_the_origin_and_the_focal_point_on_minus_z(camera):
    """The camera position maps to (0,0,0) and the focal point to (0,0,−d), d the camera distance."""
    d = np.linalg.norm(np.subtract(camera.position, camera.focal_point))
    np.testing.assert_allclose(to_view(camera, camera.position), [0, 0, 0], atol=1e-13)
    np.testing.assert_allclose(to_view(camera, camera.focal_point), [0, 0, -d], atol=1e-13)


def test_world_to_view_by_hand_for_a_camera_on_the_x_axis():
    """Eye (3,0,0): P_view = ((P−C)·U, (P−C)·V, (P−C)·N), so (1,2,3) → (−3, 2, −2)."""
    np.testing.assert_allclose(to_view(Camera(position=(3, 0, 0)), (1, 2, 3)), [-3, 2, -2], atol=1e-14)


# --------------------------------------------------------------------------- view → clip
def test_perspective_maps_the_frustum_corners_to_the_ndc_cube():
    """Angle 60°, aspect 4/3, near 1, far 10: the top-right corner at z=−near → NDC (1, 1, −1); at z=−far → (1, 1, +1)."""
    cam = Camera(view_angle=60.0)
    near, far, aspect = 1.0, 10.0, 4.0 / 3.0
    m = view_to_clip(cam, aspect, (near, far))
    t = math.tan(math.radians(30.0))
    for z, z_ndc in ((near, -1.0), (far, 1.0)):
        clip = np.array([z * t * aspect, z * t, -z, 1.0]) @ m
        assert clip[3] == pytest.approx(z)  # w_clip = −z_view
        np.testing.assert_allclose(to_ndc(clip), [1.0, 1.0, z_ndc], atol=1e-14)


def test_perspective_sends_the_view_axis_to_the_ndc_centre():
    """A point on −z between near and far has x_ndc = y_ndc = 0 and −1 < z_ndc < 1."""
    clip = np.array([0.0, 0.0, -4.0, 1.0]) @ view_to_clip(Camera(view_angle=60.0), 1.5, (1.0, 10.0))
    ndc = to_ndc(clip)
    assert ndc[0] == 0.0 and ndc[1] == 0.0 and -1.0 < ndc[2] < 1.0


def test_parallel_maps_the_view_box_to_the_ndc_cube():
    """parallel_scale 2, aspect 1.5, near 1, far 9: (3, 2, −1) → (1, 1, −1), (−3, −2, −9) → (−1, −1, 1), w stays 1."""
    m = view_to_clip(Camera(parallel=True, parallel_scale=2.0), 1.5, (1.0, 9.0))
    top = np.array([3.0, 2.0, -1.0, 1.0]) @ m
    bottom = np.array([-3.0, -2.0, -9.0, 1.0]) @ m
    assert top[3] == 1.0 and bottom[3] == 1.0
    np.testing.assert_allclose(top[:3], [1, 1, -1], atol=1e-15)
    np.testing.assert_allclose(bottom[:3], [-1, -1, 1], atol=1e-15)


@pytest.mark.parametrize("camera", [
    Camera(position=(3.0, 2.0, 4.0), focal_point=(0.2, 0.1, -0.3), view_up=(0.1, 1.0, 0.2), view_angle=40.0,
           clipping_range=(0.5, 20.0)),
    Camera(position=(1.0, 5.0, 2.0), view_up=(0.0, 0.0, 1.0), parallel=True, parallel_scale=1.7,
           clipping_range=(1.0, 9.0)),
], ids=["perspective", "parallel"])
def test_world_to_clip_is_the_transpose_of_vtks_composite_projection(vtk, camera):
    """world_to_view @ view_to_clip equals vtkCamera.GetCompositeProjectionTransformMatrix(aspect, −1, 1) transposed."""
    aspect = 4.0 / 3.0
    c = vtk_camera(vtk, camera)
    theirs = vtk_matrix(c.GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0))
    ours = world_to_view(camera) @ view_to_clip(camera, aspect, camera.clipping_range)
    np.testing.assert_allclose(ours, theirs.T, atol=1e-13)


# --------------------------------------------------------------------------- the clipping range
def numpy_scalar_fit(camera, bounds):
    """fit_clipping_range as first written, in numpy float64 scalars: the reference for its bits."""
    pos = np.asarray(camera.position, dtype=np.float64)
    vpn = np.subtract(camera.position, camera.focal_point)
    a, b, c = -(vpn / np.linalg.norm(vpn))
    d = -(a * pos[0] + b * pos[1] + c * pos[2])
    near, far = a * bounds[0] + b * bounds[2] + c * bounds[4] + d, 1e-18
    for k in range(2):
        for j in range(2):
            for i in range(2):
                dist = a * bounds[i] + b * bounds[2 + j] + c * bounds[4 + k] + d
                near, far = min(near, dist), max(far, dist)
    min_gap = (0.1 * camera.parallel_scale if camera.parallel
               else 0.2 * math.tan(math.radians(camera.view_angle) / 2.0) * far)
    if far - near < min_gap:
        min_gap = min_gap - far + near
        far, near = far + min_gap / 2.0, near - min_gap / 2.0
    near = max(near, 0.0)
    near = 0.99 * near - (far - near) * 0.5
    far = 1.01 * far + (far - near) * 0.5
    if near >= far:
        near = 0.01 * far
    return float(max(near, NEAR_CLIPPING_PLANE_TOLERANCE * far)), float(far)


def test_fit_clipping_range_has_the_bits_of_numpy_scalar_arithmetic():
    """Worked out in Python floats, the range is bit for bit the numpy-scalar one, for 500
    random cameras (perspective and parallel) and boxes, some around the eye."""
    rng = np.random.default_rng(12)
    for k in range(500):
        camera = Camera(position=tuple(rng.normal(0, 10, 3)), focal_point=tuple(rng.normal(0, 1, 3)),
                        view_angle=float(rng.uniform(10, 80)), parallel=bool(k % 4 == 0),
                        parallel_scale=float(rng.uniform(0.5, 5)))
        lo = rng.normal(0, 5, 3) if k % 5 else np.array(camera.position) - 1
        hi = lo + rng.uniform(0.01, 8, 3)
        bounds = np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])
        assert fit_clipping_range(camera, bounds) == numpy_scalar_fit(camera, bounds)


def test_fit_clipping_range_by_hand():
    """Eye (0,0,5), unit cube: corners at distances 4.5..5.5; padded: near = 0.99·4.5 − 0.5 = 3.955, far = 1.01·5.5 + 0.5·(5.5 − 3.955) = 6.3275."""
    near, far = fit_clipping_range(Camera(position=(0, 0, 5)), (-0.5, 0.5, -0.5, 0.5, -0.5, 0.5))
    assert near == pytest.approx(3.955, abs=1e-12)
    assert far == pytest.approx(6.3275, abs=1e-12)


def test_fit_clipping_range_keeps_near_at_the_depth_buffer_tolerance():
    """With the eye inside the bounds, near = NEAR_CLIPPING_PLANE_TOLERANCE · far (0.001 for a 24-bit depth buffer)."""
    near, far = fit_clipping_range(Camera(position=(0, 0, 0.3)), (-0.5, 0.5, -0.5, 0.5, -0.5, 0.5))
    assert NEAR_CLIPPING_PLANE_TOLERANCE == 0.001
    assert near == pytest.approx(0.001 * far, rel=1e-12)


@pytest.fixture(scope="module")
def vtk_renderer(vtk):
    """An offscreen vtkRenderer after one Render(), so its depth-buffer size (and tolerance) is known."""
    rw = vtk.vtkRenderWindow()
    rw.SetOffScreenRendering(1)
    rw.SetSize(64, 48)
    ren = vtk.vtkRenderer()
    rw.AddRenderer(ren)
    rw.Render()
    assert rw.GetDepthBufferSize() > 16
    yield ren
    rw.Finalize()


@pytest.mark.parametrize("bounds", BOUNDS)
@pytest.mark.parametrize("camera", PERSPECTIVE_CAMERAS + PARALLEL_CAMERAS)
def test_fit_clipping_range_equals_vtk_reset_camera_clipping_range(vtk, vtk_renderer, camera, bounds):
    """fit_clipping_range(camera, bounds) equals vtkRenderer.ResetCameraClippingRange(bounds) on a 24-bit depth buffer."""
    c = vtk_camera(vtk, camera, vtk_renderer.GetActiveCamera())
    vtk_renderer.ResetCameraClippingRange(*bounds)
    assert vtk_renderer.GetNearClippingPlaneTolerance() == NEAR_CLIPPING_PLANE_TOLERANCE
    np.testing.assert_allclose(fit_clipping_range(camera, bounds), c.GetClippingRange(), rtol=1e-12)
