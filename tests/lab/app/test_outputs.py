"""Outputs: written whole or not at all, never over an input, never deleting what scanlab
did not write; missing folders are made; --allow-large lifts the size limit."""
from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import lab.atomic
from lab.app.cli import main

REPO = Path(__file__).resolve().parents[3]


# --------------------------------------------------------------------------- atomic writes
def _writers(tmp_path):
    """(name, target, write()) for every kind of file scanlab writes."""
    from compare.images import delta_e_figure, side_by_side_figure
    from lab.png import write_png
    from compare.report import write_json
    from lab.app.fuzz import Failure, save_failure
    from lab.meshfiles import write_mesh
    from lab.shapes import cube

    rgb = np.zeros((8, 8, 3), np.uint8)
    de, mask = np.zeros((8, 8)), np.zeros((8, 8), bool)
    metrics = {"delta_e_2000": {k: 0.0 for k in ("mean", "median", "p95", "p99", "p999", "max")},
               "pixels_over_1": 0.0, "coverage_mismatch": 0.0, "max_channel_diff": 0, "shared_pixels": 64,
               "mismatch_pixels": 0}
    rows = [("png", "a.png", lambda p: write_png(p, rgb)),
            ("delta-e-figure", "d.png", lambda p: delta_e_figure(de, mask, p)),
            ("side-by-side", "s.png", lambda p: side_by_side_figure(rgb, rgb, de, mask, metrics, p)),
            ("json", "m.json", lambda p: write_json(p, {"a": 1})),
            ("html", "index.html", lambda p: lab.atomic.write_text(p, "<p>")),
            ("fuzz-input", "f.toml", lambda p: save_failure(p.parent, p.name, Failure(0, 0, "x", [], b"x", "e")))]
    rows += [(f"mesh-{fmt}", f"m.{fmt}", lambda p: write_mesh(cube(), p)) for fmt in ("ply", "obj", "stl", "vtp")]
    return rows


@pytest.mark.parametrize("index", range(10), ids=["png", "delta-e-figure", "side-by-side", "json", "html",
                                                  "fuzz-input", "mesh-ply", "mesh-obj", "mesh-stl", "mesh-vtp"])
def test_an_interrupted_write_leaves_the_old_file_and_no_temporary(index, tmp_path, monkeypatch):
    """Interrupt each writer at its rename: the target keeps its old bytes, no temporary file stays."""
    name, target, write = _writers(tmp_path)[index]
    path = tmp_path / target
    write(path)  # a complete file first
    complete = {p.name: p.read_bytes() for p in tmp_path.iterdir()}

    def interrupted(src, dst):
        raise KeyboardInterrupt

    monkeypatch.setattr(lab.atomic.os, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        write(path)
    assert {p.name: p.read_bytes() for p in tmp_path.iterdir()} == complete, name


def test_every_writer_goes_through_atomic_file():
    """No module writes a file but through lab.atomic (a guard against a new plain open(..., "w"))."""
    plain = re.compile(r"write_text\(|write_bytes\(|open\([^)]*['\"][wa]|\.savefig\((?!f,)|\.save\((?!f,)"
                       r"|copyfile|shutil\.copy|rmtree|np\.save\w*\((?!f,)|\.tofile\(")
    found = []
    for folder in ("lab", "compare", "lessons", "renderer"):
        for file in (REPO / folder).rglob("*.py"):
            if file.name == "atomic.py":
                continue
            if file.relative_to(REPO).as_posix() in ("renderer/jit.py", "lab/app/lesson_site/cache.py"):
                continue  # remove stale compiled-kernel or figure-cache folders: caches, not outputs
            if file.relative_to(REPO).as_posix() == "lab/app/exercises/runner.py":
                continue  # the sandboxed child: status and results into its private temporary folder, renamed
            for number, line in enumerate(file.read_text().splitlines(), 1):
                code = line.split("#")[0]
                if plain.search(code) and "lab.atomic" not in code and "write_text(page" not in code \
                        and not code.strip().startswith("write_text(path"):
                    found.append(f"{file.relative_to(REPO)}:{number}: {line.strip()}")
    assert not found, "\n".join(found)


# --------------------------------------------------------------------------- folders
def test_missing_output_folders_are_made_and_the_path_printed(tmp_path, capsys):
    """render and export make missing parent folders and print the path they wrote."""
    png, ply = tmp_path / "a" / "b" / "x.png", tmp_path / "c" / "d" / "x.ply"
    assert main(["render", "cube", "--size", "32x24", "-o", str(png)]) == 0
    assert main(["export", "cube", "-o", str(ply)]) == 0
    out = capsys.readouterr().out
    assert png.is_file() and ply.is_file() and f"wrote {png}" in out and f"wrote {ply}" in out


def _tree(root: Path) -> dict:
    return {str(p.relative_to(root)): (p.read_bytes() if p.is_file() else None) for p in root.rglob("*")}


def _foreign(out: Path) -> dict:
    """Put files scanlab did not write into ``out``: they must survive."""
    (out / "keep").mkdir(parents=True)
    (out / "notes.txt").write_text("mine")
    (out / "keep" / "data.bin").write_bytes(b"\x00\x01")
    (out / ".gouraud-vs-vtk").mkdir()
    (out / ".gouraud-vs-vtk" / "x").write_text("mine too")
    return _tree(out)


def test_compare_out_keeps_foreign_files(tmp_path, capsys):
    """compare --out DIR adds its five files and touches nothing else there."""
    out = tmp_path / "out"
    foreign = _foreign(out)
    assert main(["compare", "cube", "--size", "48x32", "--out", str(out)]) == 0
    after = _tree(out)
    assert {k: after[k] for k in foreign} == foreign
    assert set(after) - set(foreign) == {"ours.png", "vtk.png", "delta_e.png", "side_by_side.png", "metrics.json"}
    assert f"wrote {out}/" in capsys.readouterr().out


def test_demo_out_keeps_foreign_files(tmp_path, capsys):
    """demo --out DIR writes PRESET/* (with a copy of the scene file), index.html and summary.json, and
    touches nothing else."""
    out = tmp_path / "out"
    foreign = _foreign(out)
    assert main(["demo", "--out", str(out), "fill-rule"]) == 0
    after = _tree(out)
    assert {k: after[k] for k in foreign} == foreign
    assert set(after) - set(foreign) == {"fill-rule", "index.html", "summary.json"} | {
        f"fill-rule/{n}" for n in ("ours.png", "vtk.png", "delta_e.png", "side_by_side.png", "metrics.json",
                                   "scene.toml")}
    assert json.loads((out / "summary.json").read_text())["scenes"][0]["scene"] == "fill-rule"


# --------------------------------------------------------------------------- size limit
def test_allow_large_lifts_the_size_limit(tmp_path):
    """8193 pixels wide: refused without --allow-large (see test_errors), drawn with it, from the
    command line and from a scene file."""
    png = tmp_path / "wide.png"
    assert main(["render", "cube", "--size", "8193x2", "--allow-large", "-o", str(png)]) == 0
    assert Image.open(png).size == (8193, 2)
    scene = tmp_path / "tall.toml"
    scene.write_text('[image]\nsize = [2, 8200]\n[[object]]\nshape = "cube"\n')
    assert main(["render", str(scene), "-o", str(png)]) == 2
    assert main(["render", str(scene), "--allow-large", "-o", str(png)]) == 0
    assert Image.open(png).size == (2, 8200)
