"""The ``scanlab`` command (also ``python -m lab``).

Every expected failure — a bad scene file, a bad option, no OpenGL for VTK — ends in one
line on stderr and exit status 2; ``compare --fail-above`` exits 1 on a failed verdict.
"""
from __future__ import annotations

import argparse
import difflib
import os
import sys
from pathlib import Path

from lab.app import lessons_site
from lab.app.exercises.command import add_parser as add_exercise_parser
from lab.loading import LARGE_SIZE, MAX_SIZE, SceneError, load_scene, size_problem
from lab.presets import SCENES_DIR, preset_description, preset_names
from lab.scene import MODELS, SHADINGS


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
        near = difflib.get_close_matches(word.split("=")[0], sorted(options), n=1) if word.startswith("-") else []
        if near:
            return f" (did you mean {near[0]}?)"
    return ""


def _size(text: str) -> tuple[int, int]:
    """``WxH`` → (W, H); the limit (MAX_SIZE, or LARGE_SIZE with --allow-large) is checked in _load."""
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT such as 512x384, got {text!r}") from None
    if w < 1 or h < 1:
        raise argparse.ArgumentTypeError(f"width and height must be at least 1, got {text!r}")
    return w, h


def _allow_large_arg(p: argparse.ArgumentParser) -> None:
    p.add_argument("--allow-large", action="store_true",
                   help=f"accept images beyond {MAX_SIZE}x{MAX_SIZE} pixels (up to {LARGE_SIZE}x{LARGE_SIZE})")


def _scene_args(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", help="a scene file (.toml), a preset name (see `scanlab scenes`) or a built-in shape "
                                 "such as cube, icosahedron, quad, icosphere:level=3")
    p.add_argument("--shading", choices=SHADINGS, help="override every object's shading")
    p.add_argument("--size", type=_size, metavar="WxH",
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


def _scene_name(spec: str) -> str:
    return Path(spec).stem if spec.endswith(".toml") else spec.replace(":", "_").replace("=", "").replace(",", "_")


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
    from renderer import render

    return _draw_to_png(args, render)


def cmd_reference(args) -> int:
    from compare.reference import render_reference

    return _draw_to_png(args, render_reference)


def cmd_compare(args) -> int:
    from compare.report import OUTPUT_FILES, compare_scene, summary_line

    scene = _load(args)
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise UsageError(f"--out {args.out}: is a file, not a folder")
    for name in OUTPUT_FILES:
        _output(out / name, scene)
    m = compare_scene(scene, out, name=_scene_name(args.scene), reference=args.reference)
    print(summary_line(m))
    print(f"wrote {out}/ ({', '.join(OUTPUT_FILES)})")
    if args.fail_above is not None and m["delta_e_2000"]["p999"] > args.fail_above:
        print(f"FAIL: 99.9th percentile ΔE2000 {m['delta_e_2000']['p999']:.3f} > {args.fail_above}", file=sys.stderr)
        return 1
    return 0


def cmd_scenes(args) -> int:
    names = preset_names()
    width = max(len(n) for n in names)
    for name in names:
        print(f"{name:<{width}}  {preset_description(name)}")
    print(f"\n{len(names)} presets in {SCENES_DIR}; built-in shapes: cube, quad, icosahedron, icosphere:level=N")
    return 0


def cmd_bench(args) -> int:
    from lab.app.bench_command import run_bench

    if args.repeat < 1:
        raise UsageError("--repeat: must be at least 1")
    return run_bench(args)


def cmd_demo(args) -> int:
    from lab.app.demo import run_demo

    names = preset_names()
    for name in args.scenes:
        if name not in names:
            near = difflib.get_close_matches(name, names, n=1)
            hint = f"did you mean {near[0]}?" if near else "see `scanlab scenes`"
            raise UsageError(f"demo: {name!r} is not a preset ({hint})")
    out = Path(args.out)
    if out.exists() and not out.is_dir():
        raise UsageError(f"--out {args.out}: is a file, not a folder")
    return run_demo(out, args.scenes or names)


def cmd_export(args) -> int:
    from lab.meshfiles import MeshFileError
    from lab.meshfiles.write import writer_for

    try:
        write = writer_for(args.output)  # before anything is made
    except MeshFileError as exc:
        raise UsageError(str(exc)) from None
    scene = load_scene(args.scene, allow_large=args.allow_large)
    out = _output(args.output, scene)
    mesh = scene.world_mesh()
    write(mesh, out)
    normals = "with point normals" if mesh.point_normals is not None else "no point normals"
    print(f"wrote {out} ({mesh.n_points} points, {mesh.n_triangles} triangles, {normals})")
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

    p = sub.add_parser("compare", help="draw both, measure ΔE2000, write images and metrics.json",
                       description="Writes DIR/ours.png, vtk.png, delta_e.png, side_by_side.png and metrics.json "
                                   "and prints a one-line summary.")
    _scene_args(p)
    p.add_argument("--out", required=True, metavar="DIR", help="folder for the outputs (created if missing)")
    p.add_argument("--fail-above", type=float, metavar="DE",
                   help="exit 1 when the 99.9th percentile ΔE2000 exceeds DE")
    p.add_argument("--reference", choices=["vtk-native"],
                   help="force VTK's own shading for every object (by default textbook models are checked "
                        "against colours lit in numpy or a replaced VTK shader); shows how far textbook Gouraud "
                        "is from VTK's per-pixel 'Gouraud'")
    p.set_defaults(func=cmd_compare)

    p = sub.add_parser("scenes", help="list the preset scenes")
    p.set_defaults(func=cmd_scenes)

    p = sub.add_parser("bench", help="frame time, memory and start-up of scanlab against VTK, in one process",
                       description="Times both renderers on the same scenes, frames alternating after a warm-up, "
                                   "and prints median/min/max ms and the median ratio ours/VTK (< 1: scanlab "
                                   "is faster). With no SCENES: issue 15's benchmark set at 512x512 and 1024x1024.")
    p.add_argument("scenes", nargs="*", metavar="SCENE",
                   help="names of the benchmark set (see --list), presets, shapes or scene files")
    p.add_argument("--size", type=_size, action="append", metavar="WxH", help="image size (repeatable)")
    p.add_argument("--shading", choices=SHADINGS, help="override every object's shading")
    p.add_argument("--model", choices=MODELS, help="override every object's reflection model")
    p.add_argument("--repeat", type=int, default=15, help="timed pairs of frames per scene and size (default 15)")
    p.add_argument("--json", metavar="FILE", help="also write every figure to FILE as JSON")
    p.add_argument("--markdown", metavar="FILE", help="also write the table to FILE (between its bench markers)")
    p.add_argument("--memory", choices=["largest", "all", "none"], default="largest",
                   help="peak memory in child processes: for the largest scene only (default), all, or none")
    p.add_argument("--no-startup", action="store_true", help="skip the cold/warm start-up measurement")
    p.add_argument("--list", action="store_true", help="list the benchmark set and exit")
    p.set_defaults(func=cmd_bench)

    p = sub.add_parser("export", help="write the exact triangles both renderers draw (.ply .obj .stl .vtp)",
                       description="Writes the scene's (or shape's) triangles in world space, with point normals "
                                   "where the format holds them (PLY, OBJ, VTP; STL has none).")
    p.add_argument("scene", help="a scene file, preset or built-in shape such as menger:level=3")
    p.add_argument("-o", "--output", required=True, help="file to write; the suffix picks the format")
    _allow_large_arg(p)
    p.set_defaults(func=cmd_export)

    p = sub.add_parser("info", help="counts, bounds, area, volume and closedness of a scene or shape")
    p.add_argument("scene", help="a scene file, preset or built-in shape such as cone:segments=24")
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
    p.add_argument("--cases", type=int, default=10000, help="number of mutated files (default 10000)")
    p.add_argument("--seed", type=int, default=0, help="seed; case i of seed s is always the same file (default 0)")
    p.add_argument("--save", default="out/fuzz", metavar="DIR",
                   help="folder for failing inputs, each with a .txt of what happened (default out/fuzz)")
    p.set_defaults(func=cmd_fuzz)

    add_exercise_parser(sub)

    p = sub.add_parser("demo", help="compare every preset scene and build a page of side-by-side panels")
    p.add_argument("--out", default="out/demo", metavar="DIR", help="output folder (default out/demo)")
    p.add_argument("scenes", nargs="*", help="presets to run (default: all)")
    p.set_defaults(func=cmd_demo)
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


if __name__ == "__main__":
    sys.exit(main())
