"""The ``scanlab-exercise`` directive: one exercise's page, from the exercise registry.

``{scanlab-exercise} NAME`` writes the page of exercise ``NAME``
(:mod:`lab.app.exercises.exercise_registry`): its title and statement in the page's language, the
lesson it belongs to (a link), the function's signature, the starter file that
``scanlab exercise start`` writes, and the commands that start and check a solution with
what their exit statuses mean. The statement, the starter and the commands come from the
registry, the one place the checker reads too, so the page cannot drift from what is judged.
"""
from __future__ import annotations

from docutils import nodes
from sphinx.util.docutils import SphinxDirective

from lab.app.lesson_site.i18n import _


def _lang(config) -> str:
    return "ja" if (config.language or "en").startswith("ja") else "en"


def _literal(text: str, language: str) -> nodes.literal_block:
    block = nodes.literal_block(text, text)
    block["language"] = language
    return block


class ScanlabExercise(SphinxDirective):
    """``{scanlab-exercise} NAME``: the whole page of one exercise, headed by its title."""

    required_arguments = 1
    has_content = False

    def run(self) -> list[nodes.Node]:
        from lab.app.exercises.exercise_registry import exercises

        found = exercises()
        name = self.arguments[0]
        if name not in found:
            raise self.error(f"unknown exercise {name!r}; known: {', '.join(found)}")
        page = found[name].page(_lang(self.config))
        self.env.note_dependency(__file__)

        section = nodes.section(ids=[nodes.make_id(f"exercise-{name}")], names=[nodes.fully_normalize_name(name)])
        section += nodes.title(text=_("Exercise: {title}").format(title=page["title"]))
        prefix = "../" * self.env.docname.count("/")
        lesson = nodes.paragraph()
        lesson += nodes.Text(_("From the lesson") + ": ")
        lesson += nodes.reference("", page["lesson_title"], refuri=f"{prefix}{page['lesson']}/index.html")
        section += lesson
        section += nodes.paragraph(text=page["statement"])

        section += self._heading(name, "signature", _("The function"))
        section += _literal(page["signature"], "python")
        section += self._heading(name, "starter", _("The starter file"))
        section += nodes.paragraph(text=_("scanlab exercise start {name} writes it as {file}:").format(
            name=name, file=f"{name}.py"))
        section += _literal(page["starter"], "python")
        section += self._heading(name, "check", _("Checking a solution"))
        section += _literal(f"scanlab exercise start {name}\n{page['command']}\n{page['command']} --lang ja "
                            f"--out {name}-panels", "console")
        statuses = nodes.bullet_list()
        for text in (_("exit status 0: the solution is right;"),
                     _("exit status 1: it is wrong, and the message says what was found, with a code;"),
                     _("exit status 2: it could not be judged (a syntax error, a missing function, an exception, "
                       "a time or memory limit, arrays of the wrong type)."),
                     _("--out DIR writes the panels: your geometry drawn by scanlab and by VTK beside the "
                       "reference, with the ΔE2000 map.")):
            statuses += nodes.list_item("", nodes.paragraph(text=text))
        section += statuses
        for node in section.findall(nodes.TextElement):  # already in the page's language: not for gettext
            node["translatable"] = False
        return [section]

    @staticmethod
    def _heading(name: str, part: str, text: str) -> nodes.rubric:
        return nodes.rubric(text=text, ids=[nodes.make_id(f"{name}-{part}")])
