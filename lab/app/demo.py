"""``scanlab demo``: compare scenes with VTK and build a page of side-by-side panels.

Each SCENE — a preset name, a scene file, a mesh file or a built-in shape — is compared
into ``OUT/<name>/`` (the five files of ``scanlab compare``, plus ``scene.toml``: a copy
of its scene file, or for a shape or mesh file the scene written out by
:mod:`lab.scene_writer`). Then ``OUT/index.html`` (:mod:`lab.app.demo_page`) and
``OUT/summary.json``. Verdicts come from :mod:`compare.verdict`, the judge ``scanlab
compare`` uses: exit status 0 when every scene has its expected outcome.
"""
from __future__ import annotations

import shlex
import sys
import time
from pathlib import Path

from lab.loading import load_scene
from lab.presets import preset_description, preset_names, preset_path


def _progress(i: int, n: int, name: str, started: float) -> None:
    done = int(30 * i / n)
    sys.stdout.write(f"\r[{'#' * done}{'.' * (30 - done)}] {i}/{n} {name:<24} {time.perf_counter() - started:5.1f} s")
    sys.stdout.flush()


def scene_name(spec: str) -> str:
    """A name for a folder and an anchor: a preset's name, a file's stem, a shape spec made safe."""
    if spec in preset_names():
        return spec
    if Path(spec).suffix and ":" not in spec:
        return Path(spec).stem
    return spec.replace(":", "_").replace("=", "").replace(",", "_")


def describe(spec: str, scene) -> str:
    """One sentence about where a scene comes from (a preset's first comment line)."""
    if spec in preset_names():
        return preset_description(spec)
    path = Path(spec)
    if path.suffix.lower() == ".toml":
        first = path.read_text(encoding="utf-8", errors="replace").splitlines()[:1]
        comment = first[0].lstrip("# ").strip() if first and first[0].startswith("#") else ""
        return comment or f"the scene file {path.name}"
    triangles = sum(o.mesh.n_triangles for o in scene.objects)
    if path.suffix and ":" not in spec:
        return f"the mesh file {path.name} ({triangles:,} triangles), framed with one headlight"
    return f"the built-in shape {spec} ({triangles:,} triangles), framed with one headlight"


def scene_copy(spec: str, scene, folder: Path) -> str:
    """Put the scene's file beside its panel as ``scene.toml``; return a note on what it is.

    A preset or scene file is copied byte for byte (relative paths in it still point
    next to the original); a shape or mesh file is written out with its mesh."""
    from lab.atomic import atomic_file
    from lab.scene_writer import write_scene

    source = preset_path(spec) if spec in preset_names() else Path(spec)
    if source.suffix.lower() == ".toml":
        with atomic_file(folder / "scene.toml") as f:
            f.write(source.read_bytes())
        return f"a copy of {source}"
    write_scene(scene, folder / "scene.toml")
    return "written by scanlab export (its mesh in scene-files/)"


def reproduce_command(spec: str, out: Path) -> str:
    """The command that makes this panel again, from the folder ``demo`` ran in."""
    path = Path(spec)
    shown = spec if spec in preset_names() or not path.exists() else str(path.resolve())
    return shlex.join(["scanlab", "compare", shown, "--out", str(out)])


def png_size(path: Path) -> list[int]:
    """[width, height] of a PNG file, from its header."""
    from PIL import Image

    with Image.open(path) as im:
        return list(im.size)


def run_demo(out: Path, specs: list[str]) -> int:
    """Compare every scene of ``specs`` into ``out``; print where everything is. Exit status 0/1."""
    from compare.report import summary_line, write_json
    from lab.app.demo_page import demo_page
    from lab.atomic import write_text
    from renderer.compile_ahead import helped_cold_start

    out.mkdir(parents=True, exist_ok=True)
    started = time.perf_counter()
    print(f"scanlab demo: comparing {len(specs)} scenes with VTK (the first run compiles the renderer's kernels)")
    with helped_cold_start():  # an empty kernel cache: a second process compiles a share of the kernels
        rows = _compare_all(out, specs, started)
    _progress(len(specs), len(specs), "done", started)
    print()
    for m in rows:
        print(f"  {m['verdict']['status']:<15} {summary_line(m)}")
    write_json(out / "summary.json", {"scenes": rows})
    page = out / "index.html"
    write_text(page, demo_page(rows))
    print(f"\nside-by-side panels: {out}/<scene>/side_by_side.png")
    print(f"all of them on one page: {page.resolve()}")
    return 0 if all(m["verdict"]["ok"] for m in rows) else 1


def _compare_all(out: Path, specs: list[str], started: float) -> list[dict]:
    """Each scene of ``specs`` compared with VTK into ``out/<name>``; its metrics, in order."""
    from compare.comparison import run_comparison

    rows, names = [], set()
    for i, spec in enumerate(specs):
        name = scene_name(spec)
        while name in names:
            name += "-2"
        names.add(name)
        _progress(i, len(specs), name, started)
        scene = load_scene(spec)
        result = run_comparison(scene, name=name)
        result.write(out / name)
        m = dict(result.metrics)
        m.update(description=describe(spec, scene), settings=result.settings, spec=spec, panel_size=png_size(
                     out / name / "side_by_side.png"),
                 scene_file=f"{name}/scene.toml", scene_file_note=scene_copy(spec, scene, out / name),
                 command=reproduce_command(spec, out / name))
        rows.append(m)
    return rows
