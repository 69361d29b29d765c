"""``scanlab demo``: compare every preset and build a page of side-by-side panels.

Writes ``OUT/<preset>/`` (the five files of ``scanlab compare``) for each preset, then
``OUT/index.html`` (all panels with their figures) and ``OUT/summary.json``.
"""
from __future__ import annotations

import html
import sys
import time
from pathlib import Path

from lab.loading import load_scene
from lab.presets import preset_description, preset_path

def shows_a_failure(scene) -> bool:
    """A preset made to fail against VTK: the painter's algorithm or no hidden-surface removal."""
    return scene.render.hidden_surface != "zbuffer"


def verdict(m: dict) -> str:
    """"pass", "FAIL", "fails as meant" (a failure preset that fails) or "PASSES?" (one that does not)."""
    if m.get("meant_to_fail"):
        return "PASSES?" if passes(m) else "fails as meant"
    return "pass" if passes(m) else "FAIL"


def passes(m: dict) -> bool:
    """Whether a comparison meets the parity bars (:data:`compare.metrics.PARITY_BARS`)."""
    from compare.metrics import failed_bars

    return not failed_bars(m)


def _progress(i: int, n: int, name: str, started: float) -> None:
    done = int(30 * i / n)
    sys.stdout.write(f"\r[{'#' * done}{'.' * (30 - done)}] {i}/{n} {name:<24} {time.perf_counter() - started:5.1f} s")
    sys.stdout.flush()


def _page(rows: list[dict]) -> str:
    items = []
    for m in rows:
        de = m["delta_e_2000"]
        v = verdict(m)
        items.append(
            f"<section><h2>{html.escape(m['scene'])} <span class='{'pass' if v in ('pass', 'fails as meant') else 'FAIL'}'>"
            f"{v}</span></h2>"
            f"<p>{html.escape(m['description'])}</p>"
            f"<img src='{html.escape(m['scene'])}/side_by_side.png' alt='{html.escape(m['scene'])}'>"
            f"<p class='fig'>mean ΔE2000 {de['mean']:.3f} · p99.9 {de['p999']:.2f} · max {de['max']:.2f} · "
            f"over 1: {100 * m['pixels_over_1']:.3f} % · coverage mismatch {100 * m['coverage_mismatch']:.3f} % · "
            f"ours {m['ours_ms']:.1f} ms, VTK {m['reference_ms']:.1f} ms</p></section>")
    return ("<!doctype html><meta charset='utf-8'><title>scanlab demo</title>"
            "<style>body{font-family:sans-serif;max-width:1800px;margin:2em auto;padding:0 1em}"
            "img{max-width:100%}.pass{color:#070}.FAIL{color:#c00}.fig{font-family:monospace}</style>"
            "<h1>scanlab: our scanline renderer beside VTK</h1>"
            "<p>Each panel: scanlab's image, VTK's image of the same triangles, and the CIEDE2000 difference per "
            "pixel. Bars: coverage mismatch ≤ 0.02 %, pixels with ΔE2000 &gt; 1 ≤ 0.2 %, mean ΔE2000 ≤ 0.1.</p>"
            + "".join(items))


def run_demo(out: Path, names: list[str]) -> int:
    """Compare the named presets into ``out``; print where everything is. Exit status 0/1."""
    from compare.report import compare_scene, summary_line, write_json
    from lab.atomic import write_text

    out.mkdir(parents=True, exist_ok=True)
    rows, started = [], time.perf_counter()
    print(f"scanlab demo: comparing {len(names)} scenes with VTK (the first run compiles the renderer's kernels)")
    for i, name in enumerate(names):
        _progress(i, len(names), name, started)
        scene = load_scene(preset_path(name))
        m = compare_scene(scene, out / name, name=name)
        m["description"] = preset_description(name)
        m["meant_to_fail"] = shows_a_failure(scene)
        rows.append(m)
    _progress(len(names), len(names), "done", started)
    print()
    for m in rows:
        print(f"  {verdict(m):<15} {summary_line(m)}")
    write_json(out / "summary.json", {"scenes": rows})
    page = out / "index.html"
    write_text(page, _page(rows))
    print(f"\nside-by-side panels: {out}/<scene>/side_by_side.png")
    print(f"all of them on one page: {page.resolve()}")
    return 0 if all(verdict(m) in ("pass", "fails as meant") for m in rows) else 1
