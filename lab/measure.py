"""Measures of a triangle mesh: area, enclosed volume, and whether it is closed.

Closed and consistently oriented, here: after merging points at exactly equal positions,
every directed edge a→b is used as often as its reverse b→a. A closed two-manifold with
outward faces meets it with each edge used once each way; a Menger sponge, where four
faces meet at some edges, meets it too. The volume is the divergence theorem's
``Σ v0·(v1 × v2) / 6``, positive for outward faces.
"""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh


def surface_area(mesh: Mesh) -> float:
    """Sum of triangle areas, in squared model units."""
    p = mesh.points[mesh.triangles]
    return float(np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum() / 2.0)


def enclosed_volume(mesh: Mesh) -> float:
    """Signed volume by the divergence theorem (positive when faces point outward)."""
    p = mesh.points[mesh.triangles]
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0)


def welded_triangles(mesh: Mesh) -> np.ndarray:
    """Triangles re-indexed so that points at exactly the same position share one index."""
    _, inverse = np.unique(mesh.points, axis=0, return_inverse=True)
    return inverse.reshape(-1)[mesh.triangles]


def is_closed_and_oriented(mesh: Mesh) -> bool:
    """Every directed edge (after welding) is matched by as many reversed uses."""
    t = welded_triangles(mesh)
    t = t[(t[:, 0] != t[:, 1]) & (t[:, 1] != t[:, 2]) & (t[:, 2] != t[:, 0])]
    if len(t) == 0:
        return False
    edges = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    key = np.sort(edges, axis=1)
    sign = np.where(edges[:, 0] < edges[:, 1], 1, -1)
    uniq, inverse = np.unique(key, axis=0, return_inverse=True)
    balance = np.bincount(inverse.reshape(-1), weights=sign, minlength=len(uniq))
    return bool(np.all(balance == 0))


def mesh_summary(mesh: Mesh) -> dict:
    """Counts, bounds, area, volume and closedness of one mesh."""
    return {"points": mesh.n_points, "triangles": mesh.n_triangles, "bounds": mesh.bounds().tolist(),
            "area": surface_area(mesh), "volume": enclosed_volume(mesh),
            "closed_and_oriented": is_closed_and_oriented(mesh), "normals": mesh.point_normals is not None}
