"""The README's and docs/'s links between pages: every relative link names a file that exists,
and every ``#anchor`` names a heading of that page, slugged as GitHub slugs it (lower case,
punctuation dropped, spaces made hyphens, a repeated heading numbered -1, -2, …). A heading
renamed without its links fails here."""
from __future__ import annotations

import functools
import re
from collections import Counter
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
LINK = re.compile(r"\[[^\]]*\]\(([^)\s]+)\)")
FENCE = re.compile(r"^```.*?^```", re.S | re.M)


def slug(heading: str) -> str:
    """GitHub's anchor of a heading's text: lower case, everything but letters, digits, ``_``,
    ``-`` and spaces dropped, spaces made hyphens."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


@functools.cache
def anchors(page: Path) -> set[str]:
    """The anchors of every heading of ``page`` (fenced code left out)."""
    seen, out = Counter(), set()
    for line in FENCE.sub("", page.read_text(encoding="utf-8")).splitlines():
        m = re.match(r"#{1,6} (.+)", line)
        if m:
            base = slug(m.group(1))
            out.add(base if not seen[base] else f"{base}-{seen[base]}")
            seen[base] += 1
    return out


def relative_links(page: Path) -> list[str]:
    """The links of ``page`` that point inside the repository (no scheme, no mail)."""
    text = FENCE.sub("", page.read_text(encoding="utf-8"))
    return [t for t in LINK.findall(text) if not re.match(r"[a-z]+:", t)]


def test_slug_follows_github():
    assert slug("The frame's Python, thread wake-ups (the latest round)") == \
        "the-frames-python-thread-wake-ups-the-latest-round"
    assert slug("Lone centres tested up to 1.5 (an earlier round)") == "lone-centres-tested-up-to-15-an-earlier-round"
    assert slug("`scanlab bench` and `make_bench`") == "scanlab-bench-and-make_bench"


@pytest.mark.parametrize("page", PAGES, ids=lambda p: p.name)
def test_every_link_between_pages_resolves(page):
    broken = []
    for target in relative_links(page):
        path, _, anchor = target.partition("#")
        dest = (page.parent / path).resolve() if path else page
        if not dest.exists():
            broken.append(f"{target}: no file {dest.relative_to(ROOT) if dest.is_relative_to(ROOT) else dest}")
        elif anchor and dest.suffix == ".md" and anchor not in anchors(dest):
            broken.append(f"{target}: no heading with that anchor in {dest.name}")
    assert not broken, f"{page.name}: " + "; ".join(broken)
