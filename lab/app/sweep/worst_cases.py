"""Which cases are worst, and the frames kept for them.

A compared case's score is how far it is from the parity bars
(:data:`compare.metrics.PARITY_BARS`): the largest of coverage mismatch / 0.02 %, share of
pixels over ΔE 1 / 0.2 % and mean ΔE2000 / 0.1 — above 1 the case fails — then its 99.9th
percentile and its largest ΔE2000 to break ties. Cases that did not finish (timeouts,
crashes, errors) have no score and no frames; the page lists them apart.

Every finished case's frames (``DIR/cases/<case_id>/frames.npz``, see
:func:`lab.app.sweep.run_case.pack_frames`) are written as they arrive; :class:`FrameStore`
keeps those of the ``keep`` worst cases and deletes the others as soon as they drop out
(all are kept with ``--keep-all``), so a sweep of any length holds a bounded number of them.
"""
from __future__ import annotations

from pathlib import Path

from compare.metrics import PARITY_BARS
from lab.atomic import atomic_file

CASE_FILES = ("frames.npz", "side_by_side.png", "delta_e.png")
"""What a case's folder holds: its frames, and the panels drawn from them (:mod:`.panels`)."""

BAR_COLUMNS = {"coverage_mismatch": "coverage_mismatch", "pixels_over_1": "pixels_over_1",
               "mean": "delta_e_2000_mean"}
"""The table column of each parity bar."""


def bar_ratio(row: dict) -> float:
    """The largest value / bar over the parity bars (> 1: the case fails a bar)."""
    return max(row[column] / PARITY_BARS[bar] for bar, column in BAR_COLUMNS.items())


def score(row: dict) -> tuple[float, float, float]:
    """(bar ratio, ΔE2000 p99.9, ΔE2000 max): larger is worse."""
    return bar_ratio(row), row["delta_e_2000_p999"], row["delta_e_2000_max"]


def worst_first(rows: list[dict]) -> list[dict]:
    """The compared rows (status ok), worst first."""
    return sorted((r for r in rows if r["status"] == "ok"), key=score, reverse=True)


class FrameStore:
    """The ``DIR/cases/<case_id>/`` folders: frames (and later panels) of the worst cases."""

    def __init__(self, out: str | Path, keep: int, keep_all: bool = False):
        self.root = Path(out) / "cases"
        self.keep, self.keep_all = keep, keep_all
        self._kept: dict[str, tuple] = {}

    def folder(self, case_id: str) -> Path:
        return self.root / case_id

    def has_frames(self, case_id: str) -> bool:
        return (self.folder(case_id) / CASE_FILES[0]).exists()

    def write_frames(self, case_id: str, frames: bytes) -> None:
        """Write a case's frames (atomically; a rerun of the case replaces them)."""
        self.folder(case_id).mkdir(parents=True, exist_ok=True)
        with atomic_file(self.folder(case_id) / CASE_FILES[0]) as f:
            f.write(frames)

    def consider(self, rows: list[dict]) -> None:
        """Take in finished rows (with their frames saved); delete the frames of every case
        no longer among the ``keep`` worst (unless ``keep_all``)."""
        for row in rows:
            if row["status"] == "ok" and self.has_frames(row["case_id"]):
                self._kept[row["case_id"]] = score(row)
        if self.keep_all or len(self._kept) <= self.keep:
            return
        ranked = sorted(self._kept, key=self._kept.get, reverse=True)
        for case_id in ranked[self.keep:]:
            self._remove(case_id)
            del self._kept[case_id]

    def _remove(self, case_id: str) -> None:
        """Delete the files the sweep put in a case's folder, then the folder if that left it empty."""
        folder = self.folder(case_id)
        for name in CASE_FILES:
            (folder / name).unlink(missing_ok=True)
        if folder.is_dir() and not any(folder.iterdir()):
            folder.rmdir()
