"""The scheduler's side: a Dask cluster to run the cases on, and their results as they finish.

Without ``--scheduler`` the sweep starts a ``LocalCluster`` of ``--workers`` worker processes
with one thread each (each worker then runs one case at a time in its case process, see
:mod:`.isolation`); with ``--scheduler tcp://host:8786`` it joins a cluster someone started
with ``dask scheduler`` and ``dask worker`` (the workers need scanlab installed, and the
sweep's files at the same paths).

Every case is one task (:func:`lab.app.sweep.case_runner.run_case`) submitted with ``retries=1``.
A worker lost mid-case has its case run again on another worker; the local cluster's
scheduler gives up on a case after its second lost worker (``allowed-failures = 1``; a
cluster of your own keeps its own setting, 3 by default). Such a case is recorded as
``worker lost``; an exception raised by the task itself after its retry as ``error``.
Dask counts a lost worker against every task it held, so the local cluster hands each
worker one case at a time (``worker-saturation = 1.0``): only the case that was running
is blamed.
"""
from __future__ import annotations

import logging
import time
from contextlib import contextmanager
from typing import Iterator

from lab.app.sweep.case_runner import PLUGIN_NAME, CaseRunner, run_case


class ClusterError(RuntimeError):
    """The cluster cannot be reached or used; the message is one line."""


@contextmanager
def open_client(scheduler: str | None, workers: int, memory_limit: int, connect_timeout: str = "20s") -> Iterator:
    """A ``distributed.Client`` with the case runner registered on every worker; the local
    cluster (if one was started) and the client are closed on exit. ``connect_timeout``:
    how long to try reaching ``scheduler``."""
    import dask
    from distributed import Client, LocalCluster

    cluster = None
    try:
        if scheduler:
            client = Client(scheduler, timeout=connect_timeout)
            try:
                client.wait_for_workers(1, timeout=120)
            except TimeoutError:
                client.close()
                raise ClusterError(f"--scheduler {scheduler}: no worker has joined it in 120 s "
                                   f"(start some with `dask worker {scheduler}`)") from None
        else:
            with dask.config.set({"distributed.scheduler.allowed-failures": 1,
                                  "distributed.scheduler.worker-saturation": 1.0}):
                cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                       dashboard_address=None, silence_logs=logging.CRITICAL)
            client = Client(cluster)
    except OSError as exc:  # TimeoutError included: no scheduler answers there
        raise ClusterError(f"--scheduler {scheduler}: cannot connect ({exc})") from None
    try:
        try:
            client.register_plugin(CaseRunner(memory_limit), name=PLUGIN_NAME)
        except Exception as exc:  # noqa: BLE001 -- whatever the workers raised while unpickling
            raise ClusterError(f"the workers cannot run scanlab cases ({type(exc).__name__}: {exc}); "
                               f"install scanlab where they run (pip install -e .)") from None
        yield client
    finally:
        client.close()
        if cluster is not None:
            cluster.close()


def worker_count(client) -> int:
    """How many worker threads the cluster has now."""
    return sum(w.get("nthreads", 1) for w in client.scheduler_info()["workers"].values())


def _failed_task(exc: BaseException) -> dict:
    from distributed import KilledWorker

    if isinstance(exc, KilledWorker):
        return {"status": "worker lost", "error": "the worker running it died, and so did the one that retried it "
                                                  f"({type(exc).__name__})"}
    return {"status": "error", "error": " ".join(f"{type(exc).__name__}: {exc}".split())[:500]}


LOST_TWICE = {"status": "worker lost",
              "error": "its result was lost twice (the workers holding it died, or the scheduler dropped it)"}


def _response(future) -> dict | None:
    """A finished future's response; None if its result could not be fetched (the worker
    holding it died before the sweep got it, or the scheduler dropped the task)."""
    if future.status == "error":
        return _failed_task(future.exception())
    try:
        return future.result(timeout=120)
    except Exception:  # noqa: BLE001 -- CancelledError, a lost result, a gather timeout
        return None


def _unknown_to_scheduler(client, keys: list[str]) -> set[str]:
    """The keys the scheduler no longer has (a task it dropped would otherwise be waited for
    for ever)."""
    return set(client.run_on_scheduler(lambda dask_scheduler: [k for k in keys if k not in dask_scheduler.tasks]))


def run_cases(client, requests: dict[str, dict], timeout: float, stall: float = 60.0,
              stop=lambda: False, poll: float = 1.0) -> Iterator[list[tuple[str, dict]]]:
    """Submit every request (case_id → request, in order) and yield the results in batches
    as they finish: lists of (case_id, response). A task that failed gives a response with
    its ``status`` and ``error`` (see the module's docstring).

    Results are fetched by the sweep itself, each guarded: a result lost before it was
    fetched (its worker died just after the case) has the case submitted once more; so has
    a case the scheduler no longer knows after ``stall`` seconds without any result. A
    cluster left with no workers for that long raises ClusterError.

    ``stop()`` is asked every ``poll`` seconds and after every batch; once it is true no
    more batches come (the cases still queued or running are left to the client's close).
    """
    from distributed import wait

    def submit(case_id: str, attempt: int):
        return client.submit(run_case, requests[case_id], timeout, key=f"scanlab-case-{case_id}-{attempt}",
                             pure=False, retries=1)

    futures = {submit(case_id, 0): case_id for case_id in requests}
    attempts = dict.fromkeys(requests, 0)
    pending, quiet_since = set(futures), time.monotonic()
    while pending and not stop():
        try:
            done, pending = wait(pending, timeout=poll, return_when="FIRST_COMPLETED")
        except TimeoutError:  # nothing finished in this while
            done = set()
        dropped = set()
        if not done and time.monotonic() - quiet_since > stall:
            if worker_count(client) == 0:
                raise ClusterError(f"the cluster has had no workers for {stall:g} s; run the same command again "
                                   f"to go on when it has")
            unknown = _unknown_to_scheduler(client, [f.key for f in pending])
            dropped = {f for f in pending if f.key in unknown}
            pending -= dropped
            quiet_since = time.monotonic()
        results = []
        for future in done | dropped:
            case_id = futures.pop(future)
            response = None if future in dropped else _response(future)
            if response is None and attempts[case_id] < 1:
                attempts[case_id] += 1
                again = submit(case_id, attempts[case_id])
                futures[again] = case_id
                pending.add(again)
            else:
                results.append((case_id, response or LOST_TWICE))
        if results:
            quiet_since = time.monotonic()
            yield results
