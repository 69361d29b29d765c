"""Constructive solid geometry (CSG): the course's implicit definition, meshed with manifold3d.

The course's definition
-----------------------
A *half-space* is the set of points where an implicit function is not positive,
``f(x, y, z) <= 0``. Four kinds are used (``p`` a point, all vectors as rows):

=========  ==========================================  ===============================
kind       f(p)                                        parameters
=========  ==========================================  ===============================
plane      ``n . p - d``                               unit normal ``n``, offset ``d``
sphere     ``|p - c|^2 - r^2``                         centre ``c``, radius ``r``
cylinder   ``|p - q|^2 - (u . (p - q))^2 - r^2``       axis point ``q``, unit axis
           (squared distance to the axis, minus r^2)   ``u``, radius ``r`` (infinite)
cone       ``cos(a) |p - a0| - u . (p - a0)``          apex ``a0``, unit axis ``u``,
           (one nappe, opening towards +u)             half-angle ``a`` in (0, 90 deg)
=========  ==========================================  ===============================

A *primitive* is the intersection of its half-spaces, e.g. the course's cylinder is
``{x^2 + y^2 - r^2 <= 0, z - h <= 0, -z <= 0}``. A CSG *tree* combines primitives by
``union`` (in any child), ``intersection`` (in every child) and ``difference`` (in the
first child and in none of the others). These implicit functions are the definition:
:func:`inside` evaluates them exactly, point by point.

How the mesh is made
--------------------
VTK's boolean filters are known to fail on such trees, so the surface is built with
manifold3d, whose booleans are robust and always return a closed, oriented 2-manifold:

1. each primitive must be bounded; its axis-aligned bounds come from a small linear
   programme over its planes and polygonal outer approximations of its quadrics
   (``ValueError("... primitive is unbounded ...")`` otherwise);
2. a cube slightly larger than those bounds is cut by each plane
   (``Manifold.trim_by_plane``, which keeps ``normal . p >= offset``, so it is given
   ``-n`` and ``-d`` to keep ``n . p <= d``) and intersected with a tessellated sphere,
   a long tessellated cylinder or a tall tessellated cone for each quadric half-space;
3. the primitives are combined with manifold's ``+`` (union), ``-`` (difference) and
   ``^`` (intersection); :func:`to_mesh` returns the result as a :class:`lab.mesh.Mesh`
   whose triangles are counter-clockwise seen from outside (positive divergence-theorem
   volume, see :func:`mesh_volume`).

The mesh approximates the quadrics
----------------------------------
Planes are reproduced exactly (up to rounding). Spheres, cylinders and cones are
polyhedra with ``segments`` edges around each circle and their vertices *on* the
quadric surface, so the tessellated solid lies slightly inside the true quadric: by the
sagitta ``r (1 - cos(pi / segments))`` for a circle of radius ``r`` (about
``1.2e-3 r`` at the default 64 segments; a little more in the middle of a sphere's
geodesic triangles). Volumes therefore converge to the implicit solid's volume (see
:func:`monte_carlo_volume`) as ``segments`` grows; points farther than a few sagittas
from every surface are classified identically by the mesh and by :func:`inside`.
"""
from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from functools import reduce
from typing import Union

import numpy as np

from lab.mesh import Mesh
from lab.values import MAX_MAGNITUDE, real, show

__all__ = [
    "HalfSpace", "Primitive", "Op", "Node",
    "box", "sphere", "cylinder", "cone",
    "implicit_value", "boundary_distance", "inside", "bounds",
    "to_manifold", "to_mesh", "from_dict", "monte_carlo_volume", "mesh_volume",
    "HALFSPACE_KINDS", "OP_KINDS", "PRIMITIVE_NAMES",
]

HALFSPACE_KINDS = ("plane", "sphere", "cylinder", "cone")
OP_KINDS = ("union", "difference", "intersection")
PRIMITIVE_NAMES = ("box", "sphere", "cylinder", "cone", "halfspaces")

_AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}


def _vec3(v, what: str) -> tuple[float, float, float]:
    a = np.asarray(v, dtype=np.float64).reshape(-1)
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{what} must be 3 finite numbers, got {v!r}")
    return (float(a[0]), float(a[1]), float(a[2]))


def _unit(v, what: str) -> tuple[float, float, float]:
    a = np.array(_vec3(v, what))
    n = float(np.linalg.norm(a))
    if n == 0.0:
        raise ValueError(f"{what} must not be the zero vector")
    return tuple(float(x) for x in a / n)


# --------------------------------------------------------------------------- the tree

@dataclass(frozen=True)
class HalfSpace:
    """One implicit half-space ``f(p) <= 0`` (see the module docstring for each ``f``).

    A plain description, no callables. Use the constructors :meth:`plane`,
    :meth:`sphere`, :meth:`cylinder` and :meth:`cone`.

    Fields
    ------
    kind : "plane", "sphere", "cylinder" or "cone".
    point : sphere centre, a point on the cylinder's axis, or the cone's apex (unused
        for planes).
    direction : plane normal, cylinder axis or cone axis; stored as a unit vector (a
        plane's offset is divided by the same length, so ``n . p - d <= 0`` is the same
        set and ``f`` becomes the signed distance).
    offset : the plane's ``d``.
    radius : sphere or cylinder radius.
    half_angle : the cone's half-angle in radians, strictly between 0 and pi/2.

    >>> HalfSpace.plane((2, 0, 0), 1.0).offset
    0.5
    """

    kind: str
    point: tuple = (0.0, 0.0, 0.0)
    direction: tuple = (0.0, 0.0, 1.0)
    offset: float = 0.0
    radius: float = 0.0
    half_angle: float = 0.0

    def __post_init__(self):
        if self.kind not in HALFSPACE_KINDS:
            raise ValueError(f"unknown half-space kind {self.kind!r}; valid: {', '.join(HALFSPACE_KINDS)}")
        set_ = lambda k, v: object.__setattr__(self, k, v)  # noqa: E731
        set_("point", _vec3(self.point, f"{self.kind} point"))
        raw = np.array(_vec3(self.direction, f"{self.kind} direction"))
        length = float(np.linalg.norm(raw))
        if length == 0.0:
            raise ValueError(f"{self.kind} direction must not be the zero vector")
        set_("direction", tuple(float(x) for x in raw / length))
        for name in ("offset", "radius", "half_angle"):
            v = float(getattr(self, name))
            if not math.isfinite(v):
                raise ValueError(f"{self.kind} {name} must be finite, got {v!r}")
            set_(name, v)
        if self.kind == "plane":
            set_("offset", self.offset / length)
        if self.kind in ("sphere", "cylinder") and not self.radius > 0.0:
            raise ValueError(f"{self.kind} radius must be positive, got {self.radius!r}")
        if self.kind == "cone" and not 0.0 < self.half_angle < math.pi / 2:
            raise ValueError(f"cone half_angle must be in (0, pi/2) radians, got {self.half_angle!r}")

    @classmethod
    def plane(cls, normal, offset: float) -> "HalfSpace":
        """``normal . p - offset <= 0``."""
        return cls("plane", direction=normal, offset=offset)

    @classmethod
    def sphere(cls, center, radius: float) -> "HalfSpace":
        """``|p - center|^2 - radius^2 <= 0``."""
        return cls("sphere", point=center, radius=radius)

    @classmethod
    def cylinder(cls, point, axis, radius: float) -> "HalfSpace":
        """Infinite cylinder: squared distance to the line ``point + t axis``, minus radius^2, <= 0."""
        return cls("cylinder", point=point, direction=axis, radius=radius)

    @classmethod
    def cone(cls, apex, axis, half_angle: float) -> "HalfSpace":
        """One-nappe infinite cone opening along +axis: ``cos(a)|p - apex| - axis . (p - apex) <= 0``."""
        return cls("cone", point=apex, direction=axis, half_angle=half_angle)


@dataclass(frozen=True)
class Primitive:
    """The intersection of its half-spaces (at least one)."""

    halfspaces: tuple

    def __post_init__(self):
        hs = tuple(self.halfspaces)
        if not hs:
            raise ValueError("a primitive needs at least one half-space")
        for h in hs:
            if not isinstance(h, HalfSpace):
                raise TypeError(f"a primitive holds HalfSpace objects, got {type(h).__name__}")
        object.__setattr__(self, "halfspaces", hs)


@dataclass(frozen=True)
class Op:
    """A boolean operation on child nodes.

    ``union``: in any child; ``intersection``: in every child; ``difference``: in the
    first child and in none of the rest (the first minus the union of the rest).
    """

    kind: str
    children: tuple

    def __post_init__(self):
        if self.kind not in OP_KINDS:
            raise ValueError(f"unknown op {self.kind!r}; valid: {', '.join(OP_KINDS)}")
        ch = tuple(self.children)
        if not ch:
            raise ValueError(f"op {self.kind!r} needs at least one child")
        for c in ch:
            if not isinstance(c, (Primitive, Op)):
                raise TypeError(f"op children are Primitive or Op nodes, got {type(c).__name__}")
        object.__setattr__(self, "children", ch)


Node = Union[Primitive, Op]


# ------------------------------------------------------------- convenience primitives

def _axis_vector(axis) -> np.ndarray:
    if isinstance(axis, str):
        if axis not in _AXES:
            raise ValueError(f"axis must be 'x', 'y', 'z' or a 3-vector, got {axis!r}")
        return np.array(_AXES[axis])
    return np.array(_unit(axis, "axis"))


def _positive(v, what: str) -> float:
    v = float(v)
    if not (math.isfinite(v) and v > 0.0):
        raise ValueError(f"{what} must be a positive number, got {v!r}")
    return v


def box(size=(1.0, 1.0, 1.0), center=(0.0, 0.0, 0.0)) -> Primitive:
    """An axis-aligned box: six planes ``+-(p_i - c_i) - size_i / 2 <= 0``.

    ``size`` is 3 edge lengths or one number (a cube).
    """
    s = np.broadcast_to(np.asarray(size, dtype=np.float64), (3,))
    for i in range(3):
        _positive(s[i], "box size")
    c = np.array(_vec3(center, "box center"))
    hs = []
    for i in range(3):
        e = np.zeros(3)
        e[i] = 1.0
        hs.append(HalfSpace.plane(e, c[i] + s[i] / 2))
        hs.append(HalfSpace.plane(-e, -(c[i] - s[i] / 2)))
    return Primitive(tuple(hs))


def sphere(radius: float = 0.5, center=(0.0, 0.0, 0.0)) -> Primitive:
    """A ball: one sphere half-space."""
    return Primitive((HalfSpace.sphere(center, _positive(radius, "sphere radius")),))


def cylinder(radius: float = 0.5, height: float = 1.0, center=(0.0, 0.0, 0.0), axis="z") -> Primitive:
    """A solid cylinder as the course writes it: an infinite cylinder and two end planes.

    ``center`` is the middle of the axis segment; ``axis`` is "x", "y", "z" or a vector.
    """
    r = _positive(radius, "cylinder radius")
    h = _positive(height, "cylinder height")
    u = _axis_vector(axis)
    c = np.array(_vec3(center, "cylinder center"))
    t = float(u @ c)
    return Primitive((
        HalfSpace.cylinder(c, u, r),
        HalfSpace.plane(u, t + h / 2),       # u.p <= u.c + h/2
        HalfSpace.plane(-u, -(t - h / 2)),   # u.p >= u.c - h/2
    ))


def cone(radius: float = 0.5, height: float = 1.0, center=(0.0, 0.0, 0.0), axis="z") -> Primitive:
    """A solid right circular cone: a cone half-space and its base plane, apex at the top.

    The apex is at ``center + height/2 * axis``, the base disc (``radius``) at
    ``center - height/2 * axis``; the half-angle is ``atan(radius / height)``.
    """
    r = _positive(radius, "cone radius")
    h = _positive(height, "cone height")
    u = _axis_vector(axis)
    c = np.array(_vec3(center, "cone center"))
    apex = c + (h / 2) * u
    return Primitive((
        HalfSpace.cone(apex, -u, math.atan2(r, h)),
        HalfSpace.plane(-u, -(float(u @ c) - h / 2)),  # u.p >= u.c - h/2
    ))


# ------------------------------------------------------------------ implicit functions

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


# ---------------------------------------------------------------------------- bounds

_RING = 32  # directions of the polygons that outer-approximate cylinders and cones


def _frame(u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Two unit vectors e1, e2 with (e1, e2, u) right-handed and orthonormal.

    For a coordinate axis u, e1 and e2 are coordinate axes too (tight bounds).
    """
    helper = np.zeros(3)
    helper[int(np.argmin(np.abs(u)))] = 1.0
    e1 = np.cross(u, helper)
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(u, e1)
    return e1, e2


def _outer_planes(h: HalfSpace) -> list[tuple[np.ndarray, float]]:
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
    e1, e2 = _frame(u)
    angles = 2 * np.pi * np.arange(_RING) / _RING
    ws = np.cos(angles)[:, None] * e1 + np.sin(angles)[:, None] * e2
    if h.kind == "cylinder":  # w . (p - q) <= rho <= r for every unit w perpendicular to u
        return [(w, float(w @ q) + h.radius) for w in ws]
    # cone: w . (p - a) <= rho <= tan(alpha) u . (p - a), and u . (p - a) >= 0
    k = math.tan(h.half_angle)
    out = [(w - k * u, float((w - k * u) @ q)) for w in ws]
    out.append((-u, float(-u @ q)))
    return out


def _primitive_bounds(prim: Primitive) -> tuple[np.ndarray, np.ndarray] | None:
    from scipy.optimize import linprog

    rows = [c for h in prim.halfspaces for c in _outer_planes(h)]
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
        return _primitive_bounds(node)
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


# ---------------------------------------------------------------------------- meshing

def _placed(m, u: np.ndarray, origin: np.ndarray):
    """Rotate manifold ``m`` so that its +z axis becomes ``u``, then move its origin to ``origin``."""
    e1, e2 = _frame(u)
    R = np.column_stack([e1, e2, u])  # z -> u, det +1
    return m.transform(np.column_stack([R, origin]))


def _primitive_manifold(prim: Primitive, segments: int):
    import manifold3d

    M = manifold3d.Manifold
    b = _primitive_bounds(prim)
    if b is None:
        return M()
    lo, hi = b
    extent = hi - lo
    pad = 0.01 * float(extent.max()) + 1e-6
    lo, hi = lo - pad, hi + pad
    centre = (lo + hi) / 2
    diag = float(np.linalg.norm(hi - lo))
    corners = np.array([[x, y, z] for x in (lo[0], hi[0]) for y in (lo[1], hi[1]) for z in (lo[2], hi[2])])

    m = M.cube(tuple(hi - lo)).translate(tuple(lo))
    for h in prim.halfspaces:
        u = np.array(h.direction)
        q = np.array(h.point)
        if h.kind == "plane":
            # trim_by_plane keeps normal . p >= offset; we keep u . p <= d
            m = m.trim_by_plane(tuple(-u), -h.offset)
        elif h.kind == "sphere":
            m = m ^ M.sphere(h.radius, segments).translate(tuple(q))
        elif h.kind == "cylinder":
            length = 2.0 * diag + 2.0 * pad  # covers the padded box around its middle
            mid = q + float(u @ (centre - q)) * u
            tube = M.cylinder(length, h.radius, h.radius, segments, True)
            m = m ^ _placed(tube, u, mid)
        else:  # cone: apex at the origin opening along +z, tall enough to cover the box
            height = float(np.max((corners - q) @ u)) + pad
            if height <= 0.0:
                return M()
            top = height * math.tan(h.half_angle)
            m = m ^ _placed(M.cylinder(height, 0.0, top, segments, False), u, q)
        if m.is_empty():
            return M()
    return m


def to_manifold(node: Node, segments: int = 64):
    """The node's solid as a ``manifold3d.Manifold`` (quadrics with ``segments`` edges per circle)."""
    segments = int(segments)
    if segments < 3:
        raise ValueError(f"segments must be at least 3, got {segments}")
    if isinstance(node, Primitive):
        m = _primitive_manifold(node, segments)
    elif isinstance(node, Op):
        ms = [to_manifold(c, segments) for c in node.children]
        if node.kind == "union":
            m = reduce(lambda a, b: a + b, ms)
        elif node.kind == "intersection":
            m = reduce(lambda a, b: a ^ b, ms)
        else:
            m = ms[0] - reduce(lambda a, b: a + b, ms[1:]) if len(ms) > 1 else ms[0]
    else:
        raise TypeError(f"expected a Primitive or Op, got {type(node).__name__}")
    status = m.status()
    if status.name != "NoError":
        raise RuntimeError(f"manifold3d failed: {status.name}")
    return m


def to_mesh(node: Node, segments: int = 64) -> Mesh:
    """The node's surface as a closed :class:`lab.mesh.Mesh`, counter-clockwise from outside, no normals."""
    mm = to_manifold(node, segments).to_mesh64()
    props = np.asarray(mm.vert_properties, dtype=np.float64)
    points = props.reshape(len(props), -1)[:, :3] if props.size else np.zeros((0, 3))
    triangles = np.asarray(mm.tri_verts, dtype=np.int64).reshape(-1, 3)
    return Mesh(points, triangles)


def mesh_volume(mesh: Mesh) -> float:
    """Enclosed volume by the divergence theorem: sum of ``p0 . (p1 x p2) / 6``.

    Positive for a closed mesh whose triangles are counter-clockwise seen from outside.
    """
    p = mesh.points[mesh.triangles]
    return float(np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0)


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


# ------------------------------------------------------------------------- from_dict

def _fail(where: str, msg: str):
    raise ValueError(f"{where}: {msg}")


def _check_keys(d: Mapping, allowed: Sequence[str], where: str, what: str):
    for k in d:
        if k not in allowed:
            _fail(where, f"unknown key {show(k)} for {what}; valid: {', '.join(sorted(allowed))}")


def _num(d: Mapping, key: str, where: str, default=None, positive=False) -> float:
    if key not in d:
        if default is None:
            _fail(where, f"missing key {key!r}")
        return float(default)
    v = real(d[key])
    if v is None or not math.isfinite(v):
        _fail(f"{where}.{key}", f"must be a finite number, got {show(d[key])}")
    if abs(v) > MAX_MAGNITUDE:
        _fail(f"{where}.{key}", f"must lie within ±{MAX_MAGNITUDE:g}, got {v:g}")
    if positive and not v > 0:
        _fail(f"{where}.{key}", f"must be positive, got {v:g}")
    return v


def _vec(d: Mapping, key: str, where: str, default=None) -> tuple[float, float, float]:
    if key not in d:
        if default is None:
            _fail(where, f"missing key {key!r}")
        return default
    v = d[key]
    xs = [real(x) for x in v] if isinstance(v, (list, tuple)) and len(v) == 3 else [None]
    if any(x is None or not math.isfinite(x) for x in xs):
        _fail(f"{where}.{key}", f"must be a list of 3 finite numbers, got {show(v)}")
    if any(abs(x) > MAX_MAGNITUDE for x in xs):
        _fail(f"{where}.{key}", f"values must lie within ±{MAX_MAGNITUDE:g}, got {show(v)}")
    return tuple(xs)


def _axis(d: Mapping, where: str, default="z"):
    if "axis" not in d:
        if default is None:
            _fail(where, "missing key 'axis'")
        return default
    v = d["axis"]
    if isinstance(v, str):
        if v not in _AXES:
            _fail(f"{where}.axis", f"must be 'x', 'y', 'z' or a 3-vector, got {show(v)}")
        return v
    a = _vec(d, "axis", where)
    if a == (0.0, 0.0, 0.0):
        _fail(f"{where}.axis", "must not be the zero vector")
    return a


def _halfspace_from_dict(d, where: str) -> HalfSpace:
    if not isinstance(d, Mapping):
        _fail(where, f"a half-space must be a table, got {type(d).__name__}")
    kinds = [k for k in HALFSPACE_KINDS if k in d]
    if len(kinds) != 1:
        _fail(where, f"a half-space needs exactly one of the keys {', '.join(HALFSPACE_KINDS)}; got {sorted(d)}")
    kind = kinds[0]
    allowed = {"plane": ("plane", "offset"), "sphere": ("sphere", "radius"),
               "cylinder": ("cylinder", "axis", "radius"), "cone": ("cone", "axis", "half_angle_degrees")}[kind]
    _check_keys(d, allowed, where, f"a {kind} half-space")
    if kind == "plane":
        n = _vec(d, "plane", where)
        if n == (0.0, 0.0, 0.0):
            _fail(f"{where}.plane", "the normal must not be the zero vector")
        return HalfSpace.plane(n, _num(d, "offset", where))
    if kind == "sphere":
        return HalfSpace.sphere(_vec(d, "sphere", where), _num(d, "radius", where, positive=True))
    axis = _axis_vector(_axis(d, where, default=None))
    if kind == "cylinder":
        return HalfSpace.cylinder(_vec(d, "cylinder", where), axis, _num(d, "radius", where, positive=True))
    deg = _num(d, "half_angle_degrees", where)
    if not 0.0 < deg < 90.0:
        _fail(f"{where}.half_angle_degrees", f"must be between 0 and 90 (exclusive), got {deg!r}")
    return HalfSpace.cone(_vec(d, "cone", where), axis, math.radians(deg))


def _size(d: Mapping, where: str):
    if "size" not in d:
        return (1.0, 1.0, 1.0)
    v = d["size"]
    if isinstance(v, (int, float)) and not isinstance(v, bool):
        v = [v, v, v]
        d = {"size": v}
    s = _vec(d, "size", where)
    if min(s) <= 0:
        _fail(f"{where}.size", f"must be positive, got {d['size']!r}")
    return s


def from_dict(d, where: str = "csg") -> Node:
    """Parse a CSG tree from the dict a scene file holds under ``[object.csg]``.

    A node is either an operation or a primitive::

        {op = "union" | "difference" | "intersection", children = [node, ...]}
        {primitive = "box", size = [sx, sy, sz] | s, center = [x, y, z]}
        {primitive = "sphere", radius = r, center = [x, y, z]}
        {primitive = "cylinder" | "cone", radius = r, height = h, center = [x, y, z],
         axis = "x" | "y" | "z" | [ux, uy, uz]}
        {primitive = "halfspaces", halfspaces = [
            {plane = [nx, ny, nz], offset = d},                   # n.p - d <= 0
            {sphere = [cx, cy, cz], radius = r},
            {cylinder = [px, py, pz], axis = "z" | [..], radius = r},  # infinite
            {cone = [ax, ay, az], axis = [..], half_angle_degrees = a},  # apex, opening along axis
        ]}

    Defaults (as VTK's sources): box size 1, radius 0.5, height 1, centre at the origin,
    axis "z". Errors raise ValueError naming the path in the tree, e.g.
    ``csg.children[0].children[1]: unknown primitive 'spere'; valid: box, ...``.
    """
    if not isinstance(d, Mapping):
        _fail(where, f"a CSG node must be a table, got {type(d).__name__}")
    if ("op" in d) == ("primitive" in d):
        _fail(where, "a CSG node needs exactly one of the keys 'op' (with 'children') or 'primitive'")
    if "op" in d:
        kind = d["op"]
        if kind not in OP_KINDS:
            _fail(where, f"unknown op {show(kind)}; valid: {', '.join(OP_KINDS)}")
        _check_keys(d, ("op", "children"), where, f"op {show(kind)}")
        children = d.get("children")
        if not isinstance(children, (list, tuple)) or not children:
            _fail(where, f"op {show(kind)} needs a non-empty list 'children'")
        return Op(kind, tuple(from_dict(c, f"{where}.children[{i}]") for i, c in enumerate(children)))

    name = d["primitive"]
    if name not in PRIMITIVE_NAMES:
        _fail(where, f"unknown primitive {show(name)}; valid: {', '.join(PRIMITIVE_NAMES)}")
    origin = (0.0, 0.0, 0.0)
    if name == "box":
        _check_keys(d, ("primitive", "size", "center"), where, "primitive 'box'")
        return box(_size(d, where), _vec(d, "center", where, origin))
    if name == "sphere":
        _check_keys(d, ("primitive", "radius", "center"), where, "primitive 'sphere'")
        return sphere(_num(d, "radius", where, 0.5, positive=True), _vec(d, "center", where, origin))
    if name in ("cylinder", "cone"):
        _check_keys(d, ("primitive", "radius", "height", "center", "axis"), where, f"primitive {show(name)}")
        make = cylinder if name == "cylinder" else cone
        return make(_num(d, "radius", where, 0.5, positive=True), _num(d, "height", where, 1.0, positive=True),
                    _vec(d, "center", where, origin), _axis(d, where))
    _check_keys(d, ("primitive", "halfspaces"), where, "primitive 'halfspaces'")
    hs = d.get("halfspaces")
    if not isinstance(hs, (list, tuple)) or not hs:
        _fail(where, "primitive 'halfspaces' needs a non-empty list 'halfspaces'")
    return Primitive(tuple(_halfspace_from_dict(h, f"{where}.halfspaces[{i}]") for i, h in enumerate(hs)))
