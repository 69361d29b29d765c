"""The package compiles the renderer's kernels for 512-bit vectors where the processor has
AVX-512 (renderer/vector_width.py), unless the user chose; the width changes speed only,
never a byte."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from llvmlite import binding

from renderer import vector_width

ROOT = Path(__file__).resolve().parents[2]
HOST = binding.get_host_cpu_features().flatten()

PROBE = """
import hashlib, json, numpy as np
from lab import load_scene
from renderer import render
from renderer.jit import njit
from numba.core.registry import cpu_target

@njit
def scaled(x, out):
    for i in range(x.shape[0]):
        out[i] = x[i] * np.float32(3.0) + np.float32(1.0)

x = np.ones(64, np.float32)
scaled(x, np.empty_like(x))
digest = hashlib.sha256()
for name in ("textured-sphere", "translucent-three"):
    frame = render(load_scene(name))
    for a in (frame.rgb, frame.depth, frame.coverage):
        digest.update(np.ascontiguousarray(a).tobytes())
asm = "".join(scaled.inspect_asm().values())
print(json.dumps({"features": cpu_target.target_context.codegen()._get_host_cpu_features(),
                  "zmm": "zmm" in asm, "image": digest.hexdigest()}))
"""


def probe(**env) -> dict:
    """Draw two presets whose spans run in vector loops (lit and textured runs, translucent
    batches) in a fresh process; the kernels' features, whether a loop used ``zmm`` registers,
    and a hash of the frames."""
    environment = {k: v for k, v in os.environ.items() if k != "NUMBA_CPU_FEATURES"}
    environment.update(env)
    done = subprocess.run([sys.executable, "-c", PROBE], cwd=ROOT, env=environment, capture_output=True, text=True,
                          timeout=1200)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_avx512_features_get_wide_vectors():
    wide = vector_width.wide_features("+avx2,+avx512f,+fma")
    assert wide.split(",") == ["+avx2", "+avx512f", "+fma", "-prefer-256-bit"]


def test_a_narrow_tuning_already_listed_is_replaced_not_doubled():
    wide = vector_width.wide_features("+avx512f,+prefer-256-bit,+sse2")
    assert wide.split(",") == ["+avx512f", "+sse2", "-prefer-256-bit"]


def test_features_without_avx512_are_kept_as_they_are():
    assert vector_width.wide_features("+avx2,+fma,-avx512f") == "+avx2,+fma,-avx512f"
    assert vector_width.wide_features("") == ""


def test_the_users_features_are_kept(monkeypatch):
    monkeypatch.setenv("NUMBA_CPU_FEATURES", "+sse2")
    assert vector_width.chosen_features() is None


def test_without_a_user_choice_the_hosts_features_are_widened(monkeypatch):
    monkeypatch.delenv("NUMBA_CPU_FEATURES", raising=False)
    assert vector_width.chosen_features() == vector_width.wide_features(HOST)


@pytest.mark.skipif("+avx512f" not in HOST.split(","), reason="this processor has no AVX-512: nothing is widened")
def test_kernels_use_512_bit_registers_and_draw_the_bytes_of_256_bit_ones(tmp_path):
    wide = probe()  # the package's choice, from the suite's kernel cache
    narrow = probe(NUMBA_CPU_FEATURES=HOST, SCANLAB_KERNEL_CACHE=str(tmp_path))  # the host's own list, compiled afresh
    assert wide["features"].endswith("-prefer-256-bit") and wide["zmm"]
    assert narrow["features"] == HOST and not narrow["zmm"]
    assert wide["image"] == narrow["image"]


def test_the_chosen_features_survive_numba_reading_its_configuration_again(monkeypatch):
    """numba reads its configuration from the environment again whenever a ``NUMBA_``
    variable changes (at the next compile): the features the renderer chose are still those
    the kernels compiled after it use."""
    import numba

    from renderer import jit

    if jit.FEATURES is None:
        pytest.skip("NUMBA_CPU_FEATURES was set by the user before the renderer chose")
    monkeypatch.setenv("NUMBA_DEBUG_CACHE", "0")

    @jit.njit
    def one_more(x):
        return x + 1

    assert one_more(1) == 2
    assert numba.config.CPU_FEATURES == jit.FEATURES
