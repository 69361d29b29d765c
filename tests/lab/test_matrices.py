"""The course's row-vector matrices (P' = P @ M), checked by hand and against VTK."""
import os

import numpy as np
import pytest

from lab.matrices import model_matrix, rotation_x, rotation_y, rotation_z, scaling, translation


def apply(matrix, point):
    """One point through a row-vector matrix, back to 3D."""
    out = np.append(np.asarray(point, dtype=np.float64), 1.0) @ matrix
    return out[:3] / out[3]


def test_translation_sits_in_the_bottom_row():
    """T(tx, ty, tz) is the identity with (tx, ty, tz) in row 3, so [x, y, z, 1]·T adds the offset."""
    expected = np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [4, 5, 6, 1.0]])
    np.testing.assert_array_equal(translation(4, 5, 6), expected)
    np.testing.assert_array_equal(apply(translation(4, 5, 6), (1, 2, 3)), [5, 7, 9])


def test_scaling_is_diagonal():
    """S(sx, sy, sz) = diag(sx, sy, sz, 1) multiplies each coordinate."""
    np.testing.assert_array_equal(scaling(2, 3, 4), np.diag([2, 3, 4, 1.0]))
    np.testing.assert_array_equal(apply(scaling(2, 3, 4), (1, -1, 0.5)), [2, -3, 2])


@pytest.mark.parametrize("rotation, point, expected", [
    (rotation_z, (1, 0, 0), (0, 1, 0)),   # x → y about z
    (rotation_z, (0, 1, 0), (-1, 0, 0)),
    (rotation_x, (0, 1, 0), (0, 0, 1)),   # y → z about x
    (rotation_x, (0, 0, 1), (0, -1, 0)),
    (rotation_y, (0, 0, 1), (1, 0, 0)),   # z → x about y
    (rotation_y, (1, 0, 0), (0, 0, -1)),
])
def test_rotation_by_90_degrees_is_counter_clockwise_right_handed(rotation, point, expected):
    """A +90° rotation turns each axis into the next one (x→y→z→x), counter-clockwise seen from the axis tip."""
    np.testing.assert_allclose(apply(rotation(90), point), expected, atol=1e-15)


def test_rotation_z_matches_the_course_formula_at_30_degrees():
    """Rz(θ): x' = x·cos θ − y·sin θ, y' = x·sin θ + y·cos θ, z unchanged."""
    c, s = np.sqrt(3) / 2, 0.5
    np.testing.assert_allclose(apply(rotation_z(30), (2, 1, 7)), [2 * c - 1 * s, 2 * s + 1 * c, 7], atol=1e-15)


def test_rotation_x_and_y_match_the_course_formulas_at_30_degrees():
    """Rx: y' = y·cos − z·sin, z' = y·sin + z·cos; Ry: z' = z·cos − x·sin, x' = z·sin + x·cos."""
    c, s = np.sqrt(3) / 2, 0.5
    np.testing.assert_allclose(apply(rotation_x(30), (7, 2, 1)), [7, 2 * c - 1 * s, 2 * s + 1 * c], atol=1e-15)
    np.testing.assert_allclose(apply(rotation_y(30), (1, 7, 2)), [2 * s + 1 * c, 7, 2 * c - 1 * s], atol=1e-15)


def test_model_matrix_is_the_chain_S_Rx_Ry_Rz_T():
    """model_matrix(scale, rotate, translate) is exactly the product S·Rx·Ry·Rz·T."""
    expected = scaling(2, 3, 4) @ rotation_x(10) @ rotation_y(20) @ rotation_z(30) @ translation(1, 2, 3)
    np.testing.assert_array_equal(model_matrix((2, 3, 4), (10, 20, 30), (1, 2, 3)), expected)


def test_the_row_vector_chain_applies_scale_first_and_translation_last():
    """P·S·Rz·T with S = (2,1,1), Rz = 90°, T = (1,2,3): (1,0,0) → (2,0,0) → (0,2,0) → (1,4,3)."""
    m = model_matrix(scale=(2, 1, 1), rotate=(0, 0, 90), translate=(1, 2, 3))
    np.testing.assert_allclose(apply(m, (1, 0, 0)), [1, 4, 3], atol=1e-14)


def test_a_full_composite_by_hand():
    """S(2,3,4), Rx 90°, Rz 90°, T(10,20,30) on (1,1,1): S → (2,3,4); Rx → (2,−4,3); Rz → (4,2,3); T → (14,22,33)."""
    m = model_matrix(scale=(2, 3, 4), rotate=(90, 0, 90), translate=(10, 20, 30))
    np.testing.assert_allclose(apply(m, (1, 1, 1)), [14, 22, 33], atol=1e-13)


def test_rotation_order_is_x_then_y_then_z():
    """Rx 90° then Ry 90° sends y to z and then z to x: (0,1,0) → (0,0,1) → (1,0,0)."""
    np.testing.assert_allclose(apply(model_matrix(rotate=(90, 90, 0)), (0, 1, 0)), [1, 0, 0], atol=1e-15)


def test_our_matrix_is_the_transpose_of_vtks_column_vector_matrix():
    """vtkTransform (PostMultiply: Scale, RotateX, RotateY, RotateZ, Translate) builds the transpose of model_matrix."""
    os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
    import vtk

    scale, rotate, translate = (2.0, 0.5, 3.0), (30.0, -50.0, 70.0), (1.0, -2.0, 3.5)
    t = vtk.vtkTransform()
    t.PostMultiply()
    t.Scale(*scale)
    t.RotateX(rotate[0])
    t.RotateY(rotate[1])
    t.RotateZ(rotate[2])
    t.Translate(*translate)
    vtk_matrix = np.array([[t.GetMatrix().GetElement(i, j) for j in range(4)] for i in range(4)])
    np.testing.assert_allclose(model_matrix(scale, rotate, translate), vtk_matrix.T, atol=1e-14)
    # and VTK moves a point (as a column vector) where we move it (as a row vector)
    np.testing.assert_allclose(t.TransformPoint(1.0, 2.0, 3.0), apply(model_matrix(scale, rotate, translate), (1, 2, 3)),
                               atol=1e-13)
