"""``scanlab bench``: issue 15's benchmark, printed as a table and optionally written out.

The measuring is :mod:`compare.bench`'s; this module picks the scenes and sizes, shows
progress, and writes the JSON and Markdown files (the Markdown table goes between the
markers :data:`START` and :data:`END` of the file it is given, e.g. ``docs/performance.md``).
"""
from __future__ import annotations

import json
import os
import platform
import subprocess
import time
from pathlib import Path

import lab.atomic

START, END = "<!-- bench:start -->", "<!-- bench:end -->"


def _load_text() -> str:
    one, five, fifteen = os.getloadavg()
    return f"{one:.1f} {five:.1f} {fifteen:.1f}"


def _sizes(args) -> list[tuple[int, int]]:
    from compare.bench_scenes import DEFAULT_SIZES

    return list(args.size) if args.size else list(DEFAULT_SIZES)


def measure(args, say=print) -> dict:
    """Every figure of one ``scanlab bench`` run, as a dict (what ``--json`` writes)."""
    from compare.bench import startup_seconds, time_frames
    from compare.bench_scenes import BENCH_SCENES, MeshUnavailable, bench_scene

    names = args.scenes or list(BENCH_SCENES)
    sizes = _sizes(args)
    for name in names:  # a misspelt scene fails now, in one line, not after minutes of measuring
        if name not in BENCH_SCENES:
            bench_scene(name, (64, 64))
    run = {"started": time.strftime("%Y-%m-%d %H:%M:%S"), "machine": platform.machine(), "cpus": os.cpu_count(),
           "load_before": _load_text(), "repeat": args.repeat, "rows": []}
    cases = [(n, s) for n in names for s in sizes]
    largest = None
    for i, (name, size) in enumerate(cases, 1):
        row = {"scene": name, "size": f"{size[0]}x{size[1]}"}
        try:
            scene = bench_scene(name, size).with_overrides(shading=args.shading, model=args.model)
        except MeshUnavailable as exc:
            row["error"] = f"unavailable: {exc}"
            run["rows"].append(row)
            say(f"[{i}/{len(cases)}] {name} {row['size']}: {row['error']}")
            continue
        row["triangles"] = int(sum(o.mesh.n_triangles for o in scene.objects))
        row.update(time_frames(scene, repeat=args.repeat))
        if args.memory == "all":
            _measure_memory(row, name, size, say)
        elif args.memory == "largest" and (largest is None or (row["triangles"], size) > largest[0]):
            largest = ((row["triangles"], size), row, name, size)
        run["rows"].append(row)
        fewer = f" ({row['fewer_threads']} of {args.repeat} of our frames on fewer threads: a core was busy)" \
            if row.get("fewer_threads") else ""
        say(f"[{i}/{len(cases)}] {name} {row['size']}: ours {row['ours']['median']:.1f} ms, "
            f"VTK {row['reference']['median']:.1f} ms, ours/VTK {row['ratio']:.2f}{fewer}")
    if largest is not None:
        _, row, name, size = largest
        say(f"peak memory of {name} {row['size']} (two child processes) ...")
        _measure_memory(row, name, size, say)
    if args.contention:
        from compare.bench import busy_core, thread_contention

        run["contention"] = []
        drawn = [(n, s) for n, s in cases if any(r["scene"] == n and "error" not in r for r in run["rows"])]
        with busy_core():
            for name, size in drawn:
                r = thread_contention(bench_scene(name, size).with_overrides(shading=args.shading, model=args.model),
                                      repeat=args.repeat)
                run["contention"].append({"scene": name, "size": f"{size[0]}x{size[1]}", **r})
                say(f"other core busy, {name} {size[0]}x{size[1]}: 1 thread {r['one_thread']['median']:.1f} ms, "
                    f"2 threads {r['two_threads']['median']:.1f} ms, 2/1 {r['ratio']:.2f} "
                    f"(the frames set to 2 used 1 in {r['two_used_one']} of {args.repeat})")
    if not args.no_startup:
        say("start-up of a fresh `scanlab render icosphere:level=5`, kernel cache cold then warm ...")
        run["startup_s"] = startup_seconds()
    run["load_after"] = _load_text()
    return run


def _measure_memory(row: dict, name: str, size, say) -> None:
    """Peak memory of each side into ``row["memory"]``; a child that failed is said in one line."""
    from compare.bench import peak_memory

    try:
        row["memory"] = {side: peak_memory(side, name, size) for side in ("ours", "reference")}
    except (RuntimeError, subprocess.TimeoutExpired) as exc:
        say(f"peak memory of {name} {row['size']} not measured: {exc}")


def report(run: dict) -> str:
    """The run as the text ``scanlab bench`` prints (and ``--markdown`` writes)."""
    from compare.bench import markdown_table

    lines = [markdown_table(run["rows"]), "",
             f"{run['started']}, {run['cpus']} CPUs, load average {run['load_before']} before, "
             f"{run['load_after']} after; median of {run['repeat']} alternating pairs."]
    slowed = [r for r in run["rows"] if r.get("fewer_threads")]
    lines.append("Our frames that used fewer threads than asked, because other processes kept a core busy "
                 "(renderer/free_cores.py): " + (", ".join(f"{r['scene']} {r['size']} {r['fewer_threads']} of "
                                                           f"{run['repeat']}" for r in slowed) if slowed else "none")
                 + ".")
    if "startup_s" in run:
        s = run["startup_s"]
        lines.append(f"Start-up (`scanlab render icosphere:level=5`, fresh process): kernel cache cold "
                     f"{s['cold']:.1f} s, warm {s['warm']:.1f} s.")
    if run.get("contention"):
        c = run["contention"]
        fewer = sum(r.get("two_used_one", 0) for r in c)
        lines.append("With another process spinning on one core, our frame time with 2 threads / 1 thread "
                     f"(numba's {c[0]['layer']} layer; median of alternating pairs): " + ", ".join(
                         f"{r['scene']} {r['size']} {r['ratio']:.2f}" for r in c) + ". "
                     f"The renderer fits its threads to the cores other processes leave free: {fewer} of the "
                     f"{len(c) * run['repeat']} frames set to 2 threads used 1.")
    memory = [r for r in run["rows"] if "memory" in r]
    for r in memory:
        m = r["memory"]
        lines.append(f"Peak memory of drawing {r['scene']} at {r['size']}: ours {m['ours']:.0f} MiB, "
                     f"VTK {m['reference']:.0f} MiB (ours/VTK {m['ours'] / m['reference']:.2f}).")
    return "\n".join(lines)


def write_between_markers(path: Path, text: str) -> None:
    """Replace what lies between :data:`START` and :data:`END` in ``path`` (both added at the
    end when missing; the file is made when missing)."""
    old = path.read_text() if path.exists() else ""
    if START in old and END in old:
        head, rest = old.split(START, 1)
        tail = rest.split(END, 1)[1]
    else:
        head, tail = old + ("\n" if old and not old.endswith("\n") else ""), "\n"
    lab.atomic.write_text(path, f"{head}{START}\n{text}\n{END}{tail}")


def run_bench(args) -> int:
    """The command: measure, print, write what was asked for."""
    from compare.bench_scenes import BENCH_SCENES

    if args.list:
        for name in BENCH_SCENES:
            print(name)
        return 0
    for target in (args.json, args.markdown):  # out/ does not exist in a fresh clone: make it before measuring
        if target:
            Path(target).parent.mkdir(parents=True, exist_ok=True)
    run = measure(args)
    text = report(run)
    print(text)
    if args.json:
        lab.atomic.write_text(args.json, json.dumps(run, indent=1) + "\n")
        print(f"wrote {args.json}")
    if args.markdown:
        write_between_markers(Path(args.markdown), text)
        print(f"wrote {args.markdown}")
    return 0
