"""The sweep's page: what failed to finish, the worst cases' panels, histograms, a sortable table —
checked as HTML, and in a real browser on the page of a real 48-case sweep."""
from __future__ import annotations

import json
import re
from pathlib import Path

from lab.app.sweep.sweep_page import build_page

from ....browser import broken_images, open_browser, watch


def row(case_id, mean, status="ok", verdict="pass", error=None):
    return {"case_id": case_id, "status": status, "verdict": verdict if status == "ok" else None, "name": "cube",
            "source": "cube", "settings": json.dumps({"shading": "flat"}), "failed_bars": None, "error": error,
            "worker": "tcp://127.0.0.1:1", "case_s": 0.5, "delta_e_2000_mean": mean, "delta_e_2000_p999": mean,
            "delta_e_2000_max": mean, "pixels_over_1": 0.0, "coverage_mismatch": 0.0, "ours_ms": 1.0,
            "reference_ms": 2.0}


def test_the_page_lists_unfinished_cases_panels_of_kept_cases_and_every_case(tmp_path):
    rows = [row("a", 0.01), row("b", 0.5, verdict="FAIL"), row("c", None, status="timeout", error="no answer <b>")]
    page = build_page(tmp_path, rows, kept={"b"}, histograms=[tmp_path / "histograms" / "shading.png"],
                      facts={"command": "scanlab sweep cube", "throughput": "This run: 3 cases."}).read_text()
    assert "1 pass" in page and "1 FAIL" in page and "1 did not finish" in page
    assert "no answer &lt;b&gt;" in page, "text from the run is escaped"
    assert page.count("class='case'") == 1 and "src='cases/b/side_by_side.png'" in page
    assert "href='#case-b'" in page and "href='#case-a'" not in page
    assert "src='histograms/shading.png'" in page and "scanlab sweep cube" in page
    assert not re.search(r"(src|href)=['\"]?(https?:)?//", page), "nothing from elsewhere"


def _load_everything(page) -> None:
    for image in page.query_selector_all("img"):
        image.scroll_into_view_if_needed()
    page.wait_for_function("Array.from(document.images).every(i => i.complete)")


def _column(page, heading: str) -> list[float]:
    index = page.eval_on_selector_all("#cases th", f"hs => hs.findIndex(h => h.textContent === {heading!r})")
    return page.eval_on_selector_all(f"#cases tbody tr td:nth-child({index + 1})",
                                     "cells => cells.map(c => parseFloat(c.dataset.value))")


def test_the_page_of_a_real_sweep_works_in_a_browser_at_phone_and_desktop_width(identity_sweep, tmp_path):
    out, _ = identity_sweep
    with open_browser() as browser:
        for width in (400, 1280):
            page = browser.new_page(viewport={"width": width, "height": 900})
            log = watch(page)
            page.goto((out / "index.html").resolve().as_uri())
            _load_everything(page)
            assert log.problems() == [] and broken_images(page) == []
            assert len(page.query_selector_all("section.case img")) == 5, "--worst 5 panels"
            assert len(page.query_selector_all("#cases tbody tr")) == 48
            page.screenshot(path=str(tmp_path / f"sweep-{width}.png"), full_page=True)
            assert page.evaluate("document.documentElement.scrollWidth") <= width + 1, "no sideways scrolling"

        page.click("#cases th:text-is('mean ΔE')")
        means = _column(page, "mean ΔE")
        assert means == sorted(means, reverse=True) and means[0] > means[-1]
        page.click("#cases th:text-is('mean ΔE')")
        assert _column(page, "mean ΔE") == sorted(means)
        page.click("#cases th:text-is('rank')")
        link = page.query_selector("#cases tbody a")
        target = link.get_attribute("href")
        link.click()
        assert page.evaluate("location.hash") == target
        assert page.evaluate(f"document.querySelector({target!r}).getBoundingClientRect().top") < 5
