"""Area, divergence-theorem volume and the closed-and-oriented test."""
from __future__ import annotations

import numpy as np

from lab.measure import enclosed_volume, is_closed_and_oriented, surface_area
from lab.mesh import Mesh
from lab.shapes import cube, icosphere, quad


def test_cube_area_and_volume():
    """A cube of edge 2: area 24, volume 8."""
    m = cube(2.0)
    assert surface_area(m) == 24.0 and abs(enclosed_volume(m) - 8.0) < 1e-12


def test_inward_faces_give_negative_volume_and_open_meshes_are_not_closed():
    """Flipped winding turns the volume negative; a quad is open; one flipped face breaks orientation."""
    m = icosphere(level=1)
    flipped = Mesh(m.points, m.triangles[:, ::-1])
    assert enclosed_volume(flipped) < 0 and is_closed_and_oriented(flipped)
    assert not is_closed_and_oriented(quad())
    broken = m.triangles.copy()
    broken[0] = broken[0, ::-1]
    assert not is_closed_and_oriented(Mesh(m.points, broken))


def test_duplicated_points_are_welded():
    """A cube whose triangles each own their points is still closed (points merged by position)."""
    c = cube()
    p = c.points[c.triangles].reshape(-1, 3)
    assert is_closed_and_oriented(Mesh(p, np.arange(len(p)).reshape(-1, 3)))
