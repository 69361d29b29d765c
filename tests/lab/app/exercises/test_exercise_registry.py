"""The exercise registry: every exercise found through it, each with what the lesson site needs."""
import ast

import pytest

from lab.app.exercises.exercise_registry import EXERCISES, LESSONS, Exercise, exercises, get, register

ALL = exercises()


def test_the_course_s_exercises_and_the_pipeline_s_stages_are_registered():
    assert set(ALL) >= {"menger", "icosahedron_fractal", "icosphere", "cylinder", "cone", "look_at",
                        "covered_pixels", "perspective"}


@pytest.mark.parametrize("name", ALL)
def test_each_carries_its_page_in_both_languages(name):
    ex = ALL[name]
    assert ex.lesson in LESSONS
    for lang in ("en", "ja"):
        page = ex.page(lang)
        assert page["title"] and len(page["statement"]) > 200 and page["lesson_title"]
        assert page["command"] == f"scanlab exercise check {name} {name}.py"
    assert ex.title["en"] != ex.title["ja"] and ex.statement["en"] != ex.statement["ja"]


@pytest.mark.parametrize("name", ALL)
def test_its_cases_fit_its_parameters(name):
    ex = ALL[name]
    cases = ex.cases()
    assert cases and all(len(c.args) == len(ex.parameters) for c in cases)
    assert all(c.call.startswith(f"{name}(") for c in cases)


def test_a_name_is_registered_once_and_a_lesson_must_exist():
    ex = get("menger")
    with pytest.raises(ValueError, match="twice"):
        register(ex)
    with pytest.raises(ValueError, match="unknown lesson"):
        register(Exercise(**{**ex.__dict__, "name": "menger2", "lesson": "99-nothing"}))
    assert "menger2" not in EXERCISES


def test_an_unknown_name_is_a_key_error():
    with pytest.raises(KeyError):
        get("mengr")


def test_no_module_outside_the_catalogue_branches_on_an_exercise_name():
    """One room per exercise: no ``if name == "menger"`` anywhere in the application."""
    from pathlib import Path

    import lab.app.exercises as package

    root = Path(package.__file__).parent
    for path in root.rglob("*.py"):
        if "catalogue" in path.parts:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Compare):
                names = [c.value for c in [node.left, *node.comparators] if isinstance(c, ast.Constant)]
                assert not set(names) & set(ALL), f"{path.name}:{node.lineno} branches on an exercise name"


def test_the_lessons_are_the_lesson_site_s_folders():
    """An exercise names its lesson by the folder the lesson site builds it from (lessons/NN-name/)."""
    from pathlib import Path

    root = Path(__file__).resolve().parents[4] / "lessons"
    assert sorted(LESSONS) == sorted(p.name for p in root.iterdir() if p.is_dir() and p.name[:2].isdigit())
