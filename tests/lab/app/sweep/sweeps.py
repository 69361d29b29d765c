"""Helpers of the sweep tests: the command line of ``scanlab sweep``, and reading its table."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pyarrow.parquet as pq

from lab.presets import SCENES_DIR

IDENTITY_SOURCES = ["cube", "icosphere:level=2", str(SCENES_DIR / "torus-mesh.toml"), "textured-sphere"]
IDENTITY_GRID = ["shading=flat,gouraud,phong", "model=vtk,classic", "size=64x48,96x72"]
"""4 sources × 3 shadings × 2 models × 2 sizes = 48 cases, every setting one that
``scanlab compare`` also takes (--shading, --model, --size)."""


def sweep_command(out: Path, sources: list[str], grid: list[str], *extra: str) -> list[str]:
    return [sys.executable, "-m", "lab", "sweep", *sources, *(f"--grid={g}" for g in grid), "--out", str(out),
            *extra]


def table_rows(out: Path) -> list[dict]:
    """The rows of ``out/results.parquet``."""
    return pq.read_table(out / "results.parquet").to_pylist()


def part_rows(out: Path) -> list[dict]:
    """The rows in the part files written so far (a sweep in progress or killed)."""
    parts = sorted((out / "results.parts").glob("part-*.parquet")) if (out / "results.parts").is_dir() else []
    return [row for part in parts for row in pq.read_table(part).to_pylist()]
