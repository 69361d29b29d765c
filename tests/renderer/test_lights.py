"""Lights in view space: VTK's light complexity, each light's frame, the gathered arrays and the
light model, and one light seen from a point (attenuation and spot, shared by every model)."""
import math

import numpy as np
import pytest

from lab.scene import Camera, Light, RenderSettings, headlight
from renderer.camera import world_to_view
from renderer.lights import NO_CONE, light_at, light_complexity, light_to_view, view_lights

from .kernel_inputs import view_lights as hand_lights


# --------------------------------------------------------------------------- light complexity
@pytest.mark.parametrize("lights, expected", [
    ((), 0),
    ((Light(on=False),), 0),
    ((headlight(),), 1),
    ((Light(kind="headlight", intensity=0.5),), 1),
    ((Light(kind="scene"),), 2),
    ((Light(kind="camera"),), 2),
    ((headlight(), headlight()), 2),
    ((headlight(), Light(kind="headlight", on=False)), 1),
    ((headlight(), Light(kind="scene", on=False)), 2),
    ((Light(positional=True),), 3),
    ((Light(positional=True, on=False),), 3),
    ((headlight(), Light(kind="scene", positional=True, on=False)), 3),
], ids=["none", "all-off", "lone-headlight", "dimmed-headlight", "scene-light", "camera-light", "two-headlights",
        "headlight-plus-off-headlight", "headlight-plus-off-scene-light", "positional", "positional-off",
        "headlight-plus-positional-off"])
def test_light_complexity(lights, expected):
    """VTK's UpdateLights: 0 none on, 1 one headlight (any intensity), 2 otherwise, 3 if any light is positional, on or off."""
    assert light_complexity(lights) == expected


# --------------------------------------------------------------------------- lights in view space
CAMERA_ON_X = Camera(position=(3.0, 0.0, 0.0))  # U = (0,0,−1), V = (0,1,0), N = (1,0,0), d = 3


def test_scene_light_is_carried_by_the_view_matrix():
    """A scene light at (1,2,3) aimed at the origin, camera at (3,0,0): view position (−3,2,−2), focal point (0,0,−3)."""
    pos, foc = light_to_view(Light(kind="scene", position=(1, 2, 3), focal_point=(0, 0, 0)), CAMERA_ON_X,
                             world_to_view(CAMERA_ON_X))
    np.testing.assert_allclose(pos, [-3, 2, -2], atol=1e-14)
    np.testing.assert_allclose(foc, [0, 0, -3], atol=1e-14)


def test_headlight_sits_at_the_eye_aimed_down_minus_z():
    """A headlight ignores its own position: at (0,0,0), aimed at (0,0,−d), travelling along (0,0,−1)."""
    light = Light(kind="headlight", position=(7, 8, 9), focal_point=(1, 1, 1))
    pos, foc = light_to_view(light, CAMERA_ON_X, world_to_view(CAMERA_ON_X))
    np.testing.assert_allclose(pos, [0, 0, 0])
    np.testing.assert_allclose(foc, [0, 0, -3])
    np.testing.assert_allclose(view_lights([light], CAMERA_ON_X, world_to_view(CAMERA_ON_X)).direction, [[0, 0, -1]])


@pytest.mark.parametrize("position", [(1.0, 1.0, 1.0), (0.0, 0.0, 1.0), (-2.0, 0.5, 3.0)])
def test_camera_light_aimed_at_the_focal_point(position):
    """A camera light at (x,y,z) aimed at (0,0,0) sits at d·(x, y, z−1) and travels along normalize(−(x,y,z))."""
    light = Light(kind="camera", position=position, focal_point=(0, 0, 0))
    w2v = world_to_view(CAMERA_ON_X)
    pos, foc = light_to_view(light, CAMERA_ON_X, w2v)
    x, y, z = position
    np.testing.assert_allclose(pos, [3 * x, 3 * y, 3 * (z - 1)], atol=1e-14)
    np.testing.assert_allclose(foc, [0, 0, -3], atol=1e-14)
    direction = view_lights([light], CAMERA_ON_X, w2v).direction[0]
    np.testing.assert_allclose(direction, -np.array(position) / np.linalg.norm(position), atol=1e-14)


def test_view_lights_keeps_only_switched_on_lights():
    """view_lights gathers the lights that are on, colour × intensity, cone cosine only for positional spots."""
    lights = [Light(kind="headlight", color=(1, 0.5, 0), intensity=0.5), Light(on=False),
              Light(kind="scene", position=(0, 0, 5), positional=True, cone_angle=60, exponent=3,
                    attenuation=(1, 2, 3))]
    vl = view_lights(lights, CAMERA_ON_X, world_to_view(CAMERA_ON_X))
    assert vl.complexity == 3
    np.testing.assert_allclose(vl.intensity_rgb, [[0.5, 0.25, 0], [1, 1, 1]])
    assert vl.positional.tolist() == [False, True]
    np.testing.assert_allclose(vl.cos_cone, [NO_CONE, 0.5])
    np.testing.assert_allclose(vl.attenuation[1], [1, 2, 3])


def test_view_lights_carries_the_scene_wide_light_model():
    """global ambient, the classic ambient light, local viewer and separate specular come from ``[render]``."""
    settings = RenderSettings(global_ambient=(0.1, 0.2, 0.3), ambient=(0.5, 0.5, 0.25), local_viewer=True,
                              separate_specular=True)
    vl = view_lights([headlight()], CAMERA_ON_X, world_to_view(CAMERA_ON_X), settings)
    np.testing.assert_allclose(vl.global_ambient, [0.1, 0.2, 0.3])
    np.testing.assert_allclose(vl.ambient_light, [0.5, 0.5, 0.25])
    assert vl.local_viewer and vl.separate_specular
    default = view_lights([headlight()], CAMERA_ON_X, world_to_view(CAMERA_ON_X))
    np.testing.assert_allclose(default.global_ambient, [0.2, 0.2, 0.2])
    assert not default.local_viewer and not default.separate_specular


def test_no_cone_lies_below_every_cosine():
    """NO_CONE marks a light without a spot cone: it can never equal the cosine of a real half-angle."""
    assert NO_CONE < -1.0


# --------------------------------------------------------------------------- one light seen from a point
def at(light, p):
    return light_at(hand_lights([light]), 0, np.asarray(p, np.float64))


def test_a_directional_light_points_against_its_direction_unattenuated():
    """L = −direction, att = 1, wherever the point is (attenuation values are ignored)."""
    lx, ly, lz, att = at({"direction": (0, -3, -4), "attenuation": (5, 5, 5)}, (7, 8, -9))
    np.testing.assert_allclose([lx, ly, lz, att], [0, 0.6, 0.8, 1.0])


def test_a_point_light_is_attenuated_by_its_distance():
    """Light at (0, 3, −2), point (0, 0, 2): L = (0, 3, −4)/5, d = 5, att = 1/(1 + 0.5·5 + 0.1·25) = 1/6."""
    lx, ly, lz, att = at({"positional": True, "position": (0, 3, -2), "attenuation": (1, 0.5, 0.1)}, (0, 0, 2))
    np.testing.assert_allclose([lx, ly, lz], [0, 0.6, -0.8])
    assert att == pytest.approx(1 / 6)


def test_a_spot_weights_by_the_cosine_off_its_axis_to_the_exponent():
    """Spot at the origin aimed along −z, cone 30°, exponent 3; point 20° off the axis at distance 2 (att0 = 1):
    att = cos³20°; at 35° off the axis (outside the cone) att = 0."""
    spot = {"positional": True, "direction": (0, 0, -1), "cos_cone": math.cos(math.radians(30)), "exponent": 3}
    inside = (2 * math.sin(math.radians(20)), 0, -2 * math.cos(math.radians(20)))
    assert at(spot, inside)[3] == pytest.approx(math.cos(math.radians(20)) ** 3)
    outside = (2 * math.sin(math.radians(35)), 0, -2 * math.cos(math.radians(35)))
    assert at(spot, outside)[3] == 0.0


def test_a_point_light_without_a_cone_shines_all_round():
    """NO_CONE: no spot factor, even for a point behind the light's direction."""
    light = {"positional": True, "direction": (0, 0, -1), "exponent": 50}
    assert at(light, (0, 0, 1))[3] == 1.0
