"""lab/app/lesson_site/pages.py: the language switch, and the check that stops a build."""
from types import SimpleNamespace

import pytest

from lab.app.lesson_site import record
from lab.app.lesson_site.pages import FigureCheckError, on_env_updated, on_html_page_context


@pytest.mark.parametrize("language, pagename, href", [
    ("en", "05-scanline/index", "../../ja/05-scanline/index.html"),
    ("ja", "05-scanline/index", "../../en/05-scanline/index.html"),
    ("en", "glossary", "../ja/glossary.html"),
])
def test_every_page_links_the_same_page_in_the_other_language(language, pagename, href):
    context = {}
    on_html_page_context(SimpleNamespace(config=SimpleNamespace(language=language)), pagename, "page.html", context, None)
    assert context["scanlab_switch"]["href"] == href
    assert context["scanlab_chooser"] == href.split(("ja/" if language == "en" else "en/"))[0] + "index.html"


def test_a_figure_that_breaks_its_promise_stops_the_build():
    env = SimpleNamespace(docname="05-scanline/index")
    assert on_env_updated(None, env) == []
    record.problem(env, "05-scanline/index: figure-fill-rule-fill-rule: PASSES? (within the bars)")
    with pytest.raises(FigureCheckError, match="PASSES"):
        on_env_updated(None, env)
