"""lab.csg.bounds: axis-aligned bounds from linear programmes; unbounded primitives refused."""
from __future__ import annotations

import numpy as np
import pytest

from lab import csg
from lab.csg.bounds import RING, axis_frame, bounds, outer_planes
from lab.csg.model import HalfSpace, Op, Primitive, box, cone, cylinder, sphere


def test_a_box_has_its_own_bounds():
    lo, hi = bounds(box((2.0, 1.0, 0.5), (1.0, 0.0, -1.0)))
    assert lo.tolist() == pytest.approx([0.0, -0.5, -1.25]) and hi.tolist() == pytest.approx([2.0, 0.5, -0.75])


def test_a_ball_is_bounded_by_its_cube():
    lo, hi = bounds(sphere(0.5, (1.0, 2.0, 3.0)))
    assert lo.tolist() == pytest.approx([0.5, 1.5, 2.5]) and hi.tolist() == pytest.approx([1.5, 2.5, 3.5])


def test_an_axis_aligned_cylinder_and_cone_are_bounded_tightly():
    """The ring polygon has a side facing each coordinate axis, so the bounds are exact."""
    lo, hi = bounds(cylinder(0.5, 2.0, axis="y"))
    assert lo.tolist() == pytest.approx([-0.5, -1.0, -0.5]) and hi.tolist() == pytest.approx([0.5, 1.0, 0.5])
    lo, hi = bounds(cone(0.5, 1.0, axis="z"))
    assert lo.tolist() == pytest.approx([-0.5, -0.5, -0.5]) and hi.tolist() == pytest.approx([0.5, 0.5, 0.5])


def test_every_point_of_a_halfspace_meets_its_outer_planes():
    """Points inside each quadric (by f <= 0) satisfy every outer constraint a . p <= b."""
    rng = np.random.default_rng(5)
    p = rng.uniform(-3, 3, (20000, 3))
    for h in (HalfSpace.sphere((0.2, 0, 0), 1.0), HalfSpace.cylinder((0, 0.1, 0), (1, 1, 0), 0.7),
              HalfSpace.cone((0, 0, -1), (0, 1, 1), 0.5)):
        p_in = p[csg.implicit_value(h, p) <= 0]
        assert len(p_in) > 100
        for a, b in outer_planes(h):
            assert np.all(p_in @ a <= b + 1e-12), h.kind
    assert len(outer_planes(HalfSpace.cylinder((0, 0, 0), (0, 0, 1), 1.0))) == RING


def test_axis_frame_is_right_handed_and_orthonormal():
    for u in (np.array([0.0, 0.0, 1.0]), np.array([1.0, 2.0, -2.0]) / 3.0):
        e1, e2 = axis_frame(u)
        m = np.column_stack([e1, e2, u])
        assert np.allclose(m.T @ m, np.eye(3)) and np.linalg.det(m) == pytest.approx(1.0)


def test_operations_combine_the_bounds():
    """Union: the hull; intersection: the overlap, or None when disjoint; difference: the first."""
    a, b = box(1.0), box(1.0, (0.5, 0.0, 0.0))
    lo, hi = bounds(Op("union", (a, b)))
    assert lo[0] == pytest.approx(-0.5) and hi[0] == pytest.approx(1.0)
    lo, hi = bounds(Op("intersection", (a, b)))
    assert lo[0] == pytest.approx(0.0) and hi[0] == pytest.approx(0.5)
    lo, hi = bounds(Op("difference", (a, b)))
    assert lo[0] == pytest.approx(-0.5) and hi[0] == pytest.approx(0.5)
    assert bounds(Op("intersection", (a, box(1.0, (5.0, 0.0, 0.0))))) is None


def test_an_empty_primitive_has_no_bounds():
    """x <= -1 and x >= 1 inside a box: no point satisfies both."""
    empty = Primitive(box(4.0).halfspaces + (HalfSpace.plane((1, 0, 0), -1.0), HalfSpace.plane((-1, 0, 0), -1.0)))
    assert bounds(empty) is None
    assert bounds(Op("union", (empty,))) is None


@pytest.mark.parametrize("node", [
    csg.Primitive((csg.HalfSpace.plane((0, 0, 1), 0.0),)),
    csg.Primitive((csg.HalfSpace.cylinder((0, 0, 0), (0, 0, 1), 1.0),)),
    csg.Primitive((csg.HalfSpace.cone((0, 0, 0), (0, 0, 1), 0.3),)),
    csg.Op("difference", (csg.Primitive((csg.HalfSpace.plane((1, 0, 0), 0.0),)), csg.sphere(1.0))),
])
def test_unbounded_primitives_are_refused(node):
    """A primitive that is not bounded (a plane, an infinite cylinder or cone) raises ValueError,
    for meshing and for the Monte Carlo volume alike."""
    with pytest.raises(ValueError, match="unbounded"):
        csg.to_mesh(node)
    with pytest.raises(ValueError, match="unbounded"):
        csg.monte_carlo_volume(node)


