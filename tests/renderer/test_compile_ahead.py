"""A cold start compiles in two processes: the frame's process and a helper divide the first
frame's kernels between them (renderer/compile_ahead.py)."""
from __future__ import annotations

import os
import subprocess
import sys
import time
from pathlib import Path

from renderer import compile_ahead
from renderer.compile_ahead import Kernel, divide, first_frame_kernels, helper_order, start_helper, stop_helper

ROOT = Path(__file__).resolve().parents[2]

COUNT_COMPILES = """
import json
from numba.core import event
from lab import load_scene
from renderer import render
from renderer.compile_ahead import START_UP_SCENE
compiled = []
class Count(event.Listener):
    def on_start(self, e): compiled.append(e.data["dispatcher"].py_func.__qualname__)
    def on_end(self, e): pass
with event.install_listener("numba:compile", Count()):
    render(load_scene(START_UP_SCENE))
print(json.dumps(compiled))
"""


def _environment(cache: Path) -> dict:
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["SCANLAB_KERNEL_CACHE"] = str(cache)
    return env


def test_the_helper_alone_fills_an_empty_cache_with_all_the_first_frame_compiles(tmp_path):
    """The recorded kernels and types are the ones the start-up frame needs: after the helper
    ran on its own, a fresh process draws that frame without compiling anything. When a change
    of the renderer changes what the frame compiles, record again:
    ``python -m renderer.compile_ahead --record``."""
    assert {"transform_vertices", "setup_triangles", "rasterize", "held_colours", "paint_rows"} <= {
        k.name for k in first_frame_kernels()}
    env = _environment(tmp_path / "kernels")
    helper = subprocess.run([sys.executable, "-m", "renderer.compile_ahead"], cwd=ROOT, env=env,
                            capture_output=True, text=True, timeout=900)
    assert helper.returncode == 0, helper.stderr
    frame = subprocess.run([sys.executable, "-c", COUNT_COMPILES], cwd=ROOT, env=env, capture_output=True,
                           text=True, timeout=900)
    assert frame.returncode == 0, frame.stderr
    assert frame.stdout.strip().splitlines()[-1] == "[]", "compiled after the helper: " + frame.stdout


def test_a_helper_starts_only_when_the_cache_is_empty_and_not_when_told_not_to(tmp_path, monkeypatch):
    monkeypatch.setenv("SCANLAB_KERNEL_CACHE", str(tmp_path / "kernels"))
    monkeypatch.setenv("SCANLAB_COMPILE_AHEAD", "0")
    assert compile_ahead.cache_is_empty() and start_helper() is None
    monkeypatch.setenv("SCANLAB_COMPILE_AHEAD", "1")
    helper = start_helper()
    try:
        assert helper is not None and helper.args[-1] == "renderer.compile_ahead"
    finally:
        stop_helper(helper)
    assert helper.poll() is not None  # stopped
    from renderer.jit import cache_folder

    (cache_folder() / "kernel-1.py311.nbi").write_bytes(b"")
    assert not compile_ahead.cache_is_empty() and start_helper() is None


def test_a_list_that_cannot_be_read_compiles_nothing_ahead(tmp_path):
    broken = tmp_path / "kernels.pickle"
    broken.write_bytes(b"not a pickle")
    assert first_frame_kernels(broken) == [] and first_frame_kernels(tmp_path / "missing") == []
    compile_ahead.compile_in_order([])  # nothing to do, no error
    assert divide([]) == ([], []) and helper_order([]) == []


def test_stopping_ends_a_helper_still_at_work():
    busy = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    started = time.perf_counter()
    stop_helper(busy)
    assert busy.poll() is not None and time.perf_counter() - started < 5
    stop_helper(None)  # no helper: nothing to stop


def test_the_helper_runs_while_the_block_does_and_is_stopped_after_it(monkeypatch):
    busy = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(60)"])
    monkeypatch.setattr(compile_ahead, "start_helper", lambda: busy)
    compiled = []
    monkeypatch.setattr(compile_ahead, "compile_in_order", compiled.append)
    with compile_ahead.helped_cold_start() as helper:
        assert helper is busy and busy.poll() is None
        assert compiled == [divide(first_frame_kernels())[1]]  # the frame's share, before the block
    assert busy.poll() is not None


def _helpers_running() -> list[str]:
    found = []
    for cmdline in Path("/proc").glob("[0-9]*/cmdline"):
        try:
            if b"renderer.compile_ahead" in cmdline.read_bytes():
                found.append(cmdline.parent.name)
        except OSError:
            continue
    return found


def test_scanlab_render_on_an_empty_cache_draws_the_same_picture_and_leaves_no_helper_behind(tmp_path):
    """A cold ``scanlab render`` with its helper writes the PNG that the same command writes
    alone from the project's kernel cache (warm by now in a test session; a cold start alone,
    without the helper, is :func:`tests.renderer.test_jit.test_a_cold_start_compiles_within_the_bar`'s:
    compiled twice here it cost the suite about a minute)."""
    outputs = []
    for name, env in (("helped", {**_environment(tmp_path / "kernels"), "SCANLAB_COMPILE_AHEAD": "1"}),
                      ("alone", {**os.environ, "SCANLAB_COMPILE_AHEAD": "0"})):
        out = tmp_path / f"{name}.png"
        done = subprocess.run([sys.executable, "-m", "lab", "render", "icosphere:level=3", "-o", str(out)],
                              cwd=ROOT, env=env, capture_output=True, text=True, timeout=900)
        assert done.returncode == 0, done.stderr
        outputs.append(out.read_bytes())
        assert _helpers_running() == []
    assert outputs[0] == outputs[1]


def _kernels(*seconds) -> list[Kernel]:
    return [Kernel("renderer.m", f"k{i}", (), s) for i, s in enumerate(seconds)]


def test_the_helper_takes_the_longest_compile_and_others_within_half_the_total():
    kernels = _kernels(1.0, 0.5, 8.0, 0.2, 4.0, 0.3)  # 14 s in all: the helper's share at most 7 s, but 8 s first
    helper, frame = divide(kernels)
    assert [k.name for k in helper] == ["k2"]
    assert [k.name for k in frame] == ["k0", "k1", "k3", "k4", "k5"]  # the frame's in the order recorded
    helper, frame = divide(_kernels(3.0, 1.0, 2.0, 0.5, 2.5))  # 9 s: 3 + 1 + 0.5 within 4.5, longest first
    assert [k.name for k in helper] == ["k0", "k1", "k3"] and [k.name for k in frame] == ["k2", "k4"]


def test_alone_the_helper_compiles_every_kernel_once_its_own_share_first():
    kernels = _kernels(1.0, 0.5, 8.0, 0.2, 4.0, 0.3)
    order = helper_order(kernels)
    assert [k.name for k in order] == ["k2", "k5", "k4", "k3", "k1", "k0"]
    assert sorted(order) == sorted(kernels)


def test_the_recorded_list_says_how_long_each_kernel_took():
    kernels = first_frame_kernels()
    assert all(k.seconds > 0 for k in kernels)
    helper, frame = divide(kernels)
    assert helper and frame and len(helper) + len(frame) == len(kernels) and set(helper + frame) == set(kernels)
