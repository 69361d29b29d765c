"""Stage 7's light model: VTK's light complexity, its formulas at one fragment, and lights carried into view space."""
import math

import numpy as np
import pytest

from lab.scene import Camera, Light, headlight
from renderer.camera import world_to_view
from renderer.lighting import ViewLights, light_complexity, light_to_view, view_lights, vtk_lighting

AMB = np.array([0.1, 0.05, 0.02])
DIF = np.array([0.5, 0.4, 0.3])
SPE = np.array([0.2, 0.25, 0.3])


def shade(n, p, complexity, lights, power=1.0):
    """vtk_lighting at one fragment; ``lights`` is a list of dicts (direction, colour, position, positional, cos_cone, exponent, attenuation)."""
    k = len(lights)
    get = lambda key, default: np.array([li.get(key, default) for li in lights], dtype=np.float64).reshape(k, -1)  # noqa: E731
    direction = get("direction", (0.0, 0.0, -1.0))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    out = np.empty(3)
    view = ViewLights(complexity, direction, get("position", (0.0, 0.0, 0.0)).reshape(k, 3),
                      get("colour", (1.0, 1.0, 1.0)).reshape(k, 3),
                      np.array([li.get("positional", False) for li in lights], np.bool_),
                      get("cos_cone", -2.0).reshape(k), get("exponent", 1.0).reshape(k),
                      get("attenuation", (1.0, 0.0, 0.0)).reshape(k, 3), *(np.zeros((k, 3)),) * 3)
    vtk_lighting(np.asarray(n, np.float64), np.asarray(p, np.float64), complexity, AMB, DIF, SPE, float(power),
                 view, out)
    return out


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


def test_a_dimmed_lone_headlight_scales_the_simple_formula():
    """Complexity 1 with Lc = colour × intensity 0.5 and n = (0,0,1): Amb + 0.5·Dif + 0.5·Spe."""
    lights = view_lights([Light(kind="headlight", intensity=0.5)], Camera(), np.eye(4))
    assert lights.complexity == 1
    np.testing.assert_allclose(shade((0, 0, 1), (1, 2, -5), 1, [{"colour": lights.colour[0]}], power=9),
                               AMB + 0.5 * DIF + 0.5 * SPE)


# --------------------------------------------------------------------------- the formulas
def test_unlit_is_ambient_plus_diffuse():
    """Complexity 0: Amb + Dif, whatever the normal and lights."""
    np.testing.assert_allclose(shade((0, 1, 0), (0, 0, -5), 0, [{}]), AMB + DIF)


def test_headlight_facing_the_viewer():
    """Complexity 1, n = (0,0,1): df = 1, sf = 1, so Amb + Dif·Lc + Spe·Lc."""
    lc = np.array([1.0, 0.5, 0.25])
    np.testing.assert_allclose(shade((0, 0, 1), (0, 0, -5), 1, [{"colour": lc}], power=20), AMB + DIF * lc + SPE * lc)


def test_headlight_on_a_tilted_normal():
    """Complexity 1, n = (0, 0.6, 0.8), power 2: df = n.z = 0.8, sf = 0.8² = 0.64 (half-vector fixed at (0,0,1))."""
    np.testing.assert_allclose(shade((0, 0.6, 0.8), (3, 1, -5), 1, [{}], power=2), AMB + 0.8 * DIF + 0.64 * SPE)


def test_headlight_never_goes_fully_dark():
    """Complexity 1 clamps df at 1e-6, so a normal facing away still gets Amb + 1e-6·Dif (+ (1e-6)^p·Spe)."""
    np.testing.assert_allclose(shade((0, 0, -1), (0, 0, -5), 1, [{}], power=1), AMB + 1e-6 * DIF + 1e-6 * SPE)


def test_directional_light_head_on():
    """Complexity 2, light along (0,0,−1), n = (0,0,1), P = (0,0,−5): df = 1, reflect = (0,0,1), v = (0,0,1), sf = 1."""
    lc = np.array([1.0, 0.5, 0.25])
    out = shade((0, 0, 1), (0, 0, -5), 2, [{"direction": (0, 0, -1), "colour": lc}], power=7)
    np.testing.assert_allclose(out, AMB + DIF * lc + SPE * lc)


def test_directional_light_at_45_degrees():
    """Light along (0,−1,−1)/√2 on n = (0,0,1) seen from (0,0,1): df = 1/√2, reflect = (0,−1,1)/√2, sf = (1/√2)^p."""
    out = shade((0, 0, 1), (0, 0, -5), 2, [{"direction": (0, -1, -1)}], power=3)
    r = 1 / math.sqrt(2)
    np.testing.assert_allclose(out, AMB + r * DIF + r ** 3 * SPE)


def test_light_from_behind_gives_ambient_only():
    """A light travelling along +n (from behind the surface): df = 0, and then no specular either."""
    np.testing.assert_allclose(shade((0, 0, 1), (0, 0, -5), 2, [{"direction": (0, 0, 1)}], power=1), AMB)


def test_directional_lights_add_up():
    """Two lights: the diffuse and specular sums of each, one ambient term."""
    one = shade((0, 0, 1), (0, 0, -5), 2, [{"direction": (0, 0, -1)}], power=2)
    two = shade((0, 0, 1), (0, 0, -5), 2, [{"direction": (0, 0, -1)}, {"direction": (0, -1, -1)}], power=2)
    np.testing.assert_allclose(one, AMB + DIF + SPE)
    np.testing.assert_allclose(two, AMB + DIF * (1 + 1 / math.sqrt(2)) + SPE * (1 + 0.5))


def test_specular_uses_the_local_viewer():
    """v = normalize(−P): off-axis at P = (5,0,−5) with light along (0,0,−1), rv = reflect·v = 1/√2."""
    out = shade((0, 0, 1), (5, 0, -5), 2, [{"direction": (0, 0, -1)}], power=2)
    np.testing.assert_allclose(out, AMB + DIF + 0.5 * SPE)


def test_positional_light_attenuation():
    """Complexity 3, light at the eye, P = (0,0,−2), attenuation (1, 0.5, 0.25): 1/(1 + 0.5·2 + 0.25·4) = 1/3 on df and sf."""
    out = shade((0, 0, 1), (0, 0, -2), 3, [{"positional": True, "attenuation": (1, 0.5, 0.25)}], power=5)
    np.testing.assert_allclose(out, AMB + DIF / 3 + SPE / 3)


def test_positional_light_direction_is_from_the_light_to_the_point():
    """Complexity 3: l = normalize(P − light position); light at (0,2,−2) above P = (0,0,−2) gives df = 0 on n = (0,0,1)."""
    out = shade((0, 0, 1), (0, 0, -2), 3, [{"positional": True, "position": (0, 2, -2)}], power=1)
    np.testing.assert_allclose(out, AMB)
    out = shade((0, 1, 0), (0, 0, -2), 3, [{"positional": True, "position": (0, 2, -2)}], power=1)
    assert out[0] > AMB[0] + 0.9 * DIF[0]  # the same light, on a normal facing it


def test_spot_light_inside_the_cone():
    """Cone 30°, exponent 2, light at the eye aimed along −z, P 20° off axis: att = cos²20°, df = cos³20°, sf = cos²20°·cos40°."""
    c20 = math.cos(math.radians(20))
    p = (2 * math.tan(math.radians(20)), 0, -2)
    spot = {"positional": True, "direction": (0, 0, -1), "cos_cone": math.cos(math.radians(30)), "exponent": 2}
    out = shade((0, 0, 1), p, 3, [spot], power=1)
    np.testing.assert_allclose(out, AMB + DIF * c20 ** 3 + SPE * c20 ** 2 * math.cos(math.radians(40)))


def test_spot_light_outside_the_cone_gives_ambient_only():
    """Cone 30°, P 45° off the axis: cut off, so ambient only (no diffuse, no specular)."""
    spot = {"positional": True, "direction": (0, 0, -1), "cos_cone": math.cos(math.radians(30)), "exponent": 2}
    np.testing.assert_allclose(shade((0, 0, 1), (2, 0, -2), 3, [spot], power=1), AMB)


def test_directional_light_in_a_positional_set_is_not_attenuated():
    """Complexity 3 with a non-positional light: it uses its direction and no attenuation."""
    out = shade((0, 0, 1), (0, 0, -5), 3, [{"direction": (0, 0, -1), "attenuation": (4, 4, 4)}], power=1)
    np.testing.assert_allclose(out, AMB + DIF + SPE)


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
    np.testing.assert_allclose(vl.colour, [[0.5, 0.25, 0], [1, 1, 1]])
    assert vl.positional.tolist() == [False, True]
    np.testing.assert_allclose(vl.cos_cone, [-2.0, 0.5])
    np.testing.assert_allclose(vl.attenuation[1], [1, 2, 3])
