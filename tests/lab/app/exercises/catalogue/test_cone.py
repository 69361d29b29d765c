"""The cone exercise: right solutions pass (apex normals at mid-segment); normals not
tilted, a base sharing the ring, one apex point with (0, 0, 1) and an inward base fail."""
import pytest

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),
    ("right", "right", None),
    ("not_tilted", "wrong", "cone-normals-not-tilted"),
    ("shared_base", "wrong", "caps-share-side-points"),
    ("one_apex", "wrong", "side-normals-wrong"),
    ("base_inward", "wrong", "faces-inward"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("cone", fixture, verdict, code)


def test_the_shared_apex_is_the_point_named():
    assert judged("cone", "one_apex").findings[0].details["point"] == "(0, 0, 0.5)"
