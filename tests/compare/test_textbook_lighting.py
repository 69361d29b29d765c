"""Tests for compare/textbook_lighting.py: OpenGL 1.x and classic Phong lighting in numpy.

Expected values are worked by hand from the formulas (OpenGL 1.x specification §2.14.1;
the course slides' classic model), not taken from the code under test or from renderer/.
"""
import math

import numpy as np
import pytest

from compare.textbook_lighting import EyeLight, classic_colours, face_points_and_normals, opengl_colours, unit

S3 = math.sqrt(3.0)
UP = np.array([[0.0, 0.0, 1.0]])          # a normal facing the eye
ON_AXIS = np.array([[0.0, 0.0, -3.0]])    # a point straight ahead of the eye
WHITE = np.ones(3)
ZERO = np.zeros(3)


def directional(to_light, **colours) -> EyeLight:
    """A directional light whose L (toward the light) is ``to_light``."""
    return EyeLight(direction=-unit(np.asarray(to_light, dtype=float)), positional=False, **colours)


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

CLASSIC = dict(colour=np.array([0.6, 0.4, 0.2]), ka=0.5, kd=0.5, ks=0.8, n=4)


def test_classic_straight_on_light_and_viewer():
    """I = 0.5·O·A + 0.5·O·I + 0.8·I = (1.16, 1.04, 0.92) for O = (0.6,0.4,0.2), A = 0.2, I = 1; clamped."""
    light = directional([0, 0, 1], colour=WHITE)
    c = classic_colours(ON_AXIS, UP, lights=[light], ambient_light=0.2 * WHITE, **CLASSIC)
    np.testing.assert_allclose(c, [[1.0, 1.0, 0.92]], rtol=0, atol=1e-12)


def test_classic_light_at_30_degrees():
    """L = (1/2, 0, √3/2) → R = (−1/2, 0, √3/2): R·V = √3/2 on the axis, cos 15° from P = (1,0,−1)."""
    light = directional([0.5, 0, S3 / 2], colour=0.5 * WHITE)
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
    light = directional([0, 0.6, -0.8], colour=WHITE)
    P = np.array([[0.0, 6.0, -1.0]])      # V = (0, −6, 1)/√37: R·V = −1.6/√37 + 4.4/√37 > 0
    c = classic_colours(P, UP, **dict(CLASSIC, n=1), lights=[light], ambient_light=0.2 * WHITE)
    np.testing.assert_allclose(c, [0.5 * CLASSIC["colour"] * 0.2], rtol=0, atol=1e-12)


def test_classic_point_light_attenuation():
    """The classic model attenuates the same way: att = 1/(1 + 0.5·2 + 0.25·4) = 1/3."""
    light = EyeLight(position=np.zeros(3), positional=True, attenuation=np.array([1.0, 0.5, 0.25]), colour=WHITE)
    c = classic_colours([[0.0, 0.0, -2.0]], UP, lights=[light], ambient_light=ZERO, **CLASSIC)
    np.testing.assert_allclose(c, [(0.5 * CLASSIC["colour"] + 0.8) / 3], rtol=0, atol=1e-12)


# ---------------------------------------------------------------- shapes --------

def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _norm(a):
    length = math.sqrt(_dot(a, a))
    return [x / length for x in a]


def _slow_L_att(light, p):
    """Plain per-point L and attenuation (with spot), straight from the formulas."""
    if not light.positional:
        return [-x for x in light.direction], 1.0
    to = [light.position[k] - p[k] for k in range(3)]
    d = math.sqrt(_dot(to, to))
    L = [x / d for x in to]
    a0, a1, a2 = light.attenuation
    att = 1.0 / (a0 + a1 * d + a2 * d * d)
    if light.cos_cone is not None:
        c = -_dot(L, light.direction)
        att *= c ** light.exponent if c >= light.cos_cone else 0.0
    return L, att


def slow_opengl(p, n, Ma, Md, Ms, shininess, lights, ga, local_viewer):
    V = _norm([-x for x in p]) if local_viewer else [0.0, 0.0, 1.0]
    c = [ga[k] * Ma[k] for k in range(3)]
    for light in lights:
        L, att = _slow_L_att(light, p)
        nl = _dot(n, L)
        H = _norm([L[k] + V[k] for k in range(3)])
        s = max(_dot(n, H), 0.0) ** shininess if nl > 0 else 0.0
        for k in range(3):
            c[k] += att * (light.ambient[k] * Ma[k] + max(nl, 0.0) * light.diffuse[k] * Md[k]
                           + s * light.specular[k] * Ms[k])
    return [min(max(x, 0.0), 1.0) for x in c]


def slow_classic(p, n, O, ka, kd, ks, m, lights, A):
    V = _norm([-x for x in p])
    c = [ka * O[k] * A[k] for k in range(3)]
    for light in lights:
        L, att = _slow_L_att(light, p)
        nl = _dot(n, L)
        if nl <= 0:
            continue
        R = [2 * nl * n[k] - L[k] for k in range(3)]
        rv = max(_dot(R, V), 0.0)
        for k in range(3):
            c[k] += att * (kd * O[k] * light.colour[k] * nl + ks * light.colour[k] * rv ** m)
    return [min(max(x, 0.0), 1.0) for x in c]


@pytest.fixture
def random_scene():
    rng = np.random.default_rng(20240611)
    P = rng.uniform([-3, -3, -8], [3, 3, -1], size=(1000, 3))
    N = unit(rng.normal(size=(1000, 3)))
    lights = [
        directional(rng.normal(size=3), colour=rng.uniform(0, 2, 3), ambient=rng.uniform(0, 0.3, 3),
                    diffuse=rng.uniform(0, 2, 3), specular=rng.uniform(0, 2, 3)),
        EyeLight(position=rng.uniform(-2, 2, 3), positional=True, attenuation=np.array([1.0, 0.1, 0.02]),
                 colour=rng.uniform(0, 2, 3), ambient=rng.uniform(0, 0.3, 3), diffuse=rng.uniform(0, 2, 3),
                 specular=rng.uniform(0, 2, 3)),
        EyeLight(position=np.array([0.5, 1.0, 1.0]), direction=unit(np.array([0.0, -0.2, -1.0])), positional=True,
                 cos_cone=math.cos(math.radians(25)), exponent=3.5, attenuation=np.array([0.5, 0.2, 0.0]),
                 colour=rng.uniform(0, 2, 3), ambient=rng.uniform(0, 0.3, 3), diffuse=rng.uniform(0, 2, 3),
                 specular=rng.uniform(0, 2, 3)),
    ]
    return P, N, lights


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


def test_classic_vectorised_equals_per_point_loop(random_scene):
    """1000 random points, three kinds of light: the vectorised classic colours equal a plain loop."""
    P, N, lights = random_scene
    O, A = (0.9, 0.5, 0.2), (0.3, 0.3, 0.4)
    fast = classic_colours(P, N, O, 0.3, 0.6, 0.7, 7.0, lights, ambient_light=A)
    slow = [slow_classic(list(p), list(n), O, 0.3, 0.6, 0.7, 7.0, lights, A) for p, n in zip(P, N)]
    assert fast.shape == (1000, 3)
    np.testing.assert_allclose(fast, slow, rtol=0, atol=1e-12)
    assert (fast == 1).any() and (fast < 1).all(axis=1).any()


# ---------------------------------------------------------------- helpers -------

def test_face_points_and_normals_on_hand_triangles():
    """Centroids and unit (v1−v0)×(v2−v0): (0,0,4) → +z and (0,6,0) → +y."""
    points = np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 3]], dtype=float)
    centroids, normals = face_points_and_normals(points, np.array([[0, 1, 2], [0, 3, 1]]))
    np.testing.assert_allclose(centroids, [[2 / 3, 2 / 3, 0], [2 / 3, 0, 1]], atol=1e-15)
    np.testing.assert_allclose(normals, [[0, 0, 1], [0, 1, 0]], atol=1e-15)


def test_unit_scales_rows_and_leaves_zero_alone():
    """unit() divides each row by its length; a zero row stays zero (no NaN)."""
    np.testing.assert_allclose(unit([[3.0, 0.0, 4.0], [0.0, 0.0, 0.0]]), [[0.6, 0.0, 0.8], [0.0, 0.0, 0.0]])
