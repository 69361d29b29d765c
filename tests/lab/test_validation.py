"""lab.validation.Table: each reader's values and its one-line error, naming file, table and key."""
from __future__ import annotations

import math

import pytest

from lab.validation import REQUIRED, SceneError, Table, quantise_colour


def table(**values):
    return Table("scene.toml", "camera", values)


def error(read) -> str:
    with pytest.raises(SceneError) as info:
        read()
    message = str(info.value)
    assert "\n" not in message
    return message


# --------------------------------------------------------------------------- naming
def test_an_error_names_the_file_the_table_and_the_key():
    assert str(table().error("view_angle", "wrong")) == "scene.toml: camera.view_angle: wrong"
    assert str(Table("s.toml", "", {}).error("cammera", "wrong")) == "s.toml: cammera: wrong"
    assert str(Table("s.toml", "object[0].csg", {}).error(None, "wrong")) == "s.toml: object[0].csg: wrong"
    assert str(Table("", "csg", {}).error("radius", "wrong")) == "csg.radius: wrong"


def test_a_scene_error_is_a_value_error():
    assert issubclass(SceneError, ValueError)


def test_a_table_must_be_a_table():
    assert error(lambda: Table("s.toml", "camera", [1, 2])) == "s.toml: camera: expected a table, got [1, 2]"


# --------------------------------------------------------------------------- keys
def test_an_unknown_key_gets_the_nearest_allowed_one():
    assert error(lambda: Table("s.toml", "camera", {"view_angel": 30}, {"view_angle", "position"})) == \
        "s.toml: camera.view_angel: unknown key (did you mean 'view_angle'?)"


def test_an_unknown_key_with_nothing_near_lists_the_allowed_ones():
    assert error(lambda: Table("s.toml", "render", {"zbuffer": True}, {"ambient", "transparency"})) == \
        "s.toml: render.zbuffer: unknown key (valid: ambient, transparency)"


def test_an_odd_key_is_shown_quoted_and_short():
    message = error(lambda: Table("s.toml", "image", {"a b" * 50: 1}, {"size"}))
    assert message.startswith("s.toml: image.'a ba b") and len(message) < 120


def test_check_keys_later_for_tables_whose_keys_depend_on_a_value():
    t = Table("s.toml", "csg", {"primitive": "sphere", "radus": 1})
    assert error(lambda: t.check_keys(("primitive", "radius"))) == \
        "s.toml: csg.radus: unknown key (did you mean 'radius'?)"


def test_a_required_key_that_is_missing_is_named():
    assert error(lambda: table().number("offset", REQUIRED)) == "scene.toml: camera: missing key 'offset'"
    assert error(lambda: table().vector("plane", REQUIRED)) == "scene.toml: camera: missing key 'plane'"
    assert table(offset=2).number("offset", REQUIRED) == 2.0


# --------------------------------------------------------------------------- numbers
def test_number_reads_ints_and_floats_as_floats_and_uses_the_default():
    assert table(a=3).number("a", 0.0) == 3.0 and isinstance(table(a=3).number("a", 0.0), float)
    assert table().number("a", 0.5) == 0.5


@pytest.mark.parametrize("value, words", [
    ("30", "expected a number, got '30'"),
    (True, "expected a number, got True"),
    (math.nan, "must be finite, got nan"),
    (-math.inf, "must be finite, got -inf"),
    (10 ** 400, "must be finite, got 1" + "0" * 58 + "…"),
], ids=["string", "bool", "nan", "-inf", "int-beyond-float"])
def test_number_refuses_what_is_not_a_finite_number(value, words):
    assert error(lambda: table(a=value).number("a", 0.0)) == f"scene.toml: camera.a: {words}"


@pytest.mark.parametrize("value, bounds, message", [
    (-1, dict(lo=0.0, hi=1000.0), "-1 is outside [0, 1000]"),
    (1001, dict(lo=0.0, hi=1000.0), "1001 is outside [0, 1000]"),
    (0, dict(lo=0.0, hi=180.0, lo_open=True), "0 is outside (0, 180]"),
    (180, dict(lo=0.0, hi=180.0, lo_open=True, hi_open=True), "180 is outside (0, 180)"),
    (2e15, dict(), "2e+15 is outside [-1e+15, 1e+15]"),
    (-1, dict(lo=0.0, lo_open=True), "-1 is outside (0, 1e+15]"),
])
def test_number_keeps_its_bounds_closed_or_open(value, bounds, message):
    assert error(lambda: table(a=value).number("a", 0.0, **bounds)) == f"scene.toml: camera.a: {message}"


def test_number_accepts_its_closed_bounds():
    assert table(a=0).number("a", 1.0, 0.0, 1.0) == 0.0 and table(a=1).number("a", 0.0, 0.0, 1.0) == 1.0
    assert table(a=1e15).number("a", 0.0) == 1e15


# --------------------------------------------------------------------------- vectors
def test_vector_reads_n_numbers_as_a_tuple_of_floats():
    assert table(p=[1, 2.5, -3]).vector("p", None) == (1.0, 2.5, -3.0)
    assert table(s=[64, 48]).vector("s", None, 2) == (64.0, 48.0)
    assert table().vector("p", (0.0, 0.0, 1.0)) == (0.0, 0.0, 1.0)
    assert table().vector("p", None) is None


@pytest.mark.parametrize("value, kwargs, words", [
    ([1, 2], {}, "expected a list of 3 numbers, got [1, 2]"),
    ("1, 2, 3", {}, "expected a list of 3 numbers, got '1, 2, 3'"),
    ([1, "2", 3], {}, "expected 3 finite numbers, got [1, '2', 3]"),
    ([0, math.inf, 0], {}, "expected 3 finite numbers, got [0, inf, 0]"),
    ([1e308, 0, 0], {}, "values must lie in [-1e+15, 1e+15], got [1e+308, 0, 0]"),
    ([1, -1, 1], dict(lo=0.0), "values must lie in [0, 1e+15], got [1, -1, 1]"),
    ([1, 0, 1], dict(lo=0.0, lo_open=True), "values must lie in (0, 1e+15], got [1, 0, 1]"),
])
def test_vector_refuses_wrong_lengths_types_and_ranges(value, kwargs, words):
    assert error(lambda: table(p=value).vector("p", None, **kwargs)) == f"scene.toml: camera.p: {words}"


# --------------------------------------------------------------------------- colours
def test_colour_is_quantised_to_k_over_255():
    assert table(c=[1, 0.5, 0.1]).colour("c", None) == (1.0, 128 / 255, 26 / 255)
    assert quantise_colour((0.0, 0.999, 0.002)) == (0.0, 1.0, 1 / 255)
    assert table().colour("c", None) is None


@pytest.mark.parametrize("value", [[1.5, 0, 0], [0.5, -0.1, 0]])
def test_colour_components_lie_in_zero_one(value):
    assert "values must lie in [0, 1]" in error(lambda: table(c=value).colour("c", None))


# --------------------------------------------------------------------------- flags and choices
def test_flag_is_true_or_false_and_nothing_else():
    assert table(f=True).flag("f", False) is True and table().flag("f", False) is False
    assert error(lambda: table(f=1).flag("f", False)) == "scene.toml: camera.f: expected true or false, got 1"


def test_choice_names_the_valid_strings():
    assert table(s="phong").choice("s", "flat", ("flat", "gouraud", "phong")) == "phong"
    assert table().choice("s", "flat", ("flat", "phong")) == "flat"
    assert error(lambda: table(s="gourad").choice("s", "flat", ("flat", "gouraud"))) == \
        "scene.toml: camera.s: 'gourad' is not one of flat, gouraud (did you mean 'gouraud'?)"
    assert error(lambda: table(s=["flat"]).choice("s", "flat", ("flat", "gouraud"))) == \
        "scene.toml: camera.s: ['flat'] is not one of flat, gouraud"


def test_choice_with_a_noun_says_what_is_unknown():
    assert error(lambda: table(op="xor").choice("op", REQUIRED, ("union", "difference"), noun="op")) == \
        "scene.toml: camera.op: unknown op 'xor'; valid: union, difference"


# --------------------------------------------------------------------------- lists of tables
def test_tables_are_named_by_their_index():
    parts = Table("s.toml", "csg", {"children": [{"a": 1}, {"b": 2}]}).tables("children")
    assert [(p.where, p.table) for p in parts] == [("csg.children[0]", {"a": 1}), ("csg.children[1]", {"b": 2})]
    assert error(lambda: Table("s.toml", "csg", {"children": []}).tables("children")) == \
        "s.toml: csg.children: expected a non-empty list of tables, got []"
    assert error(lambda: Table("s.toml", "csg", {"children": [{}, "x"]}).tables("children")) == \
        "s.toml: csg.children[1]: expected a table, got 'x'"
