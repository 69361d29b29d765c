"""The parity verdict: which bars a comparison misses, and what that means for the run."""
import pytest

from compare.verdict import FIGURES, PARITY_BARS, Verdict, check_bars, failed_bars, judge, meant_to_fail, parse_bar
from lab.loading import load_scene


def metrics(coverage=0.0, over=0.0, mean=0.0, p999=0.0):
    return {"coverage_mismatch": coverage, "pixels_over_1": over, "delta_e_2000": {"mean": mean, "p999": p999}}


def test_a_result_at_the_bars_passes():
    """Exactly at each bar is a pass; the bars are inclusive."""
    assert failed_bars(metrics(PARITY_BARS["coverage_mismatch"], PARITY_BARS["pixels_over_1"],
                               PARITY_BARS["mean"])) == []


def test_each_bar_fails_on_its_own():
    """Just above any one bar fails that bar and only that one."""
    assert [f.split()[0] for f in failed_bars(metrics(coverage=0.00021))] == ["coverage_mismatch"]
    assert [f.split()[0] for f in failed_bars(metrics(over=0.0021))] == ["pixels_over_1"]
    assert [f.split()[0] for f in failed_bars(metrics(mean=0.11))] == ["mean"]


def test_the_issues_screen_interpolation_run_is_a_fail_naming_its_bars():
    """mean ΔE 1.56 with 58 % of pixels over 1 (screen-linear interpolation): FAIL, both bars named."""
    v = judge(metrics(over=0.58, mean=1.56))
    assert v.status == "FAIL" and not v.ok and not v.met_bars
    assert v.line().startswith("FAIL: pixels_over_1 0.58 > 0.002; mean 1.56 > 0.1")
    assert v.to_json()["failed"] == ["pixels_over_1 0.58 > 0.002", "mean 1.56 > 0.1"]


def test_a_scene_meant_to_fail_is_ok_when_it_fails_and_not_when_it_passes():
    why = meant_to_fail(load_scene("painter-fails"))
    assert "painter" in why
    failing, passing = judge(metrics(over=0.06), meant_to_fail=why), judge(metrics(), meant_to_fail=why)
    assert (failing.status, failing.ok) == ("fails as meant", True)
    assert (passing.status, passing.ok) == ("PASSES?", False)
    assert meant_to_fail(load_scene("cube")) is None


def test_bars_are_configurable_and_checked():
    """Extra bars (p999) and looser or tighter ones are judged; unknown names get a suggestion."""
    assert judge(metrics(p999=2.0), {**PARITY_BARS, "p999": 1.0}).failed == ("p999 2 > 1",)
    assert judge(metrics(mean=0.5), {"mean": 1.0}).met_bars
    assert parse_bar("mean=0.05") == ("mean", 0.05)
    with pytest.raises(ValueError, match="did you mean 'pixels_over_1'"):
        parse_bar("pixels_over1=0.1")
    with pytest.raises(ValueError, match="at least 0"):
        check_bars({"mean": -1})
    with pytest.raises(ValueError, match="NAME=VALUE"):
        parse_bar("mean")


def test_every_figure_reads_from_a_metrics_dict():
    m = {**metrics(mean=0.5, p999=1.0), "max_channel_diff": 3, "depth": {"over_1_step": 0.01}}
    m["delta_e_2000"]["max"] = 2.0
    assert {name: f.read(m) for name, f in FIGURES.items()}["max_channel_diff"] == 3
    assert Verdict(failed=()).status == "pass"
