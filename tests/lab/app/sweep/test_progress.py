"""The progress bar: cases done and failed, this run's rate, the time left."""
from __future__ import annotations

import io

from lab.app.sweep.progress import Progress, duration


class Clock:
    def __init__(self):
        self.now = 0.0

    def __call__(self):
        return self.now


def test_durations_read_as_a_person_would_say_them():
    assert [duration(s) for s in (4.4, 65, 3725)] == ["4 s", "1 min 05 s", "1 h 02 min"]


def test_the_line_counts_done_and_failed_and_estimates_from_this_runs_rate():
    clock = Clock()
    bar = Progress(10, done=4, failed=1, stream=io.StringIO(), clock=clock, width=10)
    assert bar.line() == "[####......] 4/10 · 1 failed · estimating the time left"
    clock.now = 100.0  # the first case of this run comes after a long start-up, which is not counted
    bar.case_finished()
    clock.now = 102.0
    bar.case_finished(failed=True)
    clock.now = 104.0
    bar.case_finished(error=True)
    assert bar.rate() == 0.5
    assert bar.line() == "[#######...] 7/10 · 3 failed (1 error) · 0.50 cases/s · 6 s left"
    for _ in range(3):
        bar.case_finished()
    assert bar.line().endswith("10/10 · 3 failed (1 error) · done")


def test_into_a_file_it_writes_a_line_now_and_then_not_on_every_case():
    clock, stream = Clock(), io.StringIO()
    bar = Progress(100, stream=stream, clock=clock, every=10)
    for i in range(100):
        clock.now = i * 0.5
        bar.case_finished()
    bar.show(final=True)
    lines = stream.getvalue().splitlines()
    assert 5 <= len(lines) <= 7 and "\r" not in stream.getvalue() and lines[-1].endswith("done")
