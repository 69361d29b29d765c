"""Whole sweeps, as a user runs them: ``scanlab sweep`` on a local Dask cluster of 2 workers.

- 48 cases give the same figures as ``scanlab compare`` run on each case alone;
- a sweep killed (SIGKILL), run again and interrupted (SIGINT), and run a third time ends
  with every case once, none run twice;
- cases made to hang, crash, run out of memory, raise, or lose their worker are recorded
  as such and the others complete;
- a sweep runs on a cluster started with ``dask scheduler`` and ``dask worker``, as the
  README shows.
"""
from __future__ import annotations

import contextlib
import json
import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

from distributed import Client

from lab.app import cli
from lab.app.sweep.sweep import SweepOptions, plan
from lab.app.sweep.table import flatten

from .sweeps import IDENTITY_SOURCES, part_rows, sweep_command, table_rows

TIMING_KEYS = ("scene", "ours_ms", "reference_ms")
"""metrics.json keys that are not figures of the images: the name, and times in ms."""


def test_a_sweep_of_48_cases_matches_scanlab_compare_run_on_each_case(identity_sweep, tmp_path):
    out, done = identity_sweep
    rows = table_rows(out)
    assert len(rows) == 48 and len({r["case_id"] for r in rows}) == 48
    assert {r["status"] for r in rows} == {"ok"}
    assert len({r["worker"] for r in rows}) == 2, "both workers ran cases"
    assert {r["source"] for r in rows} == {str(Path(s).resolve()) if s.endswith(".toml") else s
                                           for s in IDENTITY_SOURCES}
    for row in rows:
        settings = json.loads(row["settings"])
        folder = tmp_path / row["case_id"]
        status = cli.main(["compare", row["source"], "--shading", settings["shading"], "--model", settings["model"],
                           "--size", settings["size"], "--out", str(folder)])
        assert status == 0
        metrics = json.loads((folder / "metrics.json").read_text())
        expected = flatten({k: v for k, v in metrics.items() if k not in TIMING_KEYS})
        assert {k: row[k] for k in expected} == expected, row["scene"]


def _wait_for_rows(out: Path, at_least: int, proc: subprocess.Popen, limit: float = 600) -> int:
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        n = len(part_rows(out))
        if n >= at_least:
            return n
        assert proc.poll() is None, f"the sweep ended before {at_least} rows: {proc.communicate()}"
        time.sleep(0.2)
    raise AssertionError(f"fewer than {at_least} rows after {limit} s")


def _gone(group: int, limit: float = 30) -> bool:
    """Whether every process of the process group has ended within ``limit`` seconds."""
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        try:
            os.killpg(group, 0)
        except ProcessLookupError:
            return True
        time.sleep(0.5)
    return False


def _start(command) -> subprocess.Popen:
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)


def test_a_killed_then_interrupted_sweep_resumes_with_every_case_once_and_none_run_twice(tmp_path):
    out = tmp_path / "sweep"
    sources, grid = ["cube", "icosphere:level=2"], ["shading=flat,gouraud,phong", "size=96x72,128x96",
                                                     "lights=headlight,key,spot,rgb"]
    command = sweep_command(out, sources, grid, "--workers", "2")
    expected = {c.case_id for c in plan(SweepOptions(out=out, sources=sources, grid=grid))}
    assert len(expected) == 48

    first = _start(command)
    try:
        _wait_for_rows(out, 8, first)
        first.send_signal(signal.SIGKILL)
        first.wait(30)
        assert _gone(first.pid), "the killed sweep left workers or case processes behind"
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(first.pid, signal.SIGKILL)
    killed = {r["case_id"]: r["run"] for r in part_rows(out)}
    assert 8 <= len(killed) < 48 and len(set(killed.values())) == 1

    second = _start(command)
    try:
        _wait_for_rows(out, len(killed) + 8, second)
        second.send_signal(signal.SIGINT)
        _, err = second.communicate(timeout=120)
        assert second.returncode == 130
        assert "interrupted; run the same command again" in err
    finally:
        with contextlib.suppress(ProcessLookupError):
            os.killpg(second.pid, signal.SIGKILL)
    interrupted = {r["case_id"]: r["run"] for r in table_rows(out)}
    assert (out / "index.html").exists(), "an interrupted sweep still writes its page"
    assert len(killed) + 8 <= len(interrupted) < 48

    third = subprocess.run(command, capture_output=True, text=True, timeout=900)
    assert third.returncode == 0, third.stderr
    assert f"{len(interrupted)} finished before" in third.stdout
    rows = table_rows(out)
    assert sorted(r["case_id"] for r in rows) == sorted(expected), "every case once"
    runs = {r["case_id"]: r["run"] for r in rows}
    assert all(runs[c] == run for c, run in killed.items()), "no case of the killed run was run again"
    assert all(runs[c] == run for c, run in interrupted.items()), "no case of the interrupted run was run again"
    assert len(set(runs.values())) == 3


def test_cases_that_hang_crash_run_out_of_memory_or_lose_their_worker_are_recorded_and_the_rest_complete(tmp_path):
    out = tmp_path / "sweep"
    faults = ["none", "hang", "crash", "oom", "error", "lose-worker", "lose-worker-always"]
    command = sweep_command(out, ["cube"], [f"fault={','.join(faults)}", "size=64x48"], "--workers", "2",
                            "--timeout", "15", "--memory-limit", "4G")
    done = subprocess.run(command, capture_output=True, text=True, timeout=900,
                          env={**os.environ, "SCANLAB_SWEEP_TEST_FAULTS": "1"})
    assert done.returncode == 1, done.stderr
    rows = table_rows(out)
    assert len(rows) == 7
    by_fault: dict[str, set] = {}
    for row in rows:
        by_fault.setdefault(row["setting_fault"], set()).add(row["status"])
    assert by_fault == {"none": {"ok"}, "hang": {"timeout"}, "crash": {"crashed"}, "oom": {"out of memory"},
                        "error": {"error"}, "lose-worker": {"ok"}, "lose-worker-always": {"worker lost"}}
    errors = {r["setting_fault"]: r["error"] for r in rows}
    assert "SIGSEGV" in errors["crash"] and "time limit of 15 s" in errors["hang"]
    assert "MemoryError" in errors["oom"] and "on purpose" in errors["error"]
    assert [p.name for p in (out / ".faults").iterdir()] == [next(r["case_id"] for r in rows
                                                               if r["setting_fault"] == "lose-worker")], \
        "the lose-worker case lost its worker once"
    assert all(r["verdict"] == "pass" for r in rows if r["status"] == "ok")


def test_a_sweep_runs_on_a_cluster_started_with_dask_scheduler_and_dask_worker(tmp_path):
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    dask = str(Path(sys.executable).parent / "dask")
    address = f"tcp://127.0.0.1:{port}"
    started = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", str(port), "--no-dashboard"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)]
    try:
        started.append(subprocess.Popen([dask, "worker", address, "--nworkers", "2", "--nthreads", "1",
                                         "--no-dashboard"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                        start_new_session=True))
        with Client(address, timeout="60s") as client:
            client.wait_for_workers(2, timeout=120)
            workers = set(client.scheduler_info()["workers"])
        out = tmp_path / "sweep"
        done = subprocess.run(sweep_command(out, ["cube", "icosphere:level=1"], ["shading=flat,phong"],
                                            "--scheduler", address), capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
        assert f"on 2 workers ({address})" in done.stdout
        rows = table_rows(out)
        assert len(rows) == 4 and {r["status"] for r in rows} == {"ok"}
        assert {r["worker"] for r in rows} <= workers, "the cases ran on that cluster's workers"
    finally:
        for process in started:
            with contextlib.suppress(ProcessLookupError):
                os.killpg(process.pid, signal.SIGTERM)
            process.wait(60)
