"""Stage 1, model → world: points and normals through row-vector matrices."""
import contextlib

import numpy as np

from lab.matrices import model_matrix
from renderer.transform import normal_matrix, transform_points

from .single_thread import one_thread


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
    verts_view, verts_clip = np.empty((n, 3)), np.empty((n, 4))
    codes, expected = np.empty(n, np.uint8), np.empty(n, np.uint8)
    transform_vertices(points, model_to_view, view_to_clip, (0, 0), verts_view, verts_clip, codes,
                       np.empty((0, 3)), np.empty((0, 2), np.int64), np.empty(0, np.int64))
    outcodes(verts_clip, expected)
    np.testing.assert_array_equal(codes, expected)
    assert len(np.unique(codes)) > 8 and (codes == 0).any()


def test_the_vertices_mapped_in_the_transforms_loop_are_the_window_mappings_rows():
    """Given window tables with rows, each vertex is mapped to the window as it is transformed:
    the bits ``window_into`` gives for the clip-space rows written (points inside the view,
    outside it and behind the eye), on one thread and on two; the view and clip rows are those
    of the transform without the mapping."""
    from renderer.transform import transform_vertices
    from renderer.window import window_into

    rng = np.random.default_rng(4)
    points = rng.uniform(-3, 3, (5000, 3))
    model_to_view = model_matrix(translate=(0.2, -0.1, -4.0), rotate=(30.0, -15.0, 5.0), scale=(1.0, 1.5, 1.0))
    view_to_clip = np.array([[1.2, 0, 0, 0], [0, 1.6, 0, 0], [0, 0, -1.2, -1.0], [0, 0, -2.2, 0]])
    n = len(points)
    plain = np.empty((n, 3)), np.empty((n, 4)), np.empty(n, np.uint8)
    transform_vertices(points, model_to_view, view_to_clip, (0, 0), *plain, np.empty((0, 3)),
                       np.empty((0, 2), np.int64), np.empty(0, np.int64))
    expected = np.empty((n, 3)), np.empty((n, 2), np.int64), np.empty(n, np.int64)
    window_into(plain[1], 320, 200, *expected)
    assert (plain[2] != 0).any() and (plain[2] == 0).any() and (plain[1][:, 3] < 0).any()
    for threads in (one_thread, contextlib.nullcontext):
        got = np.empty((n, 3)), np.empty((n, 4)), np.empty(n, np.uint8)
        mapped = np.empty((n, 3)), np.empty((n, 2), np.int64), np.empty(n, np.int64)
        with threads():
            transform_vertices(points, model_to_view, view_to_clip, (320, 200), *got, *mapped)
        for a, b in zip(got + mapped, plain + expected):
            np.testing.assert_array_equal(a, b)


def test_normals_go_through_the_normal_matrix_and_a_mesh_without_them_gets_zeros():
    """``normals_to_view``: each row times the normal matrix (row vectors, summed in order x, y,
    z); with no normals given, every row zero."""
    from renderer.transform import normals_to_view

    rng = np.random.default_rng(6)
    normals = rng.normal(size=(300, 3))
    m = normal_matrix(model_matrix(scale=(3, 0.5, 2), rotate=(20, 40, -30)))
    out = np.full((300, 3), np.nan)
    normals_to_view(normals, m, out)
    expected = normals[:, :1] * m[0] + normals[:, 1:2] * m[1] + normals[:, 2:] * m[2]
    np.testing.assert_array_equal(out, expected)
    normals_to_view(np.empty((0, 3)), np.eye(3), out)
    assert not out.any()
