"""lab.csg.parse: a scene file's [object.csg] table → the tree, with the loader's one-line errors."""
from __future__ import annotations

import math

import pytest

from lab import csg
from lab.csg.model import HalfSpace, Op, Primitive
from lab.csg.parse import HALFSPACE_READERS, PRIMITIVE_NAMES, PRIMITIVE_READERS, from_dict
from lab.validation import SceneError


@pytest.mark.parametrize("tree, message", [
    ({"op": "intersection", "children": [
        {"op": "difference", "children": [{"primitive": "box"}, {"primitive": "spere", "radius": 1.0}]}]},
     "csg.children[0].children[1].primitive: unknown primitive 'spere' (did you mean 'sphere'?); valid: box, sphere, "
     "cylinder, cone, halfspaces"),
    ({"op": "union", "children": [{"primitive": "box"}, {"primitive": "sphere", "radius": -1}]},
     "csg.children[1].radius: -1 is outside (0, 1e+15]"),
    ({"op": "union", "children": [{"primitive": "sphere", "radus": 1}]},
     "csg.children[0].radus: unknown key (did you mean 'radius'?)"),
    ({"primitive": "box", "radius": 1}, "csg.radius: unknown key (valid: center, primitive, size)"),
    ({"op": "xor", "children": []}, "csg.op: unknown op 'xor'; valid: union, difference, intersection"),
    ({"op": "union", "children": []}, "csg.children: expected a non-empty list of tables, got []"),
    ({"op": "union", "children": [{"primitive": "box"}, 3]}, "csg.children[1]: expected a table, got 3"),
    ({"primitive": "halfspaces", "halfspaces": [{"plane": [0, 0, 1], "offset": 1}, {"plane": [0, 0], "offset": 1}]},
     "csg.halfspaces[1].plane: expected a list of 3 numbers, got [0, 0]"),
    ({"primitive": "halfspaces", "halfspaces": [{"plane": [0, 0, 0], "offset": 1}]},
     "csg.halfspaces[0].plane: the normal must not be the zero vector"),
    ({"primitive": "halfspaces", "halfspaces": [{"sphere": [0, 0, 0]}]}, "csg.halfspaces[0]: missing key 'radius'"),
    ({"primitive": "halfspaces", "halfspaces": [{"sphere": [0, 0, 0], "plane": [0, 0, 1]}]},
     "csg.halfspaces[0]: a half-space needs exactly one of the keys plane, sphere, cylinder, cone"),
    ({"primitive": "halfspaces", "halfspaces": [{"cone": [0, 0, 0], "axis": "z", "half_angle_degrees": 90}]},
     "csg.halfspaces[0].half_angle_degrees: 90 is outside (0, 90)"),
    ({"primitive": "cylinder", "axis": "w"}, "csg.axis: must be 'x', 'y', 'z' or a 3-vector, got 'w'"),
    ({"primitive": "cone", "axis": [0, 0, 0]}, "csg.axis: must not be the zero vector"),
    ({"primitive": "box", "size": [1, 0, 1]}, "csg.size: values must lie in (0, 1e+15], got [1, 0, 1]"),
    ({"primitive": "box", "size": True}, "csg.size: expected a list of 3 numbers, got True"),
    ({"primitive": "sphere", "center": [0, math.nan, 0]}, "csg.center: expected 3 finite numbers"),
    ({"primitive": "box", "op": "union"}, "csg: a CSG node needs exactly one of the keys"),
    ([{"primitive": "box"}], "csg: expected a table, got [{'primitive': 'box'}]"),
])
def test_from_dict_errors_name_the_path(tree, message):
    """Invalid trees raise SceneError (a ValueError) whose message starts with the path of the bad key."""
    with pytest.raises(SceneError) as info:
        from_dict(tree)
    assert str(info.value).startswith(message)
    assert isinstance(info.value, ValueError)


def test_errors_in_a_scene_file_name_the_file_and_the_object():
    """As the loader calls it: ``file: object[2].csg.children[0].height: ...``, one line."""
    with pytest.raises(SceneError) as info:
        from_dict({"op": "union", "children": [{"primitive": "cone", "height": "tall"}]},
                  where="object[2].csg", source="scenes/a.toml")
    assert str(info.value) == "scenes/a.toml: object[2].csg.children[0].height: expected a number, got 'tall'"


def test_from_dict_builds_the_convenience_primitives():
    """Dict primitives equal the Python constructors (defaults as VTK's sources)."""
    assert from_dict({"primitive": "box", "size": 2}) == csg.box((2, 2, 2))
    assert from_dict({"primitive": "box"}) == csg.box((1, 1, 1))
    assert from_dict({"primitive": "sphere"}) == csg.sphere(0.5)
    assert from_dict({"primitive": "cone", "axis": "y", "height": 2}) == csg.cone(0.5, 2.0, axis="y")
    assert from_dict({"primitive": "cylinder"}, where="object.csg") == csg.cylinder(0.5, 1.0, axis="z")
    assert from_dict({"primitive": "cylinder", "axis": [0, 2, 0], "center": [1, 2, 3], "radius": 0.25}) == \
        csg.cylinder(0.25, 1.0, (1, 2, 3), "y")


def test_from_dict_builds_each_halfspace_kind():
    tree = {"primitive": "halfspaces", "halfspaces": [
        {"plane": [0, 0, 2], "offset": 1.0},
        {"sphere": [1, 0, 0], "radius": 2},
        {"cylinder": [0, 0, 0], "axis": "x", "radius": 0.5},
        {"cone": [0, 0, 1], "axis": [0, 0, -1], "half_angle_degrees": 30},
    ]}
    assert from_dict(tree) == Primitive((
        HalfSpace.plane((0, 0, 1), 0.5), HalfSpace.sphere((1, 0, 0), 2.0),
        HalfSpace.cylinder((0, 0, 0), (1, 0, 0), 0.5), HalfSpace.cone((0, 0, 1), (0, 0, -1), math.radians(30))))


def test_operations_nest():
    tree = {"op": "difference", "children": [{"primitive": "box"}, {"op": "union", "children": [
        {"primitive": "sphere", "radius": 0.3}, {"primitive": "sphere", "center": [0.5, 0, 0]}]}]}
    assert from_dict(tree) == Op("difference", (csg.box(), Op("union", (csg.sphere(0.3), csg.sphere(0.5, (0.5, 0, 0))))))


def test_every_name_has_one_reader():
    assert PRIMITIVE_NAMES == ("box", "sphere", "cylinder", "cone", "halfspaces") == tuple(PRIMITIVE_READERS)
    assert tuple(HALFSPACE_READERS) == csg.HALFSPACE_KINDS
