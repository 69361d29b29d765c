"""Reading a CSG tree from the table a scene file holds under ``[object.csg]``.

A node is either an operation or a primitive::

    {op = "union" | "difference" | "intersection", children = [node, ...]}
    {primitive = "box", size = [sx, sy, sz] | s, center = [x, y, z]}
    {primitive = "sphere", radius = r, center = [x, y, z]}
    {primitive = "cylinder" | "cone", radius = r, height = h, center = [x, y, z],
     axis = "x" | "y" | "z" | [ux, uy, uz]}
    {primitive = "halfspaces", halfspaces = [
        {plane = [nx, ny, nz], offset = d},                          # n.p - d <= 0
        {sphere = [cx, cy, cz], radius = r},
        {cylinder = [px, py, pz], axis = "z" | [..], radius = r},    # infinite
        {cone = [ax, ay, az], axis = [..], half_angle_degrees = a},  # apex, opening along axis
    ]}

Defaults (as VTK's sources): box size 1, radius 0.5, height 1, centre at the origin,
axis "z". Every value is read through :class:`lab.validation.Table`, so an error is the
loader's one line naming the path in the tree, e.g.
``scene.toml: object[0].csg.children[1].primitive: unknown primitive 'spere'; valid: box, ...``.
Each primitive name and each half-space kind has one reader, found in
:data:`PRIMITIVE_READERS` and :data:`HALFSPACE_READERS`.
"""
from __future__ import annotations

import math
from collections.abc import Mapping

from lab.csg.model import AXES, HALFSPACE_KINDS, OP_KINDS, HalfSpace, Node, Op, Primitive, axis_vector, box, cone, \
    cylinder, sphere
from lab.validation import REQUIRED, Table
from lab.values import real, show

__all__ = ["from_dict", "PRIMITIVE_NAMES", "PRIMITIVE_READERS", "HALFSPACE_READERS"]

ORIGIN = (0.0, 0.0, 0.0)


def from_dict(d: Mapping, where: str = "csg", source: str = "") -> Node:
    """The CSG tree of table ``d``; ``where`` is its path and ``source`` its file, for errors.

    Raises :class:`lab.validation.SceneError` (a ValueError) whose message starts with
    ``source: `` (when given) and the path of the bad node or key, e.g.
    ``csg.children[0].radius: -1 is outside (0, 1e+15]``.
    """
    return _node(Table(source, where, d))


def _node(t: Table) -> Node:
    if ("op" in t.table) == ("primitive" in t.table):
        raise t.error(None, "a CSG node needs exactly one of the keys 'op' (with 'children') or 'primitive'")
    if "op" in t.table:
        kind = t.choice("op", REQUIRED, OP_KINDS, noun="op")
        t.check_keys(("op", "children"))
        return Op(kind, tuple(_node(child) for child in t.tables("children")))
    name = t.choice("primitive", REQUIRED, PRIMITIVE_NAMES, noun="primitive")
    read, keys = PRIMITIVE_READERS[name]
    t.check_keys(("primitive",) + keys)
    return read(t)


# ------------------------------------------------------------------- shared readers
def _positive(t: Table, key: str, default) -> float:
    return t.number(key, default, 0.0, lo_open=True)


def _axis(t: Table, default):
    """``axis``: "x", "y", "z" (returned as the name) or a nonzero 3-vector."""
    v = t.get("axis", default)
    if isinstance(v, str):
        if v not in AXES:
            raise t.error("axis", f"must be 'x', 'y', 'z' or a 3-vector, got {show(v)}")
        return v
    a = t.vector("axis", REQUIRED)
    if a == ORIGIN:
        raise t.error("axis", "must not be the zero vector")
    return a


def _size(t: Table):
    """``size``: one number (a cube) or three edge lengths, all positive."""
    if real(t.get("size", 1.0)) is not None:
        s = _positive(t, "size", 1.0)
        return (s, s, s)
    return t.vector("size", REQUIRED, 3, 0.0, lo_open=True)


# ------------------------------------------------------------------------ primitives
def _box(t: Table) -> Primitive:
    return box(_size(t), t.vector("center", ORIGIN))


def _sphere(t: Table) -> Primitive:
    return sphere(_positive(t, "radius", 0.5), t.vector("center", ORIGIN))


def _round_solid(make):
    def read(t: Table) -> Primitive:
        return make(_positive(t, "radius", 0.5), _positive(t, "height", 1.0), t.vector("center", ORIGIN),
                    _axis(t, "z"))
    return read


def _halfspaces(t: Table) -> Primitive:
    return Primitive(tuple(_halfspace(h) for h in t.tables("halfspaces")))


PRIMITIVE_READERS = {
    "box": (_box, ("size", "center")),
    "sphere": (_sphere, ("radius", "center")),
    "cylinder": (_round_solid(cylinder), ("radius", "height", "center", "axis")),
    "cone": (_round_solid(cone), ("radius", "height", "center", "axis")),
    "halfspaces": (_halfspaces, ("halfspaces",)),
}
"""Primitive name → (reader of its table, the keys it may hold besides ``primitive``)."""

PRIMITIVE_NAMES = tuple(PRIMITIVE_READERS)


# ----------------------------------------------------------------------- half-spaces
def _halfspace(t: Table) -> HalfSpace:
    kinds = [k for k in HALFSPACE_KINDS if k in t.table]
    if len(kinds) != 1:
        raise t.error(None, f"a half-space needs exactly one of the keys {', '.join(HALFSPACE_KINDS)}; "
                            f"got {show(sorted(map(str, t.table)))}")
    read, keys = HALFSPACE_READERS[kinds[0]]
    t.check_keys((kinds[0],) + keys)
    return read(t)


def _plane(t: Table) -> HalfSpace:
    normal = t.vector("plane", REQUIRED)
    if normal == ORIGIN:
        raise t.error("plane", "the normal must not be the zero vector")
    return HalfSpace.plane(normal, t.number("offset", REQUIRED))


def _sphere_halfspace(t: Table) -> HalfSpace:
    return HalfSpace.sphere(t.vector("sphere", REQUIRED), _positive(t, "radius", REQUIRED))


def _cylinder_halfspace(t: Table) -> HalfSpace:
    axis = axis_vector(_axis(t, REQUIRED))
    return HalfSpace.cylinder(t.vector("cylinder", REQUIRED), axis, _positive(t, "radius", REQUIRED))


def _cone_halfspace(t: Table) -> HalfSpace:
    axis = axis_vector(_axis(t, REQUIRED))
    degrees = t.number("half_angle_degrees", REQUIRED, 0.0, 90.0, lo_open=True, hi_open=True)
    return HalfSpace.cone(t.vector("cone", REQUIRED), axis, math.radians(degrees))


HALFSPACE_READERS = {
    "plane": (_plane, ("offset",)),
    "sphere": (_sphere_halfspace, ("radius",)),
    "cylinder": (_cylinder_halfspace, ("axis", "radius")),
    "cone": (_cone_halfspace, ("axis", "half_angle_degrees")),
}
"""Half-space kind → (reader of its table, the keys it may hold besides the kind's own)."""
