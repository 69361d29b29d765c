"""Frame time of scanlab's renderer and of VTK for the same scene, in one process.

Not a test: a command (``scanlab bench``). Each side is warmed up (numba kernels loaded,
VTK's shaders compiled, buffers allocated) and then timed ``repeat`` frames in a block of
its own; the medians are reported with the ratio VTK / scanlab (> 1 means scanlab is
faster). Blocks, not alternation: numba's worker threads spin for a while after each
parallel kernel and would steal llvmpipe's cores (VTK measured ~40 % slower when the
frames alternate), so a pause separates the blocks. VTK's frame is one ``Render()`` plus the read-back of colour and depth (what a
frame costs when its pixels are wanted in memory); scanlab's is one ``render(scene)``.
"""
from __future__ import annotations

import statistics
import time

from compare.reference import build_plotter, read_frame

WARM_UP = 5
PAUSE_S = 1.0  # lets numba's spinning worker threads go to sleep before VTK's block


def bench(scene, repeat: int = 30) -> dict:
    """Median frame times in ms, both renderers, and the ratio; see the module docstring."""
    from renderer import render

    def ours():
        render(scene)

    pl = build_plotter(scene)

    def vtk():
        pl.ren_win.Render()
        read_frame(pl)

    times = {}
    try:
        for frame in (ours, vtk):
            for _ in range(WARM_UP):
                frame()
            times[frame] = []
            for _ in range(repeat):
                t0 = time.perf_counter()
                frame()
                times[frame].append((time.perf_counter() - t0) * 1e3)
            time.sleep(PAUSE_S)
    finally:
        pl.close()
    o, v = statistics.median(times[ours]), statistics.median(times[vtk])
    return {"scene": scene.source, "size": list(scene.image.size),
            "triangles": int(sum(ob.mesh.n_triangles for ob in scene.objects)), "repeat": repeat,
            "ours_ms": o, "vtk_ms": v, "vtk_over_ours": v / o}
