"""lab/app/lesson_site/plots.py: plots from measured renders, the same bytes every time, labels in each language."""

from lab.app.lesson_site.measurement import FigureSpec
from lab.app.lesson_site.places import ROOT
from lab.app.lesson_site.plots import PLOTS, draw

SPHERE = str(ROOT / "lessons" / "09-shading" / "sphere-2.toml")


def test_the_plot_kinds():
    assert set(PLOTS) == {"mach-bands", "delta-e-histogram"}


def test_a_plot_is_drawn_twice_to_the_same_bytes_and_differs_by_language(tmp_path):
    specs = [FigureSpec(SPHERE, shading="flat"), FigureSpec(SPHERE, shading="gouraud")]
    draw("mach-bands", specs, tmp_path / "a.png", japanese=False)
    draw("mach-bands", specs, tmp_path / "b.png", japanese=False)
    draw("mach-bands", specs, tmp_path / "ja.png", japanese=True)
    a = (tmp_path / "a.png").read_bytes()
    assert a == (tmp_path / "b.png").read_bytes() and a != (tmp_path / "ja.png").read_bytes()
    assert b"Software" not in a and len(a) > 10_000
