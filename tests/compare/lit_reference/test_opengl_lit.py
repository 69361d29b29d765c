"""The opengl model's lit reference (compare/lit_reference/opengl_lit.py): OpenGL 1.x lighting in numpy.

Expected values are worked by hand from the OpenGL 1.x specification §2.14.1, not taken
from the code under test or from renderer/.
"""
import math

import numpy as np
import pytest

from compare.lit_reference.eye_space import EyeLight, unit
from compare.lit_reference.opengl_lit import opengl_colours

from .eye_cases import ON_AXIS, S3, UP, WHITE, ZERO, directional, dot, norm, random_scene, slow_L_att  # noqa: F401


# ---------------------------------------------------------------- OpenGL 1.x ----

def test_opengl_straight_on_light_clamps_to_white():
    """Light, normal and viewer aligned: 0.2·Ma + Md + Ms = (1.86, 1.86, 1.14), clamped to 1."""
    light = directional([0, 0, 1], ambient=ZERO, diffuse=WHITE, specular=WHITE)
    mat = dict(ambient=(0.8, 0.8, 0.2), diffuse=(0.8, 0.8, 0.2), specular=(0.9, 0.9, 0.9), shininess=100)
    c = opengl_colours(ON_AXIS, UP, lights=[light], **mat)
    np.testing.assert_array_equal(c, [[1.0, 1.0, 1.0]])
    # The same with Ld = Ls = 0.25, below the clamp: 0.2·Ma + 0.25·Md + 0.25·Ms.
    dim = directional([0, 0, 1], ambient=ZERO, diffuse=0.25 * WHITE, specular=0.25 * WHITE)
    c = opengl_colours(ON_AXIS, UP, lights=[dim], **mat)
    np.testing.assert_allclose(c, [[0.585, 0.585, 0.315]], rtol=0, atol=1e-12)


def test_opengl_light_from_behind_gives_ambient_only():
    """N·L < 0: only global ambient + La·Ma, no diffuse and no specular (although N·H > 0)."""
    # L = (0, 0.6, −0.8): behind the surface; H = normalize(L + V) = (0, 0.6, 0.2)/√0.4, N·H ≈ 0.32.
    light = directional([0, 0.6, -0.8], ambient=0.1 * WHITE, diffuse=WHITE, specular=WHITE)
    c = opengl_colours(ON_AXIS, UP, (0.8, 0.8, 0.2), (0.8, 0.8, 0.2), (0.9, 0.9, 0.9), 1, [light])
    np.testing.assert_allclose(c, [[0.24, 0.24, 0.06]], rtol=0, atol=1e-12)   # (0.2 + 0.1)·Ma


def test_opengl_light_at_60_degrees_infinite_viewer():
    """N·L = cos 60° = 0.5; H = normalize(L + (0,0,1)) = (1/2, 0, √3/2), so (N·H)² = 3/4."""
    light = directional([S3 / 2, 0, 0.5], ambient=ZERO, diffuse=WHITE, specular=WHITE)
    # 0.2·0.1 + 0.5·Md + 0.75·0.4 = 0.02 + (0.3, 0.2, 0.1) + 0.3; the infinite viewer ignores P.
    P = np.array([[3.0, 1.0, -5.0], [0.0, 0.0, -1.0]])
    c = opengl_colours(P, [0, 0, 1], (0.1, 0.1, 0.1), (0.6, 0.4, 0.2), (0.4, 0.4, 0.4), 2, [light])
    np.testing.assert_allclose(c, [[0.62, 0.52, 0.42]] * 2, rtol=0, atol=1e-12)


def test_opengl_local_viewer_changes_specular_not_diffuse():
    """At P = (1,0,−1) the eye is 45° off the normal: H at 22.5°, (N·H)² = (2 + √2)/4."""
    light = directional([0, 0, 1], ambient=ZERO, diffuse=WHITE, specular=WHITE)
    P = [[1.0, 0.0, -1.0]]
    args = dict(ambient=ZERO, diffuse=(0.3, 0.3, 0.3), specular=(0.5, 0.5, 0.5), shininess=2,
                lights=[light], global_ambient=ZERO)
    infinite = opengl_colours(P, UP, **args)
    local = opengl_colours(P, UP, local_viewer=True, **args)
    np.testing.assert_allclose(infinite, [[0.8] * 3], rtol=0, atol=1e-12)                 # 0.3 + 0.5·1
    np.testing.assert_allclose(local, [[0.3 + 0.5 * (2 + math.sqrt(2)) / 4] * 3], rtol=0, atol=1e-12)
    diffuse_only = dict(args, specular=ZERO)
    np.testing.assert_array_equal(opengl_colours(P, UP, **diffuse_only),
                                  opengl_colours(P, UP, local_viewer=True, **diffuse_only))


def test_opengl_point_light_attenuation():
    """Point light 2 away, (a0,a1,a2) = (1, 0.5, 0.25): att = 1/(1 + 1 + 1) = 1/3 on all three terms."""
    light = EyeLight(position=np.zeros(3), positional=True, attenuation=np.array([1.0, 0.5, 0.25]),
                     ambient=0.3 * WHITE, diffuse=0.6 * WHITE, specular=0.9 * WHITE)
    # 0.2·0.5 + (0.3·0.5 + 0.6·Md + 0.9·0.3)/3 = 0.1 + (1.02, 0.72, 0.42)/3
    c = opengl_colours([[0.0, 0.0, -2.0]], UP, (0.5, 0.5, 0.5), (1.0, 0.5, 0.0), (0.3, 0.3, 0.3), 10, [light])
    np.testing.assert_allclose(c, [[0.44, 0.34, 0.24]], rtol=0, atol=1e-12)


def test_opengl_spot_cone_and_exponent():
    """Spot at the eye down −z, 30° half-angle, exponent 2: outside the cone only global ambient is left."""
    light = EyeLight(position=np.zeros(3), direction=np.array([0.0, 0.0, -1.0]), positional=True,
                     cos_cone=S3 / 2, exponent=2.0, ambient=0.4 * WHITE, diffuse=WHITE, specular=ZERO)
    P = np.array([[2.0, 0.0, -2.0],    # 45° off the axis: outside
                  [1.0, 0.0, -2.0],    # c = 2/√5 ≈ 0.894 > cos 30°: inside, spot = c² = 0.8
                  [0.0, 0.0, -2.0]])   # on the axis: spot = 1
    half = (0.5, 0.5, 0.5)
    c = opengl_colours(P, UP, half, half, half, 1, [light])
    outside = 0.2 * 0.5
    inside = 0.1 + 0.8 * (0.4 * 0.5 + (2 / math.sqrt(5)) * 0.5)       # N·L = 2/√5 too
    on_axis = 0.1 + 0.4 * 0.5 + 1.0 * 0.5
    np.testing.assert_allclose(c, [[outside] * 3, [inside] * 3, [on_axis] * 3], rtol=0, atol=1e-12)


def test_opengl_textbook_two_lights_add_per_channel_then_clamp():
    """GL_LIGHT0 white (60° off) + GL_LIGHT1 red (straight on): each below 1, red sum 1.155 clamps."""
    light0 = directional([S3 / 2, 0, 0.5], ambient=0.1 * WHITE, diffuse=1.0 * WHITE, specular=0.9 * WHITE)
    light1 = directional([0, 0, 1], ambient=np.array([0.3, 0.1, 0.1]), diffuse=np.array([1.0, 0.1, 0.1]),
                         specular=np.array([0.9, 0.2, 0.2]))
    mat = dict(ambient=(0.4,) * 3, diffuse=(0.4,) * 3, specular=(0.2,) * 3, shininess=2)
    # global 0.2·0.4 = 0.08
    # LIGHT0: 0.1·0.4 + 0.5·0.4 + (√3/2)²·0.9·0.2 = 0.04 + 0.2 + 0.135 = 0.375
    # LIGHT1: (0.12, 0.04, 0.04) + (0.4, 0.04, 0.04) + (0.18, 0.04, 0.04) = (0.70, 0.12, 0.12)
    np.testing.assert_allclose(opengl_colours(ON_AXIS, UP, lights=[light0], **mat), [[0.455] * 3], atol=1e-12)
    np.testing.assert_allclose(opengl_colours(ON_AXIS, UP, lights=[light1], **mat), [[0.78, 0.2, 0.2]],
                               atol=1e-12)
    both = opengl_colours(ON_AXIS, UP, lights=[light0, light1], **mat)
    np.testing.assert_allclose(both, [[1.0, 0.575, 0.575]], rtol=0, atol=1e-12)   # (1.155 → 1, 0.575, 0.575)


def test_opengl_shininess_zero_gives_full_specular_when_lit():
    """Shininess 0: (N·H)^0 = 1, so a lit point gets Ls·Ms whatever N·H is; an unlit one none."""
    lit = directional([S3 / 2, 0, 0.5], ambient=ZERO, diffuse=ZERO, specular=WHITE)
    unlit = directional([0, 0.6, -0.8], ambient=ZERO, diffuse=ZERO, specular=WHITE)
    for light, expected in ((lit, 0.7), (unlit, 0.0)):
        c = opengl_colours(ON_AXIS, UP, ZERO, ZERO, (0.7, 0.7, 0.7), 0, [light])
        np.testing.assert_allclose(c, [[expected] * 3], rtol=0, atol=1e-12)


# ---------------------------------------------------------------- classic -------

def slow_opengl(p, n, Ma, Md, Ms, shininess, lights, ga, local_viewer):
    V = norm([-x for x in p]) if local_viewer else [0.0, 0.0, 1.0]
    c = [ga[k] * Ma[k] for k in range(3)]
    for light in lights:
        L, att = slow_L_att(light, p)
        nl = dot(n, L)
        H = norm([L[k] + V[k] for k in range(3)])
        s = max(dot(n, H), 0.0) ** shininess if nl > 0 else 0.0
        for k in range(3):
            c[k] += att * (light.ambient[k] * Ma[k] + max(nl, 0.0) * light.diffuse[k] * Md[k]
                           + s * light.specular[k] * Ms[k])
    return [min(max(x, 0.0), 1.0) for x in c]


@pytest.mark.parametrize("local_viewer", [False, True])
def test_opengl_vectorised_equals_per_point_loop(random_scene, local_viewer):
    """1000 random points, three kinds of light: the vectorised OpenGL colours equal a plain loop."""
    P, N, lights = random_scene
    Ma, Md, Ms, ga = (0.3, 0.2, 0.1), (0.7, 0.5, 0.3), (0.6, 0.6, 0.6), (0.2, 0.25, 0.3)
    fast = opengl_colours(P, N, Ma, Md, Ms, 12.5, lights, global_ambient=ga, local_viewer=local_viewer)
    slow = [slow_opengl(list(p), list(n), Ma, Md, Ms, 12.5, lights, ga, local_viewer) for p, n in zip(P, N)]
    assert fast.shape == (1000, 3)
    np.testing.assert_allclose(fast, slow, rtol=0, atol=1e-12)
    assert (fast == 1).any() and (fast < 1).all(axis=1).any()   # some channels clamp, some points don't


# ---------------------------------------------------------------- the model's room --

def scene_with(**render):
    from lab.scene import Camera, Image, Light, RenderSettings, Scene

    return Scene(image=Image(), camera=Camera(), objects=(), render=RenderSettings(**render),
                 lights=(Light(ambient_color=(0.1, 0.1, 0.1)), Light(ambient_color=(0.5, 0.5, 0.5), on=False)))


def gl_object(**material):
    from lab.scene import Material, SceneObject
    from lab.shapes import quad

    return SceneObject(mesh=quad(1.0), material=Material(model="opengl", **material))


def test_lit_keeps_the_specular_apart_only_when_the_scene_asks():
    """Light straight on: primary .2·Ma + Md, secondary Ms (each clamped); single colour: the sum, clamped."""
    from compare.lit_reference.opengl_lit import lit

    obj = gl_object(color=(0.5, 0.25, 0.25), specular_color=(0.25, 0.25, 0.25), shininess=10.0)
    light = directional([0, 0, 1], ambient=ZERO, diffuse=WHITE, specular=WHITE)
    rgb, secondary = lit(ON_AXIS, UP, obj, scene_with(separate_specular=True), [light])
    np.testing.assert_allclose(rgb, [[0.6, 0.3, 0.3]])
    np.testing.assert_allclose(secondary, [[0.25, 0.25, 0.25]])
    rgb, secondary = lit(ON_AXIS, UP, obj, scene_with(), [light])
    np.testing.assert_allclose(rgb, [[0.85, 0.55, 0.55]])
    assert secondary is None


def test_the_nearest_vtk_property_folds_the_ambient_lights_into_the_ambient_colour():
    """(Ga + ΣLa of the lights that are on)·Ma = (0.2 + 0.1)·Ma, coefficients 1, power shininess/4."""
    from compare.lit_reference.opengl_lit import vtk_property

    v = vtk_property(gl_object(color=(1.0, 0.5, 0.0), shininess=40.0), scene_with())
    np.testing.assert_allclose(v["ambient_color"], [0.3, 0.15, 0.0])
    assert (v["ambient"], v["diffuse"], v["specular"], v["power"]) == (1.0, 1.0, 1.0, 10.0)


def test_the_glsl_adds_the_secondary_colour_unless_it_is_kept_apart():
    from compare.lit_reference.opengl_lit import glsl

    obj, light = gl_object(), directional([0, 0, 1])
    single = glsl(obj, scene_with(), [light])
    assert "vec3 V = vec3(0.0, 0.0, 1.0);" in single and single.endswith("  c += secondary;\n")
    separate = glsl(obj, scene_with(separate_specular=True, local_viewer=True), [light])
    assert "vec3 V = normalize(-P);" in separate and "c += secondary" not in separate
