"""Stage 1, model → world: points and normals through row-vector matrices."""
import numpy as np

from lab.matrices import model_matrix
from renderer.transform import normal_matrix, transform_points


def test_transform_points_appends_w_and_multiplies_on_the_right():
    """[x, y, z] → [x, y, z, 1] @ M, for every row."""
    m = model_matrix(scale=(2, 3, 4), translate=(1, 1, 1))
    np.testing.assert_array_equal(transform_points(np.array([[1.0, 1, 1], [0, 0, 0]]), m),
                                  [[3, 4, 5, 1], [1, 1, 1, 1]])


def test_normal_matrix_keeps_normals_perpendicular_under_non_uniform_scale():
    """n' = n·inverse-transpose(M₃ₓ₃) stays perpendicular to every transformed tangent t' = t·M₃ₓ₃."""
    m = model_matrix(scale=(3, 0.5, 2), rotate=(20, 40, -30), translate=(5, 6, 7))
    # the plane x + y + z = 0: normal (1,1,1), tangents (1,−1,0) and (0,1,−1)
    n = np.array([1.0, 1.0, 1.0]) @ normal_matrix(m)
    for t in ([1.0, -1.0, 0.0], [0.0, 1.0, -1.0]):
        assert abs(np.dot(n, np.array(t) @ m[:3, :3])) < 1e-12
    # carrying the normal with M itself would not do: the scale is non-uniform
    naive = np.array([1.0, 1.0, 1.0]) @ m[:3, :3]
    assert abs(np.dot(naive, np.array([1.0, -1.0, 0.0]) @ m[:3, :3])) > 0.1


def test_normal_matrix_by_hand_for_a_pure_scale():
    """For S = diag(2, 4, 8) the normal matrix is diag(1/2, 1/4, 1/8); translation does not enter it."""
    np.testing.assert_allclose(normal_matrix(model_matrix(scale=(2, 4, 8), translate=(9, 9, 9))),
                               np.diag([0.5, 0.25, 0.125]), atol=1e-15)
