"""A whole sweep: plan the cases, skip those finished before, run the rest, write the outputs.

:func:`run_sweep` is what ``scanlab sweep`` does:

1. plan (:func:`plan`): SOURCES and the grid, checked at the edge, crossed into cases;
2. resume: the cases whose rows are already in ``DIR``'s table are skipped (with
   ``retry_errors``, those that did not finish are run again);
3. run the rest on the cluster (:mod:`.cluster`), writing each batch of rows to the table
   and each case's frames as they arrive, keeping the frames of the worst
   (:mod:`.worst`), with a progress bar (:mod:`.progress`);
4. compact the table, draw the kept cases' panels and the histograms, write the page.

Interrupted (Ctrl-C), it still does step 4 with what it has; a kill loses at most the
cases that were running. The folder accumulates: the page and the table show every case
``DIR`` holds, this sweep's and earlier ones'.
"""
from __future__ import annotations

import os
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

from compare.verdict import FAIL, PASSES_UNEXPECTEDLY
from lab.app.sweep.cases import Case, build_grid, expand, read_grid_file
from lab.app.sweep.cluster import ClusterError, open_client, run_cases, worker_count
from lab.app.sweep.histograms import write_histograms
from lab.app.sweep.interrupts import StopRequest
from lab.app.sweep.panels import draw_panels
from lab.app.sweep.progress import Progress, duration
from lab.app.sweep.sources import find_sources
from lab.app.sweep.sweep_page import build_page
from lab.app.sweep.table import ResultsTable, row_for
from lab.app.sweep.worst_cases import FrameStore


@dataclass
class SweepOptions:
    """What ``scanlab sweep`` was asked (see ``scanlab sweep --help``); sizes in bytes, times in seconds."""

    out: Path
    sources: list[str] = field(default_factory=list)
    grid: list[str] = field(default_factory=list)
    grid_file: str | None = None
    scheduler: str | None = None
    workers: int = 2
    timeout: float = 120.0
    memory_limit: int = 8 << 30
    worst: int = 12
    keep_all: bool = False
    retry_errors: bool = False
    command: str = ""


class SweepError(ValueError):
    """Nothing to sweep; the message is one line."""


def plan(options: SweepOptions) -> list[Case]:
    """The sweep's cases, every source and grid value checked (SceneError, GridError, SweepError)."""
    file_grid, file_sources = read_grid_file(options.grid_file) if options.grid_file else ({}, [])
    texts = list(options.sources) + file_sources
    if not texts:
        raise SweepError("no SOURCES: name scene files, mesh files, folders, presets or shapes "
                         "(or `sources = [...]` in the grid file)")
    return expand(find_sources(texts), build_grid(file_grid, options.grid))


def request_for(case: Case, out: Path) -> dict:
    """What the case's process needs (:func:`lab.app.sweep.run_case.execute`)."""
    return {"kind": case.source.kind, "key": case.source.key, "name": case.label, "settings": case.settings,
            "marker": str(out / ".faults" / case.case_id)}


NOT_OK = (FAIL, PASSES_UNEXPECTEDLY)
"""Verdicts that fail a sweep: a FAIL, and a scene meant to fail that passes (:mod:`compare.verdict`)."""


def _failed(row: dict) -> tuple[bool, bool]:
    """(failed, did not finish) for the progress bar and the exit status."""
    unfinished = row["status"] != "ok"
    return unfinished or row["verdict"] in NOT_OK, unfinished


def _say(text: str) -> None:
    print(text, flush=True)


def run_cases_into(options: SweepOptions, pending: list[Case], table: ResultsTable, store: FrameStore,
                   progress, run: str, stop=lambda: False) -> int:
    """Run ``pending`` on the cluster, writing rows and frames as they arrive, until every
    case is done or ``stop()`` is true; the number of workers."""
    by_id = {case.case_id: case for case in pending}
    with open_client(options.scheduler, options.workers, options.memory_limit) as client:
        workers = worker_count(client)
        where = options.scheduler or "a local cluster"
        _say(f"running {len(pending)} cases on {workers} workers ({where}); time limit {options.timeout:g} s a case")
        requests = {case.case_id: request_for(case, options.out) for case in pending}
        for batch in run_cases(client, requests, options.timeout, stop=stop):
            rows = []
            for case_id, response in batch:
                frames = response.pop("frames", None)
                if frames is not None:
                    store.write_frames(case_id, frames)
                rows.append(row_for(by_id[case_id], response, run))
            table.append(rows, run)
            store.consider(rows)
            for row in rows:
                failed, unfinished = _failed(row)
                progress.case_finished(failed=failed, error=unfinished)
    return workers


def _outputs(options: SweepOptions, table: ResultsTable, store: FrameStore, facts: dict) -> Path:
    facts["table"] = str(table.compact())
    rows = table.rows()
    kept = {row["case_id"] for row in rows if draw_panels(store.folder(row["case_id"]), row)}
    histograms = write_histograms(rows, options.out / "histograms")
    return build_page(options.out, rows, kept, histograms, facts)


def run_sweep(options: SweepOptions, progress_stream=None) -> int:
    """Do the whole sweep; exit status 0 (every case of this sweep passes), 1 (any FAIL or
    unfinished case), 130 (interrupted: Ctrl-C at any moment of the run, see :mod:`.interrupts`)."""
    with StopRequest() as stop:
        return _sweep(options, progress_stream, stop)


def _sweep(options: SweepOptions, progress_stream, stop: StopRequest) -> int:
    cases = plan(options)
    options.out.mkdir(parents=True, exist_ok=True)
    table = ResultsTable(options.out)
    finished = table.finished()
    redo = {cid for cid, status in finished.items() if status != "ok"} if options.retry_errors else set()
    pending = [c for c in cases if c.case_id not in finished or c.case_id in redo]
    store = FrameStore(options.out, options.worst, options.keep_all)
    earlier = {row["case_id"]: row for row in table.rows()}
    store.consider(list(earlier.values()))
    pending_ids = {c.case_id for c in pending}
    done_before = [earlier[c.case_id] for c in cases if c.case_id in earlier and c.case_id not in pending_ids]
    flags = [_failed(row) for row in done_before]
    progress = Progress(len(cases), done=len(done_before), failed=sum(f for f, _ in flags),
                        errors=sum(u for _, u in flags), stream=progress_stream)
    _say(f"scanlab sweep: {len(cases)} cases; {len(done_before)} finished before in {options.out}, "
         f"{len(pending)} to run")
    run = time.strftime("%Y%m%dT%H%M%S") + f"-{os.getpid()}"
    started, interrupted, stopped, workers = time.perf_counter(), False, None, 0
    try:
        if pending:
            workers = run_cases_into(options, pending, table, store, progress, run, stop)
    except KeyboardInterrupt:  # a second Ctrl-C
        interrupted = True
    except ClusterError as exc:  # written below, after the outputs of what was done
        stopped = exc
    progress.show(final=True)
    seconds = time.perf_counter() - started
    ran = progress.this_run
    throughput = (f"This run: {ran} cases in {duration(seconds)} on {workers} workers, "
                  f"{60 * ran / seconds:.1f} cases/min (cluster start and warm-up included)." if ran else "")
    page = _outputs(options, table, store, {"command": options.command, "throughput": throughput})
    if throughput:
        _say(throughput)
    _say(f"table: {table.path}\npage: {page.resolve()}")
    if stopped is not None:
        raise stopped
    if interrupted or stop.requested:
        print("scanlab sweep: interrupted; run the same command again to go on where it stopped", file=sys.stderr)
        return 130
    final = {row["case_id"]: row for row in table.rows()}
    bad = [c for c in cases if c.case_id in final and any(_failed(final[c.case_id]))]
    return 1 if bad else 0
