"""The implicit test: a point is in a half-space where ``f(p) <= 0``, evaluated exactly.

These functions are the definition of a CSG solid (see :mod:`lab.csg.model` for each
``f``); the mesh of :mod:`lab.csg.meshing` approximates them, and tests compare the two.
Points are rows: an (M, 3) array, or anything that reshapes to one.
"""
from __future__ import annotations

import math

import numpy as np

from lab.csg.bounds import bounds
from lab.csg.model import HalfSpace, Node, Op, Primitive

__all__ = ["implicit_value", "boundary_distance", "inside", "monte_carlo_volume"]


def _points(points) -> np.ndarray:
    return np.asarray(points, dtype=np.float64).reshape(-1, 3)


def implicit_value(halfspace: HalfSpace, points) -> np.ndarray:
    """``f(p)`` of one half-space at each point, vectorised: (M, 3) -> (M,). Inside where <= 0."""
    p = _points(points)
    u = np.array(halfspace.direction)
    if halfspace.kind == "plane":
        return p @ u - halfspace.offset
    v = p - np.array(halfspace.point)
    if halfspace.kind == "sphere":
        return np.einsum("ij,ij->i", v, v) - halfspace.radius ** 2
    t = v @ u
    if halfspace.kind == "cylinder":
        return np.einsum("ij,ij->i", v, v) - t * t - halfspace.radius ** 2
    # cone
    return math.cos(halfspace.half_angle) * np.linalg.norm(v, axis=1) - t


def boundary_distance(halfspace: HalfSpace, points) -> np.ndarray:
    """Exact Euclidean distance from each point to the half-space's boundary surface (M,).

    Plane: ``|n . p - d|``; sphere: ``||p - c| - r|``; cylinder: ``|dist to axis - r|``;
    cone: distance to the nearest generator ray from the apex.
    """
    p = _points(points)
    u = np.array(halfspace.direction)
    if halfspace.kind == "plane":
        return np.abs(p @ u - halfspace.offset)
    v = p - np.array(halfspace.point)
    if halfspace.kind == "sphere":
        return np.abs(np.linalg.norm(v, axis=1) - halfspace.radius)
    t = v @ u
    rho = np.sqrt(np.maximum(np.einsum("ij,ij->i", v, v) - t * t, 0.0))
    if halfspace.kind == "cylinder":
        return np.abs(rho - halfspace.radius)
    # cone: in the (t, rho) half-plane the boundary is the ray s (cos a, sin a), s >= 0
    ca, sa = math.cos(halfspace.half_angle), math.sin(halfspace.half_angle)
    s = t * ca + rho * sa
    return np.where(s >= 0.0, np.abs(rho * ca - t * sa), np.hypot(t, rho))


def inside(node: Node, points) -> np.ndarray:
    """The implicit membership test, vectorised: (M, 3) points -> (M,) bool.

    Primitive: ``f <= 0`` for every half-space; union: any child; intersection: every
    child; difference: the first child and none of the rest.
    """
    p = _points(points)
    if isinstance(node, Primitive):
        result = np.ones(len(p), dtype=bool)
        for h in node.halfspaces:
            result &= implicit_value(h, p) <= 0.0
        return result
    if not isinstance(node, Op):
        raise TypeError(f"expected a Primitive or Op, got {type(node).__name__}")
    parts = [inside(c, p) for c in node.children]
    if node.kind == "union":
        return np.logical_or.reduce(parts)
    if node.kind == "intersection":
        return np.logical_and.reduce(parts)
    rest = np.logical_or.reduce(parts[1:]) if len(parts) > 1 else np.zeros(len(p), dtype=bool)
    return parts[0] & ~rest


def monte_carlo_volume(node: Node, n: int = 200_000, seed: int = 0) -> tuple[float, float]:
    """Volume of the implicit solid by uniform sampling of its bounds with :func:`inside`.

    Returns ``(volume, standard error)``; ``(0.0, 0.0)`` if the bounds are empty.
    """
    b = bounds(node)
    if b is None or n <= 0:
        return 0.0, 0.0
    lo, hi = b
    box_volume = float(np.prod(hi - lo))
    if box_volume == 0.0:
        return 0.0, 0.0
    rng = np.random.default_rng(seed)
    hits = 0
    done = 0
    while done < n:
        k = min(1_000_000, n - done)
        hits += int(inside(node, lo + (hi - lo) * rng.random((k, 3))).sum())
        done += k
    frac = hits / n
    return box_volume * frac, box_volume * math.sqrt(frac * (1.0 - frac) / n)
