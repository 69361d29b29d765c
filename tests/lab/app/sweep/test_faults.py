"""Test-only faults: each misbehaves as named, and the dangerous ones guard themselves."""
from __future__ import annotations

import resource

import pytest

from lab.app.sweep.faults import FAULTS


def test_the_faults_tests_use_are_there():
    assert {"none", "hang", "crash", "oom", "error", "lose-worker", "lose-worker-always"} <= set(FAULTS)


def test_none_does_nothing_and_error_raises(tmp_path):
    assert FAULTS["none"](tmp_path / "m") is None
    with pytest.raises(RuntimeError, match="on purpose"):
        FAULTS["error"](tmp_path / "m")


def test_out_of_memory_refuses_to_run_without_a_memory_limit(tmp_path):
    if resource.getrlimit(resource.RLIMIT_AS)[0] != resource.RLIM_INFINITY:
        pytest.skip("this process has an address-space limit")
    with pytest.raises(RuntimeError, match="needs a memory limit"):
        FAULTS["oom"](tmp_path / "m")


def test_lose_worker_strikes_once_only(tmp_path):
    """With its marker left by the first attempt, the retry runs as usual (no process is killed here)."""
    marker = tmp_path / "faults" / "case"
    marker.parent.mkdir()
    marker.touch()
    assert FAULTS["lose-worker"](marker) is None
