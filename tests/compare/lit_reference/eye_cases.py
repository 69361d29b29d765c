"""Shared hand-made lights and a slow per-point light vector for the lit-reference tests (not a test file)."""
import math

import numpy as np
import pytest

from compare.lit_reference.eye_space import EyeLight, unit

S3 = math.sqrt(3.0)
UP = np.array([[0.0, 0.0, 1.0]])          # a normal facing the eye
ON_AXIS = np.array([[0.0, 0.0, -3.0]])    # a point straight ahead of the eye
WHITE = np.ones(3)
ZERO = np.zeros(3)


def directional(to_light, **colours) -> EyeLight:
    """A directional light whose L (toward the light) is ``to_light``."""
    return EyeLight(direction=-unit(np.asarray(to_light, dtype=float)), positional=False, **colours)


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    length = math.sqrt(dot(a, a))
    return [x / length for x in a]


def slow_L_att(light, p):
    """Plain per-point L and attenuation (with spot), straight from the formulas."""
    if not light.positional:
        return [-x for x in light.direction], 1.0
    to = [light.position[k] - p[k] for k in range(3)]
    d = math.sqrt(dot(to, to))
    L = [x / d for x in to]
    a0, a1, a2 = light.attenuation
    att = 1.0 / (a0 + a1 * d + a2 * d * d)
    if light.cos_cone is not None:
        c = -dot(L, light.direction)
        att *= c ** light.exponent if c >= light.cos_cone else 0.0
    return L, att


@pytest.fixture
def random_scene():
    rng = np.random.default_rng(20240611)
    P = rng.uniform([-3, -3, -8], [3, 3, -1], size=(1000, 3))
    N = unit(rng.normal(size=(1000, 3)))
    lights = [
        directional(rng.normal(size=3), intensity_rgb=rng.uniform(0, 2, 3), ambient=rng.uniform(0, 0.3, 3),
                    diffuse=rng.uniform(0, 2, 3), specular=rng.uniform(0, 2, 3)),
        EyeLight(position=rng.uniform(-2, 2, 3), positional=True, attenuation=np.array([1.0, 0.1, 0.02]),
                 intensity_rgb=rng.uniform(0, 2, 3), ambient=rng.uniform(0, 0.3, 3), diffuse=rng.uniform(0, 2, 3),
                 specular=rng.uniform(0, 2, 3)),
        EyeLight(position=np.array([0.5, 1.0, 1.0]), direction=unit(np.array([0.0, -0.2, -1.0])), positional=True,
                 cos_cone=math.cos(math.radians(25)), exponent=3.5, attenuation=np.array([0.5, 0.2, 0.0]),
                 intensity_rgb=rng.uniform(0, 2, 3), ambient=rng.uniform(0, 0.3, 3), diffuse=rng.uniform(0, 2, 3),
                 specular=rng.uniform(0, 2, 3)),
    ]
    return P, N, lights


