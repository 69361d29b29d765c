"""``scanlab sweep``: its options, their checks and the help that lists the grid keys.

:func:`add_parser` is called by :func:`lab.app.cli.build_parser` with the CLI's UsageError,
so a bad option ends in one line and exit status 2 like every other command.
"""
from __future__ import annotations

import argparse
import os
import re
import shlex
import sys
from pathlib import Path

from lab.app.option_types import seconds, whole
from lab.app.sweep.light_sets import LIGHT_SETS
from lab.app.sweep.settings import GRID_KEYS

DESCRIPTION = """\
Compare many cases at once — every source crossed with every combination of the grid's
values — each case as `scanlab compare` does it, in worker processes of a Dask cluster: a
local one with --workers processes, or yours with --scheduler tcp://HOST:8786.

SOURCES are scene files (.toml), mesh files (.ply .obj .stl .vtk .vtp; framed and lit like
a built-in shape), presets, built-in shapes (icosphere:level=3) and folders of scene and
mesh files (searched recursively).

Writes into DIR: results.parquet (one row per case: source, settings, every metrics.json
figure, verdict, status, error, timings, worker), index.html (the worst cases' panels,
histograms per setting, a sortable table of all cases), cases/<id>/ (frames and panels of
the --worst cases) and histograms/.

Run it again with the same --out to go on after a kill or Ctrl-C: finished cases are
skipped. A case that hangs past --timeout, crashes or runs out of memory is recorded and the
sweep goes on. Exit status: 0 all pass, 1 any FAIL or unfinished case, 2 bad input.
"""


def _epilog() -> str:
    keys = "\n".join(f"  {name:<15} {key.values}" for name, key in GRID_KEYS.items())
    lights = "\n".join(f"  {name:<15} {light_set.description}" for name, light_set in LIGHT_SETS.items())
    return (f"grid keys (--grid KEY=V1,V2,...; a grid file has KEY = [V1, V2] lines and may list sources = [...]):\n"
            f"{keys}\n\nlight sets (--grid lights=...):\n{lights}\n\n"
            "example:\n  scanlab sweep cube icosphere:level=3 meshes/ --grid shading=flat,gouraud,phong "
            "--grid lights=headlight,spot --grid size=256x192 --out out/sweep")


def _bytes(text: str) -> int:
    """``8G``, ``512M``, ``2048K``, a number of bytes, or ``none``/``0`` (no limit)."""
    if text.lower() in ("none", "0"):
        return 0
    match = re.fullmatch(r"(\d+(?:\.\d+)?)\s*([kmgt]?)i?b?", text.strip().lower())
    if not match:
        raise argparse.ArgumentTypeError(f"expected a size such as 8G or 512M (or none), got {text!r}")
    value = float(match.group(1)) * 1024 ** " kmgt".index(match.group(2) or " ")
    if value < 256 << 20:
        raise argparse.ArgumentTypeError(f"{text!r} is too little for VTK and the renderer (at least 256M)")
    return int(value)


def add_parser(sub, usage_error: type[Exception]) -> argparse.ArgumentParser:
    """Add ``sweep`` to the CLI's subcommands; ``usage_error`` is raised for bad input."""
    p = sub.add_parser("sweep", help="compare many sources × settings on a Dask cluster; a table and a page",
                       description=DESCRIPTION, epilog=_epilog(), formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("sources", nargs="*", metavar="SOURCE", help="scene files, mesh files, folders, presets, shapes")
    p.add_argument("--grid", action="append", default=[], metavar="KEY=V1,V2",
                   help="cross these values of a grid key over every source (repeat for more keys; see below)")
    p.add_argument("--grid-file", metavar="FILE", help="a TOML grid file; --grid replaces its values for a key")
    p.add_argument("--out", required=True, metavar="DIR", help="output folder; the same DIR resumes a sweep")
    p.add_argument("--scheduler", metavar="ADDRESS",
                   help="a running Dask scheduler, e.g. tcp://host:8786 (default: start a local cluster)")
    p.add_argument("--workers", type=whole(1), metavar="N",
                   help=f"worker processes of the local cluster (default: the number of cores, {os.cpu_count()})")
    p.add_argument("--timeout", type=seconds, default=120.0, metavar="S",
                   help="time limit of one case in seconds (default 120); its process is then killed")
    p.add_argument("--memory-limit", type=_bytes, default=8 << 30, metavar="SIZE",
                   help="address-space limit of a case's process, e.g. 8G (default) or none")
    p.add_argument("--worst", type=whole(0), default=12, metavar="N",
                   help="keep frames and draw panels for the N worst cases (default 12)")
    p.add_argument("--keep-all", action="store_true", help="keep frames and draw panels for every case")
    p.add_argument("--retry-errors", action="store_true",
                   help="run again the cases that timed out, crashed or failed to run in DIR")
    p.set_defaults(func=lambda args: cmd_sweep(args, usage_error))
    return p


def cmd_sweep(args, usage_error: type[Exception]) -> int:
    from lab.app.sweep.cases import GridError
    from lab.app.sweep.cluster import ClusterError
    from lab.app.sweep.sweep import SweepError, SweepOptions, run_sweep

    if args.scheduler and args.workers:
        raise usage_error("sweep: --workers sets the size of a local cluster; with --scheduler the cluster's own "
                          "workers run the cases")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise usage_error(f"--out {args.out}: is a file, not a folder")
    options = SweepOptions(out=out, sources=args.sources, grid=args.grid, grid_file=args.grid_file,
                           scheduler=args.scheduler, workers=args.workers or os.cpu_count() or 1,
                           timeout=args.timeout, memory_limit=args.memory_limit, worst=args.worst,
                           keep_all=args.keep_all, retry_errors=args.retry_errors,
                           command=shlex.join(["scanlab", *sys.argv[1:]]) if sys.argv[1:2] == ["sweep"] else "")
    try:
        return run_sweep(options)
    except (GridError, SweepError, ClusterError) as exc:
        raise usage_error(str(exc)) from None
