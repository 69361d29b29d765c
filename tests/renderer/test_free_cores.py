"""A frame uses no more threads than the cores other processes leave free (renderer/free_cores.py)."""
from __future__ import annotations

import multiprocessing
import time

import numba
import pytest

from lab import load_scene
from renderer import free_cores, render
from renderer.free_cores import CpuTimes, FreeCores, others_cores, threads_for, threads_of_this_frame


class Readings:
    """CPU times and a clock for :class:`FreeCores`, advanced by hand."""

    def __init__(self):
        self.now, self.times = 0.0, CpuTimes(busy=0, ours=0, total=0)

    def advance(self, seconds, others_ticks, our_ticks, n_cores=2):
        """``seconds`` pass (100 ticks a second a core) in which the others and we use what is given."""
        b, o, t = self.times
        self.now += seconds
        self.times = CpuTimes(b + others_ticks + our_ticks, o + our_ticks, t + round(100 * seconds * n_cores))

    def read(self):
        return self.times

    def clock(self):
        return self.now


@pytest.fixture
def dynamic(monkeypatch):
    monkeypatch.setenv("SCANLAB_DYNAMIC_THREADS", "1")


def test_other_processes_load_is_all_busy_time_but_ours_in_cores():
    before = CpuTimes(busy=1000, ours=300, total=5000)
    # 1 s on 2 cores: 200 ticks in all, 150 busy, 60 of them ours → the others used 0.9 of a core
    assert others_cores(before, CpuTimes(1150, 360, 5200), 2) == pytest.approx(0.9)
    assert others_cores(before, before, 2) == 0.0
    assert others_cores(before, CpuTimes(1000, 400, 5200), 2) == 0.0  # never below nothing


@pytest.mark.parametrize(("asked", "others", "threads"), [
    (2, 0.0, 2), (2, 0.49, 2), (2, 0.5, 1), (2, 1.0, 1), (2, 2.0, 1), (1, 0.0, 1), (4, 1.2, 1)])
def test_a_frame_gets_what_it_asked_for_at_most_a_thread_per_free_core_and_at_least_one(asked, others, threads):
    assert threads_for(asked, 2, others) == threads


def test_the_load_is_read_again_only_after_the_sampling_interval():
    r = Readings()
    cores = FreeCores(r.read, r.clock, n_cores=2)
    assert cores.threads(2) == 2  # nothing measured yet
    r.advance(free_cores.SAMPLE_SECONDS / 2, others_ticks=10, our_ticks=0)
    assert cores.threads(2) == 2  # too soon: the spinning neighbour is not seen yet
    r.advance(free_cores.SAMPLE_SECONDS, others_ticks=15, our_ticks=10)
    assert cores.threads(2) == 1
    r.advance(1.0, others_ticks=5, our_ticks=150)  # the neighbour has stopped
    assert cores.threads(2) == 2


def test_a_refresh_reads_at_once_and_two_a_moment_apart_give_the_load_of_that_moment():
    r = Readings()
    cores = FreeCores(r.read, r.clock, n_cores=2)
    r.advance(10.0, others_ticks=0, our_ticks=500)  # a long quiet time
    r.advance(0.02, others_ticks=2, our_ticks=0)  # then a neighbour starts spinning
    cores.refresh()
    assert cores.busy_elsewhere() < 0.01  # ten quiet seconds hide it
    r.advance(0.02, others_ticks=2, our_ticks=0)
    cores.refresh()
    assert cores.busy_elsewhere() == pytest.approx(1.0) and cores.threads(2) == 1


def test_without_proc_every_frame_gets_what_it_asked_for():
    cores = FreeCores(lambda: None, time.monotonic, n_cores=2)
    time.sleep(free_cores.SAMPLE_SECONDS)
    assert cores.threads(2) == 2


def test_a_frame_on_a_busy_machine_draws_with_fewer_threads_and_the_setting_comes_back(dynamic, monkeypatch):
    r = Readings()
    cores = FreeCores(r.read, r.clock, n_cores=2)
    r.advance(1.0, others_ticks=100, our_ticks=20)
    saved = numba.get_num_threads()
    numba.set_num_threads(2)
    try:
        with threads_of_this_frame(cores) as used:
            assert used == numba.get_num_threads() == 1
        assert numba.get_num_threads() == 2
        monkeypatch.setenv("SCANLAB_DYNAMIC_THREADS", "0")  # the user's choice: as many as set
        with threads_of_this_frame(cores) as used:
            assert used == numba.get_num_threads() == 2
    finally:
        numba.set_num_threads(saved)


def test_render_asks_the_machine_and_draws_the_same_bytes_with_one_thread(dynamic, monkeypatch):
    calls = []
    monkeypatch.setattr(FreeCores, "threads", lambda self, asked: calls.append(asked) or 1)
    scene = load_scene("menger")
    busy = render(scene)
    monkeypatch.setenv("SCANLAB_DYNAMIC_THREADS", "0")
    idle = render(scene)
    assert calls == [numba.get_num_threads()]
    assert (busy.rgb == idle.rgb).all() and (busy.coverage == idle.coverage).all()


def _spin(seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass


def test_a_process_spinning_on_a_core_is_seen_by_the_real_readings():
    cores = FreeCores()
    spinner = multiprocessing.get_context("spawn").Process(target=_spin, args=(1.5,))
    spinner.start()
    try:
        time.sleep(0.5)  # the child has started and spins
        cores.busy_elsewhere()
        time.sleep(0.5)
        assert cores.busy_elsewhere() >= 0.7
    finally:
        spinner.join()
