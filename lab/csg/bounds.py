"""Axis-aligned bounds of a CSG tree, from linear programmes over its half-spaces.

Meshing needs a finite box to cut each primitive from, and the Monte Carlo volume a box
to sample; both come from here. Every half-space is replaced by linear constraints
``a . p <= b`` that every point of it satisfies (a plane by itself; a sphere by its
bounding box; a cylinder or cone by a polygon of RING sides around its axis), and the
extreme coordinates of a primitive are found by linear programming (scipy, imported
only when a bound is asked for). A primitive whose programme is unbounded is refused
with ``ValueError("primitive is unbounded ...")``.
"""
from __future__ import annotations

import math

import numpy as np

from lab.csg.model import HalfSpace, Node, Primitive

__all__ = ["RING", "bounds", "axis_frame", "outer_planes", "primitive_bounds"]

RING = 32
"""Sides of the polygons that outer-approximate cylinders and cones."""


def axis_frame(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors e1, e2 with (e1, e2, u) right-handed and orthonormal.

    For a coordinate axis u, e1 and e2 are coordinate axes too (tight bounds).
    """
    helper = np.zeros(3)
    helper[int(np.argmin(np.abs(u)))] = 1.0
    e1 = np.cross(u, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(u, e1)
    return e1, e2


def outer_planes(h: HalfSpace) -> list[tuple[np.ndarray, float]]:
    """Linear constraints ``a . p <= b`` satisfied by every point of the half-space."""
    u = np.array(h.direction)
    if h.kind == "plane":
        return [(u, h.offset)]
    q = np.array(h.point)
    if h.kind == "sphere":
        out = []
        for i in range(3):
            e = np.zeros(3)
            e[i] = 1.0
            out += [(e, q[i] + h.radius), (-e, -q[i] + h.radius)]
        return out
    e1, e2 = axis_frame(u)
    angles = 2 * np.pi * np.arange(RING) / RING
    ws = np.cos(angles)[:, None] * e1 + np.sin(angles)[:, None] * e2
    if h.kind == "cylinder":  # w . (p - q) <= rho <= r for every unit w perpendicular to u
        return [(w, float(w @ q) + h.radius) for w in ws]
    # cone: w . (p - a) <= rho <= tan(alpha) u . (p - a), and u . (p - a) >= 0
    k = math.tan(h.half_angle)
    out = [(w - k * u, float((w - k * u) @ q)) for w in ws]
    out.append((-u, float(-u @ q)))
    return out


def primitive_bounds(prim: Primitive) -> tuple[np.ndarray, np.ndarray] | None:
    """Tight axis-aligned bounds of one primitive by six linear programmes, or None if empty.

    Each programme minimises or maximises one coordinate subject to every outer
    constraint of :func:`outer_planes` (scipy's HiGHS). Raises ValueError if a coordinate
    is unbounded.
    """
    from scipy.optimize import linprog  # heavy: loaded when a tree is meshed or measured

    rows = [c for h in prim.halfspaces for c in outer_planes(h)]
    A = np.array([a for a, _ in rows])
    b = np.array([bb for _, bb in rows])
    lo, hi = np.empty(3), np.empty(3)
    for i in range(3):
        for sign, store in ((1.0, lo), (-1.0, hi)):
            c = np.zeros(3)
            c[i] = sign
            res = linprog(c, A_ub=A, b_ub=b, bounds=[(None, None)] * 3, method="highs")
            if res.status == 2:  # infeasible: the primitive is empty
                return None
            if res.status == 3:
                raise ValueError(
                    "primitive is unbounded: its half-spaces "
                    f"({', '.join(h.kind for h in prim.halfspaces)}) do not enclose a finite region"
                )
            if res.status != 0:
                raise RuntimeError(f"bounds of a primitive: linear programme failed ({res.message})")
            store[i] = sign * res.fun
    return lo, hi


def bounds(node: Node) -> tuple[np.ndarray, np.ndarray] | None:
    """Axis-aligned bounds ``(lo, hi)`` enclosing the node's solid, or None if it is surely empty.

    Exact for polytopes; for quadrics slightly loose (polygonal outer approximations).
    Raises ValueError if a primitive is unbounded.
    """
    if isinstance(node, Primitive):
        return primitive_bounds(node)
    boxes = [bounds(c) for c in node.children]
    if node.kind == "difference":
        return boxes[0]
    if node.kind == "union":
        boxes = [b for b in boxes if b is not None]
        if not boxes:
            return None
        return np.min([b[0] for b in boxes], axis=0), np.max([b[1] for b in boxes], axis=0)
    if any(b is None for b in boxes):
        return None
    lo = np.max([b[0] for b in boxes], axis=0)
    hi = np.min([b[1] for b in boxes], axis=0)
    return None if np.any(lo > hi) else (lo, hi)
