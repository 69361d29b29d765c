"""Geometry judged as geometry: a student's (points, triangles) against what the surface must be.

Any point order and any valid triangulation of the right surface passes: nothing here
compares arrays with the reference's arrays. What is measured, in this order (a case
stops at the first group that makes the rest meaningless):

1. values: triangles at all, not too many, finite coordinates, indices in range;
2. triangles with no area (reported, then left out);
3. the exercise's own early check (e.g. the fractal's scale factor from its edge lengths,
   the icosphere's points on the sphere);
4. size and place: the bounding box against the expected one (relative 1e-6);
5. closure: after merging points at equal positions every edge must be used by an even
   number of triangles; if only a tolerance closes it, the points were not merged and
   differ (cracks); if the exercise wants shared points, unmerged ones are reported;
6. orientation: every triangle is probed just off its face, on both sides, with the
   exercise's inside test — outward (the solid behind it), inward, inside the solid on
   both sides (an internal face) or outside on both (a stray face);
7. volume (divergence theorem) and area against the formulas; a wrong volume is first
   offered to the exercise's ``explain`` (e.g. the Menger sponge's sub-cube count);
8. the triangle count, where the surface fixes it.

Points are row vectors in model units; triangles are counter-clockwise seen from outside.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding
from lab.mesh import Mesh
from lab.measure import enclosed_volume, surface_area

OUTWARD, INWARD, INTERNAL, STRAY = 1, -1, 0, 2
"""Codes of :attr:`Expected.outward` for each triangle."""

RTOL = 1e-6


@dataclass(frozen=True)
class Expected:
    """What one case's surface must be.

    bounds : (xmin, xmax, ymin, ymax, zmin, zmax) of the points triangles use.
    area, volume : the formulas' values (squared and cubed model units).
    outward : (probe points (T, 3) inside the triangles, unit normals (T, 3)) → (T,) codes
        :data:`OUTWARD`, :data:`INWARD`, :data:`INTERNAL` or :data:`STRAY`.
    triangles : the exact triangle count where the surface fixes it, else None.
    merged : True when triangles must share the indices of their common points.
    max_triangles : more than this is refused before anything is measured.
    early : (call, points, triangles) → findings that stop the case (step 3), or None.
    explain : (call, measured volume) → findings explaining a wrong volume, or None.
    """

    bounds: np.ndarray
    area: float
    volume: float
    outward: Callable[[np.ndarray, np.ndarray], np.ndarray]
    triangles: int | None = None
    merged: bool = False
    max_triangles: int = 2_000_000
    early: Callable | None = None
    explain: Callable | None = None


def convex_outward(centre=(0.0, 0.0, 0.0)) -> Callable:
    """The inside test of a convex solid around ``centre``: outward when n·(p − centre) > 0."""
    c = np.asarray(centre, dtype=np.float64)

    def outward(probes, normals):
        side = np.einsum("ij,ij->i", normals, probes - c)
        return np.where(side > 0, OUTWARD, INWARD)

    return outward


def probe_outward(inside: Callable[[np.ndarray], np.ndarray], step: float) -> Callable:
    """Outward codes from an inside test of the solid: probe ``step`` off each face on both sides."""

    def outward(probes, normals):
        front, back = inside(probes + step * normals), inside(probes - step * normals)
        return np.select([~front & back, front & ~back, front & back], [OUTWARD, INWARD, INTERNAL], STRAY)

    return outward


def _fmt(v) -> str:
    return "(" + ", ".join(f"{x:.4g}" for x in np.ravel(v)) + ")"


def edge_use_counts(tris: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Undirected edges (E, 2) of the triangles and how many triangles use each."""
    edges = np.sort(np.concatenate([tris[:, [0, 1]], tris[:, [1, 2]], tris[:, [2, 0]]]), axis=1)
    return np.unique(edges, axis=0, return_counts=True)


def _weld(points: np.ndarray, tris: np.ndarray) -> np.ndarray:
    """Triangles re-indexed so that points at exactly one position share an index."""
    _, inverse = np.unique(points, axis=0, return_inverse=True)
    return inverse.reshape(-1)[tris]


def _weld_within(points: np.ndarray, tris: np.ndarray, tolerance: float) -> tuple[np.ndarray, float]:
    """Triangles re-indexed so that points closer than ``tolerance`` (chains of them) share an
    index, and the largest distance between two points so merged."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    pairs = cKDTree(points).query_pairs(tolerance, output_type="ndarray")
    n = len(points)
    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    gap = float(np.linalg.norm(points[pairs[:, 0]] - points[pairs[:, 1]], axis=1).max()) if len(pairs) else 0.0
    return label[tris], gap


def values_findings(call: str, points: np.ndarray, tris: np.ndarray, max_triangles: int) -> list[Finding]:
    """Step 1: the arrays are a mesh at all."""
    n = len(points)
    if len(tris) == 0:
        return [Finding("no-triangles", {"case": call})]
    if len(tris) > max_triangles:
        return [Finding("too-many-triangles", {"case": call, "count": len(tris), "limit": max_triangles})]
    bad = ~np.isfinite(points)
    if bad.any():
        return [Finding("nonfinite-values", {"case": call, "count": int(bad.sum()), "what": "point"})]
    out = (tris < 0) | (tris >= n)
    if out.any():
        return [Finding("index-out-of-range", {"case": call, "count": int(out.sum()), "example": int(tris[out][0]),
                                               "n_points": n, "last": n - 1})]
    return []


def mesh_findings(call: str, points: np.ndarray, tris: np.ndarray, exp: Expected) -> list[Finding]:
    """Every finding for one case (see the module docstring)."""
    points = np.asarray(points, np.float64).reshape(-1, 3)
    tris = np.asarray(tris).astype(np.int64).reshape(-1, 3)
    found = values_findings(call, points, tris, exp.max_triangles)
    if found:
        return found
    corners = points[tris]
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    length = np.linalg.norm(cross, axis=1)
    size = float(np.max(exp.bounds[1::2] - exp.bounds[0::2]))
    flat = (length <= 1e-12 * size * size) | (tris[:, 0] == tris[:, 1]) | (tris[:, 1] == tris[:, 2]) | \
           (tris[:, 2] == tris[:, 0])
    if flat.all():
        return found + [Finding("no-triangles", {"case": call})]
    if flat.any():
        found.append(Finding("degenerate-triangles", {"case": call, "count": int(flat.sum()),
                                                      "example": int(np.flatnonzero(flat)[0])}))
    tris, cross, length = tris[~flat], cross[~flat], length[~flat]

    if exp.early is not None:
        early = exp.early(call, points, tris)
        if early:
            return found + early
    b = Mesh(points, tris).bounds()
    extent, expected_extent = b[1::2] - b[0::2], exp.bounds[1::2] - exp.bounds[0::2]
    if not np.allclose(extent, expected_extent, rtol=RTOL, atol=RTOL * size):
        factor = float(np.max(extent) / np.max(expected_extent))
        return found + [Finding("wrong-scale", {"case": call, "size": _fmt(extent), "expected": _fmt(expected_extent),
                                                "factor": factor})]
    centre, expected_centre = (b[1::2] + b[0::2]) / 2, (exp.bounds[1::2] + exp.bounds[0::2]) / 2
    if not np.allclose(centre, expected_centre, atol=RTOL * size):
        return found + [Finding("not-centred", {"case": call, "centre": _fmt(centre),
                                                "expected": _fmt(expected_centre)})]
    closure = closure_findings(call, points, tris, exp.merged, size)
    found += closure
    if any(f.code in ("not-closed", "cracks") for f in closure):
        return found

    normals = cross / length[:, None]
    probes = np.einsum("tcx,c->tx", corners[~flat], [0.23, 0.31, 0.46])  # a point inside each triangle
    codes = exp.outward(probes, normals)
    inward = int(np.count_nonzero(codes == INWARD))
    if inward:
        found.append(Finding("faces-inward", {"case": call, "count": inward, "total": len(tris)}))
    mesh = Mesh(points, tris)
    volume = enclosed_volume(mesh)
    if not inward and not np.isclose(volume, exp.volume, rtol=RTOL, atol=RTOL * size ** 3):
        explained = exp.explain(call, volume) if exp.explain is not None else []
        if explained:
            return found + explained
        found.append(Finding("wrong-volume", {"case": call, "volume": volume, "expected": exp.volume}))
    internal, stray = int(np.count_nonzero(codes == INTERNAL)), int(np.count_nonzero(codes == STRAY))
    if internal:
        _, uses = edge_use_counts(_weld(points, tris))
        found.append(Finding("internal-faces-kept", {"case": call, "count": internal,
                                                     "edges": int(np.count_nonzero(uses >= 4))}))
    if stray:
        found.append(Finding("stray-faces", {"case": call, "count": stray}))
    area = surface_area(mesh)
    if not internal and not np.isclose(area, exp.area, rtol=RTOL, atol=RTOL * size ** 2):
        found.append(Finding("wrong-area", {"case": call, "area": area, "expected": exp.area}))
    if not found and exp.triangles is not None and len(tris) != exp.triangles:
        found.append(Finding("wrong-triangle-count", {"case": call, "count": len(tris), "expected": exp.triangles}))
    return found


def closure_findings(call: str, points: np.ndarray, tris: np.ndarray, merged: bool, size: float) -> list[Finding]:
    """Step 5: holes, cracks and unmerged points.

    Points closer than 1e-9 of the shape's size count as one place (a sine that is 1e-16
    instead of 0 is no crack). If the edges then do not pair up but do once points
    within 1e-3 of the size are merged, the surface has cracks; otherwise holes.
    """
    welded, _ = _weld_within(points, tris, 1e-9 * size)
    edges, uses = edge_use_counts(welded)
    odd = uses % 2 == 1
    if odd.any():
        loose, gap = _weld_within(points, tris, 1e-3 * size)
        _, loose_uses = edge_use_counts(loose)
        if not (loose_uses % 2 == 1).any():
            return [Finding("cracks", {"case": call, "count": int(odd.sum()), "gap": gap})]
        first = edges[np.flatnonzero(odd)[0]]
        a = points[tris.ravel()[np.flatnonzero(welded.ravel() == first[0])[0]]]
        b = points[tris.ravel()[np.flatnonzero(welded.ravel() == first[1])[0]]]
        return [Finding("not-closed", {"case": call, "count": int(odd.sum()), "a": _fmt(a), "b": _fmt(b)})]
    used = np.unique(tris)
    distinct = len(np.unique(welded))
    if merged and len(used) > distinct:
        return [Finding("points-not-merged", {"case": call, "points": len(used), "expected": distinct})]
    return []
