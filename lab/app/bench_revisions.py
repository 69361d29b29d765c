"""``scanlab bench-revisions REV``: our frames at this tree against our frames at another git
revision, timed across processes.

Two versions of the renderer's kernels loaded into one process are not timed alike: the one
that draws first is quicker, by 5–20 % on the 2-core machine (docs/performance.md, "Two copies
of a kernel in one process are not timed alike"). Here each child process loads one tree
only: it draws the scene a few times to warm up, then times ``frames`` frames and prints
their median. The two trees' processes take turns in rounds (this tree first, then the other
first, and so on), and each scene gets the median of the rounds' ratios this tree / REV
(< 1: this tree is quicker), their range, and whether the two images are the same bytes.

The other revision is exported once (``git archive``) into the cache folder,
``~/.cache/scanlab/revisions/<commit>/`` (``$XDG_CACHE_HOME`` respected), where its kernels
are cached beside its sources as a clone's are; its first run compiles them.
"""
from __future__ import annotations

import io
import json
import os
import statistics
import subprocess
import sys
import tarfile
from pathlib import Path

import lab.atomic
from compare.bench_scenes import BENCH_SCENES, bench_scene
from renderer.jit import user_cache_home

TREE = Path(__file__).resolve().parents[2]
"""The root of the tree this module belongs to (holds ``renderer/``, ``compare/``, ``lab/``)."""

CHILD = r"""
import hashlib, json, sys, time
import numba
from compare.bench_scenes import bench_scene
from renderer import render
name, width, height, frames, threads = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]), sys.argv[5]
if threads != "default":
    numba.set_num_threads(int(threads))
scene = bench_scene(name, (width, height))
for _ in range(3):
    image = render(scene).rgb
times = []
for _ in range(frames):
    start = time.perf_counter()
    render(scene)
    times.append(time.perf_counter() - start)
print(json.dumps({"median_s": sorted(times)[len(times) // 2], "image": hashlib.sha256(image.tobytes()).hexdigest()}))
"""
"""What a child process runs, with a tree's root first on its path: only names every revision
since issue 15's benchmark has (``compare.bench_scenes.bench_scene``, ``renderer.render``)."""


class RevisionError(RuntimeError):
    """A revision that cannot be exported or timed, said in one line."""


def cache_folder() -> Path:
    """Where exported revisions live: ``$XDG_CACHE_HOME/scanlab/revisions`` (``~/.cache`` when
    unset), beside the kernels' folder (:func:`renderer.jit.user_cache_home`)."""
    return user_cache_home() / "revisions"


def commit_of(rev: str, repo: Path = TREE) -> str:
    """The full commit hash ``rev`` names in the git repository at ``repo``."""
    found = subprocess.run(["git", "-C", str(repo), "rev-parse", "--verify", "--quiet", f"{rev}^{{commit}}"],
                           capture_output=True, text=True)
    if found.returncode != 0:
        raise RevisionError(f"{rev!r} names no commit of the git repository at {repo}")
    return found.stdout.strip()


def export_revision(commit: str, repo: Path = TREE, folder: Path | None = None) -> Path:
    """The sources of ``commit`` as a folder (``folder``/``commit``/``tree``), exported with
    ``git archive`` the first time and kept: its kernel cache grows beside them."""
    tree = (folder or cache_folder()) / commit / "tree"
    if tree.is_dir():
        return tree
    archive = subprocess.run(["git", "-C", str(repo), "archive", "--format=tar", commit], capture_output=True)
    if archive.returncode != 0:
        raise RevisionError(f"git archive {commit} failed: {archive.stderr.decode(errors='replace').strip()}")
    partial = tree.with_name(f".tree-{os.getpid()}")
    partial.mkdir(parents=True, exist_ok=True)
    with tarfile.open(fileobj=io.BytesIO(archive.stdout)) as tar:
        tar.extractall(partial, filter="data")
    partial.rename(tree)
    return tree


def child_environment(tree: Path) -> dict:
    """The environment of a child timing ``tree``: its root first on the path, and no shared
    kernel cache folder (each tree keeps its kernels beside its sources)."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(tree)] + [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p])
    env.pop("SCANLAB_KERNEL_CACHE", None)
    return env


def time_in_child(tree: Path, scene: str, size: tuple[int, int], frames: int, threads: str) -> dict:
    """One child process's median frame time (``median_s``) and image hash (``image``) for ``tree``."""
    run = subprocess.run([sys.executable, "-c", CHILD, scene, str(size[0]), str(size[1]), str(frames), threads],
                         capture_output=True, text=True, env=child_environment(tree), cwd=tree)
    if run.returncode != 0:
        last = (run.stderr.strip().splitlines() or ["no output"])[-1]
        raise RevisionError(f"timing {scene} at {tree} failed: {last}")
    return json.loads(run.stdout.strip().splitlines()[-1])


def paired_summary(ours: list[float], theirs: list[float]) -> dict:
    """Rounds' times of this tree and of the other revision, paired by round: the median of
    the per-round ratios ours/theirs, their least and greatest, and each side's median time."""
    if len(ours) != len(theirs) or not ours:
        raise ValueError("the two sides need the same number of rounds, at least one")
    ratios = sorted(a / b for a, b in zip(ours, theirs))
    return {"ratio": statistics.median(ratios), "ratio_min": ratios[0], "ratio_max": ratios[-1],
            "ours_ms": 1000 * statistics.median(ours), "theirs_ms": 1000 * statistics.median(theirs)}


def compare_scene(trees: dict, scene: str, size: tuple[int, int], rounds: int, frames: int, threads: str,
                  say=print) -> dict:
    """``rounds`` rounds of one child per tree (``trees``: ``{"ours": path, "theirs": path}``),
    this tree first in even rounds and last in odd ones; :func:`paired_summary` of them."""
    times, images = {"ours": [], "theirs": []}, {"ours": set(), "theirs": set()}
    for r in range(rounds):
        for side in (("ours", "theirs") if r % 2 == 0 else ("theirs", "ours")):
            got = time_in_child(trees[side], scene, size, frames, threads)
            times[side].append(got["median_s"])
            images[side].add(got["image"])
        say(f"  round {r + 1}/{rounds}: ours {1000 * times['ours'][-1]:.1f} ms, "
            f"theirs {1000 * times['theirs'][-1]:.1f} ms")
    same = len(images["ours"] | images["theirs"]) == 1
    return {"scene": scene, "size": f"{size[0]}x{size[1]}", "same_image": same,
            **paired_summary(times["ours"], times["theirs"])}


def report_line(row: dict) -> str:
    """One scene's result as a line of text."""
    return (f"{row['scene']} {row['size']}: ours {row['ours_ms']:.1f} ms, theirs {row['theirs_ms']:.1f} ms, "
            f"ours/theirs {row['ratio']:.3f} (rounds {row['ratio_min']:.3f}–{row['ratio_max']:.3f}), "
            f"{'the same image' if row['same_image'] else 'images differ'}")


def run_bench_revisions(args) -> int:
    """The command: export the revision, time every scene and size, print and write the results."""
    for scene in args.scenes:  # a misspelt scene fails now, in one line (SceneError), not in a child
        if scene not in BENCH_SCENES:
            bench_scene(scene, (16, 16))
    if args.json:  # out/ does not exist in a fresh clone
        Path(args.json).parent.mkdir(parents=True, exist_ok=True)
    try:
        commit = commit_of(args.rev)
        print(f"this tree: {TREE}\nagainst:   {args.rev} = {commit}")
        trees = {"ours": TREE, "theirs": export_revision(commit)}
        print(f"exported to {trees['theirs']} (its kernels compile on its first run)")
        rows = []
        cases = [(scene, size) for scene in args.scenes for size in (args.size or [(512, 512)])]
        for i, (scene, size) in enumerate(cases, 1):
            print(f"[{i}/{len(cases)}] {scene} {size[0]}x{size[1]}: {args.rounds} rounds of a process a side, "
                  f"{args.frames} frames each", flush=True)
            rows.append(compare_scene(trees, scene, size, args.rounds, args.frames, str(args.threads or "default"),
                                      say=lambda text: print(text, flush=True)))
    except RevisionError as exc:
        print(f"scanlab bench-revisions: {exc}", file=sys.stderr)
        return 2
    print(f"\nours = {TREE}, theirs = {commit[:12]}; median of {args.rounds} rounds' ratios (< 1: ours is quicker)")
    for row in rows:
        print(report_line(row))
    if args.json:
        path = Path(args.json)
        lab.atomic.write_text(path, json.dumps({"ours": str(TREE), "theirs": commit, "rounds": args.rounds,
                                                "frames": args.frames, "rows": rows}, indent=2))
        print(f"wrote {path}")
    return 0

