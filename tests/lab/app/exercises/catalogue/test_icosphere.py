"""The icosphere exercise: right solutions pass; midpoints left inside the sphere, not
shared, or a child turned clockwise fail with their diagnosis."""
import pytest

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),
    ("right", "right", None),            # children listed in another order
    ("not_pushed", "wrong", "points-off-sphere"),
    ("unshared", "wrong", "points-not-merged"),
    ("middle_inward", "wrong", "faces-inward"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("icosphere", fixture, verdict, code)


def test_one_child_in_four_is_counted_inward():
    d = judged("icosphere", "middle_inward").findings[0].details
    assert (d["count"], d["total"]) == (20, 80)


def test_levels_0_to_5_are_checked():
    assert [line.split(":")[0] for line in judged("icosphere", "right").checked["en"][:6]] == \
        [f"icosphere({n})" for n in range(6)]
