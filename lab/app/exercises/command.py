"""``scanlab exercise list|start|check|grade``: the command line of the exercises.

Exit statuses (fixed: scripts depend on them): ``check`` 0 right, 1 wrong (with the
diagnosis), 2 the file cannot be judged — or a usage error; ``list``, ``start`` and
``grade`` 0 when done, 2 on a usage error. Errors are one line on stderr, no traceback.
"""
from __future__ import annotations

import argparse
import difflib
import os
import sys
import time
from pathlib import Path

from lab.app.exercises.sandbox import Limits
from lab.app.option_types import seconds, whole


class ExerciseUsageError(Exception):
    """A bad name, file or folder on the command line; the message says which."""


def _exercise(name: str):
    from lab.app.exercises.exercise_registry import exercises

    found = exercises()
    if name not in found:
        near = difflib.get_close_matches(name, list(found), n=1)
        hint = f"did you mean {near[0]}?" if near else f"one of: {', '.join(found)}"
        raise ExerciseUsageError(f"no exercise called {name!r} ({hint}; see `scanlab exercise list`)")
    return found[name]


def _limits(args) -> Limits:
    return Limits(cpu_seconds=args.time_limit, memory_mb=args.memory_limit)


def cmd_list(args) -> int:
    from lab.app.exercises.exercise_registry import LESSONS, exercises

    found = exercises()
    width = max(map(len, found))
    for name, ex in found.items():
        print(f"{name:<{width}}  {ex.lesson:<18}  {ex.title[args.lang]}  ({LESSONS[ex.lesson][args.lang]})")
    return 0


def cmd_start(args) -> int:
    from lab.atomic import write_text

    ex = _exercise(args.name)
    folder = Path(args.dir)
    if folder.exists() and not folder.is_dir():
        raise ExerciseUsageError(f"{args.dir}: is a file, not a folder")
    path = folder / ex.starter_file
    if path.exists():
        raise ExerciseUsageError(f"{path}: already exists; remove it or give another folder")
    folder.mkdir(parents=True, exist_ok=True)
    write_text(path, ex.starter)
    print(f"wrote {path}")
    print(f"write `{ex.signature}` there, then run: scanlab exercise check {ex.name} {path}")
    return 0


def _readable(file: str) -> Path:
    path = Path(file)
    if not path.is_file():
        raise ExerciseUsageError(f"{file}: {'is a folder' if path.is_dir() else 'no such file'}")
    return path


def cmd_check(args) -> int:
    from lab.app.exercises.checker import check_file

    ex = _exercise(args.name)
    path = _readable(args.file)
    report = check_file(ex, path, _limits(args))
    print("\n".join(report.lines(args.lang)))
    if args.out and report.panels:
        for written in report.write_panels(Path(args.out), path.stem):
            print(f"wrote {written}")
    return report.status


def _progress(done: int, total: int, row: dict) -> None:
    bar = "#" * int(30 * done / total)
    print(f"[{bar:<30}] {done}/{total} {row['file']:<28} {row['verdict']:<13} {' '.join(row['codes'])}", flush=True)


def cmd_grade(args) -> int:
    from lab.app.exercises.grader import grade_folder, grades_csv
    from lab.app.exercises.page import grades_page
    from lab.atomic import write_text

    ex = _exercise(args.name)
    folder = Path(args.submissions)
    if not folder.is_dir():
        raise ExerciseUsageError(f"{args.submissions}: not a folder")
    files = sorted(folder.glob("*.py"))
    if not files:
        raise ExerciseUsageError(f"{args.submissions}: no *.py files to grade")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise ExerciseUsageError(f"--out {args.out}: is a file, not a folder")
    if args.workers < 1:
        raise ExerciseUsageError(f"--workers {args.workers}: must be at least 1")
    out.mkdir(parents=True, exist_ok=True)
    limits = _limits(args)
    print(f"grading {len(files)} submissions of {ex.name} with {args.workers} workers "
          f"(limits: {limits.cpu_seconds:g} s CPU, {limits.memory_mb} MiB each)")
    started = time.perf_counter()
    rows = grade_folder(ex.name, files, out, args.workers, limits, progress=_progress)
    seconds = time.perf_counter() - started
    for path, text in ((out / "grades.csv", grades_csv(rows)),
                       (out / "index.html", grades_page(ex, rows, args.lang, seconds, args.workers, limits))):
        write_text(path, text)
    counts = {v: sum(r["verdict"] == v for r in rows) for v in ("right", "wrong", "cannot-judge")}
    print(f"{len(rows)} graded in {seconds:.1f} s: {counts['right']} right, {counts['wrong']} wrong, "
          f"{counts['cannot-judge']} cannot be judged")
    print(f"wrote {out / 'grades.csv'}")
    print(f"wrote {(out / 'index.html').resolve()}")
    return 0


def _guarded(command):
    def run(args) -> int:
        try:
            return command(args)
        except ExerciseUsageError as exc:
            print(f"scanlab exercise: {exc}", file=sys.stderr)
            return 2
    return run


def _common(p: argparse.ArgumentParser, lang_help: str) -> None:
    p.add_argument("--lang", choices=("en", "ja"), default="en", help=lang_help)


def _limit_options(p: argparse.ArgumentParser) -> None:
    p.add_argument("--time-limit", type=seconds, default=Limits.cpu_seconds, metavar="SECONDS",
                   help=f"CPU seconds a submission may use (default {Limits.cpu_seconds:g}; wall clock: twice that + 5)")
    p.add_argument("--memory-limit", type=whole(64, 1 << 20, "a size in MiB"), default=Limits.memory_mb, metavar="MIB",
                   help=f"memory a submission may use, MiB (default {Limits.memory_mb})")


def add_parser(sub) -> None:
    """Register ``scanlab exercise`` and its four actions on the main parser's subparsers."""
    p = sub.add_parser("exercise", help="exercises that check themselves: list, start, check, grade",
                       description="The course's exercises, judged against the project's own shapes and stages "
                                   "and VTK. A student's code runs in a separate, limited process.")
    actions = p.add_subparsers(dest="action", required=True, metavar="ACTION")

    q = actions.add_parser("list", help="the exercises, one line each, with their lessons")
    _common(q, "language of the titles (default en)")
    q.set_defaults(func=_guarded(cmd_list))

    q = actions.add_parser("start", help="write the starter file NAME.py",
                           description="Writes DIR/NAME.py: the function's signature, a docstring with every "
                                       "convention, and `raise NotImplementedError`. Never overwrites a file.")
    q.add_argument("name", help="the exercise (see `scanlab exercise list`)")
    q.add_argument("dir", nargs="?", default=".", help="folder for the starter (default: here)")
    q.set_defaults(func=_guarded(cmd_start))

    q = actions.add_parser("check", help="judge one solution: exit 0 right, 1 wrong, 2 cannot be judged",
                           description="Runs FILE's function in a separate, limited process, judges what it returns "
                                       "and prints the verdict with each diagnosis. Exit status 0: right; 1: wrong; "
                                       "2: the file cannot be judged (syntax error, missing function, exception, "
                                       "time or memory limit, wrong return types).")
    q.add_argument("name", help="the exercise")
    q.add_argument("file", help="the solution, e.g. menger.py")
    _common(q, "language of the diagnosis (default en)")
    q.add_argument("--out", metavar="DIR", help="write the panels (yours | reference | ΔE, and VTK's picture of "
                                                "your geometry) as PNGs into DIR")
    _limit_options(q)
    q.set_defaults(func=_guarded(cmd_check))

    q = actions.add_parser("grade", help="judge every *.py of a folder into grades.csv and index.html",
                           description="Judges every *.py in SUBMISSIONS in parallel and writes DIR/grades.csv "
                                       "(file, verdict, diagnosis codes, seconds), DIR/index.html (one row per "
                                       "submission with its panel and feedback) and DIR/panels/.")
    q.add_argument("name", help="the exercise")
    q.add_argument("submissions", help="folder of the students' .py files")
    q.add_argument("--out", required=True, metavar="DIR", help="folder for grades.csv, index.html and panels/")
    q.add_argument("--workers", type=whole(1), default=os.cpu_count() or 1,
                   help=f"submissions judged at once (default: the number of cores, {os.cpu_count()})")
    _common(q, "language of the page (default en)")
    _limit_options(q)
    q.set_defaults(func=_guarded(cmd_grade))
