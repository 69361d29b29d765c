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

Polygons and triangle strips are triangulated once, here in ``lab/``, the way VTK's OpenGL
mapper (VTK 9.7) cuts them for drawing: a polygon as a fan from its first vertex (every
quad, even a concave one, and every polygon whose fan is sound; VTK cuts the others its own
way, which :func:`unfanned_polygons` finds so that readers can refuse them), a strip as
consecutive triangles with every second one's last two vertices swapped to keep the
winding. Both renderers then receive the very same triangles.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

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
        range, so an unreferenced point far away must not widen it. Worked out once per mesh
        (a mesh is not changed in place; VTK too keeps a polydata's bounds until it is
        modified): every frame without a clipping range asks for them, and for a mesh of
        134k points they took 9 ms a frame. Each call returns a fresh copy.
        """
        return self._bounds.copy()

    @cached_property
    def _bounds(self) -> np.ndarray:
        points = self.points
        if self.n_triangles:
            used = np.zeros(self.n_points, np.bool_)
            used[self.triangles.ravel()] = True
            points = points[used]
        lo = points.min(axis=0)
        hi = points.max(axis=0)
        return np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])


def fan_triangles(offsets, connectivity) -> np.ndarray:
    """Triangles of polygons stored as a VTK cell array, each cut as a fan from its first vertex.

    Parameters
    ----------
    offsets : (n + 1,) integer array; polygon i is ``connectivity[offsets[i]:offsets[i + 1]]``.
    connectivity : integer array of point indices.

    Returns
    -------
    (M, 3) int64 array; a polygon of k vertices gives k − 2 triangles ``(v0, v[j], v[j+1])``,
    j = 1 … k − 2, in order, so the winding is kept; polygons of fewer than 3 vertices
    give none. This is how VTK's OpenGL mapper draws every quad and every polygon whose
    fan is sound (checked by rendering; see :func:`unfanned_polygons` for the others).

    Examples
    --------
    >>> fan_triangles([0, 4, 7], [0, 1, 2, 3, 4, 5, 6]).tolist()
    [[0, 1, 2], [0, 2, 3], [4, 5, 6]]
    """
    offsets = np.asarray(offsets, dtype=np.int64)
    connectivity = np.asarray(connectivity, dtype=np.int64)
    if len(offsets) < 2:
        return np.zeros((0, 3), dtype=np.int64)
    sizes = np.diff(offsets)
    if (sizes == 3).all():  # triangles only: the cells themselves
        return connectivity[offsets[0]:offsets[-1]].reshape(-1, 3)
    per_polygon = np.maximum(sizes - 2, 0)
    first = np.repeat(offsets[:-1], per_polygon)  # where each triangle's polygon starts
    j = np.arange(len(first)) - np.repeat(np.cumsum(per_polygon) - per_polygon, per_polygon)
    return np.column_stack([connectivity[first], connectivity[first + 1 + j], connectivity[first + 2 + j]])


def strip_triangles(offsets, connectivity) -> np.ndarray:
    """Triangles of triangle strips stored as a VTK cell array, as VTK's mapper draws them.

    Parameters
    ----------
    offsets, connectivity : as for :func:`fan_triangles`, one strip per cell.

    Returns
    -------
    (M, 3) int64 array; a strip ``p0 p1 … p(k−1)`` gives k − 2 triangles, triangle j being
    ``(p[j], p[j+1], p[j+2])`` for even j and ``(p[j], p[j+2], p[j+1])`` for odd j, so
    all keep the winding of the first (``vtkOpenGLIndexBufferObject::AppendStripIndexBuffer``).

    Examples
    --------
    >>> strip_triangles([0, 5], [0, 1, 2, 3, 4]).tolist()
    [[0, 1, 2], [1, 3, 2], [2, 3, 4]]
    """
    offsets = np.asarray(offsets, dtype=np.int64)
    connectivity = np.asarray(connectivity, dtype=np.int64)
    if len(offsets) < 2:
        return np.zeros((0, 3), dtype=np.int64)
    per_strip = np.maximum(np.diff(offsets) - 2, 0)
    first = np.repeat(offsets[:-1], per_strip)
    j = np.arange(len(first)) - np.repeat(np.cumsum(per_strip) - per_strip, per_strip)
    odd = j % 2
    at = first + j
    return np.column_stack([connectivity[at], connectivity[at + 1 + odd], connectivity[at + 2 - odd]])


def unfanned_polygons(points, offsets, connectivity) -> np.ndarray:
    """Indices of the polygons of 5 vertices or more that VTK's mapper does not draw as a fan.

    VTK 9.7's mapper draws a triangle, a quad (even a concave one) and any polygon whose
    fan from its first vertex is sound as that fan (:func:`fan_triangles`); it cuts the
    other polygons of 5 vertices or more its own way, which none of ``vtkPolygon``'s
    triangulations reproduces (both found by rendering). A fan is sound when none of its
    triangles turns against the polygon: each triangle's normal has a positive part along
    the polygon's vector area (sum of ``p_i × p_{i+1}``; a flat triangle counts as sound).

    Examples
    --------
    >>> notch = [[0, 0, 0], [2, 0, 0], [1, 0.5, 0], [2, 2, 0], [0, 2, 0]]  # concave at point 2
    >>> unfanned_polygons(notch, [0, 5, 10], [0, 1, 2, 3, 4, 1, 2, 3, 4, 0]).tolist()
    [1]
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    offsets = np.asarray(offsets, dtype=np.int64)
    connectivity = np.asarray(connectivity, dtype=np.int64)
    sizes = np.diff(offsets)
    polygons = np.flatnonzero(sizes >= 5)
    if len(polygons) == 0:
        return polygons
    k = sizes[polygons]
    first = np.cumsum(k) - k  # where each polygon's corners start in the arrays below
    start = np.repeat(offsets[polygons], k)
    i = np.arange(k.sum()) - np.repeat(first, k)  # corner within its polygon
    here = points[connectivity[start + i]]
    after = points[connectivity[start + (i + 1) % np.repeat(k, k)]]
    area = np.add.reduceat(np.cross(here, after), first)  # the polygon's vector area (times 2)
    apex = here[np.repeat(first, k)]
    fan = np.cross(here - apex, after - apex)  # corner i's fan triangle (apex, i, i+1); zero at the ends
    along = np.einsum("ij,ij->i", fan, np.repeat(area, k, axis=0))
    scale = np.linalg.norm(fan, axis=1) * np.repeat(np.linalg.norm(area, axis=1), k)
    against = along < -1e-12 * scale
    return polygons[np.add.reduceat(against, first) > 0]
