"""The CSG tree: half-spaces, the primitives they make, and the boolean operations.

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
first child and in none of the others).

This module holds only the description (frozen dataclasses, no callables) and the
constructors of the usual solids; :mod:`lab.csg.implicit` evaluates the functions,
:mod:`lab.csg.meshing` turns a tree into a mesh, :mod:`lab.csg.parse` reads one from a
scene file.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Union

import numpy as np

__all__ = ["HalfSpace", "Primitive", "Op", "Node", "box", "sphere", "cylinder", "cone", "axis_vector",
           "AXES", "HALFSPACE_KINDS", "OP_KINDS"]

HALFSPACE_KINDS = ("plane", "sphere", "cylinder", "cone")
OP_KINDS = ("union", "difference", "intersection")

AXES = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}
"""The coordinate axes a primitive's ``axis`` may name."""


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

def axis_vector(axis) -> np.ndarray:
    """A unit axis from "x", "y", "z" or any nonzero 3-vector (normalised)."""
    if isinstance(axis, str):
        if axis not in AXES:
            raise ValueError(f"axis must be 'x', 'y', 'z' or a 3-vector, got {axis!r}")
        return np.array(AXES[axis])
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
    u = axis_vector(axis)
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
    u = axis_vector(axis)
    c = np.array(_vec3(center, "cone center"))
    apex = c + (h / 2) * u
    return Primitive((
        HalfSpace.cone(apex, -u, math.atan2(r, h)),
        HalfSpace.plane(-u, -(float(u @ c) - h / 2)),  # u.p >= u.c - h/2
    ))
