"""The diagnosis registry: stable codes, each in one family, in English and Japanese."""
import pytest

from lab.app.exercises.diagnoses.codes import FAMILIES, Diagnosis, Finding, load_families, register, status, text

ALL = load_families()


def test_every_family_registers_its_codes():
    assert {d.family for d in ALL.values()} == set(FAMILIES)
    assert len(ALL) >= 45


def test_only_the_runtime_family_means_cannot_be_judged():
    assert {d.code for d in ALL.values() if d.status == 2} == {d.code for d in ALL.values() if d.family == "runtime"}
    assert status([]) == 0 and status([Finding("faces-inward")]) == 1
    assert status([Finding("faces-inward"), Finding("time-limit")]) == 2


def test_codes_are_registered_once():
    with pytest.raises(ValueError, match="twice"):
        register("faces-inward", "mesh", "x", "x")


def test_a_missing_figure_shows_as_a_question_mark_not_an_exception():
    assert "?" in text(Finding("faces-inward", {}), "en")


@pytest.mark.parametrize("code", sorted(ALL))
def test_every_code_has_text_in_both_languages(code):
    d: Diagnosis = ALL[code]
    assert d.en and d.ja and d.en != d.ja
