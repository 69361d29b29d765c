"""View-space helpers of the lit references (compare/lit_reference/eye_space.py): vectors,
face centroids, the light vector with attenuation and spot, and the same in GLSL."""
import math

import numpy as np

from compare.lit_reference.eye_space import EyeLight, face_points_and_normals, glsl_light_vector, light_vector, unit


def test_face_points_and_normals_on_hand_triangles():
    """Centroids and unit (v1−v0)×(v2−v0): (0,0,4) → +z and (0,6,0) → +y."""
    points = np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0], [0, 0, 3]], dtype=float)
    centroids, normals = face_points_and_normals(points, np.array([[0, 1, 2], [0, 3, 1]]))
    np.testing.assert_allclose(centroids, [[2 / 3, 2 / 3, 0], [2 / 3, 0, 1]], atol=1e-15)
    np.testing.assert_allclose(normals, [[0, 0, 1], [0, 1, 0]], atol=1e-15)


def test_unit_scales_rows_and_leaves_zero_alone():
    """unit() divides each row by its length; a zero row stays zero (no NaN)."""
    np.testing.assert_allclose(unit([[3.0, 0.0, 4.0], [0.0, 0.0, 0.0]]), [[0.6, 0.0, 0.8], [0.0, 0.0, 0.0]])


def test_the_light_vector_of_a_spot_with_attenuation():
    """Spot at the origin aimed down −z, cone 30°, exponent 2, attenuation (1, .5, 0); points at distance 2:
    on the axis att = 1/2; 20° off it cos²20°/2; 40° off it 0. L points from each point to the light."""
    spot = EyeLight(position=np.zeros(3), direction=np.array([0.0, 0.0, -1.0]), positional=True,
                    cos_cone=math.cos(math.radians(30)), exponent=2.0, attenuation=np.array([1.0, 0.5, 0.0]))
    angles = np.radians([0.0, 20.0, 40.0])
    P = 2 * np.c_[np.sin(angles), np.zeros(3), -np.cos(angles)]
    L, att = light_vector(spot, P)
    np.testing.assert_allclose(L, -P / 2, atol=1e-15)
    np.testing.assert_allclose(att, [0.5, math.cos(angles[1]) ** 2 / 2, 0.0])


def test_the_glsl_light_vector_writes_the_same_formula():
    directional = glsl_light_vector(EyeLight(direction=np.array([0.0, 0.0, -1.0])))
    assert directional == "    L = -vec3(0, 0, -1); att = 1.0;\n"
    spot = glsl_light_vector(EyeLight(positional=True, cos_cone=0.5, exponent=2.0))
    assert "dist = length(L)" in spot and "att = cs >= 0.5 ? att * pow(cs, 2) : 0.0;" in spot
