"""The raster exercise: right solutions pass on every pixel of about 400 triangles; each
mistaken fill rule is classified pixel by pixel and named."""
import pytest

from lab.app.exercises.exercise_registry import get

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),
    ("right", "right", None),            # edge functions over the window, no scanlines
    ("inclusive", "wrong", "ties-drawn-twice"),
    ("exclusive", "wrong", "ties-missed"),
    ("mirrored_rule", "wrong", "tie-rule-mirrored"),
    ("rows_flipped", "wrong", "rows-flipped"),
    ("corners", "wrong", "corners-not-centres"),
    ("clockwise", "wrong", "clockwise-missed"),
    ("unsnapped", "wrong", "no-subpixel-snap"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("covered_pixels", fixture, verdict, code)


def test_hundreds_of_triangles_are_asked():
    assert len(get("covered_pixels").cases()) >= 300


def test_every_wrong_rule_also_gets_the_pixel_classes_with_the_first_triangles_and_pixels():
    d = judged("covered_pixels", "inclusive").findings[-1].details
    assert d["counts"]["duplicated"] > 0 and d["counts"]["missing"] == 0
    first = d["first"]["duplicated"]
    assert len(first["triangles"]) == 2 and first["mesh"] == "fan around a pixel centre"
    assert {"x", "y", "corners"} <= set(first)


def test_the_mirrored_rule_loses_and_adds_pixels_only_along_outlines():
    d = judged("covered_pixels", "mirrored_rule").findings[-1].details["counts"]
    assert d["duplicated"] == 0 and d["missing"] > 0 and d["unexpected"] > 0


def test_the_panel_is_drawn_for_right_and_wrong(tmp_path):
    for fixture in ("right", "inclusive"):
        (path,) = judged("covered_pixels", fixture).write_panels(tmp_path, fixture)
        assert path.stat().st_size > 10_000
