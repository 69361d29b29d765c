"""The benchmark's measurements (compare/bench.py), each on a tiny scene."""
from __future__ import annotations

import os
import time

import pytest

from compare.bench import alternate, busy_core, markdown_table, peak_memory, thread_contention, time_frames
from compare.bench_scenes import bench_scene
from renderer.free_cores import MACHINE, SAMPLE_SECONDS


def test_frames_of_both_renderers_are_timed_in_pairs():
    r = time_frames(bench_scene("icosphere:level=1", (64, 48)), repeat=3, warm_up=1)
    for side in ("ours", "reference"):
        assert 0 < r[side]["min"] <= r[side]["median"] <= r[side]["max"]
    assert r["ratio"] > 0


def test_peak_memory_grows_with_the_image():
    small = peak_memory("ours", "icosphere:level=1", (64, 64))
    large = peak_memory("ours", "icosphere:level=1", (1024, 1024))
    # a 1024² frame needs at least its 3 MiB of colour, more for depth and triangle ids
    assert large - small > 3


def test_the_table_has_a_row_per_measurement_and_names_errors():
    rows = [{"scene": "a", "size": "8x8", "triangles": 1200, "ours": {"median": 2.0, "min": 1.0, "max": 3.0},
             "reference": {"median": 4.0, "min": 3.5, "max": 5.0}, "ratio": 0.5, "memory": {"ours": 10.0, "reference": 20.0}},
            {"scene": "b", "size": "8x8", "error": "unavailable: no file"}]
    table = markdown_table(rows).splitlines()
    assert table[2] == "| a | 8x8 | 1,200 | 2.0 (1.0–3.0) | 4.0 (3.5–5.0) | 0.50 | 10 / 20 |"
    assert "unavailable: no file" in table[3]


def test_one_thread_and_two_are_timed_in_pairs_while_a_core_is_busy(monkeypatch):
    monkeypatch.setenv("SCANLAB_DYNAMIC_THREADS", "1")  # as outside the tests: threads fitted to free cores
    with busy_core() as busy:
        child = busy.child.pid
        assert os.path.exists(f"/proc/{child}")
        r = thread_contention(bench_scene("icosphere:level=1", (64, 48)), repeat=3, warm_up=1)
    assert busy.child.poll() is not None  # the spinning child is gone
    for side in ("one_thread", "two_threads"):
        assert 0 < r[side]["min"] <= r[side]["median"] <= r[side]["max"]
    assert r["ratio"] > 0 and r["layer"] == "tbb"
    assert r["two_used_one"] == 3  # the spinning child holds a core: one thread is what is left


def test_our_frames_on_fewer_threads_are_counted(monkeypatch):
    """A frame of ours drawn on one thread of two, because another process holds a core, is
    counted: each timed frame while a child spins, none when the threads are not fitted."""
    scene = bench_scene("icosphere:level=1", (64, 48))
    monkeypatch.setenv("SCANLAB_DYNAMIC_THREADS", "0")
    assert time_frames(scene, repeat=3, warm_up=1)["fewer_threads"] == 0
    monkeypatch.setenv("SCANLAB_DYNAMIC_THREADS", "1")
    with busy_core():
        MACHINE.refresh()  # the load of the last moment, not since the tests before
        time.sleep(SAMPLE_SECONDS)
        MACHINE.refresh()
        assert time_frames(scene, repeat=3, warm_up=1)["fewer_threads"] == 3


def test_pairs_alternate_which_frame_goes_first_after_the_warm_up():
    calls = []
    first, second, ratios = alternate(lambda: calls.append("a"), lambda: calls.append("b"), repeat=3, warm_up=1)
    assert "".join(calls) == "ab" + "ab" + "ba" + "ab"
    assert len(first) == len(second) == len(ratios) == 3
    assert all(r == pytest.approx(a / b) for r, a, b in zip(ratios, first, second))
