"""Naming a matrix mistake: the variant equal to the student's matrix on every wrong case."""
import numpy as np

from lab.app.exercises.matrixexercise import MatrixExercise, judge_matrices
from lab.app.exercises.exercise_registry import Case

CASES = [Case((k,), f"m({k})") for k in (1.0, 2.0, 3.0)]
RIGHT = lambda case: np.diag([case.args[0], 1, 1, 1]) + np.eye(4, k=1)  # noqa: E731
SPEC = MatrixExercise(reference=RIGHT, variants=(("fov-not-halved", lambda case: RIGHT(case) * 2),))


def judge(make):
    return judge_matrices(SPEC, CASES, [[make(c)] for c in CASES])


def test_right_matrices_pass():
    assert judge(RIGHT).findings == []


def test_a_known_mistake_is_named_with_its_first_case():
    (f,) = judge(lambda c: RIGHT(c) * 2).findings
    assert (f.code, f.details["case"]) == ("fov-not-halved", "m(1.0)")


def test_a_transposed_mistake_is_named_twice():
    assert [f.code for f in judge(lambda c: (RIGHT(c) * 2).T).findings] == ["matrix-transposed", "fov-not-halved"]
    assert [f.code for f in judge(lambda c: RIGHT(c).T).findings] == ["matrix-transposed"]


def test_anything_else_quotes_the_largest_wrong_entry():
    def wrong(c):
        m = RIGHT(c)
        m[2, 3] += 5 if c.args[0] == 2.0 else 0
        return m
    (f,) = judge(wrong).findings
    assert (f.code, f.details["case"], f.details["row"], f.details["col"], f.details["count"]) == \
        ("matrix-wrong", "m(2.0)", 2, 3, 1)


def test_non_finite_entries_are_reported():
    assert [f.code for f in judge(lambda c: RIGHT(c) * np.nan).findings] == ["nonfinite-values"]
