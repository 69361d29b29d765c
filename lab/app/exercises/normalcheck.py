"""Point normals of a round shape with smooth sides and flat caps (the cylinder, the cone),
judged point by point against the surface's own direction there.

A triangle is a *cap* triangle when its three corners lie on one cap's plane
(z = ±height/2), a *side* triangle otherwise. Then, over the points triangles use:

- every normal must be of length 1 (``normals-not-unit``);
- no point may belong to a cap and to the side (``caps-share-side-points``): one normal
  cannot be both (0, 0, ±1) and the side's;
- cap points carry (0, 0, ±1), the sign of their cap (``cap-normals-wrong``);
- side points carry the side's outward normal at their angle θ = atan2(y, x)
  (:attr:`RoundShape.side_normal`). Wrong ones are sorted by signature: pointing inward
  (``normals-inward``), equal to the flat normal of a side triangle they belong to
  (``side-faceted``), horizontal on a cone (``cone-normals-not-tilted``), or else
  ``side-normals-wrong``;
- an apex point (the cone's, one per side triangle or shared) has no single right
  normal: it passes when it is within one segment's turn (2π/segments) of the side's
  normal at an angle inside its triangles' span.

Points and normals are model-space row vectors.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding

UNIT_TOLERANCE = 1e-6
ANGLE_TOLERANCE = 1e-5  # radians


@dataclass(frozen=True)
class RoundShape:
    """segments, radius, height of the case; ``side_normal(θ)`` (K,) → (K, 3) unit normals;
    ``apex`` the apex position (a cone) or None; ``formula`` the side normal, as text."""

    segments: int
    radius: float
    height: float
    side_normal: Callable[[np.ndarray], np.ndarray]
    formula: str
    apex: tuple | None = None


def _fmt(v) -> str:
    return "(" + ", ".join(f"{x:.3g}" for x in np.ravel(v)) + ")"


def normal_findings(call: str, points: np.ndarray, tris: np.ndarray, normals: np.ndarray,
                    shape: RoundShape) -> list[Finding]:
    """Every normals finding of one case (see the module docstring)."""
    used = np.unique(tris)
    if not np.isfinite(normals[used]).all():
        return [Finding("nonfinite-values", {"case": call, "count": int((~np.isfinite(normals[used])).sum()),
                                             "what": "normal"})]
    found = []
    length = np.linalg.norm(normals, axis=1)
    off = used[np.abs(length[used] - 1.0) > UNIT_TOLERANCE]
    if off.size:
        found.append(Finding("normals-not-unit", {"case": call, "count": int(off.size), "example": int(off[0]),
                                                  "length": float(length[off[0]])}))
    unit = normals / np.maximum(length, 1e-300)[:, None]

    corners = points[tris]
    cross = np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
    plane = cross / np.maximum(np.linalg.norm(cross, axis=1), 1e-300)[:, None]
    h2, tol = shape.height / 2.0, 1e-9 * max(shape.height, shape.radius)
    z = corners[:, :, 2]
    cap = np.all(np.abs(z - h2) <= tol, axis=1) | np.all(np.abs(z + h2) <= tol, axis=1)
    cap_points, side_points = np.unique(tris[cap]), np.unique(tris[~cap])
    shared = np.intersect1d(cap_points, side_points)
    if shared.size:
        found.append(Finding("caps-share-side-points", {"case": call, "count": int(shared.size)}))

    caps_only = np.setdiff1d(cap_points, shared)
    want = np.zeros((len(caps_only), 3))
    want[:, 2] = np.sign(points[caps_only, 2])
    bad = caps_only[np.einsum("ij,ij->i", unit[caps_only], want) < 1.0 - UNIT_TOLERANCE]
    if bad.size:
        found.append(Finding("cap-normals-wrong", {"case": call, "count": int(bad.size), "sign": "+" if
                                                   points[bad[0], 2] > 0 else "−", "normal": _fmt(normals[bad[0]]),
                                                   "point": _fmt(points[bad[0]])}))

    side_only = np.setdiff1d(side_points, shared)
    at_apex = np.zeros(len(side_only), bool) if shape.apex is None else \
        np.linalg.norm(points[side_only] - np.asarray(shape.apex), axis=1) <= tol
    found += _side_findings(call, points, tris[~cap], plane[~cap], unit, side_only[~at_apex], shape)
    found += _apex_findings(call, points, tris[~cap], unit, side_only[at_apex], shape, found)
    return found


def _side_findings(call, points, side_tris, side_planes, unit, ring, shape) -> list[Finding]:
    theta = np.arctan2(points[ring, 1], points[ring, 0])
    want = shape.side_normal(theta)
    dot = np.einsum("ij,ij->i", unit[ring], want)
    wrong = dot < np.cos(ANGLE_TOLERANCE)
    if not wrong.any():
        return []
    found = []
    inward = wrong & (dot < -np.cos(ANGLE_TOLERANCE))
    faceted = wrong & ~inward & _matches_a_face(ring, unit, side_tris, side_planes)
    flat = np.column_stack([np.cos(theta), np.sin(theta), np.zeros_like(theta)])
    horizontal = wrong & ~inward & ~faceted & (shape.apex is not None) & \
        (np.einsum("ij,ij->i", unit[ring], flat) > np.cos(ANGLE_TOLERANCE))
    other = wrong & ~inward & ~faceted & ~horizontal
    if inward.any():
        found.append(Finding("normals-inward", {"case": call, "count": int(inward.sum())}))
    if faceted.any():
        found.append(Finding("side-faceted", {"case": call, "count": int(faceted.sum()), "formula": shape.formula}))
    if horizontal.any():
        found.append(Finding("cone-normals-not-tilted", {"case": call, "count": int(horizontal.sum())}))
    if other.any():
        k = np.flatnonzero(other)[0]
        found.append(Finding("side-normals-wrong", {"case": call, "count": int(other.sum()),
                                                    "normal": _fmt(unit[ring[k]]), "point": _fmt(points[ring[k]]),
                                                    "expected": _fmt(want[k])}))
    return found


def _matches_a_face(ring, unit, side_tris, side_planes) -> np.ndarray:
    """For each ring point, whether its normal is the plane normal of a side triangle using it."""
    corner_point = side_tris.ravel()
    corner_plane = np.repeat(side_planes, 3, axis=0)
    same = np.einsum("ij,ij->i", unit[corner_point], corner_plane) > np.cos(ANGLE_TOLERANCE)
    matched = np.zeros(unit.shape[0], bool)
    matched[corner_point[same]] = True
    return matched[ring]


def _apex_findings(call, points, side_tris, unit, apex_points, shape, found) -> list[Finding]:
    """Apex normals within one segment's turn of the side normal over their triangles' span."""
    if not apex_points.size:
        return []
    bad = []
    for p in apex_points:
        n = unit[p]
        azimuth = np.arctan2(n[1], n[0])
        ok = False
        for tri in side_tris[np.any(side_tris == p, axis=1)]:
            ring = [q for q in tri if q != p]
            a = np.arctan2(points[ring, 1], points[ring, 0])
            lo, span = a[0], (a[1] - a[0]) % (2 * np.pi)
            if span > np.pi:
                lo, span = a[1], 2 * np.pi - span
            d = (azimuth - lo) % (2 * np.pi)  # the normal's angle, clamped into [lo, lo + span]
            t = azimuth if d <= span else (lo if 2 * np.pi - d < d - span else lo + span)
            if np.dot(n, shape.side_normal(np.array([t]))[0]) >= np.cos(2 * np.pi / shape.segments + ANGLE_TOLERANCE):
                ok = True
                break
        if not ok:
            bad.append(p)
    if not bad or any(f.code in ("side-faceted", "normals-inward", "cone-normals-not-tilted", "side-normals-wrong")
                      for f in found):
        return []
    k = bad[0]
    return [Finding("side-normals-wrong", {"case": call, "count": len(bad), "normal": _fmt(unit[k]),
                                           "point": _fmt(points[k]), "expected": "a side normal at its angle"})]
