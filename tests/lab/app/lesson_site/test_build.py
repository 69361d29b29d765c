"""scanlab lessons build / measure: the site is built only when every figure keeps its lesson's promise.

The checks are run on small Sphinx projects of one page each, made here with the lessons'
own configuration, so that a failure can be provoked without touching the lessons.
"""
from __future__ import annotations

import io
import shutil
import textwrap
from pathlib import Path

import pytest

from lab.app.cli import main
from lab.app.lesson_site.build import LESSONS, BuildFailed, Progress, build_site, chooser_page, safe_jobs

CONF = f"""
exec(open({str(LESSONS / 'conf.py')!r}).read())
templates_path = [{str(LESSONS / '_templates')!r}]
html_static_path = [{str(LESSONS / '_static')!r}]
locale_dirs = [{str(LESSONS / 'locales')!r}]
"""


def project(tmp_path: Path, page: str, scenes=("05-scanline/fill-rule.toml",)) -> Path:
    src = tmp_path / "src"
    (src / "lesson").mkdir(parents=True)
    (src / "conf.py").write_text(CONF)
    (src / "index.md").write_text("# Test\n\n```{toctree}\nlesson/index\n```\n")
    (src / "lesson" / "index.md").write_text(textwrap.dedent(page))
    for scene in scenes:
        shutil.copy(LESSONS / scene, src / "lesson")
    return src


def build(tmp_path, src):
    return build_site(tmp_path / "out", ("en",), cache=tmp_path / "cache", jobs=1, stream=io.StringIO(), source=src)


def test_a_page_whose_figures_keep_their_promise_is_built(tmp_path):
    src = project(tmp_path, """\
        # Lesson
        ```{scanlab-figure} fill-rule.toml
        Kept.
        ```
        ```{scanlab-figure} fill-rule.toml
        :break: fill-rule
        Broken.
        ```
        """)
    index = build(tmp_path, src)
    page = (tmp_path / "out" / "en" / "lesson" / "index.html").read_text()
    assert index.is_file() and page.count('data-verdict="pass"') == 1 and page.count('data-verdict="fails as meant"') == 1
    for key in (tmp_path / "out" / "en" / "_figures").iterdir():
        assert sorted(p.name for p in key.iterdir()) == ["delta_e.png", "ours.png", "vtk.png"]
    assert (tmp_path / "out" / "en" / "_scenes" / "lesson" / "fill-rule.toml").is_file()


def test_a_break_it_figure_that_passes_fails_the_build_and_keeps_failing(tmp_path):
    src = project(tmp_path, """\
        # Lesson
        ```{scanlab-figure} fill-rule.toml
        :expect: fail
        Claimed broken, but intact.
        ```
        """)
    for _ in range(2):  # a second build, with nothing changed, must not pass either
        with pytest.raises(BuildFailed, match=r"PASSES\? \(within the bars\)") as failure:
            build(tmp_path, src)
        assert failure.value.status == 1
    assert not (tmp_path / "out" / "en" / "lesson" / "index.html").exists()


def test_a_figure_that_should_pass_and_drifts_outside_the_bars_fails_the_build(tmp_path):
    src = project(tmp_path, """\
        # Lesson
        ```{scanlab-figure} crossing-boxes.toml
        Claimed to pass.
        ```
        """, scenes=("06-hidden-surfaces/crossing-boxes.toml",))
    scene = src / "lesson" / "crossing-boxes.toml"
    scene.write_text(scene.read_text().replace('hidden_surface = "zbuffer"', 'hidden_surface = "painter"'))
    with pytest.raises(BuildFailed, match=r"figure-crossing-boxes \[crossing-boxes.toml\]: FAIL \(pixels_over_1"):
        build(tmp_path, src)


def test_a_lesson_that_names_missing_code_fails_the_build(tmp_path):
    src = project(tmp_path, "# Lesson\n\nThe fill: {src}`renderer/raster.py::scanline_fill`.\n", scenes=())
    with pytest.raises(BuildFailed, match="defines no scanline_fill") as failure:
        build(tmp_path, src)
    assert failure.value.status == 1


def test_a_process_that_has_run_the_renderer_reads_pages_in_one_process():
    from lab.loading import load_scene
    from renderer import render

    render(load_scene("cube"))  # numba's OpenMP threads start: forking is no longer safe
    assert safe_jobs(2) == 1


def test_the_progress_bar_follows_reading_and_writing_but_not_the_catalogs():
    """Sphinx writes a step and its item in two writes; the catalogs' "writing output" steps
    come before "building [html]" and must not move the bar (they once took it to 100 %)."""
    out = io.StringIO()
    progress = Progress(("en", "ja"), out)
    progress.start(1)
    for text in ("building [mo]: targets for 1 po files that are out of date\n", "writing output... [100%] ",
                 "locales/ja/LC_MESSAGES/05-scanline.mo", "\n"):
        progress.write(text)
    assert progress.fraction == 0.0
    progress.write("building [html]: targets for 24 source files that are out of date\n")
    progress.write("reading sources... [ 50%] ")
    progress.write("05-scanline/index")
    assert progress.fraction == pytest.approx(0.4)
    progress.write("writing output... [100%] ")
    progress.write("index\n")
    assert progress.fraction == pytest.approx(1.0) and "100 % ja" in out.getvalue().split("\r")[-1]
    progress.start(0)  # the next language starts over: its catalogs are skipped again
    progress.write("writing output... [100%] ")
    assert progress.fraction == 0.0


def test_the_chooser_links_both_languages_and_nothing_outside():
    page = chooser_page()
    assert 'href="en/index.html"' in page and 'href="ja/index.html"' in page and "日本語" in page
    assert "http" not in page and "<script" not in page


def test_build_refuses_a_file_as_output_folder(tmp_path, capsys):
    (tmp_path / "f").write_text("x")
    assert main(["lessons", "build", "--out", str(tmp_path / "f")]) == 2
    assert capsys.readouterr().err.strip().count("\n") == 0


def test_measure_writes_the_figure_and_says_the_verdict(tmp_path, capsys):
    out = tmp_path / "m"
    assert main(["lessons", "measure", str(LESSONS / "05-scanline" / "fill-rule.toml"), "--break", "fill-rule",
                 "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "fails as meant" in printed and "coverage mismatch 0.810 %" in printed
    assert sorted(p.name for p in out.iterdir()) == ["delta_e.png", "metrics.json", "ours.png", "vtk.png"]
