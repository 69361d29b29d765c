"""The scheduler's side: failed tasks become statuses; an unreachable scheduler is one line."""
from __future__ import annotations

import pytest
from distributed import KilledWorker

from lab.app.sweep.cluster import ClusterError, _failed_task, open_client


def test_a_case_whose_workers_died_is_worker_lost_and_other_failures_are_errors():
    assert _failed_task(KilledWorker("scanlab-case-x", "tcp://127.0.0.1:1", 1))["status"] == "worker lost"
    other = _failed_task(RuntimeError("the case process ended\nwhile warming up"))
    assert other == {"status": "error", "error": "RuntimeError: the case process ended while warming up"}


def test_an_unreachable_scheduler_is_one_line():
    with pytest.raises(ClusterError, match="--scheduler tcp://127.0.0.1:9: cannot connect"):
        with open_client("tcp://127.0.0.1:9", 1, 0, connect_timeout="2s"):
            pass
