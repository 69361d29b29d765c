"""The Menger sponge exercise: the reference and a differently written right solution pass;
the typical mistakes fail with their diagnosis, in English and Japanese."""
import pytest

from lab.app.exercises.exercise_registry import get

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),        # the built-in shape handed in
    ("right", "right", None),            # other point order, other diagonals
    ("inward", "wrong", "faces-inward"),
    ("internal_faces", "wrong", "internal-faces-kept"),
    ("centre_only", "wrong", "wrong-subcubes"),
    ("unmerged", "wrong", "points-not-merged"),
    ("unscaled", "wrong", "wrong-scale"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("menger", fixture, verdict, code)


def test_every_face_of_the_clockwise_sponge_is_counted():
    finding = judged("menger", "inward").findings[0]
    assert finding.details["count"] == finding.details["total"] == 12 and finding.details["case"] == "menger(0)"


def test_the_sub_cube_count_is_read_from_the_volume():
    finding = judged("menger", "centre_only").findings[0]
    assert (finding.details["cells"], finding.details["expected"]) == (26, 20)


def test_internal_faces_show_as_edges_used_four_times():
    finding = judged("menger", "internal_faces").findings[0]
    assert finding.details["count"] > 0 and finding.details["edges"] > 0


def test_the_right_solution_is_drawn_at_level_3_and_meets_the_bars():
    report = judged("menger", "right")
    (panel,) = report.panels
    assert panel.call == "menger(3)" and panel.failed == []


def test_level_3_is_checked_as_the_textbook_asks():
    assert [c.args for c in get("menger").cases()] == [(0,), (1,), (2,), (3,)]
