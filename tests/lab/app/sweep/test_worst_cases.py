"""The worst cases: scored against the parity bars; only the worst few keep their frames."""
from __future__ import annotations

from lab.app.sweep.worst_cases import FrameStore, bar_ratio, score, worst_first


def row(case_id, mean=0.0, over=0.0, coverage=0.0, p999=0.0, top=0.0, status="ok"):
    return {"case_id": case_id, "status": status, "delta_e_2000_mean": mean, "pixels_over_1": over,
            "coverage_mismatch": coverage, "delta_e_2000_p999": p999, "delta_e_2000_max": top}


def test_the_score_is_the_worst_ratio_to_a_bar_then_p999_then_max():
    assert bar_ratio(row("a", mean=0.05)) == 0.5
    assert bar_ratio(row("a", coverage=0.0004, mean=0.05)) == 2.0
    assert bar_ratio(row("a", over=0.001)) == 0.5
    assert score(row("a", p999=1, top=2)) == (0.0, 1, 2)


def test_worst_first_ranks_compared_cases_only():
    rows = [row("calm"), row("loud", mean=0.5), row("hung", status="timeout"), row("tie", p999=3.0)]
    assert [r["case_id"] for r in worst_first(rows)] == ["loud", "tie", "calm"]


def test_only_the_worst_keep_their_frames_unless_all_are_kept(tmp_path):
    store = FrameStore(tmp_path, keep=2)
    for i, mean in enumerate([0.01, 0.5, 0.02, 0.3]):
        store.write_frames(f"c{i}", b"frames")
        store.consider([row(f"c{i}", mean=mean)])
    assert sorted(p.name for p in store.root.iterdir()) == ["c1", "c3"]
    everything = FrameStore(tmp_path / "all", keep=1, keep_all=True)
    for i in range(3):
        everything.write_frames(f"c{i}", b"frames")
        everything.consider([row(f"c{i}", mean=i)])
    assert len(list(everything.root.iterdir())) == 3


def test_a_resumed_sweep_takes_in_the_frames_it_finds(tmp_path):
    FrameStore(tmp_path, keep=5).write_frames("old", b"frames")
    store = FrameStore(tmp_path, keep=1)
    store.consider([row("old", mean=0.01), row("gone", mean=9)])
    store.write_frames("new", b"frames")
    store.consider([row("new", mean=0.5)])
    assert [p.name for p in store.root.iterdir()] == ["new"]
