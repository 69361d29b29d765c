"""The look-at exercise: right solutions pass; a transposed matrix, mirrored or upside-down
frames, a reversed N and an untilted up are named."""
import numpy as np
import pytest

from lab.app.exercises.catalogue.look_at import CASES as CAMERAS, frame, reference
from lab.app.exercises.exercise_registry import Case

from ..checked_fixtures import expect, judged

CASES = [
    ("reference", "right", None),
    ("right", "right", None),
    ("transposed", "wrong", "matrix-transposed"),
    ("mirrored", "wrong", "camera-mirrored"),
    ("upside_down", "wrong", "camera-upside-down"),
    ("reversed", "wrong", "view-direction-reversed"),
    ("raw_up", "wrong", "up-not-orthogonalised"),
]


@pytest.mark.parametrize("fixture, verdict, code", CASES)
def test_fixture_is_judged_as_expected(fixture, verdict, code):
    expect("look_at", fixture, verdict, code)


@pytest.mark.parametrize("args", CAMERAS)
def test_the_exercise_s_frame_is_the_renderer_s(args):
    assert np.allclose(frame(*args), reference(Case(args, "")), atol=1e-12)


def test_a_mirrored_frame_is_left_handed_and_an_upside_down_one_is_not():
    args = CAMERAS[0]
    assert np.linalg.det(frame(*args, v_flipped=True)[:3, :3]) == pytest.approx(-1)
    assert np.linalg.det(frame(*args, u_flipped=True)[:3, :3]) == pytest.approx(1)


def test_the_panel_shows_the_scene_through_the_student_s_camera():
    """Right: the picture meets the bars; mirrored: it does not; transposed: no picture (not affine)."""
    assert judged("look_at", "right").panels[0].failed == []
    assert judged("look_at", "mirrored").panels[0].failed != []
    assert judged("look_at", "transposed").panels == []
