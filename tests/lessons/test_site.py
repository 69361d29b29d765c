"""The lesson site in a real browser: every page from file://, offline, in English and Japanese.

One build is shared by the whole module (the figures are drawn once; the figure cache
lives in the user's cache folder, so a second run of the suite draws nothing). Every
request that leaves file:// is aborted and fails the test (:mod:`tests.browser`).
Screenshots of every page are checked not blank and kept in ``SCANLAB_SCREENSHOTS``
(default: the build's temporary folder) for a person to look at.
"""
from __future__ import annotations

import io
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from lab.app.lesson_site.build import LESSONS

from ..browser import broken_images, open_browser, watch

JAPANESE = re.compile(r"[\u3040-\u30ff\u4e00-\u9fff]")
LESSON_DIRS = sorted(p.name for p in LESSONS.iterdir() if p.is_dir() and re.match(r"\d\d-", p.name))


def figure_cache() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "scanlab" / "lesson-site-tests"


@pytest.fixture(scope="module")
def site(tmp_path_factory):
    """The site, built by the command as a user runs it (in a fresh process: Sphinx forks its
    two readers, which a test session that has already rendered must not do)."""
    out = tmp_path_factory.mktemp("lessons")
    done = subprocess.run([sys.executable, "-m", "lab", "lessons", "build", "--out", str(out),
                           "--cache", str(figure_cache())], capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stdout + done.stderr
    assert done.stdout.strip().splitlines()[-1] == f"lesson site: {(out / 'index.html').resolve()}"
    return out


@pytest.fixture(scope="module")
def browser():
    with open_browser() as b:
        yield b


def pages(site: Path, lang: str) -> list[Path]:
    return sorted(p for p in (site / lang).rglob("*.html") if "_static" not in p.parts)


def open_page(browser, path: Path, query: str = ""):
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    log = watch(page)
    page.goto(path.as_uri() + query)
    page.wait_for_load_state("load")
    return page, log


def ink(png: bytes) -> float:
    """Share of a screenshot's pixels that stand out from its commonest grey level (0 = blank)."""
    grey = np.asarray(Image.open(io.BytesIO(png)).convert("L"), dtype=np.int16)
    background = np.bincount(grey.ravel()).argmax()
    return float(np.mean(np.abs(grey - background) > 40))


def test_ink_tells_a_blank_page_from_a_page_with_text():
    blank, text = Image.new("RGB", (200, 100), "white"), Image.new("RGB", (200, 100), "white")
    text.paste((20, 20, 20), (10, 10, 190, 30))
    as_png = lambda im: (lambda b: (im.save(b, format="PNG"), b.getvalue())[1])(io.BytesIO())  # noqa: E731
    assert ink(as_png(blank)) == 0.0 and ink(as_png(text)) > 0.15


def test_the_site_has_every_lesson_the_glossary_and_a_chooser(site):
    assert LESSON_DIRS == [f"{i:02d}-{name}" for i, name in enumerate(
        ["polygon-model", "homogeneous", "camera", "clipping", "scanline", "hidden-surfaces", "reflection", "lights",
         "shading", "interpolation", "textures", "transparency", "csg"], start=1)]
    for lang in ("en", "ja"):
        names = {p.relative_to(site / lang).as_posix() for p in pages(site, lang)}
        assert {f"{d}/index.html" for d in LESSON_DIRS} | {"index.html", "glossary.html", "search.html"} <= names
    from lab.app.exercises.exercise_registry import exercises

    for lang in ("en", "ja"):  # one page per exercise, from the registry the checker reads (issue 14)
        names = {p.relative_to(site / lang).as_posix() for p in pages(site, lang)}
        assert {f"exercises/{name}.html" for name in exercises()} | {"exercises/index.html"} <= names
    chooser = (site / "index.html").read_text()
    assert 'href="en/index.html"' in chooser and 'href="ja/index.html"' in chooser and "http" not in chooser


def text_blocks(page) -> list[str]:
    """Visible text of the article's blocks and the navigation, code and formulas left out."""
    return page.evaluate("""() => {
        const skip = 'code, pre, .math, mjx-container, script, style, .scanlab-src';
        const blocks = [...document.querySelectorAll(
            'article p:not(td p), article li, article h1, article h2, article h3, article th, article button, ' +
            'article .scanlab-panel-title, article .scanlab-wipe-title, article .scanlab-legend, ' +
            'article .scanlab-break-title, article .scanlab-rule, .sidebar-tree a')];
        return blocks.map(b => { const c = b.cloneNode(true);
            c.querySelectorAll(skip).forEach(e => e.remove()); return c.textContent.trim(); });
    }""")


def figures(page) -> list[tuple[str, str, str, int]]:
    """(id, kind, verdicts, images) of every figure and plot on the page."""
    return page.evaluate("""() => [...document.querySelectorAll('figure.scanlab-figure, figure.scanlab-plot')].map(
        f => [f.id, f.classList.contains('scanlab-break') ? 'break' : f.classList.contains('scanlab-contrast')
              ? 'contrast' : 'figure', [...f.querySelectorAll('.scanlab-metrics')].map(t => t.dataset.verdict).join(','),
              f.querySelectorAll('img').length])""")


@pytest.fixture(scope="module")
def crawl(site, browser):
    """Every page of both languages visited once: what went wrong, what it shows, its screenshot."""
    shots = Path(os.environ.get("SCANLAB_SCREENSHOTS") or site.parent / "screenshots")
    seen = {}
    for lang in ("en", "ja"):
        (shots / lang).mkdir(parents=True, exist_ok=True)
        for path in pages(site, lang):
            page, log = open_page(browser, path)
            page.wait_for_timeout(300)  # MathJax typesets after load
            name = path.relative_to(site / lang).as_posix()
            png = page.screenshot(full_page=True)
            (shots / lang / name.replace("/", "_").replace(".html", ".png")).write_bytes(png)
            seen[lang, name] = {"problems": log.problems(), "broken": broken_images(page), "ink": ink(png),
                                "text": text_blocks(page), "figures": figures(page)}
            page.close()
    return seen


def test_every_page_loads_offline_with_no_error_every_image_and_something_to_see(crawl):
    assert len(crawl) == 2 * 25  # 13 lessons, 8 exercises and their index, the glossary, the start page, search; twice
    for (lang, name), seen in crawl.items():
        assert seen["problems"] == [], (lang, name)
        assert seen["broken"] == [], (lang, name)
        assert seen["ink"] > 0.005, f"{lang}/{name}: the screenshot is nearly blank ({100 * seen['ink']:.2f} % ink)"


def test_the_wipe_slider_moves_the_overlay(site, browser):
    page, log = open_page(browser, site / "en" / "05-scanline" / "index.html")
    wipe = page.locator(".scanlab-wipe").first
    over = wipe.locator(".scanlab-wipe-over")
    assert over.evaluate("e => e.style.clipPath") == "inset(0px 50% 0px 0px)"
    for value, right in (("0", "100%"), ("80", "20%"), ("100", "0%")):
        wipe.locator("input[type=range]").fill(value)
        assert over.evaluate("e => e.style.clipPath") == f"inset(0px {right} 0px 0px)"
    assert over.bounding_box()["width"] > 100 and log.problems() == []


def test_the_shading_switch_swaps_the_images(site, browser):
    page, log = open_page(browser, site / "en" / "01-polygon-model" / "index.html")
    figure = page.locator("figure.scanlab-figure:has(.scanlab-switch)").first
    buttons = figure.locator(".scanlab-switch button")
    assert buttons.all_inner_texts() == ["flat", "Gouraud", "Phong"]

    def shown():
        return figure.locator(".scanlab-variant:visible img").first.get_attribute("src")

    first = shown()
    buttons.nth(2).click()
    assert shown() != first and buttons.nth(2).get_attribute("aria-pressed") == "true"
    assert figure.locator(".scanlab-variant:visible").count() == 1
    buttons.nth(0).click()
    assert shown() == first and log.problems() == []


@pytest.mark.parametrize("lesson", ["05-scanline", "09-shading", "glossary"])
def test_the_language_switch_lands_on_the_same_page_in_the_other_language(site, browser, lesson):
    name = f"{lesson}/index.html" if lesson != "glossary" else "glossary.html"
    page, log = open_page(browser, site / "en" / name)
    assert page.locator("html").get_attribute("lang") == "en"
    page.locator("a.scanlab-lang-switch").click()
    page.wait_for_load_state("load")
    assert page.url == (site / "ja" / name).as_uri()
    assert page.locator("html").get_attribute("lang") == "ja"
    page.locator("a.scanlab-lang-switch").click()
    page.wait_for_load_state("load")
    assert page.url == (site / "en" / name).as_uri() and log.problems() == []


@pytest.mark.parametrize("term, lesson", [("スキャンライン", "05-scanline"), ("隠面消去", "06-hidden-surfaces")])
def test_the_japanese_search_finds_the_course_terms(site, browser, term, lesson):
    page, log = open_page(browser, site / "ja" / "search.html", f"?q={term}")
    results = page.locator("#search-results li a")
    results.first.wait_for(timeout=10_000)
    hrefs = results.evaluate_all("links => links.map(a => a.getAttribute('href'))")
    assert any(h.startswith(f"{lesson}/index.html") for h in hrefs), hrefs
    assert log.problems() == []


def english_words(text: str) -> int:
    return len(re.findall(r"\b[A-Za-z]{3,}\b", re.sub(r"\b(VTK|CSG|OpenGL|GL_\w+|scanlab|ΔE2000|RGB)\b", "", text)))


def test_every_japanese_page_is_in_japanese(crawl):
    """Every block of words (paragraph, list item, heading, caption, label, button, table
    heading, navigation link) holds Japanese; English is allowed only in code, formulas,
    names (VTK, OpenGL, ...) and table cells (values, and the glossary's English column)."""
    untranslated = [f"{name}: {text[:80]}" for (lang, name), seen in crawl.items() if lang == "ja"
                    and name != "search.html" for text in seen["text"]
                    if english_words(text) >= 2 and not JAPANESE.search(text)]
    assert untranslated == []
    assert sum(len(seen["text"]) for (lang, _), seen in crawl.items() if lang == "ja") > 500


def test_every_figure_appears_in_both_languages_with_the_verdict_it_promises(crawl):
    kinds = {"figure": 0, "break": 0, "contrast": 0}
    for lesson in LESSON_DIRS:
        name = f"{lesson}/index.html"
        assert crawl["en", name]["figures"] == crawl["ja", name]["figures"], lesson
        for figure_id, kind, verdicts, images in crawl["en", name]["figures"]:
            assert images >= 1, figure_id
            want = {"pass"} if kind == "figure" else {"fails as meant"}
            assert not verdicts or set(verdicts.split(",")) == want, (figure_id, verdicts)
            kinds[kind] += 1
    assert kinds["break"] == 6 and kinds["contrast"] == 2 and sum(kinds.values()) >= 27, kinds
