"""The scheduler's side: failed tasks become statuses; lost results and dropped tasks are run
again once (checked with a scripted client, since a real cluster loses them only by chance);
an unreachable scheduler or a cluster without workers is one line."""
from __future__ import annotations

from concurrent.futures import CancelledError

import pytest
from distributed import KilledWorker

from lab.app.sweep.cluster import ClusterError, _failed_task, open_client, run_cases


def test_a_case_whose_workers_died_is_worker_lost_and_other_failures_are_errors():
    assert _failed_task(KilledWorker("scanlab-case-x", "tcp://127.0.0.1:1", 1))["status"] == "worker lost"
    other = _failed_task(RuntimeError("the case process ended\nwhile warming up"))
    assert other == {"status": "error", "error": "RuntimeError: the case process ended while warming up"}


def test_an_unreachable_scheduler_is_one_line():
    with pytest.raises(ClusterError, match="--scheduler tcp://127.0.0.1:9: cannot connect"):
        with open_client("tcp://127.0.0.1:9", 1, 0, connect_timeout="2s"):
            pass


class FakeFuture:
    """A finished task: ``outcomes`` is what each fetch of its result gives (an exception is raised)."""

    def __init__(self, key, outcome):
        self.key, self.outcome, self.status = key, outcome, "finished"

    def result(self, timeout=None):
        if isinstance(self.outcome, BaseException):
            raise self.outcome
        return self.outcome


class FakeClient:
    """Submits tasks whose results come from ``script[case_id]`` in turn; the scheduler forgets ``forgotten``."""

    def __init__(self, script, forgotten=(), workers=1):
        self.script, self.forgotten, self.workers, self.submitted = script, set(forgotten), workers, []

    def submit(self, fn, request, timeout, key, pure, retries):
        case_id = key.split("-")[2]
        self.submitted.append(key)
        return FakeFuture(key, self.script[case_id].pop(0))

    def run_on_scheduler(self, function):
        """The scheduler holds every task but the forgotten cases'."""
        class Tasks:
            def __contains__(_, key):
                return key.split("-")[2] not in self.forgotten
        return function(dask_scheduler=type("Scheduler", (), {"tasks": Tasks()}))

    def scheduler_info(self):
        return {"workers": {f"w{i}": {"nthreads": 1} for i in range(self.workers)}}


def fake_wait(hold: set):
    """distributed.wait that finishes every future not in ``hold`` (by case id) and times out on the rest."""
    def wait(pending, timeout, return_when):
        done = {f for f in pending if f.key.split("-")[2] not in hold}
        if not done:
            raise TimeoutError
        return done, pending - done
    return wait


def run(client, ids, monkeypatch, hold=(), stall=60.0):
    import distributed
    monkeypatch.setattr(distributed, "wait", fake_wait(set(hold)))
    return [pair for batch in run_cases(client, {i: {} for i in ids}, 10.0, stall=stall) for pair in batch]


def test_a_result_lost_before_it_was_fetched_has_its_case_run_once_more(monkeypatch):
    lost = CancelledError("scanlab-case-a-0")
    client = FakeClient({"a": [lost, {"status": "ok"}], "b": [{"status": "ok"}], "c": [lost, lost]})
    results = dict(run(client, ["a", "b", "c"], monkeypatch))
    assert results["a"] == {"status": "ok"} and results["b"] == {"status": "ok"}
    assert results["c"]["status"] == "worker lost" and "lost twice" in results["c"]["error"]
    assert sorted(client.submitted) == ["scanlab-case-a-0", "scanlab-case-a-1", "scanlab-case-b-0",
                                        "scanlab-case-c-0", "scanlab-case-c-1"]


def test_a_case_the_scheduler_dropped_is_run_again_after_a_quiet_spell(monkeypatch):
    client = FakeClient({"a": [{"status": "ok"}, {"status": "ok"}]}, forgotten={"a"})
    calls = {"n": 0}

    def first_time_dropped(pending, timeout, return_when):
        calls["n"] += 1
        if calls["n"] == 1:
            raise TimeoutError
        return set(pending), set()

    import distributed
    monkeypatch.setattr(distributed, "wait", first_time_dropped)
    results = [pair for batch in run_cases(client, {"a": {}}, 10.0, stall=0.0) for pair in batch]
    assert results == [("a", {"status": "ok"})] and client.submitted == ["scanlab-case-a-0", "scanlab-case-a-1"]


def test_a_cluster_left_without_workers_ends_the_run_in_one_line(monkeypatch):
    client = FakeClient({"a": [{"status": "ok"}]}, workers=0)
    with pytest.raises(ClusterError, match="no workers for 0 s"):
        run(client, ["a"], monkeypatch, hold={"a"}, stall=0.0)


def test_once_stop_is_asked_for_no_more_batches_come_even_while_cases_are_still_running(monkeypatch):
    import distributed
    client = FakeClient({"a": [{"status": "ok"}], "b": [{"status": "ok"}]})
    calls = {"n": 0}

    def one_at_a_time_then_nothing(pending, timeout, return_when):
        calls["n"] += 1
        if calls["n"] == 1:
            first = min(pending, key=lambda f: f.key)
            return {first}, pending - {first}
        raise AssertionError("waited on the cluster after the stop was asked for")  # "b" would run on and on

    monkeypatch.setattr(distributed, "wait", one_at_a_time_then_nothing)
    asked = []
    batches = run_cases(client, {"a": {}, "b": {}}, 10.0, stop=lambda: len(asked) > 0, poll=0.01)
    assert next(batches) == [("a", {"status": "ok"})]
    asked.append(True)
    assert list(batches) == [], "the generator ends at the next question, not after b"
