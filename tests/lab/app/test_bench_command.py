"""``scanlab bench``: the command's list, its checks, and where it writes the table."""
from __future__ import annotations

import json
import os
import subprocess
import sys

from compare.bench_scenes import BENCH_SCENES
from lab.app.bench_command import END, START, report, write_between_markers


def scanlab(*args):
    return subprocess.run([sys.executable, "-m", "lab", *args], capture_output=True, text=True, timeout=600)


def test_list_names_the_default_set():
    done = scanlab("bench", "--list")
    assert done.returncode == 0
    assert done.stdout.split() == list(BENCH_SCENES)


def test_a_misspelt_scene_fails_at_once_in_one_line():
    done = scanlab("bench", "ico5-phong", "icosfere", "--no-startup")
    assert done.returncode == 2
    assert len(done.stderr.strip().splitlines()) == 1 and "icosfere" in done.stderr


def test_a_run_writes_json_and_the_table_between_the_markers(tmp_path):
    page = tmp_path / "performance.md"
    page.write_text(f"# Performance\n\nintro\n\n{START}\nold table\n{END}\n\nafter\n")
    out = tmp_path / "bench.json"
    done = scanlab("bench", "icosphere:level=1", "--size", "64x48", "--repeat", "2", "--memory", "none",
                   "--no-startup", "--json", str(out), "--markdown", str(page))
    assert done.returncode == 0, done.stderr
    run = json.loads(out.read_text())
    assert [r["scene"] for r in run["rows"]] == ["icosphere:level=1"]
    text = page.read_text()
    assert "old table" not in text and text.startswith("# Performance\n\nintro\n") and text.endswith("\n\nafter\n")
    assert "| icosphere:level=1 | 64x48 | 80 |" in text


def test_markers_are_added_to_a_page_without_them(tmp_path):
    page = tmp_path / "p.md"
    page.write_text("text")
    write_between_markers(page, "T")
    assert page.read_text() == f"text\n{START}\nT\n{END}\n"


def test_a_public_mesh_that_cannot_be_read_is_a_row_that_says_so_even_with_contention(tmp_path):
    """No network, or a broken copy: the run goes on with the other scenes, in every loop."""
    (tmp_path / "igea.ply").write_text("not a ply\n")
    done = subprocess.run([sys.executable, "-m", "lab", "bench", "igea-270k", "icosphere:level=1", "--size", "64x48",
                           "--repeat", "2", "--memory", "none", "--no-startup", "--contention"],
                          capture_output=True, text=True, timeout=600,
                          env={**os.environ, "SCANLAB_BENCH_MESHES": str(tmp_path)})
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr
    assert "igea-270k 64x48: unavailable: the public mesh is not the binary PLY expected" in done.stdout + done.stderr
    assert "other core busy, icosphere:level=1 64x48" in done.stdout + done.stderr


def test_memory_all_measures_both_sides_of_every_row(tmp_path):
    out = tmp_path / "bench.json"
    done = scanlab("bench", "icosphere:level=1", "--size", "64x48", "--repeat", "1", "--memory", "all",
                   "--no-startup", "--json", str(out))
    assert done.returncode == 0 and "Traceback" not in done.stderr, done.stderr
    memory = json.loads(out.read_text())["rows"][0]["memory"]
    assert set(memory) == {"ours", "reference"} and all(v >= 0 for v in memory.values())


def test_json_and_markdown_go_into_folders_that_do_not_exist_yet(tmp_path):
    """A fresh clone has no out/: ``make bench`` writes out/bench.json there all the same."""
    out, page = tmp_path / "out" / "bench.json", tmp_path / "new" / "page.md"
    done = scanlab("bench", "ico5-flat", "--size", "32x32", "--repeat", "1", "--memory", "none", "--no-startup",
                   "--json", str(out), "--markdown", str(page))
    assert done.returncode == 0, done.stderr
    assert json.loads(out.read_text())["rows"][0]["scene"] == "ico5-flat"
    assert START in page.read_text()


def test_the_report_names_the_rows_whose_frames_used_fewer_threads():
    row = {"size": "8x8", "triangles": 10, "ours": {"median": 2.0, "min": 1.0, "max": 3.0},
           "reference": {"median": 4.0, "min": 3.5, "max": 5.0}, "ratio": 0.5}
    run = {"started": "now", "cpus": 2, "load_before": "0", "load_after": "0", "repeat": 15,
           "rows": [{"scene": "a", **row, "fewer_threads": 0}, {"scene": "b", **row, "fewer_threads": 4}]}
    assert "kept a core busy (renderer/free_cores.py): b 8x8 4 of 15." in report(run)
    run["rows"][1]["fewer_threads"] = 0
    assert "kept a core busy (renderer/free_cores.py): none." in report(run)
