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


def test_transform_vertices_writes_each_vertex_outcode_as_the_clipper_works_it_out():
    """The outcodes worked out with the vertices are the clipper's own (renderer.clip.outcodes)
    of the clip-space positions written: points inside, beyond each plane, and on a plane."""
    from renderer.clip import outcodes
    from renderer.transform import transform_vertices

    rng = np.random.default_rng(2)
    points = np.concatenate([rng.uniform(-3, 3, (200, 3)), [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, -1.0]]])
    model_to_view = model_matrix(translate=(0.0, 0.0, -2.0), rotate=(10.0, 20.0, 0.0), scale=(1.0, 1.0, 1.0))
    view_to_clip = np.array([[1.0, 0, 0, 0], [0, 1.0, 0, 0], [0, 0, -1.5, -1.0], [0, 0, -2.5, 0]])
    n = len(points)
    verts_view, verts_clip, normals_view = np.empty((n, 3)), np.empty((n, 4)), np.empty((n, 3))
    codes, expected = np.empty(n, np.uint8), np.empty(n, np.uint8)
    transform_vertices(points, model_to_view, view_to_clip, np.empty((0, 3)), np.eye(3), verts_view, verts_clip,
                       normals_view, codes)
    outcodes(verts_clip, expected)
    np.testing.assert_array_equal(codes, expected)
    assert len(np.unique(codes)) > 8 and (codes == 0).any()
