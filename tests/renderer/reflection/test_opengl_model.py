"""The opengl reflection model: fixed-function OpenGL at one point, worked by hand (OpenGL 1.x §2.14.1).

``c = Ga·Ma + Σ att·(La·Ma + max(n·L, 0)·Ld·Md + [n·L > 0]·max(n·H, 0)^s·Ls·Ms)``, clamped.
"""
import math

import numpy as np

from lab.scene import Material
from renderer.reflection.opengl_model import material_row, opengl_lighting

from ..kernel_inputs import materials, view_lights

S3 = math.sqrt(3.0)
UP = np.array([0.0, 0.0, 1.0])
MA, MD, MS = (0.1, 0.1, 0.1), (0.6, 0.4, 0.2), (0.4, 0.4, 0.4)


def light(n, p, to_light, shininess=2.0, **model):
    """opengl_lighting of one object (MA, MD, MS, ``shininess``) under one white directional light whose
    L (toward the light) is ``to_light``; returns (primary, secondary)."""
    lights = view_lights([{"direction": -np.asarray(to_light, float), **model.pop("light", {})}], **model)
    colour = opengl_lighting(np.asarray(n, float), np.asarray(p, float), 0,
                             materials(MA, MD, MS, shininess, model="opengl"), lights)
    return np.array(colour[:3]), np.array(colour[3:])


def test_a_light_at_60_degrees_for_the_infinite_viewer():
    """n·L = ½; H = normalize(L + (0,0,1)) = (½, 0, √3/2), (n·H)² = ¾: 0.2·0.1 + ½·Md + ¾·0.4 = (.62, .52, .42)."""
    out, spec = light(UP, (3, 1, -5), (S3 / 2, 0, 0.5))
    np.testing.assert_allclose(out, [0.62, 0.52, 0.42])
    assert spec.tolist() == [0.0, 0.0, 0.0]


def test_separate_specular_keeps_the_highlight_apart():
    """The same light with GL_SEPARATE_SPECULAR_COLOR: primary (.32, .22, .12), secondary ¾·0.4 = .3."""
    out, spec = light(UP, (3, 1, -5), (S3 / 2, 0, 0.5), separate_specular=True)
    np.testing.assert_allclose(out, [0.32, 0.22, 0.12])
    np.testing.assert_allclose(spec, [0.3, 0.3, 0.3])


def test_a_light_from_behind_gives_ambient_only():
    """n·L < 0: Ga·Ma + La·Ma = (0.2 + 0.1)·0.1 = .03, no diffuse and no specular although n·H > 0."""
    out, _ = light(UP, (0, 0, -3), (0, 0.6, -0.8), light={"gl_ambient": (0.1, 0.1, 0.1)})
    np.testing.assert_allclose(out, [0.03, 0.03, 0.03])


def test_the_local_viewer_moves_the_highlight():
    """Light straight on, point (1, 0, −1): V = (−1, 0, 1)/√2, H at 22.5°, (n·H)² = (2 + √2)/4."""
    out, _ = light(UP, (1, 0, -1), (0, 0, 1), local_viewer=True)
    np.testing.assert_allclose(out, 0.02 + np.array(MD) + 0.4 * (2 + math.sqrt(2)) / 4)
    infinite, _ = light(UP, (1, 0, -1), (0, 0, 1))
    np.testing.assert_allclose(infinite, [1.0, 0.82, 0.62])  # (n·H) = 1: 0.02 + Md + 0.4, red clamped


def test_the_row_is_the_materials_opengl_colours_and_shininess():
    row = material_row(Material(color=(0.5, 0.5, 0.5), ambient_color=(0.1, 0.2, 0.3), specular_color=(1, 1, 1),
                                shininess=64.0))
    np.testing.assert_allclose(row.ambient, [0.1, 0.2, 0.3])
    np.testing.assert_allclose(row.diffuse, [0.5, 0.5, 0.5])
    np.testing.assert_allclose(row.specular, [1, 1, 1])
    assert row.power == 64.0
