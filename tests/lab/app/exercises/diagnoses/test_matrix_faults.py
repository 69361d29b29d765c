"""Matrices family: each mistake named with the rule that mends it."""
from lab.app.exercises.diagnoses.codes import Finding, text


def test_a_mirrored_frame_is_called_left_handed():
    assert "determinant is −1" in text(Finding("camera-mirrored", {"case": "c"}), "en")
    assert "行列式が −1" in text(Finding("camera-mirrored", {"case": "c"}), "ja")


def test_a_wrong_entry_is_quoted():
    f = Finding("matrix-wrong", {"case": "look_at(…)", "row": 3, "col": 0, "got": 1.5, "expected": -2.25, "count": 3})
    assert text(f, "en") == "(look_at(…)) entry [3, 0] is 1.5, expected -2.25 (largest of 3 wrong entries)"
