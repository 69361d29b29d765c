"""Normals family: the formula to use is in the message."""
from lab.app.exercises.diagnoses.codes import Finding, text


def test_the_side_normal_formula_is_quoted_in_both_languages():
    f = Finding("side-faceted", {"case": "cylinder(8, 0.5, 1)", "count": 16, "formula": "(cos θ_k, sin θ_k, 0)"})
    assert "(cos θ_k, sin θ_k, 0)" in text(f, "en") and "(cos θ_k, sin θ_k, 0)" in text(f, "ja")
    assert "16 points" in text(f, "en") and "16 個" in text(f, "ja")


def test_the_cone_normal_is_spelled_out():
    assert "(h·cos θ, h·sin θ, r) / √(h² + r²)" in text(Finding("cone-normals-not-tilted", {"case": "c", "count": 3}), "en")
