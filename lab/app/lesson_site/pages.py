"""Build-wide steps of the lesson site: language settings, the language switch, checks, copies.

- ``config-inited``: Japanese pages get a Japanese site title and index their text with
  Janome and the course's terms (:mod:`lab.app.lesson_site.search`).
- ``builder-inited``: MathJax and a Japanese font join the static files (:mod:`lab.app.lesson_site.assets`);
  English pages need the font too, for the link to the Japanese ones.
- ``html-page-context``: every page gets a link to the same page in the other language
  (the site is published as ``en/`` and ``ja/`` side by side).
- ``env-updated``: the build stops if any figure's verdict is not the one its lesson
  promises (:class:`FigureCheckError`).
- ``build-finished``: the figures the pages show are copied from the cache to
  ``_figures/``, the scene files to ``_scenes/``.
"""
from __future__ import annotations

from pathlib import Path

from sphinx.errors import SphinxError

from lab.app.lesson_site import record
from lab.app.lesson_site.assets import copy_file, static_folder
from lab.app.lesson_site.search import TERMS, search_options

LANGUAGES = {"en": "English", "ja": "日本語"}


class FigureCheckError(SphinxError):
    """Figures whose verdict is not the one their lesson promises."""

    category = "Figure check failed"


def is_japanese(config) -> bool:
    return (config.language or "en").startswith("ja")


def on_config_inited(app, config) -> None:
    if not config.scanlab_figure_cache:  # sphinx-build run by hand: beside the doctrees
        config.scanlab_figure_cache = str(Path(app.doctreedir).parent / "scanlab-figures")
    if is_japanese(config):
        config.html_title = config.project = "scanlab レッスン"
        config.html_search_options = search_options(TERMS.with_suffix(".csv"))  # beside the terms: one path,
        # whatever the output folder, so that two builds of the site are the same bytes


def on_builder_inited(app) -> None:
    if app.builder.format != "html":
        return
    extra = static_folder(Path(app.doctreedir) / "static-extra")
    app.config.html_static_path = [*app.config.html_static_path, str(extra)]


def other_language(language: str) -> str:
    return "en" if language.startswith("ja") else "ja"


def on_html_page_context(app, pagename, templatename, context, doctree) -> None:
    """``scanlab_switch``: the same page in the other language, relative to this one."""
    other = other_language(app.config.language or "en")
    up = "../" * (pagename.count("/") + 1)
    context["scanlab_switch"] = {"href": f"{up}{other}/{pagename}.html", "label": LANGUAGES[other], "lang": other}
    context["scanlab_chooser"] = f"{up}index.html"


def on_env_updated(app, env) -> list:
    problems = [p for doc in sorted(record.all_of(env, "scanlab_problems"))
                for p in record.all_of(env, "scanlab_problems")[doc]]
    if problems:
        raise FigureCheckError("\n".join(problems))
    return []


def figure_keys(env) -> set[str]:
    return {k for keys in record.all_of(env, "scanlab_figures").values() for k in keys}


def on_build_finished(app, exception) -> None:
    if exception is not None or app.builder.format != "html":
        return
    out = Path(app.outdir)
    cache = Path(app.config.scanlab_figure_cache)
    for key in sorted(figure_keys(app.env)):
        for image in (cache / key).glob("*.png"):
            copy_file(image, out / "_figures" / key / image.name)
    srcdir = Path(app.srcdir).resolve()
    for paths in record.all_of(app.env, "scanlab_scenes").values():
        for path in paths:
            copy_file(Path(path), out / "_scenes" / Path(path).resolve().relative_to(srcdir))
