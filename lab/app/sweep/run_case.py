"""One case, in the case's own process: load the source, apply the settings, compare.

:func:`run_one_case` is the only place a sweep calls the comparison (scanlab's render,
VTK's render, the ΔE2000 metrics and the verdict against the parity bars); it builds the
same ``metrics.json`` dict as ``scanlab compare`` (:func:`compare.comparison.compare_scene`), but
writes nothing: the frames travel back to the sweep, which keeps those of the worst cases.

:func:`execute` wraps it for one request from the sweep: it loads the source (the last few
loaded scenes are kept, so a source's cases load it once per process), applies the grid's
settings (:mod:`lab.app.sweep.settings`), triggers a test-only fault if asked
(:mod:`lab.app.sweep.faults`), and turns anything that goes wrong into a response with a
status instead of an exception.
"""
from __future__ import annotations

import functools
import io
import time
import traceback
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from compare.metrics import coverage_masks
from lab.app.sweep.faults import FAULTS
from lab.app.sweep.settings import apply_settings
from lab.app.sweep.sources import load_source
from lab.loading import SceneError


@dataclass(frozen=True)
class CaseOutcome:
    """What one comparison gives: ``metrics`` (the keys of ``metrics.json``), the parity bars
    it fails (``[]`` = pass), the verdict (``"pass"``, ``"FAIL"``, ``"fails as meant"`` ...;
    :class:`compare.verdict.Verdict`), both images ((H, W, 3) uint8, row 0 at the top), the
    ΔE2000 map ((H, W) float, 0 off the shared coverage) and the two coverage masks ((H, W) bool)."""

    metrics: dict
    failed_bars: list[str]
    verdict: str
    ours: np.ndarray
    reference: np.ndarray
    delta_e: np.ndarray
    shared: np.ndarray
    mismatch: np.ndarray


def run_one_case(scene, name: str, reference: str | None = None) -> CaseOutcome:
    """Compare ``scene`` exactly as ``scanlab compare`` does (:func:`compare.comparison.run_comparison`,
    ``reference="vtk-native"`` as its ``--reference``), judged by the same verdict."""
    from compare.comparison import run_comparison

    result = run_comparison(scene, name=name, reference=reference)
    shared, mismatch = coverage_masks(result.ours_frame, result.reference_frame)
    return CaseOutcome(result.metrics, list(result.verdict.failed), result.verdict.status, result.ours,
                       result.reference, result.delta_e, shared, mismatch)


def pack_frames(outcome: CaseOutcome) -> bytes:
    """The outcome's images, ΔE map (float32) and masks as compressed ``.npz`` bytes."""
    with io.BytesIO() as f:  # in memory: the sweep writes the bytes (lab.atomic) where it keeps them
        np.savez_compressed(f, ours=outcome.ours, reference=outcome.reference,
                            delta_e=outcome.delta_e.astype(np.float32), shared=outcome.shared, mismatch=outcome.mismatch)
        return f.getvalue()


@functools.lru_cache(maxsize=4)
def _scene(kind: str, key: str):
    return load_source(kind, key)


def _failure(status: str, exc: BaseException, started: float) -> dict:
    message = " ".join(f"{type(exc).__name__}: {exc}".split())[:500]
    return {"status": status, "error": message, "traceback": traceback.format_exc()[-4000:],
            "case_s": time.perf_counter() - started}


def execute(request: dict) -> dict:
    """Run one request — ``kind``, ``key`` and ``name`` of the source, ``settings`` (grid key →
    canonical value), ``marker`` (a per-case path for test-only faults) — and return the
    response: ``status`` "ok" with ``metrics``, ``verdict``, ``failed_bars``, ``frames``
    (:func:`pack_frames`), or "error" / "out of memory" with ``error`` (one line) and
    ``traceback``; always ``load_s`` and ``case_s`` (seconds)."""
    started = time.perf_counter()
    settings = dict(request["settings"])
    try:
        scene = apply_settings(_scene(request["kind"], request["key"]), settings)
    except SceneError as exc:
        return {**_failure("error", exc, started), "error": f"cannot load: {exc}"}
    except MemoryError as exc:
        return _failure("out of memory", exc, started)
    except Exception as exc:  # noqa: BLE001 -- a case's failure is a result, not the sweep's end
        return _failure("error", exc, started)
    loaded = time.perf_counter()
    try:
        if "fault" in settings:
            FAULTS[settings["fault"]](Path(request["marker"]))
        reference = None if settings.get("reference", "auto") == "auto" else settings["reference"]
        outcome = run_one_case(scene, request["name"], reference)
        frames = pack_frames(outcome)
    except MemoryError as exc:
        return {**_failure("out of memory", exc, started), "load_s": loaded - started}
    except Exception as exc:  # noqa: BLE001
        return {**_failure("error", exc, started), "load_s": loaded - started}
    return {"status": "ok", "metrics": outcome.metrics, "verdict": outcome.verdict,
            "failed_bars": outcome.failed_bars, "frames": frames, "load_s": loaded - started,
            "case_s": time.perf_counter() - started}
