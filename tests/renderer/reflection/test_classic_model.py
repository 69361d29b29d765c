"""The classic reflection model: the course's Phong at one point, worked by hand.

``I = Ka·O·A + Σ att·[L·N > 0]·(Kd·O·I·(L·N) + Ks·I·max(R·V, 0)^n)``, clamped; one colour.
"""
import math

import numpy as np

from lab.scene import Material
from renderer.reflection.classic_model import classic_lighting, material_row

from ..kernel_inputs import materials, view_lights

O, KA, KD, KS, N = np.array([0.6, 0.4, 0.2]), 0.5, 0.5, 0.8, 4.0
UP = np.array([0.0, 0.0, 1.0])


def light(p, to_light, ambient_light=(0.2, 0.2, 0.2), intensity=1.0, **extra):
    """classic_lighting of the course's example material at point ``p`` with normal (0, 0, 1) under
    one light (L toward it = ``to_light``, or a positional light given in ``extra``)."""
    lights = view_lights([{"direction": -np.asarray(to_light, float), "intensity_rgb": (intensity,) * 3, **extra}],
                         ambient_light=ambient_light)
    colour = classic_lighting(UP, np.asarray(p, float), 0, materials(KA * O, KD * O, (KS,) * 3, N, model="classic"),
                              lights)
    assert colour[3:] == (0.0, 0.0, 0.0)  # the course has one colour
    return np.array(colour[:3])


def test_straight_on_light_and_viewer_clamps():
    """R = V = N: .5·O·.2 + .5·O + .8 = (1.16, 1.04, .92) → clamped to (1, 1, .92)."""
    np.testing.assert_allclose(light((0, 0, -3), (0, 0, 1)), [1.0, 1.0, 0.92])


def test_a_light_at_30_degrees_on_axis():
    """L·N = √3/2, R = (−½, 0, √3/2), V = (0,0,1): R·V = √3/2; intensity ½:
    .1·O + .5·O·½·√3/2 + .8·½·(√3/2)^4."""
    c = math.sqrt(3) / 2
    expected = 0.1 * O + 0.5 * O * 0.5 * c + 0.8 * 0.5 * c ** 4
    np.testing.assert_allclose(light((0, 0, -3), (0.5, 0, c), intensity=0.5), expected)


def test_a_face_turned_away_gets_ambient_only():
    """L·N < 0: neither diffuse nor specular, Ka·O·A = .5·O·.2."""
    np.testing.assert_allclose(light((0, 0, -3), (0, 0.6, -0.8)), 0.1 * O)


def test_a_point_light_is_attenuated():
    """Light at the eye, point at distance 2, attenuation (1, .5, .25): 1/3 of (.5·O + .8), no ambient light."""
    out = light((0, 0, -2), (0, 0, 1), ambient_light=(0, 0, 0), positional=True, position=(0, 0, 0),
                attenuation=(1, 0.5, 0.25))
    np.testing.assert_allclose(out, (0.5 * O + 0.8) / 3)


def test_the_row_is_ka_o_kd_o_ks_white_and_n_unclamped():
    row = material_row(Material(color=(0.6, 0.4, 0.2), ambient=0.5, diffuse=0.25, specular=0.8, specular_power=500.0))
    np.testing.assert_allclose(row.ambient, [0.3, 0.2, 0.1])
    np.testing.assert_allclose(row.diffuse, [0.15, 0.1, 0.05])
    np.testing.assert_allclose(row.specular, [0.8, 0.8, 0.8])
    assert row.power == 500.0
