"""The project's triangle mesh: what both renderers draw.

Conventions
-----------
- ``points`` are model-space positions, one row per point (row vectors, as in the
  course), float64.
- ``triangles`` index ``points``; a triangle is counter-clockwise when seen from the
  outside of a closed surface (the course's face orientation rule).
- ``point_normals`` are unit model-space normals, one per point, or ``None`` when the
  mesh has none (the renderers then use the plane normal of each triangle).
- ``tcoords`` are texture coordinates (s, t), one pair per point, or ``None``; (0, 0) is
  the bottom-left of a texture image and (1, 1) its top-right (OpenGL's convention).

Polygons are triangulated once, here in ``lab/``, by a fan from each polygon's first
vertex (what VTK's OpenGL mapper does for convex polygons), so both renderers receive the
very same triangles.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True, eq=False)
class Mesh:
    """A triangle mesh in model coordinates.

    Parameters
    ----------
    points : (N, 3) float64 array, model space.
    triangles : (M, 3) int64 array of point indices, counter-clockwise from outside.
    point_normals : (N, 3) float64 array of unit normals, or None.
    tcoords : (N, 2) float64 texture coordinates (s, t), or None.

    Examples
    --------
    >>> m = Mesh(np.zeros((3, 3)), np.array([[0, 1, 2]]))
    >>> m.n_triangles
    1
    """

    points: np.ndarray
    triangles: np.ndarray
    point_normals: np.ndarray | None = None
    tcoords: np.ndarray | None = None

    def __post_init__(self):
        object.__setattr__(self, "points", np.ascontiguousarray(self.points, dtype=np.float64).reshape(-1, 3))
        object.__setattr__(self, "triangles", np.ascontiguousarray(self.triangles, dtype=np.int64).reshape(-1, 3))
        if self.point_normals is not None:
            n = np.ascontiguousarray(self.point_normals, dtype=np.float64).reshape(-1, 3)
            object.__setattr__(self, "point_normals", n)
        if self.tcoords is not None:
            object.__setattr__(self, "tcoords", np.ascontiguousarray(self.tcoords, dtype=np.float64).reshape(-1, 2))

    @property
    def n_points(self) -> int:
        return len(self.points)

    @property
    def n_triangles(self) -> int:
        return len(self.triangles)

    def bounds(self) -> np.ndarray:
        """(xmin, xmax, ymin, ymax, zmin, zmax) of the points that triangles use, VTK's order.

        As ``vtkPolyData::ComputeBounds``: points no triangle references are left out (a
        mesh without triangles uses all its points). The bounds fit the camera's clipping
        range, so an unreferenced point far away must not widen it.
        """
        points = self.points
        if self.n_triangles:
            used = np.zeros(self.n_points, np.bool_)
            used[self.triangles.ravel()] = True
            points = points[used]
        lo = points.min(axis=0)
        hi = points.max(axis=0)
        return np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])


def fan_triangulate(polygons) -> np.ndarray:
    """Triangulate polygons by a fan from each one's first vertex.

    Parameters
    ----------
    polygons : iterable of sequences of point indices (3 or more each).

    Returns
    -------
    (M, 3) int64 array; a polygon of k vertices gives k - 2 triangles
    ``(v0, v[i], v[i+1])`` in order, so winding is kept.

    Examples
    --------
    >>> fan_triangulate([[0, 1, 2, 3]]).tolist()
    [[0, 1, 2], [0, 2, 3]]
    """
    tris = []
    for poly in polygons:
        poly = list(poly)
        for i in range(1, len(poly) - 1):
            tris.append((poly[0], poly[i], poly[i + 1]))
    return np.array(tris, dtype=np.int64).reshape(-1, 3)
