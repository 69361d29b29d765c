"""lab/app/lesson_site/exercise.py: an exercise's page is built from the exercise registry, in the page's language."""
import pytest
from docutils import nodes

from lab.app.exercises.exercise_registry import exercises
from lab.app.lesson_site import exercise
from lab.app.lesson_site.places import LESSONS


class _Config:
    def __init__(self, language):
        self.language = language


@pytest.mark.parametrize("language, lang", [("en", "en"), ("ja", "ja"), (None, "en")])
def test_the_language_is_read_from_the_config(language, lang):
    assert exercise._lang(_Config(language)) == lang


def test_every_exercise_page_has_a_directive_page_in_the_site():
    """lessons/exercises/<name>.md exists for every registered exercise, and names it."""
    folder = LESSONS / "exercises"
    for name in exercises():
        assert (folder / f"{name}.md").read_text().strip() == f"```{{scanlab-exercise}} {name}\n```"
        assert f"\n{name}\n" in (folder / "index.md").read_text()


def test_a_literal_block_keeps_its_language():
    block = exercise._literal("x = 1", "python")
    assert isinstance(block, nodes.literal_block) and block["language"] == "python" and block.astext() == "x = 1"
