"""Plane normals of triangles (renderer/plane_normals.py): unit cross products, worked out for
the triangles asked for and no others."""
import numpy as np

from renderer.jit import njit
from renderer.plane_normals import corners_normal, face_normals, face_normals_of, plane_normal


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


@njit
def normals_from_corners(verts, triangles):
    out = np.empty((triangles.shape[0], 3))
    for t in range(triangles.shape[0]):
        out[t, 0], out[t, 1], out[t, 2] = corners_normal(verts, triangles, t)
    return out


def test_a_normal_worked_out_from_the_corners_has_the_bits_of_the_table():
    """corners_normal (the held colours' normal, read from the corners) gives every triangle
    the bits face_normals writes into its row, degenerate ones (zero) included."""
    rng = np.random.default_rng(5)
    verts = rng.uniform(-1.0, 1.0, (40, 3)) * rng.uniform(0.01, 100.0, (40, 1))
    triangles = np.array([rng.choice(40, 3, replace=False) for _ in range(300)] + [[0, 0, 1]])
    every = np.empty((len(triangles), 3))
    face_normals(verts, triangles, every)
    np.testing.assert_array_equal(normals_from_corners(verts, triangles), every)
    assert not every[-1].any()
