"""The classic model's lit reference (compare/lit_reference/classic_lit.py): the course's Phong in numpy.

Expected values are worked by hand from the course slides' formula, not taken from the
code under test or from renderer/.
"""
import math

import numpy as np

from compare.lit_reference.classic_lit import classic_colours
from compare.lit_reference.eye_space import EyeLight

from .eye_cases import ON_AXIS, S3, UP, WHITE, ZERO, directional, dot, norm, random_scene, slow_L_att  # noqa: F401

CLASSIC = dict(colour=np.array([0.6, 0.4, 0.2]), ka=0.5, kd=0.5, ks=0.8, n=4)


def test_classic_straight_on_light_and_viewer():
    """I = 0.5·O·A + 0.5·O·I + 0.8·I = (1.16, 1.04, 0.92) for O = (0.6,0.4,0.2), A = 0.2, I = 1; clamped."""
    light = directional([0, 0, 1], intensity_rgb=WHITE)
    c = classic_colours(ON_AXIS, UP, lights=[light], ambient_light=0.2 * WHITE, **CLASSIC)
    np.testing.assert_allclose(c, [[1.0, 1.0, 0.92]], rtol=0, atol=1e-12)


def test_classic_light_at_30_degrees():
    """L = (1/2, 0, √3/2) → R = (−1/2, 0, √3/2): R·V = √3/2 on the axis, cos 15° from P = (1,0,−1)."""
    light = directional([0.5, 0, S3 / 2], intensity_rgb=0.5 * WHITE)
    P = np.array([[0.0, 0.0, -3.0], [1.0, 0.0, -1.0]])   # V = (0,0,1); V = (−1,0,1)/√2 (45°)
    c = classic_colours(P, UP, lights=[light], ambient_light=0.2 * WHITE, **CLASSIC)
    O = CLASSIC["colour"]
    diffuse_and_ambient = 0.5 * O * 0.2 + 0.5 * O * 0.5 * (S3 / 2)
    cos15 = math.cos(math.radians(15))
    expected = [diffuse_and_ambient + 0.8 * 0.5 * (S3 / 2) ** 4,      # (√3/2)⁴ = 9/16
                diffuse_and_ambient + 0.8 * 0.5 * cos15 ** 4]
    np.testing.assert_allclose(c, expected, rtol=0, atol=1e-12)
    np.testing.assert_allclose(c[0], [0.414904, 0.351603, 0.288301], atol=1e-6)   # by hand


def test_classic_face_turned_away_gets_ambient_only():
    """N·L = −0.8 < 0: no (negative) diffuse and no specular, though R·V ≈ 0.46 > 0 here."""
    light = directional([0, 0.6, -0.8], intensity_rgb=WHITE)
    P = np.array([[0.0, 6.0, -1.0]])      # V = (0, −6, 1)/√37: R·V = −1.6/√37 + 4.4/√37 > 0
    c = classic_colours(P, UP, **dict(CLASSIC, n=1), lights=[light], ambient_light=0.2 * WHITE)
    np.testing.assert_allclose(c, [0.5 * CLASSIC["colour"] * 0.2], rtol=0, atol=1e-12)


def test_classic_point_light_attenuation():
    """The classic model attenuates the same way: att = 1/(1 + 0.5·2 + 0.25·4) = 1/3."""
    light = EyeLight(position=np.zeros(3), positional=True, attenuation=np.array([1.0, 0.5, 0.25]), intensity_rgb=WHITE)
    c = classic_colours([[0.0, 0.0, -2.0]], UP, lights=[light], ambient_light=ZERO, **CLASSIC)
    np.testing.assert_allclose(c, [(0.5 * CLASSIC["colour"] + 0.8) / 3], rtol=0, atol=1e-12)


def slow_classic(p, n, O, ka, kd, ks, m, lights, A):
    V = norm([-x for x in p])
    c = [ka * O[k] * A[k] for k in range(3)]
    for light in lights:
        L, att = slow_L_att(light, p)
        nl = dot(n, L)
        if nl <= 0:
            continue
        R = [2 * nl * n[k] - L[k] for k in range(3)]
        rv = max(dot(R, V), 0.0)
        for k in range(3):
            c[k] += att * (kd * O[k] * light.intensity_rgb[k] * nl + ks * light.intensity_rgb[k] * rv ** m)
    return [min(max(x, 0.0), 1.0) for x in c]


def test_classic_vectorised_equals_per_point_loop(random_scene):
    """1000 random points, three kinds of light: the vectorised classic colours equal a plain loop."""
    P, N, lights = random_scene
    O, A = (0.9, 0.5, 0.2), (0.3, 0.3, 0.4)
    fast = classic_colours(P, N, O, 0.3, 0.6, 0.7, 7.0, lights, ambient_light=A)
    slow = [slow_classic(list(p), list(n), O, 0.3, 0.6, 0.7, 7.0, lights, A) for p, n in zip(P, N)]
    assert fast.shape == (1000, 3)
    np.testing.assert_allclose(fast, slow, rtol=0, atol=1e-12)
    assert (fast == 1).any() and (fast < 1).all(axis=1).any()


# ---------------------------------------------------------------- the model's room --

def classic_object():
    from lab.scene import Material, SceneObject
    from lab.shapes import quad

    return SceneObject(mesh=quad(1.0), material=Material(model="classic", color=(0.6, 0.4, 0.2), ambient=0.5,
                                                         diffuse=0.5, specular=0.8, specular_power=4.0))


def scene_with_ambient(ambient):
    from lab.scene import Camera, Image, RenderSettings, Scene

    return Scene(image=Image(), camera=Camera(), lights=(), objects=(), render=RenderSettings(ambient=ambient))


def test_lit_is_the_course_formula_with_the_scenes_ambient_light():
    """The straight-on case above through the room: (1, 1, .92), and no secondary colour."""
    from compare.lit_reference.classic_lit import lit

    rgb, secondary = lit(ON_AXIS, UP, classic_object(), scene_with_ambient((0.2, 0.2, 0.2)),
                         [directional([0, 0, 1], intensity_rgb=WHITE)])
    np.testing.assert_allclose(rgb, [[1.0, 1.0, 0.92]])
    assert secondary is None


def test_the_vtk_property_maps_one_to_one():
    """O·A, Ka; O, Kd; white, Ks; n."""
    from compare.lit_reference.classic_lit import vtk_property

    from lab.scene import Material, SceneObject
    from lab.shapes import quad

    m = Material(model="classic", color=(0.6, 0.4, 0.2), ambient=0.1, diffuse=0.7, specular=0.3, specular_power=9.0)
    v = vtk_property(SceneObject(mesh=quad(1.0), material=m), scene_with_ambient((0.5, 0.5, 0.5)))
    np.testing.assert_allclose(v["ambient_color"], [0.3, 0.2, 0.1])
    np.testing.assert_allclose(v["diffuse_color"], [0.6, 0.4, 0.2])
    np.testing.assert_allclose(v["specular_color"], [1, 1, 1])
    assert (v["ambient"], v["diffuse"], v["specular"], v["power"]) == (0.1, 0.7, 0.3, 9.0)


def test_the_glsl_lights_only_the_front_and_never_touches_the_secondary():
    from compare.lit_reference.classic_lit import glsl

    code = glsl(classic_object(), scene_with_ambient((1, 1, 1)), [directional([0, 0, 1])])
    assert "if (att > 0.0 && ndl > 0.0)" in code and "vec3 R = 2.0 * ndl * n - L;" in code
    assert "secondary" not in code
