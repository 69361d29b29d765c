"""The results table: one Parquet row per case, written as cases finish.

Layout in the sweep's folder ``DIR``:

- ``DIR/results.parts/part-<run>-<n>.parquet``: each batch of rows that reaches the sweep is
  written at once as a small file of its own (a temporary file, then a rename), so a sweep
  killed at any moment keeps every row it had received;
- ``DIR/results.parquet``: the whole table, written when a sweep ends (:meth:`ResultsTable.compact`):
  the previous table and every part, one row per case (the latest wins), sorted by source
  and settings; the parts it took in are then removed.

:meth:`ResultsTable.rows` reads both, so a table is complete between a kill and a resume.
Columns (:func:`row_for`) are the case's identity (``case_id``, ``source``, ``kind``,
``name``, ``settings`` as JSON and one ``setting_<key>`` column per grid key), every key of
``metrics.json`` flattened (``delta_e_2000_mean``, ``pixels_over_1``, ...; nested keys joined
with ``_``), the ``verdict`` and the bars it fails, ``status`` and ``error``, timings
(``case_s``, ``load_s``, ``wall_s``, ``warm_up_s``, ``ours_ms``, ``reference_ms``,
``started_at``, ``finished_at``), where it ran (``worker``, ``host``) and which run of the
sweep wrote it (``run``).
"""
from __future__ import annotations

import json
from pathlib import Path

import pyarrow as pa
import pyarrow.parquet as pq

from lab.atomic import atomic_file

STATUSES = ("ok", "error", "timeout", "crashed", "out of memory", "worker lost")
"""A row's ``status``: ``ok`` (compared; see ``verdict``) or how the case failed to finish."""


def flatten(data: dict, prefix: str = "") -> dict:
    """``{"delta_e_2000": {"mean": 1}}`` → ``{"delta_e_2000_mean": 1}``; lists and scalars kept."""
    flat = {}
    for key, value in data.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            flat.update(flatten(value, name + "_"))
        else:
            flat[name] = value
    return flat


def row_for(case, response: dict, run: str) -> dict:
    """The table row of a finished case (:class:`lab.app.sweep.cases.Case`) from its response."""
    settings = dict(case.settings)
    row = {"case_id": case.case_id, "source": case.source.key, "kind": case.source.kind, "name": case.source.name,
           "settings": json.dumps(settings, sort_keys=True),
           **{f"setting_{key}": value for key, value in settings.items()},
           "status": response["status"], "verdict": response.get("verdict"),
           "failed_bars": "; ".join(response.get("failed_bars") or []) or None,
           "error": response.get("error"), "traceback": response.get("traceback")}
    row.update(flatten(response.get("metrics") or {}))
    for key in ("case_s", "load_s", "wall_s", "warm_up_s", "started_at", "finished_at", "worker", "host"):
        row[key] = response.get(key)
    row["run"] = run
    return row


def to_arrow(rows: list[dict]) -> pa.Table:
    """A table of ``rows`` with every column any row has (missing values null); each column's
    type is inferred from all its values (``Table.from_pylist`` would read the first row's keys only)."""
    columns: dict[str, None] = {}
    for row in rows:
        columns.update(dict.fromkeys(row))
    return pa.Table.from_pydict({name: [row.get(name) for row in rows] for name in columns})


class ResultsTable:
    """The Parquet table of a sweep folder (see the module's docstring)."""

    def __init__(self, out: str | Path):
        self.out = Path(out)
        self.parts = self.out / "results.parts"
        self.path = self.out / "results.parquet"
        self._written = 0

    def _part_files(self) -> list[Path]:
        return sorted(self.parts.glob("part-*.parquet")) if self.parts.is_dir() else []

    def append(self, rows: list[dict], run: str) -> Path | None:
        """Write ``rows`` at once as a new part file; return its path (None for no rows)."""
        if not rows:
            return None
        self.parts.mkdir(parents=True, exist_ok=True)
        self._written += 1
        path = self.parts / f"part-{run}-{self._written:06d}.parquet"
        with atomic_file(path) as f:
            pq.write_table(to_arrow(rows), f)
        return path

    def _tables(self) -> list[pa.Table]:
        files = ([self.path] if self.path.exists() else []) + self._part_files()
        return [pq.read_table(f) for f in files]

    def rows(self) -> list[dict]:
        """Every case's latest row (the table, then the parts in the order they were written)."""
        latest: dict[str, dict] = {}
        for table in self._tables():
            for row in table.to_pylist():
                latest[row["case_id"]] = row
        return list(latest.values())

    def finished(self) -> dict[str, str]:
        """case_id → status of every case that has a row."""
        return {row["case_id"]: row["status"] for row in self.rows()}

    def compact(self) -> Path:
        """Write every case's latest row to ``results.parquet`` (sorted by source and settings)
        and remove the parts it now holds; return its path."""
        parts = self._part_files()
        rows = sorted(self.rows(), key=lambda r: (r["source"], r["settings"]))
        with atomic_file(self.path) as f:
            pq.write_table(to_arrow(rows), f)
        for part in parts:
            part.unlink()
        if self.parts.is_dir() and not any(self.parts.iterdir()):
            self.parts.rmdir()
        return self.path
