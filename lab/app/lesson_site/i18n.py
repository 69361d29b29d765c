"""Words the lesson site's own code puts on pages, and their Japanese.

The lessons' text is translated by Sphinx's i18n (``locales/ja/LC_MESSAGES/<lesson>.po``);
the words the figure directive and the plots generate (panel titles, metric names,
verdicts, button labels) come from the message catalog :data:`CATALOG`
(``locales/ja/LC_MESSAGES/scanlab.po``), looked up with :func:`_` in the page's language.
"""
from __future__ import annotations

from pathlib import Path

from sphinx.locale import get_translation

from lab.app.lesson_site.places import LOCALES

CATALOG = "scanlab"
LOCALE_DIR = LOCALES
"""``lessons/locales``: the Japanese .po files of the pages and of :data:`CATALOG`."""

_translate = get_translation(CATALOG)


def _(message: str) -> str:
    """``message`` in the build's language (as it is, outside a Sphinx build)."""
    return str(_translate(message))


def compile_catalog(language: str, locale_dir: Path = LOCALE_DIR) -> Path | None:
    """Compile ``<locale_dir>/<language>/LC_MESSAGES/scanlab.po`` to its ``.mo`` when it is
    newer; return the .mo (None when the language has no catalog, e.g. English)."""
    from sphinx.util.i18n import CatalogInfo

    folder = locale_dir / language / "LC_MESSAGES"
    if not (folder / f"{CATALOG}.po").is_file():
        return None
    info = CatalogInfo(str(folder), CATALOG, "utf-8")
    if info.is_outdated():
        info.write_mo(language)
    return folder / f"{CATALOG}.mo"


def setup_catalog(app) -> None:
    """Register :data:`CATALOG` for the build's language (compiled first)."""
    compile_catalog(app.config.language)
    app.add_message_catalog(CATALOG, str(LOCALE_DIR))
