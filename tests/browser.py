"""A real browser for the page tests: Playwright's Python package driving Debian's Chromium.

Playwright's own browser download cannot work here (no network but the package
registries), so Chromium comes from Debian (``.ci/run`` installs it when missing) and is
named by ``executable_path``. The flags keep it from calling home: without
``--disable-background-networking`` and friends it opens connections that the closed
network refuses. ``--no-sandbox`` because CI runs as root.

Use :func:`open_browser` as a context manager, then :func:`watch` each page: it records
console errors, failed requests and every request that leaves the allowed origins (by
default only ``file://``), and *aborts* those requests so nothing reaches a CDN.

>>> from ..browser import open_browser, watch    # from a test in tests/<floor>/   # doctest: +SKIP
>>> with open_browser() as browser:                          # doctest: +SKIP
...     page = browser.new_page(viewport={"width": 400, "height": 800})
...     log = watch(page)
...     page.goto(Path("out/demo/index.html").resolve().as_uri())
...     assert log.problems() == []
"""
from __future__ import annotations

import shutil
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Iterator

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMIUM_ARGS = ["--no-sandbox", "--headless", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]


@contextmanager
def open_browser() -> Iterator:
    """A headless Chromium (a Playwright ``Browser``), closed on exit."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        try:
            yield browser
        finally:
            browser.close()


@dataclass
class PageLog:
    """What a page did that a test may object to."""

    console_errors: list[str] = field(default_factory=list)
    page_errors: list[str] = field(default_factory=list)
    failed_requests: list[str] = field(default_factory=list)
    outside_requests: list[str] = field(default_factory=list)

    def problems(self) -> list[str]:
        return ([f"console: {m}" for m in self.console_errors] + [f"page error: {m}" for m in self.page_errors]
                + [f"failed: {u}" for u in self.failed_requests] + [f"outside: {u}" for u in self.outside_requests])


def watch(page, allowed: tuple[str, ...] = ("file://",)) -> PageLog:
    """Record ``page``'s console errors, uncaught exceptions and failed requests, and abort
    (and record) every request whose URL starts with none of ``allowed`` (``data:`` and
    ``blob:`` URLs are always allowed)."""
    log = PageLog()
    ok = tuple(allowed) + ("data:", "blob:")

    def route(r):
        if r.request.url.startswith(ok):
            r.continue_()
        else:
            log.outside_requests.append(r.request.url)
            r.abort()

    page.route("**/*", route)
    page.on("console", lambda m: log.console_errors.append(m.text) if m.type == "error" else None)
    page.on("pageerror", lambda e: log.page_errors.append(str(e)))
    page.on("requestfailed", lambda r: log.failed_requests.append(r.url)
            if r.url.startswith(ok) else None)
    return log


def broken_images(page) -> list[str]:
    """The ``src`` of every ``<img>`` on the page that has not loaded (``naturalWidth == 0``)."""
    return page.eval_on_selector_all(
        "img", "imgs => imgs.filter(i => !(i.complete && i.naturalWidth > 0)).map(i => i.src)")
