"""Histograms of a sweep: mean ΔE2000 and coverage mismatch, one figure per grid key.

Each figure has two plots — mean ΔE2000 over the shared pixels, and coverage mismatch in %
of all pixels — with one step line per value of the key (``shading``: flat, gouraud,
phong), so a setting that moves the distribution shows at a glance. The x axes are
logarithmic: values below the axis floor (exact zeros included: most passing cases) are
counted in the first bin, whose label says so. The dashed line is the parity bar.
Drawn with matplotlib's object-oriented API (``Figure``; no pyplot state).
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from compare.metrics import PARITY_BARS
from lab.atomic import atomic_file

PLOTS = (  # column, axis title, scale to the shown unit, axis floor, bar
    ("delta_e_2000_mean", "mean ΔE2000", 1.0, 1e-4, PARITY_BARS["mean"]),
    ("coverage_mismatch", "coverage mismatch (% of pixels)", 100.0, 1e-4, 100.0 * PARITY_BARS["coverage_mismatch"]),
)
BINS = 32


def grid_values(rows: list[dict]) -> dict[str, list[str]]:
    """Grid key → its values, in the order first met, over the compared rows."""
    found: dict[str, dict[str, None]] = {}
    for row in rows:
        for key, value in json.loads(row["settings"]).items():
            found.setdefault(key, {})[value] = None
    return {key: list(values) for key, values in found.items()}


def _edges(values: np.ndarray, floor: float) -> np.ndarray:
    top = max(float(values.max()) if values.size else 1.0, floor * 10, 1.0) * 1.05
    return np.geomspace(floor, top, BINS + 1)


def histogram_figure(rows: list[dict], key: str | None, path: Path) -> None:
    """Write the figure for grid ``key`` (None: all cases as one group) as a PNG."""
    groups = {"all cases": rows} if key is None else {}
    if key is not None:
        for value in grid_values(rows)[key]:
            groups[f"{key}={value}"] = [r for r in rows if json.loads(r["settings"]).get(key) == value]
    fig = Figure(figsize=(11, 3.6), dpi=100, layout="constrained")
    for ax, (column, title, scale, floor, bar) in zip(fig.subplots(1, 2), PLOTS):
        every = np.array([r[column] * scale for r in rows], dtype=float)
        edges = _edges(every, floor)
        for label, members in groups.items():
            values = np.clip(np.array([r[column] * scale for r in members], dtype=float), floor, None)
            ax.hist(values, bins=edges, histtype="step", linewidth=1.6, label=f"{label} ({len(members)})")
        ax.axvline(bar, color="0.3", linestyle="--", linewidth=1, label=f"bar {bar:g}")
        ax.set_xscale("log")
        ax.set_xlabel(title)
        ax.set_title(f"first bin: ≤ {floor:g}, zeros included", fontsize=9, loc="left")
        ax.set_ylabel("cases")
        ax.legend(fontsize=8, frameon=False)
    fig.suptitle(f"by {key}" if key else "all cases", fontsize=11)
    with atomic_file(path) as f:
        fig.savefig(f, format="png")


def write_histograms(rows: list[dict], folder: Path) -> list[Path]:
    """One figure per grid key (or one of all cases when there is no grid) into ``folder``;
    only compared rows (status ok) count. Returns the files written."""
    compared = [r for r in rows if r["status"] == "ok"]
    if not compared:
        return []
    folder.mkdir(parents=True, exist_ok=True)
    keys = [k for k, values in grid_values(compared).items() if len(values) > 1] or [None]
    written = []
    for key in keys:
        path = folder / f"{key or 'all'}.png"
        histogram_figure(compared, key, path)
        written.append(path)
    return written
