"""lab/app/lesson_site/measurement.py: one measurement per figure, VTK always intact, the verdict a lesson promises."""
from __future__ import annotations


from lab.app.lesson_site.measurement import FigureSpec, as_expected, command, measure_figure, verdict
from lab.app.lesson_site.places import ROOT

FILL_RULE = str(ROOT / "lessons" / "05-scanline" / "fill-rule.toml")


def test_a_break_it_figure_breaks_only_our_side_and_fails_the_bars():
    intact = measure_figure(FigureSpec(FILL_RULE))
    broken = measure_figure(FigureSpec(FILL_RULE, breakage="fill-rule"))
    assert intact.metrics["failed_bars"] == [] and intact.metrics["reference"] == "vtk-native"
    assert (broken.ref.rgb == intact.ref.rgb).all()  # VTK drew the same, intact scene
    assert broken.metrics["coverage_mismatch"] > 0.0002 and broken.metrics["failed_bars"]
    assert broken.mismatch.sum() == broken.metrics["mismatch_pixels"] > 0


def test_the_expectation_follows_the_figure():
    assert FigureSpec("a.toml").expect == "pass"
    assert FigureSpec("a.toml", breakage="painter").expect == "fail"
    assert FigureSpec("a.toml", reference="vtk-native").expect == "fail"
    assert FigureSpec("a.toml", expectation="fail").expect == "fail"


def test_the_verdict_names_surprises_both_ways():
    ok, bad = {"failed_bars": []}, {"failed_bars": ["mean 2 > 0.1"]}
    assert [verdict(ok, "pass"), verdict(bad, "pass"), verdict(bad, "fail"), verdict(ok, "fail")] == \
        ["pass", "FAIL", "fails as meant", "PASSES?"]
    assert as_expected(ok, "pass") and as_expected(bad, "fail")
    assert not as_expected(bad, "pass") and not as_expected(ok, "fail")


def test_the_command_is_scanlab_compare_unless_a_rule_is_broken():
    assert command(FigureSpec(FILL_RULE, shading="gouraud"), ROOT, "out/x") == \
        "scanlab compare lessons/05-scanline/fill-rule.toml --shading gouraud --out out/x"
    assert command(FigureSpec(FILL_RULE, breakage="fill-rule"), ROOT, "out/x") == \
        "scanlab lessons measure lessons/05-scanline/fill-rule.toml --break fill-rule --out out/x"
