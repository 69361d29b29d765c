"""Which threads run the renderer's parallel loops: numba's threading layer and wait policy,
chosen by the package before numba starts (not left to the user's shell).

Preferred: **TBB** (Intel oneTBB, the ``tbb`` wheel this package depends on). Its threads
take work from one another, so when another process holds a core the thread on the free
core does the larger share of a loop instead of waiting at the end of it for the one that
was put aside. Measured (``scanlab bench --contention``-style, another process spinning,
2 cores, 512², 2 threads / 1 thread): ico5-phong 0.94, menger3 0.95 with TBB; 2.37 and
2.50 with OpenMP, whose loops are cut in equal, fixed halves. Every loop writes rows of its
own, so the layer decides speed only, never bytes (``tests/renderer/test_threads.py``).

Fallback: numba's **OpenMP** layer with ``OMP_WAIT_POLICY=passive`` (idle threads sleep
rather than spin: measured ico5 512² 132 ms spinning, 39–46 ms passive, another core busy).

A value the user set (``NUMBA_THREADING_LAYER``, ``OMP_WAIT_POLICY``) is kept.
"""
from __future__ import annotations

import ctypes
import os
from importlib import metadata

TBB_LIBRARY = "libtbb.so.12"
"""The oneTBB library numba's TBB layer is linked against (by this name)."""


def tbb_library_paths() -> list[str]:
    """Where ``libtbb.so.12`` may be: the system's loader path first, then the file the
    ``tbb`` wheel installed (under the environment's ``lib/``, where the loader does not look)."""
    paths = [TBB_LIBRARY]
    try:
        files = metadata.files("tbb") or []
    except metadata.PackageNotFoundError:
        files = []
    paths += [str(f.locate()) for f in files if f.name == TBB_LIBRARY]
    return paths


def load_tbb() -> bool:
    """Load oneTBB into the process, globally, so that numba's TBB layer links; False when
    no copy loads."""
    for path in tbb_library_paths():
        try:
            ctypes.CDLL(path, mode=ctypes.RTLD_GLOBAL)
            return True
        except OSError:
            continue
    return False


def choose_threading_layer() -> str:
    """Set numba's threading layer before numba is imported: "tbb" when oneTBB loads, else
    "omp" (with passive waiting); the user's ``NUMBA_THREADING_LAYER`` wins. Returns the
    layer asked for."""
    os.environ.setdefault("OMP_WAIT_POLICY", "passive")
    chosen = os.environ.get("NUMBA_THREADING_LAYER")
    if chosen:
        if chosen == "tbb":
            load_tbb()  # the user's choice, made loadable
        return chosen
    layer = "tbb" if load_tbb() else "omp"
    os.environ["NUMBA_THREADING_LAYER"] = layer
    return layer
