"""A cold start in two processes: a fresh ``scanlab render`` and a helper process divide the
first frame's kernels between them, each compiling its share into the same kernel cache
(:mod:`renderer.jit`), and each finds there what the other has finished. The machine has
two cores; a cold start used one.

The division (:func:`divide`): the helper takes the kernel that compiles longest (the raster
loop and the band fill it calls, about half of a cold start), then others, longest first,
while its share stays within half the total; the frame's process compiles the rest in the
order the pipeline reaches them (:func:`compile_in_order`), then draws, loading the helper's
kernels from the cache. When the helper is done with its share it goes on through the
frame's, from the last one backwards, so alone it fills the whole cache. (Before, the
helper took the whole list backwards while the frame compiled on demand: both met at the
raster loop, and the frame waited for its own compile of it.) The frame's share is the
start-up scene's, so a command drawing a scene of another kind compiles some kernels it does
not use (the held colours of a flat frame: a cold textured scene took about 2 % longer).

Which kernels, with which argument types, and how long each took: :data:`KERNELS_FILE`,
recorded by ``python -m renderer.compile_ahead --record`` from the kernels a fresh process
compiles to draw :data:`START_UP_SCENE` (the scene of issue 15's start-up figure) with an
empty cache: a :class:`Kernel` for each kernel called from Python, in the order they were
compiled (the kernels those call are compiled with them). A test draws that scene in a
fresh process after the helper alone filled an empty cache and checks that nothing is
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
import time
from pathlib import Path
from typing import NamedTuple

from lab.atomic import atomic_file
from lab.collector import fewer_collections

KERNELS_FILE = Path(__file__).with_name("first_frame_kernels.pickle")
"""The first frame's kernels, argument types and compile times (a pickle of numba types; :func:`record`)."""

START_UP_SCENE = "icosphere:level=5"


class Kernel(NamedTuple):
    """A kernel the first frame compiles: ``module`` and ``name`` of its dispatcher, the
    argument types (numba types) and the ``seconds`` its compile took when recorded (with
    the kernels it calls)."""

    module: str
    name: str
    args: tuple
    seconds: float


def first_frame_kernels(path: Path = KERNELS_FILE) -> list[Kernel]:
    """The recorded :class:`Kernel` list, or [] where it cannot be read."""
    try:
        return [Kernel(*k) for k in pickle.loads(path.read_bytes())]
    except Exception:  # a missing file, an older list, or types this numba cannot rebuild: nothing to compile ahead
        return []


def record(path: Path = KERNELS_FILE, scene: str = START_UP_SCENE) -> list[Kernel]:
    """Draw ``scene`` in this process and write the kernels it compiled from Python (numba's
    compile events, outermost only), with the seconds each took, to ``path``. Run it with an
    empty kernel cache (the ``--record`` command does), else a kernel loaded from the cache
    is not seen."""
    from numba.core import event

    from lab import load_scene
    from renderer.pipeline import render

    compiled, started = [], []

    class Outermost(event.Listener):
        def on_start(self, e):
            started.append(time.perf_counter())

        def on_end(self, e):
            seconds = time.perf_counter() - started.pop()
            if not started:
                func = e.data["dispatcher"].py_func
                compiled.append(Kernel(func.__module__, func.__qualname__, tuple(e.data["args"]), seconds))

    with event.install_listener("numba:compile", Outermost()):
        render(load_scene(scene))
    with atomic_file(path) as f:
        f.write(pickle.dumps([tuple(k) for k in compiled], protocol=4))
    return compiled


def divide(kernels: list[Kernel]) -> tuple[list[Kernel], list[Kernel]]:
    """``(helper's share, frame's share)`` of ``kernels``: the helper takes the longest compile,
    then others, longest first, while its share stays within half the total; the frame's
    share is the rest, in the recorded order (the order the pipeline reaches them)."""
    half = sum(k.seconds for k in kernels) / 2
    helper, taken = [], 0.0
    for i in sorted(range(len(kernels)), key=lambda i: -kernels[i].seconds):
        if not helper or taken + kernels[i].seconds <= half:
            helper.append(i)
            taken += kernels[i].seconds
    return [kernels[i] for i in helper], [k for i, k in enumerate(kernels) if i not in helper]


def compile_in_order(kernels: list[Kernel]) -> None:
    """Compile ``kernels`` in the order given, each into the kernel cache (a kernel already
    there is loaded, not compiled)."""
    for k in kernels:
        getattr(importlib.import_module(k.module), k.name).compile(k.args)


def helper_order(kernels: list[Kernel]) -> list[Kernel]:
    """What the helper compiles, in order: its share (:func:`divide`), then the frame's share
    from the last one backwards (all of them: alone, the helper fills the cache)."""
    helper, frame = divide(kernels)
    return helper + frame[::-1]


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
    """A ``with`` block for a command's first frame: when the kernel cache is empty, a helper
    compiles its share of the first frame's kernels while this process compiles the other
    share (:func:`divide`) before the block runs; the helper is stopped after the block."""
    helper = start_helper()
    try:
        if helper is not None:
            with contextlib.suppress(Exception):  # a list older than the code: the frame compiles what it needs
                compile_in_order(divide(first_frame_kernels())[1])
        yield helper
    finally:
        stop_helper(helper)


def main(argv: list[str]) -> int:
    if argv == ["--record"]:
        os.environ["SCANLAB_KERNEL_CACHE"] = tempfile.mkdtemp()  # empty: every kernel is compiled, and seen
        kernels = record()
        print(f"wrote {KERNELS_FILE}: {len(kernels)} kernels")
        return 0
    with fewer_collections():  # compiling makes objects that live on (lab.collector)
        compile_in_order(helper_order(first_frame_kernels()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
