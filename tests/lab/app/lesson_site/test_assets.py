"""lab/app/lesson_site/assets.py: MathJax from the pinned npm package, the Japanese font from PyPI, nothing else."""
import json

from lab.app.lesson_site.assets import LESSONS, japanese_font, locked_mathjax_version, static_folder


def test_mathjax_is_pinned_to_version_3():
    pinned = json.loads((LESSONS / "package.json").read_text())["dependencies"]["mathjax"]
    assert pinned == locked_mathjax_version() and pinned.startswith("3.")


def test_the_static_folder_holds_mathjax_and_its_fonts_and_the_font(tmp_path):
    folder = static_folder(tmp_path)
    assert (folder / "mathjax" / "tex-chtml.js").stat().st_size > 500_000
    assert list((folder / "mathjax" / "output" / "chtml" / "fonts" / "woff-v2").glob("*.woff"))
    assert (folder / "fonts" / "ipaexg.ttf").read_bytes() == japanese_font().read_bytes()
