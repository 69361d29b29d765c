"""The vtk reflection model: VTK's formula at one fragment, by light complexity, and its material row.

Each case is worked by hand from VTK's shader (``vtkOpenGLPolyDataMapper::ReplaceShaderLight``):
``Amb + Σ df·Dif·Lc + Σ sf·Spe·Lc`` with the complexity's own df and sf.
"""
import math

import numpy as np
import pytest

from lab.mesh import Mesh
from lab.scene import Camera, Light, Material, SceneObject
from lab.shapes import quad
from renderer.lights import view_lights as scene_view_lights
from renderer.reflection.materials import PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED
from renderer.reflection.vtk_model import VTK_MAX_SPECULAR_POWER, material_row, shading_path, vtk_lighting

from ..kernel_inputs import materials, view_lights

AMB = np.array([0.1, 0.05, 0.02])
DIF = np.array([0.5, 0.4, 0.3])
SPE = np.array([0.2, 0.25, 0.3])


def shade(n, p, complexity, lights, power=1.0, lit=True):
    """vtk_lighting of a one-object table (AMB, DIF, SPE, ``power``) at one fragment; ``lights``
    is a list of dicts (see ``kernel_inputs.view_lights``)."""
    colour = vtk_lighting(np.asarray(n, np.float64), np.asarray(p, np.float64), 0,
                          materials(AMB, DIF, SPE, power, lit=lit), view_lights(lights, complexity))
    assert colour[3:] == (0.0, 0.0, 0.0)  # VTK has one colour
    return np.array(colour[:3])


# --------------------------------------------------------------------------- the formulas
def test_a_dimmed_lone_headlight_scales_the_simple_formula():
    """Complexity 1 with Lc = colour × intensity 0.5 and n = (0,0,1): Amb + 0.5·Dif + 0.5·Spe."""
    lights = scene_view_lights([Light(kind="headlight", intensity=0.5)], Camera(), np.eye(4))
    assert lights.complexity == 1
    np.testing.assert_allclose(shade((0, 0, 1), (1, 2, -5), 1, [{"intensity_rgb": lights.intensity_rgb[0]}], power=9),
                               AMB + 0.5 * DIF + 0.5 * SPE)


def test_unlit_is_ambient_plus_diffuse():
    """Complexity 0: Amb + Dif, whatever the normal and lights."""
    np.testing.assert_allclose(shade((0, 1, 0), (0, 0, -5), 0, [{}]), AMB + DIF)


def test_headlight_facing_the_viewer():
    """Complexity 1, n = (0,0,1): df = 1, sf = 1, so Amb + Dif·Lc + Spe·Lc."""
    lc = np.array([1.0, 0.5, 0.25])
    np.testing.assert_allclose(shade((0, 0, 1), (0, 0, -5), 1, [{"intensity_rgb": lc}], power=20), AMB + DIF * lc + SPE * lc)


def test_headlight_on_a_tilted_normal():
    """Complexity 1, n = (0, 0.6, 0.8), power 2: df = n.z = 0.8, sf = 0.8² = 0.64 (half-vector fixed at (0,0,1))."""
    np.testing.assert_allclose(shade((0, 0.6, 0.8), (3, 1, -5), 1, [{}], power=2), AMB + 0.8 * DIF + 0.64 * SPE)


def test_headlight_never_goes_fully_dark():
    """Complexity 1 clamps df at 1e-6, so a normal facing away still gets Amb + 1e-6·Dif (+ (1e-6)^p·Spe)."""
    np.testing.assert_allclose(shade((0, 0, -1), (0, 0, -5), 1, [{}], power=1), AMB + 1e-6 * DIF + 1e-6 * SPE)


def test_directional_light_head_on():
    """Complexity 2, light along (0,0,−1), n = (0,0,1), P = (0,0,−5): df = 1, reflect = (0,0,1), v = (0,0,1), sf = 1."""
    lc = np.array([1.0, 0.5, 0.25])
    out = shade((0, 0, 1), (0, 0, -5), 2, [{"direction": (0, 0, -1), "intensity_rgb": lc}], power=7)
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


def test_an_unlit_object_draws_ambient_plus_diffuse_whatever_the_lights():
    """lighting = false: complexity 0 for that object, Amb + Dif, though the scene's lights are on."""
    np.testing.assert_allclose(shade((0, 0, 1), (0, 0, -5), 2, [{}], lit=False), AMB + DIF)


# --------------------------------------------------------------------------- the material row
def test_material_row_is_ka_c_kd_c_ks_cs():
    """Ka·C, Kd·C, Ks·Cs: colour (1, .5, .25), Ka .2, Kd .6, Ks .4 with specular colour (0, 1, 0), power 7."""
    row = material_row(Material(color=(1.0, 0.5, 0.25), ambient=0.2, diffuse=0.6, specular=0.4,
                                specular_color=(0.0, 1.0, 0.0), specular_power=7.0))
    np.testing.assert_allclose(row.ambient, [0.2, 0.1, 0.05])
    np.testing.assert_allclose(row.diffuse, [0.6, 0.3, 0.15])
    np.testing.assert_allclose(row.specular, [0.0, 0.4, 0.0])
    assert row.power == 7.0


@pytest.mark.parametrize("power, drawn", [(1000.0, 128.0), (128.0, 128.0), (127.5, 127.5), (0.0, 0.0)])
def test_the_specular_power_is_clamped_at_128_as_vtk_clamps_it(power, drawn):
    """vtkProperty clamps SpecularPower to [0, 128]: 1000 is drawn as 128 (measured), smaller powers as given."""
    assert material_row(Material(specular_power=power)).power == drawn == min(power, VTK_MAX_SPECULAR_POWER)


def test_the_shading_path_is_per_pixel_two_sided_when_smooth_else_the_face_normal():
    """VTK lights every pixel: with the interpolated normal (gouraud and phong with normals), else the plane normal."""
    flat = quad(1.0)
    smooth = Mesh(flat.points, flat.triangles, point_normals=np.tile([0.0, 0.0, 1.0], (len(flat.points), 1)))
    assert shading_path(SceneObject(mesh=smooth, shading="gouraud")) == PIXEL_TWO_SIDED
    assert shading_path(SceneObject(mesh=smooth, shading="phong")) == PIXEL_TWO_SIDED
    assert shading_path(SceneObject(mesh=smooth, shading="flat")) == PIXEL_FACE_NORMAL
    assert shading_path(SceneObject(mesh=flat, shading="phong")) == PIXEL_FACE_NORMAL
