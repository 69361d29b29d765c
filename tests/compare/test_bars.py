"""The parity verdict: which bars a comparison misses."""
from compare.metrics import PARITY_BARS, failed_bars


def metrics(coverage=0.0, over=0.0, mean=0.0):
    return {"coverage_mismatch": coverage, "pixels_over_1": over, "delta_e_2000": {"mean": mean}}


def test_a_result_at_the_bars_passes():
    """Exactly at each bar is a pass; the bars are inclusive."""
    assert failed_bars(metrics(PARITY_BARS["coverage_mismatch"], PARITY_BARS["pixels_over_1"],
                               PARITY_BARS["mean"])) == []


def test_each_bar_fails_on_its_own():
    """Just above any one bar fails that bar and only that one."""
    assert [f.split()[0] for f in failed_bars(metrics(coverage=0.00021))] == ["coverage_mismatch"]
    assert [f.split()[0] for f in failed_bars(metrics(over=0.0021))] == ["pixels_over_1"]
    assert [f.split()[0] for f in failed_bars(metrics(mean=0.11))] == ["mean"]
