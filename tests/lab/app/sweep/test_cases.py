"""Cases: the grid from --grid options and a grid file, crossed over the sources; stable identities."""
from __future__ import annotations

import pytest

from lab.app.sweep.cases import Case, GridError, build_grid, expand, parse_grid_option, read_grid_file
from lab.app.sweep.sources import Source

CUBE, ICO = Source("shape", "cube", "cube"), Source("shape", "icosphere:level=1", "icosphere:level=1")


def test_a_grid_option_gives_its_key_and_canonical_values_once_each():
    assert parse_grid_option("size=64X48,64x48, 80x60") == ("size", ["64x48", "80x60"])


@pytest.mark.parametrize("text, message", [
    ("shading", "expected KEY=V1,V2"), ("shadin=flat", "did you mean shading?"),
    ("shading=flat,flatt", "did you mean flat?"), ("shading=", "not one of")])
def test_a_bad_grid_option_is_refused_in_one_line(text, message):
    with pytest.raises(GridError, match=message.replace("?", r"\?")):
        parse_grid_option(text)


def test_every_source_is_crossed_with_every_combination_in_grid_key_order():
    cases = expand([CUBE, ICO], {"lights": ["key", "spot"], "shading": ["flat", "gouraud", "phong"]})
    assert len(cases) == 12
    assert cases[0].settings == (("shading", "flat"), ("lights", "key"))
    assert cases[1].settings == (("shading", "flat"), ("lights", "spot")), "the last key varies fastest"
    assert [c.source for c in cases[:6]] == [CUBE] * 6
    assert cases[0].label == "cube shading=flat lights=key"


def test_no_grid_gives_one_case_per_source():
    assert [c.settings for c in expand([CUBE, ICO], {})] == [(), ()]


def test_a_case_is_named_by_its_source_and_settings_whatever_their_order():
    a = Case(CUBE, (("shading", "flat"), ("lights", "key")))
    assert a.case_id == Case(CUBE, (("lights", "key"), ("shading", "flat"))).case_id
    assert len(a.case_id) == 16
    assert a.case_id != Case(ICO, a.settings).case_id
    assert a.case_id != Case(CUBE, (("shading", "flat"), ("lights", "spot"))).case_id


def test_a_grid_file_holds_keys_and_sources_and_an_option_replaces_a_key(tmp_path):
    (tmp_path / "meshes").mkdir()
    grid_file = tmp_path / "grid.toml"
    grid_file.write_text('sources = ["meshes", "cube"]\nshading = ["flat", "phong"]\nsize = "64x48"\nopacity = 0.5\n')
    grid, sources = read_grid_file(grid_file)
    assert grid == {"shading": ["flat", "phong"], "size": ["64x48"], "opacity": ["0.5"]}
    assert sources == [str(tmp_path / "meshes"), "cube"], "paths are relative to the grid file"
    assert build_grid(grid, ["shading=gouraud"])["shading"] == ["gouraud"]


@pytest.mark.parametrize("text, message", [
    ("shading = [", "not a TOML grid file"), ("colour = ['red']", "unknown grid key"),
    ("shading = [true]", "expected a value or a list"), ("sources = 'cube'", "sources: expected a list"),
    ("size = ['64y48']", "WIDTHxHEIGHT")])
def test_a_bad_grid_file_is_refused_naming_the_file(tmp_path, text, message):
    grid_file = tmp_path / "grid.toml"
    grid_file.write_text(text)
    with pytest.raises(GridError, match=message) as err:
        read_grid_file(grid_file)
    assert str(err.value).startswith(str(grid_file))


def test_a_key_given_twice_on_the_command_line_is_refused():
    with pytest.raises(GridError, match="given twice"):
        build_grid({}, ["shading=flat", "shading=phong"])
