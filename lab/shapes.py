"""Built-in shapes, in model space, each a function returning a :class:`lab.mesh.Mesh`.

All faces are counter-clockwise seen from outside (the course's orientation rule).
Shapes carry no normals unless stated: the renderers then shade each triangle with its
plane normal.
"""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh

PHI = (1.0 + 5.0 ** 0.5) / 2.0  # the golden ratio


def cube(size: float = 1.0) -> Mesh:
    """An axis-aligned cube of edge ``size`` centred at the origin: 8 points, 12 triangles.

    The face table follows the course's cube (six quads, counter-clockwise from outside),
    each quad split into two triangles.

    >>> cube().n_triangles
    12
    """
    h = size / 2.0
    pts = np.array([[x, y, z] for z in (-h, h) for y in (-h, h) for x in (-h, h)])
    # point index = x + 2y + 4z with x, y, z in {0, 1}
    quads = [
        (0, 2, 3, 1),  # z = -h, seen from -z
        (4, 5, 7, 6),  # z = +h
        (0, 1, 5, 4),  # y = -h
        (2, 6, 7, 3),  # y = +h
        (0, 4, 6, 2),  # x = -h
        (1, 3, 7, 5),  # x = +h
    ]
    tris = [(q[0], q[i], q[i + 1]) for q in quads for i in (1, 2)]
    return Mesh(pts, np.array(tris))


def quad(size: float = 1.0) -> Mesh:
    """A square of edge ``size`` in the z = 0 plane, centred at the origin, facing +z.

    >>> quad().n_triangles
    2
    """
    h = size / 2.0
    pts = np.array([[-h, -h, 0.0], [h, -h, 0.0], [h, h, 0.0], [-h, h, 0.0]])
    return Mesh(pts, np.array([[0, 1, 2], [0, 2, 3]]))


def _icosahedron_points_faces() -> tuple[np.ndarray, np.ndarray]:
    """The 12 golden-ratio vertices (0, ±1, ±φ) and cyclic shifts, and the 20 faces."""
    p = PHI
    pts = np.array([
        [-1, p, 0], [1, p, 0], [-1, -p, 0], [1, -p, 0],
        [0, -1, p], [0, 1, p], [0, -1, -p], [0, 1, -p],
        [p, 0, -1], [p, 0, 1], [-p, 0, -1], [-p, 0, 1],
    ], dtype=np.float64)
    faces = np.array([
        [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
        [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
        [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
        [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
    ])
    return pts, faces


def icosahedron(radius: float = 1.0) -> Mesh:
    """The regular icosahedron of the textbook, scaled to circumradius ``radius``.

    Vertices are the cyclic permutations of (0, ±1, ±φ); 20 outward faces.

    >>> icosahedron().n_triangles
    20
    """
    pts, faces = _icosahedron_points_faces()
    pts = pts / np.linalg.norm(pts[0]) * radius
    return Mesh(pts, faces)


def icosphere(level: int = 2, radius: float = 1.0) -> Mesh:
    """The textbook's subdivided icosahedron: 20·4^level faces on a sphere of ``radius``.

    Each triangle (a, b, c) is split into four, (a, ab, ca), (b, bc, ab), (c, ca, bc),
    (ab, bc, ca), and each new edge midpoint is pushed out onto the circumscribed sphere.
    Midpoints are shared between neighbouring triangles, so the surface stays closed.

    >>> icosphere(level=1).n_triangles
    80
    """
    mesh = icosahedron(radius)
    pts, tris = mesh.points, mesh.triangles
    for _ in range(int(level)):
        edges = np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]])
        keys = np.sort(edges, axis=1)
        uniq, inverse = np.unique(keys, axis=0, return_inverse=True)
        mid = (pts[uniq[:, 0]] + pts[uniq[:, 1]]) / 2.0
        mid *= radius / np.linalg.norm(mid, axis=1, keepdims=True)
        m = inverse.reshape(3, -1) + len(pts)  # rows: ab, bc, ca per triangle
        ab, bc, ca = m
        a, b, c = tris.T
        tris = np.concatenate([
            np.stack([a, ab, ca], axis=1), np.stack([b, bc, ab], axis=1),
            np.stack([c, ca, bc], axis=1), np.stack([ab, bc, ca], axis=1),
        ])
        pts = np.concatenate([pts, mid])
    return Mesh(pts, tris)


SHAPES = {"cube": cube, "quad": quad, "icosahedron": icosahedron, "icosphere": icosphere}
