"""The ``scanlab`` command (also ``python -m lab``).

Every expected failure — a bad scene file, a bad option, no OpenGL for VTK — ends in one
line on stderr and exit status 2; ``compare --fail-above`` exits 1 on a failed verdict.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from lab.loading import SCENES_DIR, SceneError, load_scene
from lab.scene import MODELS, SHADINGS


class UsageError(Exception):
    """A problem with the command line; the message says which option and why."""


def _size(text: str) -> tuple[int, int]:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT such as 512x384, got {text!r}") from None
    if not (1 <= w <= 8192 and 1 <= h <= 8192):
        raise argparse.ArgumentTypeError(f"width and height must lie in 1..8192, got {text!r}")
    return w, h


def _scene_args(p: argparse.ArgumentParser) -> None:
    p.add_argument("scene", help="a scene file (.toml), a preset name (see `scanlab scenes`) or a built-in shape "
                                 "such as cube, icosahedron, quad, icosphere:level=3")
    p.add_argument("--shading", choices=SHADINGS, help="override every object's shading")
    p.add_argument("--size", type=_size, metavar="WxH", help="override the image size, e.g. 640x480")
    p.add_argument("--model", choices=MODELS, help="override every object's reflection model: vtk (VTK's own), "
                                                   "opengl (fixed-function OpenGL) or classic (the course's)")


def _load(args):
    return load_scene(args.scene).with_overrides(shading=args.shading, size=args.size, model=args.model)


def _scene_name(spec: str) -> str:
    return Path(spec).stem if spec.endswith(".toml") else spec.replace(":", "_").replace("=", "").replace(",", "_")


def _output(path: str, scene_spec: str) -> Path:
    out = Path(path)
    if out.exists() and Path(scene_spec).exists() and out.resolve() == Path(scene_spec).resolve():
        raise UsageError(f"{path}: the output would overwrite the input")
    out.parent.mkdir(parents=True, exist_ok=True)
    return out


def _draw_to_png(args, draw) -> int:
    from compare.images import write_png

    scene = _load(args)
    out = _output(args.output, args.scene)
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
    from compare.report import compare_scene, summary_line

    scene = _load(args)
    m = compare_scene(scene, _output(str(Path(args.out) / "metrics.json"), args.scene).parent,
                      name=_scene_name(args.scene), reference=args.reference)
    print(summary_line(m))
    print(f"wrote {args.out}/ (ours.png, vtk.png, delta_e.png, side_by_side.png, metrics.json)")
    if args.fail_above is not None and m["delta_e_2000"]["p999"] > args.fail_above:
        print(f"FAIL: 99.9th percentile ΔE2000 {m['delta_e_2000']['p999']:.3f} > {args.fail_above}", file=sys.stderr)
        return 1
    return 0


def preset_names() -> list[str]:
    return sorted(p.stem for p in SCENES_DIR.glob("*.toml"))


def preset_description(name: str) -> str:
    first = (SCENES_DIR / f"{name}.toml").read_text(encoding="utf-8").splitlines()[0]
    return first.lstrip("# ").strip()


def cmd_scenes(args) -> int:
    names = preset_names()
    width = max(len(n) for n in names)
    for name in names:
        print(f"{name:<{width}}  {preset_description(name)}")
    print(f"\n{len(names)} presets in {SCENES_DIR}; built-in shapes: cube, quad, icosahedron, icosphere:level=N")
    return 0


def cmd_bench(args) -> int:
    from compare.bench import bench

    r = bench(_load(args), repeat=args.repeat)
    print(f"{r['scene']} at {r['size'][0]}x{r['size'][1]}, {r['triangles']} triangles, median of {r['repeat']}:")
    print(f"  scanlab {r['ours_ms']:.2f} ms/frame, VTK (llvmpipe) {r['vtk_ms']:.2f} ms/frame: "
          f"VTK/scanlab = {r['vtk_over_ours']:.2f}")
    return 0


def cmd_demo(args) -> int:
    from lab.demo import run_demo

    return run_demo(Path(args.out), args.scenes or preset_names())


def cmd_export(args) -> int:
    from lab.meshfiles import MeshFileError, write_mesh

    scene = load_scene(args.scene)
    out = _output(args.output, args.scene)
    mesh = scene.world_mesh()
    try:
        write_mesh(mesh, out)
    except MeshFileError as exc:
        raise UsageError(str(exc)) from None
    normals = "with point normals" if mesh.point_normals is not None else "no point normals"
    print(f"wrote {out} ({mesh.n_points} points, {mesh.n_triangles} triangles, {normals})")
    return 0


def cmd_info(args) -> int:
    from lab.measure import mesh_summary

    scene = load_scene(args.scene)
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


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="scanlab",
        description="scanlab draws a scene with its own scanline renderer and with VTK, and measures, pixel by "
                    "pixel, how far apart the two images are (CIEDE2000).")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

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

    p = sub.add_parser("bench", help="frame time of scanlab and of VTK for one scene, in one process")
    _scene_args(p)
    p.add_argument("--repeat", type=int, default=30, help="timed frames per renderer (default 30)")
    p.set_defaults(func=cmd_bench)

    p = sub.add_parser("export", help="write the exact triangles both renderers draw (.ply .obj .stl .vtp)",
                       description="Writes the scene's (or shape's) triangles in world space, with point normals "
                                   "where the format holds them (PLY, OBJ, VTP; STL has none).")
    p.add_argument("scene", help="a scene file, preset or built-in shape such as menger:level=3")
    p.add_argument("-o", "--output", required=True, help="file to write; the suffix picks the format")
    p.set_defaults(func=cmd_export)

    p = sub.add_parser("info", help="counts, bounds, area, volume and closedness of a scene or shape")
    p.add_argument("scene", help="a scene file, preset or built-in shape such as cone:segments=24")
    p.set_defaults(func=cmd_info)

    p = sub.add_parser("lessons", help="lesson material: `scanlab lessons figures` makes the lesson figures")
    lsub = p.add_subparsers(dest="action", required=True, metavar="ACTION")
    q = lsub.add_parser("figures", help="render the measured figures the lessons show")
    q.add_argument("--out", default="lessons/figures", metavar="DIR", help="output folder (default lessons/figures)")
    q.set_defaults(func=cmd_lessons_figures)

    p = sub.add_parser("demo", help="compare every preset scene and build a page of side-by-side panels")
    p.add_argument("--out", default="out/demo", metavar="DIR", help="output folder (default out/demo)")
    p.add_argument("scenes", nargs="*", help="presets to run (default: all)")
    p.set_defaults(func=cmd_demo)
    return parser


def main(argv=None) -> int:
    from compare.vtk_backend import ReferenceUnavailable

    args = build_parser().parse_args(argv)
    try:
        return args.func(args)
    except (SceneError, UsageError, ReferenceUnavailable) as exc:
        print(f"scanlab: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("scanlab: interrupted", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
