"""Meshing a CSG tree with manifold3d: a closed, outward-facing triangle mesh.

How the mesh is made
--------------------
VTK's boolean filters are known to fail on such trees, so the surface is built with
manifold3d, whose booleans are robust and always return a closed, oriented 2-manifold:

1. each primitive must be bounded; its axis-aligned bounds come from a small linear
   programme over its planes and polygonal outer approximations of its quadrics
   (:mod:`lab.csg.bounds`; ``ValueError("... primitive is unbounded ...")`` otherwise);
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
:func:`lab.csg.implicit.monte_carlo_volume`) as ``segments`` grows; points farther than
a few sagittas from every surface are classified identically by the mesh and by
:func:`lab.csg.implicit.inside`.

manifold3d is imported only when a tree is meshed.
"""
from __future__ import annotations

import math
from functools import reduce

import numpy as np

from lab.csg.bounds import axis_frame, primitive_bounds
from lab.csg.model import Node, Op, Primitive
from lab.measure import enclosed_volume as mesh_volume
from lab.mesh import Mesh

__all__ = ["to_manifold", "to_mesh", "mesh_volume"]


def _placed(m, u: np.ndarray, origin: np.ndarray):
    """Rotate manifold ``m`` so that its +z axis becomes ``u``, then move its origin to ``origin``."""
    e1, e2 = axis_frame(u)
    R = np.column_stack([e1, e2, u])  # z -> u, det +1
    return m.transform(np.column_stack([R, origin]))


def _primitive_manifold(prim: Primitive, segments: int):
    import manifold3d

    M = manifold3d.Manifold
    b = primitive_bounds(prim)
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
