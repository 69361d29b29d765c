"""Specification of ``lab.meshfiles.validate.make_mesh``: the one place a read mesh is checked."""
from __future__ import annotations

import numpy as np
import pytest

from lab.meshfiles.validate import make_mesh

TRI = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float32)


def test_types_and_unit_normals():
    m = make_mesh(TRI, [[0, 1, 2]], normals=np.array([[0, 0, 2], [0, 3, 0], [0, 0, 0]], np.float32),
                  tcoords=np.zeros((3, 2), np.float32))
    assert m.points.dtype == m.point_normals.dtype == m.tcoords.dtype == np.float64
    assert m.triangles.dtype == np.int64
    np.testing.assert_array_equal(m.point_normals, [[0, 0, 1], [0, 1, 0], [0, 0, 0]])  # zero stays zero
    m = make_mesh(TRI, [[0, 1, 2]], normals=np.array([[0, 0, 2], [0, 3, 0], [4, 0, 0]], np.float32))
    np.testing.assert_array_equal(m.point_normals, [[0, 0, 1], [0, 1, 0], [1, 0, 0]])


def test_the_readers_arrays_are_left_alone():
    normals = np.array([[0, 0, 2.0]] * 3)
    make_mesh(TRI, [[0, 1, 2]], normals=normals)
    assert normals[0, 2] == 2.0


@pytest.mark.parametrize("args, words", [
    ((np.array([[0, 0, np.nan], [1, 0, 0], [0, 1, 0]]), [[0, 1, 2]]), "point coordinates contain NaN"),
    ((TRI * 1e16, [[0, 1, 2]]), "beyond"),
    ((TRI, np.zeros((0, 3))), "no triangles"),
    ((TRI, [[0, 1, 3]]), "point index 3 out of range (there are 3 points)"),
    ((TRI, [[0, -1, 2]]), "point index -1 out of range"),
])
def test_refused(args, words):
    with pytest.raises(ValueError) as info:
        make_mesh(*args)
    assert words in str(info.value)


def test_refused_normals_and_tcoords():
    with pytest.raises(ValueError, match="2 normals for 3 points"):
        make_mesh(TRI, [[0, 1, 2]], normals=np.zeros((2, 3)))
    with pytest.raises(ValueError, match="normals contain NaN"):
        make_mesh(TRI, [[0, 1, 2]], normals=np.full((3, 3), np.inf))
    with pytest.raises(ValueError, match="2 texture coordinates for 3 points"):
        make_mesh(TRI, [[0, 1, 2]], tcoords=np.zeros((2, 2)))
    with pytest.raises(ValueError, match="texture coordinates contain NaN"):
        make_mesh(TRI, [[0, 1, 2]], tcoords=np.full((3, 2), np.nan))
