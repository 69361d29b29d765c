"""lab/app/live/render_service.py: worker processes stay warm, the newest request wins, stale
results are dropped, a failing job is one line, a stuck worker is replaced, and stop() ends them."""
from __future__ import annotations

import asyncio
import os
import time
from pathlib import Path

import pytest

from lab.app.live.render_service import MEASURE_ENV, MEASURE_NICE, Lane, RenderService, Worker

HERE = Path(__file__).parent


@pytest.fixture
def tasks(monkeypatch):
    monkeypatch.syspath_prepend(str(HERE))  # spawned workers find the module by name, too
    import live_service_tasks
    return live_service_tasks


@pytest.fixture
def loop():
    loop = asyncio.new_event_loop()
    yield loop
    loop.close()


def _run_until(loop, done, timeout=30.0):
    async def wait():
        t0 = time.monotonic()
        while not done():
            assert time.monotonic() - t0 < timeout, "timed out"
            await asyncio.sleep(0.01)
    loop.run_until_complete(wait())


def _lane(loop, worker, **kw):
    got = []
    lane = Lane(worker, lambda kind, n, result: got.append((kind, n, result)), **kw)
    lane.attach(loop)
    _run_until(loop, lambda: lane.ready)
    return lane, got


def test_the_newest_request_replaces_the_waiting_one(tasks, loop):
    lane, got = _lane(loop, Worker("t", tasks.sleep_then_tell, tasks.warm_nothing))
    try:
        for n, seconds in [(1, 0.5), (2, 0), (3, 0)]:
            lane.submit(tasks.SleepJob(n, seconds))
        _run_until(loop, lambda: len(got) == 2 and lane.running is None)
        assert [n for _, n, _ in got] == [1, 3] and lane.dropped == 1
        assert got[0][2]["pid"] == got[1][2]["pid"]  # one warm process
    finally:
        lane.stop()


def test_a_quiet_lane_waits_for_the_controls_to_rest(tasks, loop):
    lane, got = _lane(loop, Worker("t", tasks.sleep_then_tell, tasks.warm_nothing), quiet=0.3)
    try:
        t0 = time.monotonic()
        lane.submit(tasks.SleepJob(1))
        _run_until(loop, lambda: got)
        assert time.monotonic() - t0 >= 0.3
    finally:
        lane.stop()


def test_a_failing_job_comes_back_as_one_line(tasks, loop):
    lane, got = _lane(loop, Worker("t", tasks.fail, tasks.warm_nothing))
    try:
        lane.submit(tasks.SleepJob(4))
        _run_until(loop, lambda: got)
        assert got == [("error", 4, "a bad value")]
    finally:
        lane.stop()


def test_a_worker_that_cannot_warm_up_says_why(tasks, loop):
    lane, _ = _lane(loop, Worker("t", tasks.sleep_then_tell, tasks.warm_badly))
    try:
        assert lane.problem == "no OpenGL here"
    finally:
        lane.stop()


def test_a_worker_busy_past_its_patience_is_replaced_when_a_newer_request_waits(tasks, loop):
    lane, got = _lane(loop, Worker("t", tasks.sleep_then_tell, tasks.warm_nothing), patience=0.3)
    try:
        lane.submit(tasks.SleepJob(1, 60.0))
        _run_until(loop, lambda: lane.running is not None)
        old = lane.worker.process.pid
        loop.run_until_complete(asyncio.sleep(0.4))
        t0 = time.monotonic()
        lane.submit(tasks.SleepJob(2, 0))
        assert time.monotonic() - t0 < 0.1  # replacing it does not hold up the server's event loop
        _run_until(loop, lambda: got)
        assert [n for _, n, _ in got] == [2] and got[0][2]["pid"] != old
        assert time.monotonic() - t0 < 20
    finally:
        lane.stop()


def test_a_measurement_older_than_the_newest_request_is_dropped_but_our_image_is_shown(tasks, loop):
    shown = []
    service = RenderService(lambda lane, kind, n, r: shown.append((lane, n)),
                            workers={"ours": Worker("o", tasks.sleep_then_tell, tasks.warm_nothing),
                                     "measure": Worker("m", tasks.sleep_then_tell, tasks.warm_nothing)})
    service.lanes["measure"].quiet = 0.0
    service.attach(loop)
    try:
        _run_until(loop, lambda: all(lane.ready for lane in service.lanes.values()))
        service.submit(tasks.SleepJob(1, 0.4))
        loop.run_until_complete(asyncio.sleep(0.1))
        service.submit(tasks.SleepJob(2, 0.0), lanes=("ours",))  # a newer request while 1 is measured
        _run_until(loop, lambda: ("ours", 2) in shown and service.lanes["measure"].running is None)
        assert shown == [("ours", 1), ("ours", 2)] and service.stale["measure"] == 1
    finally:
        service.stop()


def test_stop_ends_the_processes(tasks, loop):
    worker = Worker("t", tasks.sleep_then_tell, tasks.warm_nothing)
    process = worker.process
    lane, _ = _lane(loop, worker)
    lane.submit(tasks.SleepJob(1, 60.0))
    lane.stop()
    assert not process.is_alive()


def test_the_measure_worker_yields_the_cores_to_ours(tasks, loop):
    """Lower priority and a one-thread llvmpipe, set before the worker imports anything;
    the server's own priority and environment stay as they were."""
    lane, got = _lane(loop, Worker("t", tasks.sleep_then_tell, tasks.warm_nothing, MEASURE_NICE, MEASURE_ENV))
    try:
        lane.submit(tasks.SleepJob(1))
        _run_until(loop, lambda: got)
        assert got[0][2]["nice"] == os.nice(0) + MEASURE_NICE and got[0][2]["lp"] == "1"
        assert os.environ.get("LP_NUM_THREADS") != "1"
    finally:
        lane.stop()
