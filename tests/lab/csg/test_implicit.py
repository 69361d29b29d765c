"""lab.csg.implicit: f(p) <= 0 evaluated exactly, the inside test of a tree, the Monte Carlo volume."""
from __future__ import annotations

import math

import numpy as np
import pytest

from lab import csg
from lab.csg.implicit import boundary_distance, implicit_value, inside, monte_carlo_volume
from lab.csg.model import HalfSpace, Op, Primitive, box, sphere


def test_implicit_values_and_boundary_distances():
    """f < 0 inside, f > 0 outside for each kind; boundary distances are Euclidean."""
    p = np.array([[0.0, 0.0, 0.5], [0.0, 0.0, 3.0], [2.0, 0.0, 1.0]])
    hs = {
        "plane": HalfSpace.plane((0, 0, 2), 2.0),       # z <= 1
        "sphere": HalfSpace.sphere((0, 0, 0), 1.0),
        "cylinder": HalfSpace.cylinder((0, 0, 0), (0, 0, 5), 1.0),
        "cone": HalfSpace.cone((0, 0, 0), (0, 0, 1), math.pi / 4),
    }
    signs = {k: np.sign(implicit_value(h, p)).tolist() for k, h in hs.items()}
    assert signs == {"plane": [-1, 1, 0], "sphere": [-1, 1, 1], "cylinder": [-1, -1, 1], "cone": [-1, -1, 1]}
    assert np.allclose(boundary_distance(hs["plane"], p), [0.5, 2.0, 0.0])
    assert np.allclose(boundary_distance(hs["sphere"], p), [0.5, 2.0, math.sqrt(5) - 1])
    assert np.allclose(boundary_distance(hs["cylinder"], p), [1.0, 1.0, 1.0])
    assert np.allclose(boundary_distance(hs["cone"], p), [0.5 / math.sqrt(2), 3 / math.sqrt(2), 1 / math.sqrt(2)])
    below = np.array([[0.0, 0.0, -1.0]])  # nearest boundary point is the apex
    assert boundary_distance(hs["cone"], below) == pytest.approx([1.0])




def test_the_course_cylinder_is_three_halfspaces_by_hand():
    """{x^2 + y^2 - r^2 <= 0, z - h <= 0, -z <= 0} with r = 1, h = 2, at points worked out by hand."""
    course = Primitive((HalfSpace.cylinder((0, 0, 0), (0, 0, 1), 1.0),
                        HalfSpace.plane((0, 0, 1), 2.0), HalfSpace.plane((0, 0, -1), 0.0)))
    p = [[0.5, 0.5, 1.0],    # 0.5 - 1 < 0, 1 - 2 < 0, -1 < 0: inside
         [0.8, 0.8, 1.0],    # x^2 + y^2 = 1.28 > 1: outside the side
         [0.0, 0.0, 2.5],    # above the top
         [0.0, 0.0, -0.1],   # below the bottom
         [1.0, 0.0, 2.0]]    # on the side and the top: f = 0 counts as inside
    assert inside(course, p).tolist() == [True, False, False, False, True]
    assert implicit_value(course.halfspaces[0], p).tolist() == pytest.approx([-0.5, 0.28, -1.0, -1.0, 0.0])


@pytest.mark.parametrize("kind, expected", [
    ("union", [True, True, True, False]),
    ("intersection", [False, True, False, False]),
    ("difference", [True, False, False, False]),
])
def test_operations_combine_the_children_as_sets(kind, expected):
    """Unit cube [0, 1]^3 and a ball of radius 0.5 at (1, 0.5, 0.5), at four points."""
    node = Op(kind, (box(1.0, (0.5, 0.5, 0.5)), sphere(0.5, (1.0, 0.5, 0.5))))
    p = [[0.2, 0.5, 0.5],   # cube only
         [0.9, 0.5, 0.5],   # both
         [1.3, 0.5, 0.5],   # ball only
         [3.0, 3.0, 3.0]]   # neither
    assert inside(node, p).tolist() == expected


def test_difference_removes_every_later_child():
    """difference(a, b, c) is a minus (b union c); with one child it is the child itself."""
    a, b, c = box(2.0), sphere(0.4, (0.6, 0, 0)), sphere(0.4, (-0.6, 0, 0))
    p = [[0.6, 0, 0], [-0.6, 0, 0], [0, 0.8, 0]]
    assert inside(Op("difference", (a, b, c)), p).tolist() == [False, False, True]
    assert inside(Op("difference", (a,)), p).tolist() == [True, True, True]


def test_inside_refuses_what_is_not_a_node():
    with pytest.raises(TypeError, match="Primitive or Op"):
        inside("sphere", [[0, 0, 0]])


def test_monte_carlo_volume_of_a_ball_and_its_error():
    """4/3 pi r^3 within four standard errors, and the error shrinks like 1/sqrt(n)."""
    ball = sphere(0.75)
    exact = 4 / 3 * math.pi * 0.75 ** 3
    v, err = monte_carlo_volume(ball, n=400_000, seed=2)
    assert abs(v - exact) < 4 * err and err < 0.01 * exact
    _, err_small = monte_carlo_volume(ball, n=100_000, seed=2)
    assert err_small == pytest.approx(2 * err, rel=0.05)


def test_monte_carlo_volume_of_an_empty_tree_is_zero():
    """Two disjoint balls intersected: the bounds are empty, so (0, 0) without sampling."""
    node = Op("intersection", (sphere(0.5), sphere(0.5, (3.0, 0.0, 0.0))))
    assert monte_carlo_volume(node) == (0.0, 0.0)
    assert csg.bounds(node) is None
