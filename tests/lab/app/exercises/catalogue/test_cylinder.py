"""The cylinder exercise: right solutions pass (fans with or without a centre, either
diagonal); a faceted side, caps sharing the rim, normals not unit or inward fail."""
import pytest

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),
    ("right", "right", None),
    ("faceted", "wrong", "side-faceted"),
    ("shared_caps", "wrong", "caps-share-side-points"),
    ("not_unit", "wrong", "normals-not-unit"),
    ("normals_inward", "wrong", "normals-inward"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("cylinder", fixture, verdict, code)


def test_the_faceted_side_also_fails_the_picture():
    """Gouraud shading shows the facets: the render misses the bars as well."""
    assert "render-differs" in judged("cylinder", "faceted").codes


def test_non_unit_normals_are_measured():
    assert judged("cylinder", "not_unit").findings[0].details["length"] == pytest.approx(0.5)
