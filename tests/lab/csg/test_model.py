"""lab.csg.model: half-spaces are stored normalised and checked; the usual solids are the course's half-spaces."""
from __future__ import annotations

import math

import pytest

from lab.csg.model import AXES, HalfSpace, Op, Primitive, axis_vector, box, cone, cylinder, sphere


def test_a_plane_is_stored_with_a_unit_normal_and_a_scaled_offset():
    """2x <= 1 is stored as x <= 0.5: the same set, and f becomes the signed distance."""
    h = HalfSpace.plane((2, 0, 0), 1.0)
    assert h.direction == (1.0, 0.0, 0.0) and h.offset == 0.5


def test_axes_of_cylinders_and_cones_are_stored_as_unit_vectors():
    assert HalfSpace.cylinder((0, 0, 0), (0, 3, 4), 1.0).direction == pytest.approx((0.0, 0.6, 0.8))
    assert HalfSpace.cone((1, 2, 3), (0, 0, -2), 0.5).direction == (0.0, 0.0, -1.0)


@pytest.mark.parametrize("make, message", [
    (lambda: HalfSpace("torus"), "unknown half-space kind 'torus'"),
    (lambda: HalfSpace.plane((0, 0, 0), 1.0), "must not be the zero vector"),
    (lambda: HalfSpace.sphere((0, 0, 0), 0.0), "radius must be positive"),
    (lambda: HalfSpace.cylinder((0, 0, 0), (0, 0, 1), -1.0), "radius must be positive"),
    (lambda: HalfSpace.cone((0, 0, 0), (0, 0, 1), math.pi / 2), r"half_angle must be in \(0, pi/2\)"),
    (lambda: HalfSpace.sphere((0, math.nan, 0), 1.0), "3 finite numbers"),
    (lambda: HalfSpace.plane((0, 0, 1), math.inf), "offset must be finite"),
    (lambda: Primitive(()), "at least one half-space"),
    (lambda: Op("xor", (sphere(),)), "unknown op 'xor'"),
    (lambda: Op("union", ()), "needs at least one child"),
    (lambda: axis_vector("w"), "axis must be 'x', 'y', 'z'"),
    (lambda: box((1, 0, 1)), "box size must be a positive number"),
    (lambda: cone(0.5, -1.0), "cone height must be a positive number"),
])
def test_a_wrong_description_raises_value_error(make, message):
    with pytest.raises(ValueError, match=message):
        make()


def test_nodes_hold_only_nodes():
    with pytest.raises(TypeError, match="HalfSpace objects"):
        Primitive(("plane",))
    with pytest.raises(TypeError, match="Primitive or Op"):
        Op("union", (HalfSpace.sphere((0, 0, 0), 1.0),))


def test_axis_vector_names_the_coordinate_axes_or_normalises():
    assert [axis_vector(a).tolist() for a in "xyz"] == [list(AXES[a]) for a in "xyz"]
    assert axis_vector((0, 0, -5)).tolist() == [0.0, 0.0, -1.0]


def test_box_is_six_planes_at_half_its_size_from_the_centre():
    """size (2, 4, 6) at (1, 0, 0): x <= 2, -x <= 0, y <= 2, -y <= 2, z <= 3, -z <= 3."""
    planes = box((2.0, 4.0, 6.0), (1.0, 0.0, 0.0)).halfspaces
    assert [h.kind for h in planes] == ["plane"] * 6
    assert [(h.direction, h.offset) for h in planes] == [
        ((1.0, 0.0, 0.0), 2.0), ((-1.0, 0.0, 0.0), 0.0), ((0.0, 1.0, 0.0), 2.0), ((0.0, -1.0, 0.0), 2.0),
        ((0.0, 0.0, 1.0), 3.0), ((0.0, 0.0, -1.0), 3.0)]
    assert box(2.0) == box((2.0, 2.0, 2.0))


def test_cylinder_is_the_course_cylinder_an_infinite_tube_and_two_caps():
    """radius 0.5, height 2, centre (0, 1, 0), axis y: tube about the y axis, 0 <= y <= 2."""
    tube, top, bottom = cylinder(0.5, 2.0, (0.0, 1.0, 0.0), "y").halfspaces
    assert (tube.kind, tube.point, tube.direction, tube.radius) == ("cylinder", (0.0, 1.0, 0.0), (0.0, 1.0, 0.0), 0.5)
    assert (top.direction, top.offset) == ((0.0, 1.0, 0.0), 2.0)
    assert (bottom.direction, bottom.offset) == ((0.0, -1.0, 0.0), 0.0)


def test_cone_has_its_apex_at_the_top_and_opens_downwards():
    """radius 1, height 1, axis z at the origin: apex (0, 0, 0.5), axis -z, half-angle 45°, base z >= -0.5."""
    nappe, base = cone(1.0, 1.0).halfspaces
    assert nappe.point == (0.0, 0.0, 0.5) and nappe.direction == (0.0, 0.0, -1.0)
    assert nappe.half_angle == pytest.approx(math.pi / 4)
    assert (base.direction, base.offset) == ((0.0, 0.0, -1.0), 0.5)


def test_sphere_is_one_halfspace_and_nodes_compare_by_value():
    assert sphere(0.5, (1, 2, 3)) == Primitive((HalfSpace.sphere((1.0, 2.0, 3.0), 0.5),))
    assert Op("union", [sphere(), box()]) == Op("union", (sphere(), box()))
    assert sphere(2.0).halfspaces[0].radius == 2.0
