"""The package chooses numba's threading layer (renderer/threads.py): TBB, whose threads share
a loop's work, unless the user chose; the layer changes speed only, never a byte."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from renderer import threads

ROOT = Path(__file__).resolve().parents[2]

RENDER = """
import hashlib, json, os, numba
from lab import load_scene
from renderer import render
numba.set_num_threads(int(os.environ.get("THREADS", "2")))
frame = render(load_scene("translucent-three"))
frame2 = render(load_scene("menger"))
print(json.dumps({"layer": numba.threading_layer(), "wait": os.environ.get("OMP_WAIT_POLICY"),
                  "image": hashlib.sha256(frame.rgb.tobytes() + frame2.rgb.tobytes()).hexdigest()}))
"""


def run(**env) -> dict:
    environment = {k: v for k, v in os.environ.items() if k not in ("NUMBA_THREADING_LAYER", "OMP_WAIT_POLICY")}
    environment.update(env)
    done = subprocess.run([sys.executable, "-c", RENDER], cwd=ROOT, env=environment, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_the_tbb_wheel_is_found_where_the_loader_does_not_look():
    assert any(Path(p).is_file() for p in threads.tbb_library_paths()[1:])
    assert threads.load_tbb()


def test_frames_run_on_tbb_unless_the_user_chose_and_every_layer_gives_the_same_bytes():
    tbb2, tbb1 = run(THREADS="2"), run(THREADS="1")
    omp = run(NUMBA_THREADING_LAYER="omp")
    assert tbb2["layer"] == tbb1["layer"] == "tbb"
    assert omp["layer"] == "omp" and omp["wait"] == "passive"
    assert tbb2["image"] == tbb1["image"] == omp["image"]


def test_the_users_wait_policy_is_kept(monkeypatch):
    monkeypatch.setenv("OMP_WAIT_POLICY", "active")
    monkeypatch.setenv("NUMBA_THREADING_LAYER", "omp")
    assert threads.choose_threading_layer() == "omp"
    assert os.environ["OMP_WAIT_POLICY"] == "active"
