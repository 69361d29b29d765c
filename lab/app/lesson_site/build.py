"""``scanlab lessons build``: the bilingual lesson site, with its figures drawn and checked.

Runs Sphinx on ``lessons/`` once per language (English from the sources, Japanese with
``language = "ja"`` and the translations in ``lessons/locales/ja``), reading pages on
``jobs`` cores, and writes::

    OUT/index.html      a language chooser (plain links: works from file://)
    OUT/en/...          the English site
    OUT/ja/...          the Japanese site

Figures are drawn by both renderers while pages are read and cached under ``CACHE``
(by default ``OUT/.build``, with Sphinx's own build state), so a second build draws
nothing that has not changed. The build fails (exit 1) if a figure that should pass the
parity bars does not, or a "break it" figure passes them (:mod:`lab.app.lesson_site.pages`),
and on any Sphinx warning (a broken link, a bad directive): a lesson site with a hole in
it is not published.
"""
from __future__ import annotations

import argparse
import html
import io
import re
import sys
import time
from pathlib import Path

from lab.app.lesson_site.places import LESSONS

LANGUAGES = ("en", "ja")
NAMES = {"en": "English", "ja": "日本語"}

_ANSI = re.compile(r"\x1b\[[0-9;]*m")
_STEP = re.compile(r"^(reading sources|writing output)\.\.\. \[\s*(\d+)%\] ", re.M)
"""Sphinx's progress lines. Compiling the .po catalogs also says "writing output", before the
HTML build starts (and the catalog's name comes in a write of its own): such lines are
skipped until "building [html]" has been seen."""


class BuildFailed(Exception):
    """The site was not built; ``status`` is the exit status (1: a check failed, 2: could not build)."""

    def __init__(self, message: str, status: int):
        super().__init__(message)
        self.status = status


class Progress:
    """A one-line progress bar over the languages, fed with Sphinx's status text.

    Reading a page (and drawing its figures) counts for 80 % of a language, writing for 20 %.
    """

    def __init__(self, languages: tuple[str, ...], stream=sys.stdout):
        self.languages, self.stream = languages, stream
        self.index, self.fraction, self.started, self.html = 0, 0.0, time.perf_counter(), False
        self.log: list[str] = []

    def start(self, i: int) -> None:
        self.index, self.fraction, self.html = i, 0.0, False
        self.draw("starting")

    def write(self, text: str) -> int:
        text = _ANSI.sub("", text)
        self.log.append(text)
        self.html = self.html or "building [html]" in text
        for phase, pct in _STEP.findall(text) if self.html else ():
            self.fraction = (0.8 if phase == "reading sources" else 0.2) * int(pct) / 100 + \
                (0.8 if phase == "writing output" else 0.0)
            self.draw(phase.split()[0])
        return len(text)

    def flush(self) -> None:
        pass

    def isatty(self) -> bool:
        return False

    def draw(self, what: str) -> None:
        total = (self.index + self.fraction) / len(self.languages)
        done = int(30 * total)
        lang = self.languages[min(self.index, len(self.languages) - 1)]
        self.stream.write(f"\r[{'#' * done}{'.' * (30 - done)}] {100 * total:3.0f} % {lang}: {what:<8} "
                          f"{time.perf_counter() - self.started:6.1f} s")
        self.stream.flush()


def chooser_page() -> str:
    """``OUT/index.html``: one link per language, nothing else to load."""
    links = "".join(f'<li><a href="{lang}/index.html" hreflang="{lang}" lang="{lang}">{html.escape(NAMES[lang])}</a></li>'
                    for lang in LANGUAGES)
    return ("<!doctype html><html lang='en'><meta charset='utf-8'>"
            "<meta name='viewport' content='width=device-width, initial-scale=1'>"
            "<title>scanlab lessons · scanlab レッスン</title>"
            "<style>body{font-family:sans-serif;max-width:36em;margin:4em auto;padding:0 1em;text-align:center}"
            "ul{list-style:none;padding:0;font-size:1.6em}li{margin:.6em}</style>"
            "<h1>scanlab lessons<br>scanlab レッスン</h1>"
            "<p>The polygon pipeline, measured against VTK · ポリゴンのレンダリングパイプラインを VTK と比べて学ぶ</p>"
            f"<ul>{links}</ul></html>\n")


def forget(doctrees: Path) -> None:
    """Drop Sphinx's saved state after a failed build: a page that warned would otherwise not
    be read again, and the next build would pass without its warning (figures stay cached)."""
    (doctrees / "environment.pickle").unlink(missing_ok=True)


def safe_jobs(jobs: int) -> int:
    """``jobs``, or 1 if this process has already run the renderer's parallel kernels.

    Sphinx reads pages in forked processes; a process whose OpenMP threads (numba's threading
    layer) have started cannot fork safely ("fork() called from a process already using GNU
    OpenMP" ends the child). ``scanlab lessons build`` starts clean; a caller that has
    rendered before (a test session) gets one reader, or should run the command instead."""
    parallel = sys.modules.get("numba.np.ufunc.parallel")
    return 1 if parallel is not None and getattr(parallel, "_is_initialized", False) else jobs


def build_language(lang: str, out: Path, cache: Path, jobs: int, progress: Progress, source: Path = LESSONS) -> set[str]:
    """Build one language of the Sphinx project ``source`` into ``out/lang``; return the cache
    keys of the figures it shows."""
    from sphinx.application import Sphinx
    from sphinx.errors import SphinxError
    from sphinx.util import console
    from sphinx.util.docutils import docutils_namespace, patch_docutils

    from lab.app.lesson_site.pages import FigureCheckError, figure_keys

    console.nocolor()
    warnings = io.StringIO()
    doctrees = cache / "doctrees" / lang
    try:
        with patch_docutils(str(source)), docutils_namespace():  # as sphinx-build: one build's registrations
            app = Sphinx(str(source), str(source), str(out / lang), str(doctrees), "html",
                         confoverrides={"language": lang, "scanlab_figure_cache": str(cache / "figures")},
                         status=progress, warning=warnings, freshenv=False, warningiserror=True,
                         parallel=safe_jobs(jobs))
            app.build()
    except FigureCheckError as exc:
        forget(doctrees)
        raise BuildFailed(f"{lang}: figures that break their lesson's promise:\n  " + str(exc).replace("\n", "\n  "),
                          1) from None
    except SphinxError as exc:
        forget(doctrees)
        raise BuildFailed(f"{lang}: {exc.category}: {exc}", 2) from None
    if app.statuscode:
        forget(doctrees)
        text = warnings.getvalue().strip()
        raise BuildFailed(f"{lang}: the build has warnings (treated as errors):\n{text}", 1)
    return figure_keys(app.env)


def build_site(out: Path, languages: tuple[str, ...] = LANGUAGES, cache: Path | None = None, jobs: int = 2,
               stream=sys.stdout, source: Path = LESSONS) -> Path:
    """Build the site into ``out`` (see the module docstring); return ``out/index.html``.

    ``source`` is the Sphinx project (``lessons/``; the tests build small ones of their own)."""
    from lab.atomic import write_text
    from lab.app.lesson_site.cache import prune

    cache = cache or out / ".build"
    progress = Progress(languages, stream)
    keys: set[str] = set()
    for i, lang in enumerate(languages):
        progress.start(i)
        keys |= build_language(lang, out, cache, jobs, progress, source)
    progress.index, progress.fraction = len(languages), 0.0
    progress.draw("done")
    stream.write("\n")
    if set(languages) == set(LANGUAGES):  # every page seen: figures no page shows are dropped
        prune(cache / "figures", keys)
    page = out / "index.html"
    write_text(page, chooser_page())
    return page


# ------------------------------------------------------------------ the command line
def cmd_build(args) -> int:
    from lab.app.lesson_site.assets import AssetError

    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise args.usage_error(f"--out {args.out}: is a file, not a folder")
    languages = LANGUAGES if args.lang == "all" else (args.lang,)
    print(f"scanlab lessons build: {' and '.join(NAMES[lang] for lang in languages)} into {out}/ "
          f"(figures are drawn by both renderers; a warm cache draws none)")
    try:
        index = build_site(out, languages, Path(args.cache) if args.cache else None, args.jobs)
    except BuildFailed as exc:
        print(f"\nscanlab lessons build: {exc}", file=sys.stderr)
        return exc.status
    except AssetError as exc:
        raise args.usage_error(str(exc)) from None
    for lang in languages:
        print(f"{NAMES[lang]}: {(out / lang / 'index.html').resolve()}")
    print(f"lesson site: {index.resolve()}")
    return 0


def cmd_measure(args) -> int:
    """Measure one figure as a lesson page does and write its images and metrics."""
    from compare.report import write_json
    from lab.app.lesson_site.figure_images import write_figure_images
    from lab.app.lesson_site.measurement import FigureSpec, measure_figure, verdict

    spec = FigureSpec(args.scene, args.shading, args.model, args.breakage, args.reference)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    m = measure_figure(spec)
    names = write_figure_images(m, out)
    write_json(out / "metrics.json", m.metrics)
    de = m.metrics["delta_e_2000"]
    print(f"{args.scene}{' broken: ' + args.breakage if args.breakage else ''}: mean ΔE2000 {de['mean']:.3f}, "
          f"p99.9 {de['p999']:.2f}, over 1: {100 * m.metrics['pixels_over_1']:.3f} %, coverage mismatch "
          f"{100 * m.metrics['coverage_mismatch']:.3f} % vs {m.metrics['reference']}: "
          f"{verdict(m.metrics, spec.expect)}")
    print(f"wrote {out}/ ({', '.join(names + ['metrics.json'])})")
    return 0


def add_parsers(lessons: argparse._SubParsersAction, usage_error) -> None:
    """``scanlab lessons build`` and ``scanlab lessons measure`` (``usage_error``: the CLI's one-line error)."""
    from lab.scene import MODELS, SHADINGS
    from renderer.breakages import BREAKAGES

    q = lessons.add_parser("build", help="build the English and Japanese lesson site (figures drawn and checked)",
                           description="Writes OUT/index.html (a language chooser), OUT/en/ and OUT/ja/. Every "
                                       "figure is drawn by scanlab and by VTK and measured; the build fails if a "
                                       "figure that should pass the parity bars does not, or a 'break it' figure "
                                       "passes them.")
    q.add_argument("--out", default="out/lessons", metavar="DIR", help="output folder (default out/lessons)")
    q.add_argument("--lang", choices=("en", "ja", "all"), default="all", help="which language(s) (default all)")
    q.add_argument("--cache", metavar="DIR", help="figure cache and Sphinx state (default OUT/.build)")
    q.add_argument("--jobs", type=int, default=2, metavar="N", help="processes that read pages (default 2)")
    q.set_defaults(func=cmd_build, usage_error=usage_error)

    q = lessons.add_parser("measure", help="measure one lesson figure, a rule broken on purpose if asked",
                           description="Draws SCENE with scanlab (with --break: a rule broken, see the lessons) "
                                       "and with VTK (intact), and writes ours.png, vtk.png, delta_e.png and "
                                       "metrics.json into DIR, as the lesson pages show them.")
    q.add_argument("scene", help="a scene file (.toml), preset or built-in shape")
    q.add_argument("--shading", choices=SHADINGS, help="override every object's shading")
    q.add_argument("--model", choices=MODELS, help="override every object's reflection model")
    q.add_argument("--break", dest="breakage", choices=list(BREAKAGES), help="break one rule in our renderer")
    q.add_argument("--reference", choices=["vtk-native"], help="force VTK's own lighting for every object")
    q.add_argument("--out", required=True, metavar="DIR", help="folder for the outputs (created if missing)")
    q.set_defaults(func=cmd_measure)
