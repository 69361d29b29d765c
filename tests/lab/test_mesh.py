"""The mesh model: bounds as VTK computes them."""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh


def test_bounds_leave_out_points_no_triangle_uses():
    """An unreferenced point far away is not in the bounds (vtkPolyData::ComputeBounds)."""
    m = Mesh(np.array([[50.0, -60.0, 70.0], [0, 0, 0], [1, 0, 0], [0, 2, 0]]), np.array([[1, 2, 3]]))
    np.testing.assert_array_equal(m.bounds(), [0, 1, 0, 2, 0, 0])


def test_bounds_of_a_mesh_without_triangles_use_every_point():
    m = Mesh(np.array([[1.0, 2.0, 3.0], [-1.0, 0.0, 5.0]]), np.zeros((0, 3), np.int64))
    np.testing.assert_array_equal(m.bounds(), [-1, 1, 0, 2, 3, 5])
