"""lab/app/lesson_site/i18n.py and the Japanese catalogs: every word the site shows has its Japanese."""
import ast
import re
from pathlib import Path

from babel.messages.pofile import read_po

from lab.app.lesson_site import i18n
from lab.app.lesson_site.i18n import LOCALE_DIR, compile_catalog

SITE = Path(i18n.__file__).resolve().parent
CATALOGS = LOCALE_DIR / "ja" / "LC_MESSAGES"


def generated_words() -> set[str]:
    """Every literal passed to ``_()`` in the site's code."""
    words = set()
    for path in SITE.glob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and getattr(node.func, "id", None) == "_" and node.args \
                    and isinstance(node.args[0], ast.Constant):
                words.add(node.args[0].value)
    return words


def test_every_generated_word_has_its_japanese():
    catalog = {m.id: m.string for m in read_po(open(CATALOGS / "scanlab.po", "rb")) if m.id}
    words = generated_words()
    assert len(words) > 50
    missing = sorted(w for w in words if not catalog.get(w))
    assert missing == []
    assert sorted(set(catalog) - words) == []  # nothing stale either


def needs_words(msgid: str) -> bool:
    """Whether a message has English words outside code, roles and formulas."""
    text = re.sub(r"\{src\}`[^`]*`|`[^`]*`|\$\$.*?\$\$|\$[^$]*\$", "", msgid, flags=re.S)
    text = re.sub(r"\\[a-zA-Z]+(\{[a-zA-Z*]+\})?", "", text)
    return re.search(r"[A-Za-z]{2,}", text) is not None


def test_every_lesson_message_is_translated_and_none_is_fuzzy():
    problems = []
    for path in sorted(CATALOGS.glob("*.po")):
        for m in read_po(open(path, "rb")):
            if m.id and (m.fuzzy or (needs_words(m.id) and not m.string)):
                problems.append(f"{path.name}: {'fuzzy' if m.fuzzy else 'untranslated'}: {m.id[:60]}")
    assert problems == []
    assert len(list(CATALOGS.glob("*.po"))) == 18  # 13 lessons, exercises, glossary, index, scanlab, sphinx


def test_the_catalog_compiles_for_japanese_and_english_has_none():
    assert compile_catalog("ja").is_file() and compile_catalog("en") is None
