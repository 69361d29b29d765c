"""The mesh model: bounds as VTK computes them; polygons and strips cut into triangles as VTK draws them."""
from __future__ import annotations

from dataclasses import replace

import numpy as np

from lab.mesh import Mesh, fan_triangles, strip_triangles, unfanned_polygons


def test_bounds_leave_out_points_no_triangle_uses():
    """An unreferenced point far away is not in the bounds (vtkPolyData::ComputeBounds)."""
    m = Mesh(np.array([[50.0, -60.0, 70.0], [0, 0, 0], [1, 0, 0], [0, 2, 0]]), np.array([[1, 2, 3]]))
    np.testing.assert_array_equal(m.bounds(), [0, 1, 0, 2, 0, 0])


def test_bounds_of_a_mesh_without_triangles_use_every_point():
    m = Mesh(np.array([[1.0, 2.0, 3.0], [-1.0, 0.0, 5.0]]), np.zeros((0, 3), np.int64))
    np.testing.assert_array_equal(m.bounds(), [-1, 1, 0, 2, 3, 5])


# --------------------------------------------------------------------------- triangulation
def test_fan_triangles_by_hand():
    """Triangle, quad, pentagon and a 2-point cell: fans from each polygon's first vertex, in order."""
    offsets = [0, 3, 7, 12, 14]
    connectivity = [0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13]
    assert fan_triangles(offsets, connectivity).tolist() == [
        [0, 1, 2], [3, 4, 5], [3, 5, 6], [7, 8, 9], [7, 9, 10], [7, 10, 11]]


def test_fan_triangles_of_triangles_only_and_of_nothing():
    assert fan_triangles([0, 3, 6], [5, 6, 7, 7, 6, 8]).tolist() == [[5, 6, 7], [7, 6, 8]]
    assert fan_triangles([0], []).shape == (0, 3)
    assert fan_triangles([], []).shape == (0, 3)


def test_strip_triangles_by_hand():
    """Strip 0..5 and a strip of 3: every second triangle has its last two vertices swapped
    (VTK's index buffer order), so all keep the first one's winding."""
    tris = strip_triangles([0, 6, 9], [0, 1, 2, 3, 4, 5, 10, 11, 12])
    assert tris.tolist() == [[0, 1, 2], [1, 3, 2], [2, 3, 4], [3, 5, 4], [10, 11, 12]]
    points = np.array([[i // 2, i % 2, 0] for i in range(6)], dtype=float)  # a zig-zag in the plane z = 0
    p = points[tris[:4]]
    normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert (np.sign(normals[:, 2]) == np.sign(normals[0, 2])).all()


def test_unfanned_polygons_by_hand():
    """The rule found by rendering with VTK 9.7: a quad is always fanned; a polygon of 5 or
    more vertices is fanned when no fan triangle turns against it, concave or not."""
    notch = [[0, 0, 0], [2, 0, 0], [1, 0.5, 0], [2, 2, 0], [0, 2, 0], [2.5, 1, 0], [1, 0, 0]]
    offsets = [0, 5, 10, 14, 19, 24]
    connectivity = [0, 1, 2, 3, 4,  # concave at point 2, but the fan from point 0 is sound
                    1, 2, 3, 4, 0,  # the fan from point 1 has (1, 3, 4) turned against the polygon
                    1, 2, 3, 0,     # a concave quad (a dart): fanned all the same
                    0, 1, 5, 3, 4,  # convex
                    0, 6, 1, 3, 4]  # point 6 on the edge 0–1: a flat fan triangle is no fault
    assert unfanned_polygons(notch, offsets, connectivity).tolist() == [1]


def test_unfanned_polygons_in_any_plane():
    """Judged against the polygon's own vector area, whatever its orientation or winding."""
    notch = np.array([[0, 0, 0], [2, 0, 0], [1, 0.5, 0], [2, 2, 0], [0, 2, 0]], dtype=float)
    rotation = np.linalg.qr(np.random.default_rng(3).normal(size=(3, 3)))[0]
    points = notch @ rotation.T + [5, -2, 1]
    offsets = [0, 5, 10, 15, 20]
    connectivity = [0, 1, 2, 3, 4, 1, 2, 3, 4, 0, 0, 4, 3, 2, 1, 1, 0, 4, 3, 2]  # and both reversed, same apex
    assert unfanned_polygons(points, offsets, connectivity).tolist() == [1, 3]


def test_bounds_are_worked_out_once_and_handed_out_as_copies():
    m = Mesh(np.array([[0.0, 0, 0], [1, 0, 0], [0, 2, 0]]), np.array([[0, 1, 2]]))
    first = m.bounds()
    first[:] = 99.0  # a caller scribbling on its copy
    np.testing.assert_array_equal(m.bounds(), [0, 1, 0, 2, 0, 0])
    assert m.bounds() is not m.bounds()
    moved = replace(m, points=m.points + 1.0)  # a changed mesh is a new mesh, with its own bounds
    np.testing.assert_array_equal(moved.bounds(), [1, 2, 1, 3, 1, 1])
