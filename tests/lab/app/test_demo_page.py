"""The demo page, opened in a real browser (headless Chromium) at phone and desktop widths.

No console errors, every image loaded, nothing fetched from outside; the summary table's
links land on their panels; the table sorts; the page is no wider than the window; every
font size comes from the one type scale.
"""
from __future__ import annotations

import re

import pytest

from lab.app.demo_page import TYPE_SCALE, anchor, demo_page

from ...browser import broken_images, open_browser, watch

WIDTHS = (400, 1280)


@pytest.fixture(scope="module")
def browser():
    with open_browser() as b:
        yield b


@pytest.mark.parametrize("width", WIDTHS)
def test_the_page_loads_cleanly_and_fits_the_window(demo_run, browser, width, tmp_path):
    out, _, _ = demo_run
    page = browser.new_page(viewport={"width": width, "height": 900})
    log = watch(page)
    page.goto((out / "index.html").as_uri())
    page.wait_for_load_state("load")
    assert log.problems() == [] and broken_images(page) == []
    assert page.evaluate("document.documentElement.scrollWidth") <= width
    assert page.locator("section.panel img").count() == 3
    page.screenshot(path=str(tmp_path / f"page-{width}.png"), full_page=True)
    page.close()


@pytest.mark.parametrize("width", WIDTHS)
def test_every_summary_link_lands_on_its_panel(demo_run, browser, width):
    out, _, _ = demo_run
    page = browser.new_page(viewport={"width": width, "height": 700})
    watch(page)
    page.goto((out / "index.html").as_uri())
    page.wait_for_load_state("load")
    links = page.locator("#summary tbody a")
    names = [links.nth(i).inner_text() for i in range(links.count())]
    assert names == ["fill-rule", "mine", "torus"]
    for name in names:
        page.locator("#summary tbody a", has_text=name).click()
        page.wait_for_function(f"location.hash === '#{anchor(name)}'")
        target = page.evaluate("(() => { const t = document.querySelector(':target'); const e = document."
                               "documentElement; return t && [t.id, t.getBoundingClientRect().top,"
                               " scrollY + innerHeight >= e.scrollHeight - 1]; })()")
        # at the top of the window, or as near as the page scrolls (the last panel at the page's end)
        assert target[0] == anchor(name) and -1 <= target[1] and (target[1] <= 20 or target[2]), (name, target)
        page.goto((out / "index.html").as_uri())  # back to the top for the next link
    page.close()


def test_the_summary_table_sorts_by_a_column_both_ways(demo_run, browser):
    out, _, _ = demo_run
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    log = watch(page)
    page.goto((out / "index.html").as_uri())
    column = page.locator("#summary thead th button", has_text="depth Δ, max steps")
    values = lambda: [float(v) for v in page.eval_on_selector_all(  # noqa: E731
        "#summary tbody tr td:nth-child(10)", "cells => cells.map(c => c.dataset.sort)")]
    column.click()
    assert values() == sorted(values())
    assert page.locator("#summary thead th[aria-sort=ascending]").count() == 1
    column.click()
    assert values() == sorted(values(), reverse=True)
    page.locator("#summary thead th button", has_text="scene").click()
    assert page.eval_on_selector_all("#summary tbody a", "a => a.map(x => x.textContent)") == ["fill-rule", "mine",
                                                                                                "torus"]
    assert log.problems() == []
    page.close()


@pytest.mark.parametrize("width", WIDTHS)
def test_every_font_size_is_on_the_type_scale(demo_run, browser, width):
    out, _, _ = demo_run
    page = browser.new_page(viewport={"width": width, "height": 900})
    page.goto((out / "index.html").as_uri())
    sizes = set(page.evaluate("""Array.from(document.querySelectorAll('body *'))
        .filter(e => Array.from(e.childNodes).some(n => n.nodeType === 3 && n.textContent.trim()))
        .map(e => parseFloat(getComputedStyle(e).fontSize))"""))
    scale = {round(16 * float(v.rstrip("rem")), 2) for v in TYPE_SCALE.values()}
    assert {round(s, 2) for s in sizes} <= scale, sizes
    page.close()


def test_the_page_text_holds_each_panels_figures_scene_file_and_command(demo_run):
    out, _, _ = demo_run
    text = (out / "index.html").read_text()
    for name in ("fill-rule", "mine", "torus"):
        assert f"id='{anchor(name)}'" in text and f"href='#{anchor(name)}'" in text
        assert f"href='{name}/scene.toml'" in text and f"scanlab compare" in text
    assert not re.search(r"(src|href)=['\"]https?:", text)  # nothing from a CDN


def test_a_page_of_no_rows_is_still_a_page():
    assert "<table" in demo_page([])
