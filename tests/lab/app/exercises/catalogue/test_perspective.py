"""The perspective exercise: right solutions pass; transposed, Direct3D's depth range, the
whole angle and degrees given to tan are named."""
import numpy as np
import pytest

from lab.app.exercises.catalogue.perspective import CASES as CAMERAS, projection, reference
from lab.app.exercises.exercise_registry import Case

from ..checked_fixtures import expect

CASES = [
    ("reference", "right", None),
    ("right", "right", None),
    ("transposed", "wrong", "matrix-transposed"),
    ("zero_to_one", "wrong", "depth-range-0-1"),
    ("whole_angle", "wrong", "fov-not-halved"),
    ("degrees", "wrong", "fov-in-degrees"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("perspective", fixture, verdict, code)


@pytest.mark.parametrize("args", CAMERAS)
def test_the_exercise_s_matrix_is_the_renderer_s_and_maps_near_and_far(args):
    m = projection(*args)
    assert np.allclose(m, reference(Case(args, "")), atol=1e-12)
    near, far = args[2], args[3]
    for z, ndc in ((-near, -1.0), (-far, 1.0)):
        clip = np.array([0.0, 0.0, z, 1.0]) @ m
        assert clip[2] / clip[3] == pytest.approx(ndc)
