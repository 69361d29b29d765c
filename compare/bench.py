"""Frame time, peak memory and start-up of scanlab's renderer against VTK's (``scanlab bench``).

Not a test: a command. What is measured, and how:

- **Frame time.** Both renderers hold the same scene in one process. After a warm-up
  (numba kernels loaded, VTK's shaders compiled, buffers allocated), frames alternate in
  pairs, ours first in even pairs and VTK first in odd ones, so that a load change on the
  machine hits both alike. A frame is scene-ready to uint8 image in memory: for VTK one
  ``Render()`` and the read-back of colour and depth (:func:`compare.reference.read_frame`);
  for ours everything :func:`renderer.render` does (nothing that depends on the camera is
  kept from one frame to the next). Reported: median, min and max of each, the median
  of the per-pair ratios ours/VTK (< 1: ours is faster), and how many of our frames used
  fewer threads than asked because another process kept a core busy
  (:mod:`renderer.free_cores`).
- **Peak memory** (:func:`peak_memory`). Each renderer draws the scene in a child process
  of its own: it first warms up on a tiny scene (kernels loaded; VTK's OpenGL context and
  shaders made), then loads the scene, hands the free memory of its heap back to the system
  (``malloc_trim``: our renderer keeps freed memory for the next frame,
  :mod:`renderer.workspace`, and loading the scene freed some), notes its resident set (the
  baseline: interpreter, libraries and the scene's own arrays), resets the kernel's high-water mark
  (``/proc/self/clear_refs``) and draws two frames — for VTK building the plotter (its
  polydata and GPU buffers), rendering and reading back. Reported: the high-water mark
  minus the baseline, the memory drawing the scene took, in MiB.
- **Start-up** (:func:`startup_seconds`). The wall time of a fresh ``scanlab render
  icosphere:level=5`` process, to its PNG, with an empty kernel cache (cold: every kernel
  is compiled) and then again with the cache that run filled (warm).
- **Contention** (:func:`thread_contention`). With another process spinning on one core
  (:func:`busy_core`), our frames alternate between one numba thread and two, in one
  process; reported: the median of the per-pair ratios 2 threads / 1 thread (> 1: the
  second thread makes a frame slower when its core is taken).
"""
from __future__ import annotations

import ctypes
import ctypes.util
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from compare.bench_scenes import bench_scene
from compare.reference import build_plotter, read_frame

WARM_UP = 3
TINY = "icosphere:level=1"
STARTUP_SCENE = "icosphere:level=5"


def _summary(times: list[float]) -> dict:
    return {"median": statistics.median(times), "min": min(times), "max": max(times)}


def alternate(first, second, repeat: int, warm_up: int) -> tuple[list[float], list[float], list[float]]:
    """Times (ms) of two frame functions called in pairs, ``first`` first in even pairs and
    ``second`` first in odd ones, after ``warm_up`` untimed pairs; returns both lists of times
    and the per-pair ratios first/second."""
    for _ in range(warm_up):
        first()
        second()
    times: tuple[list[float], list[float]] = ([], [])
    for i in range(repeat):
        pair = [0.0, 0.0]
        for k in ((0, 1) if i % 2 == 0 else (1, 0)):
            t0 = time.perf_counter()
            (first, second)[k]()
            pair[k] = (time.perf_counter() - t0) * 1e3
        times[0].append(pair[0])
        times[1].append(pair[1])
    return times[0], times[1], [a / b for a, b in zip(*times)]


def time_frames(scene, repeat: int = 15, warm_up: int = WARM_UP) -> dict:
    """Frame times (ms) of both renderers on ``scene``, alternating in pairs; see the module
    docstring. Returns ``{"ours": {median, min, max}, "reference": {...}, "ratio": median of
    ours/VTK, "fewer_threads": n}``, n the timed frames of ours that used fewer threads than
    numba was set to, because other processes kept a core busy (:mod:`renderer.free_cores`):
    a frame so drawn is slower for a reason outside the renderer."""
    import numba

    from renderer import render
    from renderer.free_cores import MACHINE

    pl = build_plotter(scene)
    used = []  # threads each of our frames used

    def our_frame():
        render(scene)
        used.append(MACHINE.last_frame)

    def vtk_frame():
        pl.ren_win.Render()
        read_frame(pl)

    try:
        ours, vtk, ratios = alternate(our_frame, vtk_frame, repeat, warm_up)
    finally:
        pl.close()
    asked = numba.get_num_threads()
    fewer = sum(1 for n in used[-repeat:] if n is not None and n < asked)
    return {"ours": _summary(ours), "reference": _summary(vtk), "ratio": statistics.median(ratios),
            "fewer_threads": fewer}


def thread_contention(scene, repeat: int = 15, warm_up: int = WARM_UP) -> dict:
    """Our frame time (ms) with one numba thread and with two, alternating in pairs (two
    threads first in even pairs), the median ratio two/one, numba's threading layer and how
    many of the frames set to two threads used one (the renderer fits its threads to the
    free cores, :mod:`renderer.free_cores`; the machine's load is read afresh first).
    Run it with :func:`busy_core` holding a core to see contention."""
    import numba

    from renderer import render
    from renderer.free_cores import MACHINE, SAMPLE_SECONDS

    used = []  # threads the frames set to two really used (renderer.free_cores), timed frames only

    def with_threads(n):
        def frame():
            numba.set_num_threads(min(n, numba.config.NUMBA_NUM_THREADS))
            render(scene)
            if n == 2:
                used.append(MACHINE.last_frame)
        return frame

    MACHINE.refresh()  # the machine's load as it is now, not since the frames before the spinner started
    time.sleep(SAMPLE_SECONDS)
    MACHINE.refresh()
    saved = numba.get_num_threads()
    try:
        two, one, ratios = alternate(with_threads(2), with_threads(1), repeat, warm_up)
    finally:
        numba.set_num_threads(saved)
    return {"one_thread": _summary(one), "two_threads": _summary(two), "ratio": statistics.median(ratios),
            "layer": numba.threading_layer(), "two_used_one": used[-len(two):].count(1)}


class busy_core:
    """A child process spinning on one core for as long as the ``with`` block lasts."""

    def __enter__(self):
        self.child = subprocess.Popen([sys.executable, "-c", "n = 0\nwhile 1: n += 1"])
        time.sleep(0.5)
        return self

    def __exit__(self, *exc):
        self.child.kill()
        self.child.wait()


def _status_kib(field: str) -> int:
    for line in Path("/proc/self/status").read_text().splitlines():
        if line.startswith(field + ":"):
            return int(line.split()[1])
    raise RuntimeError(f"no {field} in /proc/self/status")


def _give_back_free_memory() -> None:
    """glibc's ``malloc_trim(0)``: free heap memory back to the system, so that the resident
    set counts live memory only (nothing where the C library is not glibc)."""
    try:
        ctypes.CDLL(ctypes.util.find_library("c")).malloc_trim(0)
    except (OSError, AttributeError, TypeError):
        pass


def _measure_in_this_process(side: str, name: str, size) -> dict:
    """The child's side of :func:`peak_memory`: baseline and high-water mark, in KiB."""
    import gc

    if side == "ours":
        from renderer import render

        def draw(scene):
            render(scene)
            render(scene)
    else:
        def draw(scene):
            pl = build_plotter(scene)
            for _ in range(2):
                pl.ren_win.Render()
                read_frame(pl)
            pl.close()
    draw(bench_scene(TINY, (64, 64)))
    scene = bench_scene(name, size)
    gc.collect()
    _give_back_free_memory()
    baseline = _status_kib("VmRSS")
    refs = os.open("/proc/self/clear_refs", os.O_WRONLY)  # "5": the high-water mark starts again from here
    os.write(refs, b"5")
    os.close(refs)
    draw(scene)
    return {"baseline_kib": baseline, "peak_kib": _status_kib("VmHWM")}


def peak_memory(side: str, name: str, size) -> float:
    """MiB that drawing scene ``name`` at ``size`` took in a fresh process, ``side`` "ours"
    or "reference" (see the module docstring)."""
    done = subprocess.run([sys.executable, "-m", "compare.bench", "memory", side, name, f"{size[0]}x{size[1]}"],
                          capture_output=True, text=True, timeout=1800)
    if done.returncode != 0:
        raise RuntimeError(f"memory child failed: {done.stderr.strip().splitlines()[-1:]}")
    m = json.loads(done.stdout.strip().splitlines()[-1])
    return (m["peak_kib"] - m["baseline_kib"]) / 1024.0


def startup_seconds() -> dict:
    """Seconds from a fresh ``scanlab render icosphere:level=5`` process to its PNG, with the
    kernel cache cold and then warm (``SCANLAB_KERNEL_CACHE`` set to an empty folder)."""
    result = {}
    with tempfile.TemporaryDirectory() as tmp:
        env = {**os.environ, "SCANLAB_KERNEL_CACHE": str(Path(tmp) / "kernels")}
        for state in ("cold", "warm"):
            t0 = time.perf_counter()
            subprocess.run([sys.executable, "-m", "lab", "render", STARTUP_SCENE, "-o", str(Path(tmp) / "out.png")],
                           env=env, check=True, capture_output=True, timeout=1800)
            result[state] = time.perf_counter() - t0
    return result


def markdown_table(rows: list[dict]) -> str:
    """The frame-time rows (and memory where measured) as a Markdown table."""
    lines = ["| scene | size | triangles | ours ms (min–max) | VTK ms (min–max) | ours/VTK | memory ours / VTK MiB |",
             "|---|---|---|---|---|---|---|"]
    for r in rows:
        if "error" in r:
            lines.append(f"| {r['scene']} | {r['size']} | | {r['error']} | | | |")
            continue
        o, v = r["ours"], r["reference"]
        mem = f"{r['memory']['ours']:.0f} / {r['memory']['reference']:.0f}" if "memory" in r else ""
        lines.append(f"| {r['scene']} | {r['size']} | {r['triangles']:,} | {o['median']:.1f} ({o['min']:.1f}–"
                     f"{o['max']:.1f}) | {v['median']:.1f} ({v['min']:.1f}–{v['max']:.1f}) | {r['ratio']:.2f} | {mem} |")
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    """``python -m compare.bench memory SIDE NAME WxH``: the child of :func:`peak_memory`."""
    if len(argv) == 4 and argv[0] == "memory":
        w, h = (int(v) for v in argv[3].split("x"))
        print(json.dumps(_measure_in_this_process(argv[1], argv[2], (w, h))))
        return 0
    print("usage: python -m compare.bench memory ours|reference SCENE WxH (use `scanlab bench` instead)", file=sys.stderr)
    return 2


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
