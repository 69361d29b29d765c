"""Plane normals of triangles (renderer/plane_normals.py): unit cross products, worked out for
the triangles asked for and no others."""
import numpy as np

from renderer.plane_normals import face_normals, face_normals_of, plane_normal


def test_plane_normal_is_the_unit_cross_product_and_zero_when_degenerate():
    """(1,0,0) − 0 × (0,2,0) − 0 = (0,0,2) → (0,0,1); three points on a line → 0."""
    n = np.empty(3)
    plane_normal(np.zeros(3), np.array([1.0, 0, 0]), np.array([0, 2.0, 0]), n)
    np.testing.assert_allclose(n, [0, 0, 1])
    plane_normal(np.zeros(3), np.array([1.0, 0, 0]), np.array([2.0, 0, 0]), n)
    np.testing.assert_allclose(n, [0, 0, 0])


def test_the_normals_asked_for_are_those_of_all_and_the_other_rows_are_left_alone():
    """face_normals_of writes the rows of the triangles ``which`` names (repeats allowed), with
    the bits face_normals gives them; the other rows keep what they held."""
    rng = np.random.default_rng(2)
    verts = rng.uniform(-1.0, 1.0, (50, 3))
    triangles = np.array([rng.choice(50, 3, replace=False) for _ in range(200)])
    every = np.empty((200, 3))
    face_normals(verts, triangles, every)
    assert np.allclose(np.linalg.norm(every, axis=1), 1.0)
    some = np.full((200, 3), np.nan)
    which = np.array([3, 150, 3, 7, 199, 0], np.int64)
    face_normals_of(verts, triangles, which, some)
    np.testing.assert_array_equal(some[which], every[which])
    assert np.isnan(np.delete(some, which, axis=0)).all()
