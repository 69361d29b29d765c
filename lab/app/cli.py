"""The ``scanlab`` command (also ``python -m lab``).

Every expected failure — a bad scene file, a bad option, no OpenGL for VTK — ends in one
line on stderr and exit status 2. ``compare`` and ``demo`` judge against the parity bars
(:mod:`compare.verdict`): exit status 0 on a pass (or a scene meant to fail that fails),
1 on a FAIL.
"""
from __future__ import annotations

import argparse
import os
import re
import sys
from pathlib import Path

from lab.app.lesson_site import build as lessons_site
from lab.app.demo import scene_name
from lab.app.exercises.command import add_parser as add_exercise_parser
from lab.app.live import live_command
from lab.app.option_types import image_size, number, whole
from lab.app.process_exit import exit_now
from lab.app.sweep import sweep_command
from lab.collector import collections_paused, fewer_collections
from lab.loading import LARGE_SIZE, MAX_SIZE, SceneError, load_scene, size_problem
from lab.presets import SCENES_DIR, preset_description, preset_names
from lab.scene import MODELS, SHADINGS
from lab.shapes import SHAPES, shape_summary
from lab.suggest import closest, did_you_mean


class UsageError(Exception):
    """A problem with the command line; the message says which option and why."""


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors: ``scanlab render: unrecognized arguments: --sise (did
    you mean --size?); see scanlab render --help``, exit status 2."""

    commands: dict = {}
    """Subcommand name → its parser (set by build_parser), to name it in errors."""

    def parse_args(self, args=None, namespace=None):
        args, extras = self.parse_known_args(args, namespace)
        if extras:  # blame the subcommand, whose options the user meant
            self.commands.get(getattr(args, "command", None), self).error(
                f"unrecognized arguments: {' '.join(extras)}")
        return args

    def error(self, message: str):
        message = " ".join(message.split())
        if message.startswith("unrecognized arguments:"):
            message += _option_hint(self, message.split(":", 1)[1].split())
        choice = re.search(r"invalid choice: '(.*?)' \(choose from (.*)\)$", message)
        if choice:
            message += did_you_mean(choice.group(1), re.findall(r"'([^']*)'", choice.group(2)))
        self.exit(2, f"{self.prog}: {message}; see {self.prog} --help\n")


def _option_hint(parser: argparse.ArgumentParser, unknown: list[str]) -> str:
    """" (did you mean --size?)" for the first unknown option, from every (sub)command's options."""
    options = set()
    for action in parser._actions:  # noqa: SLF001 -- argparse keeps no public list
        options.update(action.option_strings)
        for sub in getattr(action, "choices", None) or {}:
            if isinstance(action.choices, dict):
                options.update(o for a in action.choices[sub]._actions for o in a.option_strings)
    for word in unknown:
        near = closest(word.split("=")[0], sorted(options)) if word.startswith("-") else None
        if near:
            return f" (did you mean {near}?)"
    return ""


def _bar(text: str) -> tuple[str, float]:
    """``NAME=VALUE``, a bar of :mod:`compare.verdict` (checked there)."""
    from compare.verdict import parse_bar

    try:
        return parse_bar(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


SCENE_HELP = ("a scene file (.toml), a preset name (see `scanlab scenes`), a mesh file (.ply .obj .stl .vtk .vtp) "
              f"or a built-in shape such as icosphere:level=3 (shapes: {', '.join(SHAPES)})")


def _allow_large_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--allow-large", action="store_true",
                   help=f"accept images beyond {MAX_SIZE}x{MAX_SIZE} pixels (up to {LARGE_SIZE}x{LARGE_SIZE})")


def _scene_args(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", help=SCENE_HELP)
    p.add_argument("--shading", choices=SHADINGS, help="override every object's shading")
    p.add_argument("--size", type=image_size, metavar="WxH",
                   help=f"override the image size, e.g. 640x480 (at most {MAX_SIZE}x{MAX_SIZE} without --allow-large)")
    p.add_argument("--model", choices=MODELS, help="override every object's reflection model: vtk (VTK's own), "
                                                   "opengl (fixed-function OpenGL) or classic (the course's)")
    _allow_large_arg(p)


def _load(args):
    """The scene of ``args.scene`` with the command line's overrides, all checked."""
    if args.size is not None:
        problem = size_problem(args.size, args.allow_large)
        if problem:
            raise UsageError(f"--size: {problem}")
    scene = load_scene(args.scene, allow_large=args.allow_large)
    return scene.with_overrides(shading=args.shading, size=args.size, model=args.model)


def _same_file(a: Path, b: Path) -> bool:
    """Whether two paths name one file (through links and relative parts); False if either is missing."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def _output(path, scene) -> Path:
    """Check an output path before anything is written, and create its folder.

    Refused (UsageError): an output that is one of the scene's input files (scene file,
    mesh, texture), or a folder in the way. Missing parent folders are created.
    """
    out = Path(path)
    for source in scene.inputs:
        if _same_file(out, Path(source)):
            raise UsageError(f"{path}: the output would overwrite the input {source}")
    if out.is_dir():
        raise UsageError(f"{path}: is a folder; give a file name")
    try:
        out.parent.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UsageError(f"{path}: cannot create the folder {out.parent}: {exc.strerror or exc}") from None
    return out


def _draw_to_png(args, draw) -> int:
    from lab.png import write_png

    scene = _load(args)
    out = _output(args.output, scene)
    write_png(out, draw(scene).rgb)
    print(f"wrote {out}")
    return 0


def cmd_render(args) -> int:
    with collections_paused():  # importing numba makes some 10^5 objects and no garbage (lab.collector)
        from renderer import render
        from renderer.compile_ahead import helped_cold_start

    with fewer_collections(), helped_cold_start():  # an empty kernel cache: a helper compiles a share of the kernels
        return _draw_to_png(args, render)


def cmd_reference(args) -> int:
    from compare.reference import render_reference

    return _draw_to_png(args, render_reference)


def _out_folder(args, scene, files) -> Path:
    """``--out DIR`` checked: not a file, and none of ``files`` in it would overwrite an input."""
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise UsageError(f"--out {args.out}: is a file, not a folder")
    for name in files:
        _output(out / name, scene)
    return out


def _bars(args) -> dict | None:
    """The bars of ``--bar`` and ``--fail-above`` over the parity bars, or None for the parity bars alone."""
    from compare.verdict import PARITY_BARS

    extra = dict(args.bar or [])
    if args.fail_above is not None:
        extra["p999"] = args.fail_above
    return {**PARITY_BARS, **extra} if extra else None


def cmd_compare(args) -> int:
    from compare.comparison import run_comparison
    from compare.report import OUTPUT_FILES, summary_line
    from compare.stages import STAGE_FILES

    scene = _load(args)
    files = OUTPUT_FILES + (STAGE_FILES if args.stages else ())
    out = _out_folder(args, scene, files)
    result = run_comparison(scene, name=scene_name(args.scene), reference=args.reference, bars=_bars(args),
                            stages=args.stages)
    result.write(out)
    print(summary_line(result.metrics))
    print(f"wrote {out}/ ({', '.join(files)})")
    verdict = result.verdict
    print(verdict.line(), file=sys.stdout if verdict.ok else sys.stderr)
    return 0 if verdict.ok else 1


def cmd_stages(args) -> int:
    from compare.comparison import run_comparison
    from compare.report import write_json
    from compare.stages import STAGE_FILES, stages_figure

    scene = _load(args)
    out = _out_folder(args, scene, STAGE_FILES + ("metrics.json",))
    result = run_comparison(scene, name=scene_name(args.scene), stages=True, timings=False)
    out.mkdir(parents=True, exist_ok=True)
    stages_figure(result.ours_frame, result.stages, result.reference_frame, out / STAGE_FILES[0],
                  title=f"{result.name}: the stages before the colours", culling=scene.render.cull_backfaces)
    write_json(out / "metrics.json", result.metrics)
    d = result.metrics["depth"]
    print(f"{result.name}: depth (ours − VTK, 24-bit steps) max {d['max_steps']}, 99th percentile "
          f"{d['p99_steps']:g}, more than one step apart on {d['pixels_over_1_step']:,} of "
          f"{d['compared_pixels']:,} pixels ({100 * d['over_1_step']:.3f} %)")
    print(f"wrote {out}/ ({', '.join(STAGE_FILES + ('metrics.json',))})")
    return 0


def cmd_scenes(args) -> int:
    names = preset_names()
    width = max(len(n) for n in names)
    print("presets:")
    for name in names:
        print(f"  {name:<{width}}  {preset_description(name)}")
    print(f"\nbuilt-in shapes, as NAME or NAME:key=value,... (parameter=default, whole-number range):")
    for name in SHAPES:
        print(f"  {shape_summary(name)}")
    print(f"\n{len(names)} presets in {SCENES_DIR}; {len(SHAPES)} shapes in lab/shapes.py. "
          "A scene file (.toml) or a mesh file also works as SCENE.")
    return 0


def cmd_bench(args) -> int:
    from lab.app.bench_command import run_bench

    return run_bench(args)


def cmd_bench_revisions(args) -> int:
    from lab.app.bench_revisions import run_bench_revisions

    return run_bench_revisions(args)


def cmd_demo(args) -> int:
    from lab.app.demo import run_demo

    specs = args.scenes or preset_names()
    for spec in specs:  # every scene is checked before the first comparison starts
        load_scene(spec)
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise UsageError(f"--out {args.out}: is a file, not a folder")
    with fewer_collections():  # a fresh clone's demo compiles every kernel (lab.collector)
        return run_demo(out, specs)


def cmd_export(args) -> int:
    from lab.meshfiles import MeshFileError
    from lab.meshfiles.write import writer_for

    if Path(args.output).suffix.lower() == ".toml":
        return _export_scene(args)
    try:
        write = writer_for(args.output)  # before anything is made
    except MeshFileError as exc:
        raise UsageError(f"{exc}; or .toml for the whole scene") from None
    scene = load_scene(args.scene, allow_large=args.allow_large)
    out = _output(args.output, scene)
    mesh = scene.world_mesh()
    write(mesh, out)
    normals = "with point normals" if mesh.point_normals is not None else "no point normals"
    print(f"wrote {out} ({mesh.n_points} points, {mesh.n_triangles} triangles, {normals})")
    return 0


def _export_scene(args) -> int:
    """``export SCENE -o NAME.toml``: the scene file, its meshes and textures in NAME-files/."""
    from lab.scene_writer import scene_files, write_scene

    scene = load_scene(args.scene, allow_large=args.allow_large)
    out = _output(args.output, scene)
    meshes, textures = scene_files(scene, out)
    for path in [*meshes, *textures]:
        if path is not None:
            _output(path, scene)
    write_scene(scene, out)
    print(f"wrote {out} ({len(scene.objects)} object(s); meshes and textures in {meshes[0].parent}/)")
    return 0


def cmd_info(args) -> int:
    from lab.measure import mesh_summary

    scene = load_scene(args.scene, allow_large=args.allow_large)
    rows = [(o.name, mesh_summary(o.world_mesh())) for o in scene.objects]
    if len(rows) > 1:
        rows.append(("scene", mesh_summary(scene.world_mesh())))
    print(f"{scene.source}: {len(scene.objects)} object(s)")
    for name, m in rows:
        b = m["bounds"]
        print(f"  {name}: {m['points']} points, {m['triangles']} triangles, "
              f"{'point normals' if m['normals'] else 'no point normals'}")
        print(f"    bounds x [{b[0]:.6g}, {b[1]:.6g}] y [{b[2]:.6g}, {b[3]:.6g}] z [{b[4]:.6g}, {b[5]:.6g}]")
        print(f"    area {m['area']:.10g}, volume {m['volume']:.10g}, "
              f"closed and consistently oriented: {'yes' if m['closed_and_oriented'] else 'no'}")
    return 0


def cmd_lessons_figures(args) -> int:
    from lessons.figures import build_figures

    out = Path(args.out)
    results = build_figures(out)
    for name in results:
        print(f"wrote {out / (name + '.png')}")
    return 0


def cmd_fuzz(args) -> int:
    from lab.app.fuzz import run_fuzz

    save = Path(args.save)

    def progress(i, summary):
        print(f"  {i} cases, {len(summary.failures)} failures", flush=True)

    summary = run_fuzz(args.cases, args.seed, save=save, progress=progress)
    print(summary.line())
    for f in summary.failures[:10]:
        print(f"  FAIL {save / f'fuzz-{f.seed}-{f.case}-{f.preset}.toml'}: {f.error.splitlines()[0][:200]}")
    if summary.failures:
        print(f"failing inputs and their tracebacks are in {save}/")
    return 1 if summary.failures else 0


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="scanlab",
        description="scanlab draws a scene with its own scanline renderer and with VTK, and measures, pixel by "
                    "pixel, how far apart the two images are (CIEDE2000).")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    parser.commands = sub.choices

    p = sub.add_parser("render", help="draw a scene with scanlab's renderer")
    _scene_args(p)
    p.add_argument("-o", "--output", default="scanlab.png", help="PNG to write (default: scanlab.png)")
    p.set_defaults(func=cmd_render)

    p = sub.add_parser("reference", help="draw a scene with VTK (offscreen)")
    _scene_args(p)
    p.add_argument("-o", "--output", default="vtk.png", help="PNG to write (default: vtk.png)")
    p.set_defaults(func=cmd_reference)

    p = sub.add_parser("compare", help="draw both, measure ΔE2000, judge, write images and metrics.json",
                       description="Writes DIR/ours.png, vtk.png, delta_e.png, side_by_side.png and metrics.json, "
                                   "prints a one-line summary and the verdict against the parity bars (coverage "
                                   "mismatch ≤ 0.02 %%, ΔE2000 > 1 on ≤ 0.2 %% of shared pixels, mean ΔE2000 ≤ 0.1). "
                                   "Exit status 0 on a pass, 1 on a FAIL, 2 on bad input.")
    _scene_args(p)
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the outputs (created if missing)")
    p.add_argument("--bar", type=_bar, action="append", metavar="NAME=VALUE",
                   help="judge against this bar too, or instead of a parity bar of that name (repeatable); names: "
                        "coverage_mismatch, pixels_over_1 (fractions 0..1), mean, p999, max (ΔE2000), "
                        "max_channel_diff, depth_over_1_step")
    p.add_argument("--fail-above", type=number(0.0), metavar="DE",
                   help="also fail when the 99.9th percentile ΔE2000 exceeds DE (the same as --bar p999=DE)")
    p.add_argument("--stages", action="store_true",
                   help="also write stages.png: both depth buffers and their difference, triangle IDs, the "
                        "clipped wireframe (see `scanlab stages`)")
    p.add_argument("--reference", choices=["vtk-native"],
                   help="force VTK's own shading for every object (by default textbook models are checked "
                        "against colours lit in numpy or a replaced VTK shader); shows how far textbook Gouraud "
                        "is from VTK's per-pixel 'Gouraud'")
    p.set_defaults(func=cmd_compare)

    p = sub.add_parser("stages", help="compare what the pipelines hold before the colours: depth, triangles",
                       description="Writes DIR/stages.png (our z-buffer beside VTK's, read back from the same "
                                   "render, their difference in 24-bit steps; the triangle-ID image; the clipped "
                                   "triangles as a wireframe, back faces marked) and DIR/metrics.json with 'depth'.")
    _scene_args(p)
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the outputs (created if missing)")
    p.set_defaults(func=cmd_stages)

    p = sub.add_parser("scenes", help="list the preset scenes and the built-in shapes with their parameters")
    p.set_defaults(func=cmd_scenes)

    p = sub.add_parser("bench", help="frame time, memory and start-up of scanlab against VTK, in one process",
                       description="Times both renderers on the same scenes, frames alternating after a warm-up, "
                                   "and prints median/min/max ms and the median ratio ours/VTK (< 1: scanlab "
                                   "is faster). With no SCENES: issue 15's benchmark set at 512x512 and 1024x1024.")
    p.add_argument("scenes", nargs="*", metavar="SCENE",
                   help="names of the benchmark set (see --list), presets, shapes or scene files")
    p.add_argument("--size", type=image_size, action="append", metavar="WxH", help="image size (repeatable)")
    p.add_argument("--shading", choices=SHADINGS, help="override every object's shading")
    p.add_argument("--model", choices=MODELS, help="override every object's reflection model")
    p.add_argument("--repeat", type=whole(1), default=15, help="timed pairs of frames per scene and size (default 15)")
    p.add_argument("--json", metavar="FILE", help="also write every figure to FILE as JSON")
    p.add_argument("--markdown", metavar="FILE", help="also write the table to FILE (between its bench markers)")
    p.add_argument("--memory", choices=["largest", "all", "none"], default="largest",
                   help="peak memory in child processes: for the largest scene only (default), all, or none")
    p.add_argument("--no-startup", action="store_true", help="skip the cold/warm start-up measurement")
    p.add_argument("--contention", action="store_true",
                   help="also time our frames with 1 and 2 threads while another process keeps one core busy")
    p.add_argument("--list", action="store_true", help="list the benchmark set and exit")
    p.set_defaults(func=cmd_bench)

    p = sub.add_parser("bench-revisions", help="our frame time at this tree against another git revision, "
                                               "across processes",
                       description="Times our renderer at this tree and at REV (exported once into "
                                   "~/.cache/scanlab/revisions), each child process loading one tree only, the two "
                                   "taking turns in rounds; prints the median of the rounds' ratios this tree / REV "
                                   "(< 1: this tree is quicker) and whether the images are the same bytes. Two "
                                   "versions of the kernels in one process are not timed alike (docs/performance.md).")
    p.add_argument("rev", metavar="REV", help="a git revision of this repository (a commit, branch or tag)")
    p.add_argument("scenes", nargs="+", metavar="SCENE", help="names of the benchmark set (scanlab bench --list), "
                                                             "presets or shapes")
    p.add_argument("--size", type=image_size, action="append", metavar="WxH",
                   help="image size (repeatable; default 512x512)")
    p.add_argument("--rounds", type=whole(1), default=10, help="rounds of one process a side (default 10)")
    p.add_argument("--frames", type=whole(1), default=15, help="timed frames in each process (default 15)")
    p.add_argument("--threads", type=whole(1), help="numba threads in each process (default: numba's)")
    p.add_argument("--json", metavar="FILE", help="also write every figure to FILE as JSON")
    p.set_defaults(func=cmd_bench_revisions)

    p = sub.add_parser("export", help="write the exact triangles both renderers draw (.ply .obj .stl .vtp), "
                                      "or the whole scene as a scene file (.toml)",
                       description="Writes the scene's (or shape's) triangles in world space, with point normals "
                                   "where the format holds them (PLY, OBJ, VTP; STL has none). With a .toml output, "
                                   "writes the whole scene as a scene file, its meshes and textures in NAME-files/ "
                                   "beside it: loading it gives the same scene.")
    p.add_argument("scene", help=SCENE_HELP)
    p.add_argument("-o", "--output", required=True, help="file to write; the suffix picks the format")
    _allow_large_arg(p)
    p.set_defaults(func=cmd_export)

    p = sub.add_parser("info", help="counts, bounds, area, volume and closedness of a scene or shape")
    p.add_argument("scene", help=SCENE_HELP)
    _allow_large_arg(p)
    p.set_defaults(func=cmd_info)

    p = sub.add_parser("lessons", help="lesson material: `scanlab lessons build` builds the lesson site")
    lsub = p.add_subparsers(dest="action", required=True, metavar="ACTION")
    q = lsub.add_parser("figures", help="render the measured figures the lessons show")
    q.add_argument("--out", default="lessons/figures", metavar="DIR", help="output folder (default lessons/figures)")
    q.set_defaults(func=cmd_lessons_figures)
    lessons_site.add_parsers(lsub, UsageError)

    p = sub.add_parser("fuzz", help="feed mutated preset scene files to the loader; report any traceback",
                       description="Seeded random mutations of lab/scenes/*.toml, each loaded: it must give a scene "
                                   "or one clear SceneError line. Exit 1 if any case does not.")
    p.add_argument("--cases", type=whole(1), default=10000, help="number of mutated files (default 10000)")
    p.add_argument("--seed", type=int, default=0, help="seed; case i of seed s is always the same file (default 0)")
    p.add_argument("--save", default="out/fuzz", metavar="DIR",
                   help="folder for failing inputs, each with a .txt of what happened (default out/fuzz)")
    p.set_defaults(func=cmd_fuzz)

    add_exercise_parser(sub)

    p = sub.add_parser("demo", help="compare every preset scene (or the scenes named) and build a page of panels",
                       description="Compares each SCENE with VTK into DIR/<name>/ and writes DIR/index.html (a "
                                   "summary table, then every panel with its scene file and the command that "
                                   "reproduces it) and DIR/summary.json. Exit status 0 when every verdict is the "
                                   "expected one.")
    p.add_argument("--out", default="out/demo", metavar="DIR", help="output folder (default out/demo)")
    p.add_argument("scenes", nargs="*", metavar="SCENE",
                   help="presets, scene files, mesh files or shapes to compare (default: every preset)")
    p.set_defaults(func=cmd_demo)

    sweep_command.add_parser(sub, UsageError)
    live_command.add_parser(sub, UsageError)
    return parser


def main(argv=None) -> int:
    from compare.vtk_backend import ReferenceUnavailable

    try:
        args = build_parser().parse_args(argv)
    except SystemExit as exc:  # argparse has printed its one line (or the help)
        return exc.code if isinstance(exc.code, int) else 2
    try:
        return args.func(args)
    except (SceneError, UsageError, ReferenceUnavailable) as exc:
        print(f"scanlab: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:  # writing an output: a full disk, no permission ...
        where = f"{exc.filename}: " if exc.filename else ""
        print(f"scanlab: {where}cannot write: {exc.strerror or exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("scanlab: interrupted", file=sys.stderr)
        return 130


def run() -> None:
    """The ``scanlab`` command: :func:`main` on the process's arguments, then the process ends
    without tearing its modules down (:mod:`lab.app.process_exit`)."""
    exit_now(main())


if __name__ == "__main__":
    run()
