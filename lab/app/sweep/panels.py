"""The panels of a kept case: ``side_by_side.png`` and ``delta_e.png``, drawn from its frames.

The same figures ``scanlab compare`` writes (:mod:`compare.images`), drawn when the page is
built and only for the cases whose frames were kept (:mod:`.worst`): drawing takes several
times longer than comparing a small case, so a sweep draws what a person will look at.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from compare.images import PanelText, delta_e_figure, side_by_side_figure
from lab.app.sweep.worst_cases import CASE_FILES

FRAMES, *PANEL_FILES = CASE_FILES


def case_title(row: dict) -> str:
    """``name · shading=flat · lights=key`` (the source's short name and the case's settings)."""
    settings = json.loads(row["settings"])
    return " · ".join([row["name"], *(f"{k}={v}" for k, v in settings.items())])


def metrics_of(row: dict) -> dict:
    """The nested ``metrics.json`` figures :func:`compare.images.metrics_lines` prints, from a row."""
    keys = ("pixels_over_1", "coverage_mismatch", "max_channel_diff", "shared_pixels", "mismatch_pixels",
            "ours_ms", "reference_ms")
    return {"delta_e_2000": {k[len("delta_e_2000_"):]: v for k, v in row.items() if k.startswith("delta_e_2000_")},
            **{k: row[k] for k in keys}}


def draw_panels(folder: Path, row: dict) -> bool:
    """Draw the two panels into ``folder`` from its ``frames.npz`` unless they are newer than
    it; False if the case has no frames."""
    frames = folder / FRAMES
    if not frames.exists():
        return False
    if all((folder / name).exists() and (folder / name).stat().st_mtime >= frames.stat().st_mtime
           for name in PANEL_FILES):
        return True
    with np.load(frames) as data:
        ours, ref, de = data["ours"], data["reference"], data["delta_e"].astype(np.float64)
        shared, mismatch = data["shared"], data["mismatch"]
    side_by_side_figure(ours, ref, de, mismatch, metrics_of(row), folder / "side_by_side.png",
                        PanelText(title=case_title(row)), shared=shared)
    delta_e_figure(de, mismatch, folder / "delta_e.png", shared=shared)
    return True
