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
