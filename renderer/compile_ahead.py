"""A cold start in two processes: while a fresh ``scanlab render`` compiles the first frame's
kernels in the order the pipeline reaches them, a helper process compiles the same kernels
from the last one backwards, into the same kernel cache (:mod:`renderer.jit`), and each
process finds there what the other has finished. The machine has two cores; a cold start
used one.

Which kernels, with which argument types: :data:`KERNELS_FILE`, recorded by
``python -m renderer.compile_ahead --record`` from the kernels a fresh process compiles to
draw :data:`START_UP_SCENE` (the scene of issue 15's start-up figure) with an empty cache:
``(module, name, argument types)`` for each kernel called from Python, in the order they
were compiled (the kernels those call are compiled with them). A test draws that scene in
a fresh process after the helper alone filled an empty cache and checks that nothing is
left to compile: when a change of the renderer changes a kernel's argument types, it fails
until the file is recorded again.

The helper is started only when the kernel cache is empty (:func:`start_helper`; never
with ``SCANLAB_COMPILE_AHEAD=0``), and
stopped when the frame is done (:func:`stop_helper`); a helper that cannot read the file
(an older numba, a renamed type) exits and the frame compiles everything itself, as before.
Two processes filing kernels in one cache at once is safe: :mod:`renderer.jit` saves each
kernel's index under a file lock.
"""
from __future__ import annotations

import contextlib
import importlib
import os
import pickle
import subprocess
import sys
import tempfile
from pathlib import Path

from lab.atomic import atomic_file

KERNELS_FILE = Path(__file__).with_name("first_frame_kernels.pickle")
"""The first frame's kernels and argument types (a pickle of numba types; :func:`record`)."""

START_UP_SCENE = "icosphere:level=5"


def first_frame_kernels(path: Path = KERNELS_FILE) -> list[tuple]:
    """The recorded ``(module, name, argument types)`` list, or [] where it cannot be read."""
    try:
        return pickle.loads(path.read_bytes())
    except Exception:  # a missing file, or types this numba cannot rebuild: nothing to compile ahead
        return []


def record(path: Path = KERNELS_FILE, scene: str = START_UP_SCENE) -> list[tuple]:
    """Draw ``scene`` in this process and write the kernels it compiled from Python (numba's
    compile events, outermost only) to ``path``. Run it with an empty kernel cache (the
    ``--record`` command does), else a kernel loaded from the cache is not seen."""
    from numba.core import event

    from lab import load_scene
    from renderer.pipeline import render

    compiled, depth = [], [0]

    class Outermost(event.Listener):
        def on_start(self, e):
            if depth[0] == 0:
                func = e.data["dispatcher"].py_func
                compiled.append((func.__module__, func.__qualname__, tuple(e.data["args"])))
            depth[0] += 1

        def on_end(self, e):
            depth[0] -= 1

    with event.install_listener("numba:compile", Outermost()):
        render(load_scene(scene))
    with atomic_file(path) as f:
        f.write(pickle.dumps(compiled, protocol=4))
    return compiled


def compile_backwards(kernels: list[tuple]) -> None:
    """Compile ``kernels`` (as :func:`first_frame_kernels` gives them) last first, each into
    the kernel cache (a kernel already there is loaded, not compiled)."""
    for module, name, args in reversed(kernels):
        getattr(importlib.import_module(module), name).compile(args)


def cache_is_empty() -> bool:
    """True when this source tree's kernel folder holds no kernel yet (a fresh clone, or the
    first run after an edit of the renderer)."""
    from renderer.jit import cache_folder

    return not any(cache_folder().glob("*.nbi"))


def start_helper() -> subprocess.Popen | None:
    """Start the helper process when the kernel cache is empty (and ``SCANLAB_COMPILE_AHEAD``
    is not ``0``); else None."""
    if os.environ.get("SCANLAB_COMPILE_AHEAD", "1") == "0" or not KERNELS_FILE.exists() or not cache_is_empty():
        return None
    return subprocess.Popen([sys.executable, "-m", "renderer.compile_ahead"], stdin=subprocess.DEVNULL,
                            stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def stop_helper(helper: subprocess.Popen | None) -> None:
    """End the helper (its finished kernels are in the cache; a kernel half done is not)."""
    if helper is not None and helper.poll() is None:
        helper.terminate()
        with contextlib.suppress(subprocess.TimeoutExpired):
            helper.wait(timeout=5)


@contextlib.contextmanager
def helped_cold_start():
    """A ``with`` block for a command's first frame: the helper runs while the block does."""
    helper = start_helper()
    try:
        yield helper
    finally:
        stop_helper(helper)


def main(argv: list[str]) -> int:
    if argv == ["--record"]:
        os.environ["SCANLAB_KERNEL_CACHE"] = tempfile.mkdtemp()  # empty: every kernel is compiled, and seen
        kernels = record()
        print(f"wrote {KERNELS_FILE}: {len(kernels)} kernels")
        return 0
    compile_backwards(first_frame_kernels())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
