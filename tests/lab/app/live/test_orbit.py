"""lab/app/live/orbit.py: a drag turns the camera about the focal point as VTK's trackball does,
the wheel dollies, and the view up stays a unit vector across the view direction."""
from __future__ import annotations

import numpy as np
import pytest

from lab.app.live.orbit import orbit, rotation, usable, zoom

CAMERA = {"position": [0.0, 0.0, 5.0], "focal_point": [0.0, 0.0, 0.0], "view_up": [0.0, 1.0, 0.0],
          "view_angle": 30.0, "parallel": False, "parallel_scale": 2.0}


def test_rotation_is_right_handed():
    np.testing.assert_allclose(rotation([0, 0, 1], 90) @ [1, 0, 0], [0, 1, 0], atol=1e-12)


def test_dragging_right_half_the_width_turns_the_camera_90_degrees_to_the_left():
    cam = orbit(CAMERA, 0.5, 0.0)
    np.testing.assert_allclose(cam["position"], [-5.0, 0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(cam["view_up"], [0.0, 1.0, 0.0], atol=1e-12)


def test_dragging_down_lifts_the_camera_over_the_top():
    cam = orbit(CAMERA, 0.0, 0.25)
    np.testing.assert_allclose(cam["position"], [0.0, 5 * np.sqrt(0.5), 5 * np.sqrt(0.5)], atol=1e-12)
    over = orbit(CAMERA, 0.0, 0.75)  # 135°: past the pole, the view up turns with the camera
    d = np.subtract(over["position"], over["focal_point"])
    assert abs(np.dot(over["view_up"], d)) < 1e-9 and np.isclose(np.linalg.norm(over["view_up"]), 1)


@pytest.mark.parametrize("right,down", [(0.1, 0.3), (-0.7, 0.05), (0.33, -0.9)])
def test_an_orbit_keeps_the_distance_and_an_orthogonal_view_up(right, down):
    cam = orbit({**CAMERA, "focal_point": [1.0, 2.0, 3.0], "view_up": [0.2, 1.0, 0.0]}, right, down)
    d = np.subtract(cam["position"], cam["focal_point"])
    assert np.isclose(np.linalg.norm(d), np.linalg.norm(np.subtract(CAMERA["position"], [1.0, 2.0, 3.0])))
    assert abs(np.dot(cam["view_up"], d)) < 1e-9 and np.isclose(np.linalg.norm(cam["view_up"]), 1)


def test_zoom_dollies_a_perspective_camera_and_scales_a_parallel_one():
    np.testing.assert_allclose(zoom(CAMERA, 2.0)["position"], [0.0, 0.0, 2.5])
    assert zoom({**CAMERA, "parallel": True}, 2.0)["parallel_scale"] == 1.0


def test_a_camera_being_typed_is_not_moved():
    assert usable(CAMERA)
    assert not usable({**CAMERA, "position": ["", 0, 5]}) and not usable({**CAMERA, "position": [0, 0, 0]})
    assert not usable({})
