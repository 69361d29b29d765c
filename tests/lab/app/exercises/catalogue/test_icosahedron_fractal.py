"""The icosahedron fractal exercise: right solutions pass (merged or separate copies); a
wrong scale factor, inward faces and misplaced copies fail with their diagnosis."""
import numpy as np
import pytest

from lab import shapes
from lab.app.exercises.catalogue.icosahedron_fractal import S, centres, expected
from lab.app.exercises.exercise_registry import Case
from lab.measure import enclosed_volume, surface_area

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),
    ("right", "right", None),
    ("half_scale", "wrong", "wrong-scale-factor"),
    ("inward", "wrong", "faces-inward"),
    ("copies_at_vertices", "wrong", "wrong-scale"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("icosahedron_fractal", fixture, verdict, code)


def test_the_scale_factor_is_read_from_the_edges():
    assert judged("icosahedron_fractal", "half_scale").findings[0].details["factor"] == pytest.approx(0.5)


@pytest.mark.parametrize("level", [0, 1, 2, 3])
def test_the_formulas_are_the_built_in_shape_s(level):
    """Area and volume 12^N·s^(2N), 12^N·s^(3N) times the icosahedron's; the centres are the built-in's."""
    mesh, exp = shapes.icosahedron_fractal(level), expected(Case((level,), ""))
    assert exp.area == pytest.approx(surface_area(mesh), rel=1e-12)
    assert exp.volume == pytest.approx(enclosed_volume(mesh), rel=1e-12)
    assert np.allclose(mesh.points.reshape(-1, 12, 3).mean(axis=1), centres(level))
    assert S == pytest.approx(1 / (1 + shapes.PHI))
