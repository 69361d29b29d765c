"""A case that hangs, crashes or runs out of memory ends as a status; the next case runs on a fresh process."""
from __future__ import annotations

import pytest

from lab.app.sweep.isolation import CaseProcess, CaseProcessError
from lab.app.sweep.settings import TEST_FAULTS_ENV


def request(*settings):
    return {"kind": "shape", "key": "cube", "name": "cube", "settings": (("size", "40x30"), *settings),
            "marker": "/nonexistent"}


def test_bad_ends_are_reported_and_the_process_is_replaced(monkeypatch):
    monkeypatch.setenv(TEST_FAULTS_ENV, "1")
    process = CaseProcess(memory_limit=4 << 30)
    try:
        assert process.run(request(), timeout=60)["status"] == "ok"
        assert process.starts == 1 and process.warm_up_s > 0

        hung = process.run(request(("fault", "hang")), timeout=3)
        assert hung["status"] == "timeout" and "time limit of 3 s" in hung["error"] and 3 <= hung["case_s"] < 10

        crashed = process.run(request(("fault", "crash")), timeout=60)
        assert crashed["status"] == "crashed" and "SIGSEGV" in crashed["error"]
        assert "Fatal Python error: Segmentation fault" in crashed["error"], "faulthandler's line is quoted"

        oom = process.run(request(("fault", "oom")), timeout=60)
        assert oom["status"] == "out of memory" and "MemoryError" in oom["error"]
        assert not process.alive(), "a process that ran out of memory is not used again"

        raised = process.run(request(("fault", "error")), timeout=60)
        assert raised["status"] == "error" and process.alive(), "an exception leaves the process usable"

        assert process.run(request(), timeout=60)["status"] == "ok"
        assert process.starts == 4, "one start, then one after each of the timeout, the crash and the oom"
    finally:
        process.close()


def test_a_process_that_cannot_start_says_why():
    process = CaseProcess(memory_limit=64 << 20)
    with pytest.raises(CaseProcessError, match="warming up.*(MemoryError|Error)"):
        process.start()
    assert not process.alive()
