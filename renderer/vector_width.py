"""How wide the vectors of the renderer's kernels are: 512 bits where the processor has AVX-512,
chosen by the package before numba compiles anything (not left to the user's shell).

LLVM, tuning for an AVX-512 processor (Ice Lake, Sapphire Rapids: this machine is one),
still vectorises loops 256 bits wide, 8 float32 lanes (its ``prefer-256-bit`` tuning, once
meant for processors whose clock dropped on 512-bit instructions). The renderer's lighting,
texturing and span loops are arithmetic over runs of pixels, and 16 lanes do them in fewer
instructions. numba compiles for the host's own features (llvmlite's
``get_host_cpu_features``); with ``-prefer-256-bit`` added to that list, LLVM uses the
``zmm`` registers (:func:`wide_features`).

The bytes cannot change: the kernels use no fast-math, so LLVM vectorises no float sum out of
its written order and each lane computes what the scalar code computes, IEEE operation by
IEEE operation (every preset and every bench scene at both sizes: the same rgb, depth and
coverage with and without; ``tests/renderer/test_vector_width.py``). Measured, whole frames
in alternating processes (two threads, medians of 25 frames, two or three rounds, before → after,
ms): ico5-phong at 1024² 7.16–8.17 → 6.92–7.11, textured-sphere at 1024² 6.56–6.76 →
6.12–6.46, ico5-phong at 512² 3.88–4.01 → 3.50–3.90, the 1,024-segment cylinder at 512²
2.94–3.24 → 2.76–2.96. Frames bound by their triangles (the level-7 icospheres, the sponges, the
Igea scans) moved within the noise; the raster stage alone is a few per cent slower in most
rounds (−6 to +14 %, docs/performance.md): its lanes of 8 depths fit 256 bits.

A choice the user made (``NUMBA_CPU_FEATURES`` set) is kept; without AVX-512 nothing changes.
numba's kernel cache files each kernel under the features it was compiled for, so a cache
made before this choice is not served after it.
"""
from __future__ import annotations

import os

from llvmlite import binding  # numba's own compiler back end

NARROW_TUNING = "prefer-256-bit"
"""LLVM's tuning feature that holds vectors to 256 bits on AVX-512 processors."""


def wide_features(host: str) -> str:
    """``host``, LLVM's comma-separated feature list (``+avx2,-amx-int8,…``), with
    ``-prefer-256-bit`` added when it has AVX-512 (``+avx512f``); else ``host`` unchanged."""
    features = host.split(",") if host else []
    if "+avx512f" not in features:
        return host
    return ",".join([f for f in features if f.lstrip("+-") != NARROW_TUNING] + ["-" + NARROW_TUNING])


def chosen_features() -> str | None:
    """The feature list the renderer's kernels are compiled for: None when the user chose
    (``NUMBA_CPU_FEATURES`` set: numba reads it); else :func:`wide_features` of the host's."""
    if os.environ.get("NUMBA_CPU_FEATURES"):
        return None
    return wide_features(binding.get_host_cpu_features().flatten())
