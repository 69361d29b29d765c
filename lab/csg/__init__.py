"""Constructive solid geometry (CSG): the course's implicit definition, meshed with manifold3d.

One room per step, each with its own tests (``tests/lab/csg/``):

- :mod:`lab.csg.model`: the tree — half-spaces ``f(p) <= 0`` (plane, sphere, cylinder,
  cone), primitives as their intersections, union/difference/intersection nodes, and
  the usual solids (box, sphere, cylinder, cone);
- :mod:`lab.csg.implicit`: the exact inside test and the Monte Carlo volume;
- :mod:`lab.csg.bounds`: axis-aligned bounds by linear programming (scipy, lazily);
- :mod:`lab.csg.meshing`: the closed, outward mesh made with manifold3d (lazily);
- :mod:`lab.csg.parse`: the ``[object.csg]`` table of a scene file → a tree.

The names below are the package's public API (``from lab import csg; csg.to_mesh(...)``).
"""
from lab.csg.bounds import bounds
from lab.csg.implicit import boundary_distance, implicit_value, inside, monte_carlo_volume
from lab.csg.meshing import mesh_volume, to_manifold, to_mesh
from lab.csg.model import HALFSPACE_KINDS, OP_KINDS, HalfSpace, Node, Op, Primitive, box, cone, cylinder, sphere
from lab.csg.parse import PRIMITIVE_NAMES, from_dict

__all__ = [
    "HalfSpace", "Primitive", "Op", "Node",
    "box", "sphere", "cylinder", "cone",
    "implicit_value", "boundary_distance", "inside", "bounds",
    "to_manifold", "to_mesh", "from_dict", "monte_carlo_volume", "mesh_volume",
    "HALFSPACE_KINDS", "OP_KINDS", "PRIMITIVE_NAMES",
]
