"""Japanese search: the course's terms kept whole.

Japanese has no spaces, so Sphinx's search index splits Japanese text into words with a
morphological analyser (Janome, ``sphinx.search.ja.JanomeSplitter``). Its dictionary
does not know the course's compound terms and cuts them up: スキャンライン becomes
スキャン + ライン, 隠面消去 becomes 隠 + 面 + 消去. The search box does not split what a
reader types, so a search for スキャンライン would then find nothing. A user dictionary
of the course's terms (``locales/ja/search-terms.txt``, one per line) keeps each one a
single word in the index.
"""
from __future__ import annotations

from pathlib import Path

from lab.app.lesson_site.places import LOCALES

TERMS = LOCALES / "ja" / "search-terms.txt"

NOUN_ID = 1285
"""IPADIC's context id of a common noun (名詞,一般)."""

COST = -5000
"""A low cost, so that the whole term wins over any split of it."""


def course_terms(path: Path = TERMS) -> list[str]:
    """The terms of ``search-terms.txt`` (blank lines and ``#`` comments skipped)."""
    lines = (line.strip() for line in path.read_text(encoding="utf-8").splitlines())
    return [line for line in lines if line and not line.startswith("#")]


def user_dictionary(path: Path, terms: list[str] | None = None) -> Path:
    """Write the terms as a Janome user dictionary (MeCab IPADIC CSV) to ``path``; return it."""
    from lab.atomic import write_text

    rows = [f"{t},{NOUN_ID},{NOUN_ID},{COST},名詞,一般,*,*,*,*,{t},*,*" for t in (terms or course_terms())]
    path.parent.mkdir(parents=True, exist_ok=True)
    write_text(path, "\n".join(rows) + "\n")
    return path


def search_options(dest: Path) -> dict:
    """``html_search_options`` for Japanese pages: Janome with the course's terms."""
    return {"type": "sphinx.search.ja.JanomeSplitter", "user_dic": str(user_dictionary(dest)), "user_dic_enc": "utf8"}
