"""Frame time of scanlab's renderer and of VTK for the same scene, in one process.

Not a test: a command (``scanlab bench``). Both sides are warmed up first (numba kernels
loaded, VTK's shaders compiled), then each is timed ``repeat`` times; the median is
reported with the ratio VTK / scanlab (> 1 means scanlab is faster). VTK's time is one
``Render()`` plus the read-back of colour and depth, which is what a frame costs when the
pixels are wanted in memory; scanlab's is one ``render(scene)`` call.
"""
from __future__ import annotations

import statistics
import time

from compare.reference import build_plotter, read_frame


def bench(scene, repeat: int = 20) -> dict:
    """Median frame times in ms, both renderers, and the ratio; see the module docstring."""
    from renderer import render

    render(scene)
    ours = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        render(scene)
        ours.append((time.perf_counter() - t0) * 1e3)
    pl = build_plotter(scene)
    try:
        pl.ren_win.Render()
        read_frame(pl)
        vtk_times = []
        for _ in range(repeat):
            pl.ren_win.Modified()
            t0 = time.perf_counter()
            pl.ren_win.Render()
            read_frame(pl)
            vtk_times.append((time.perf_counter() - t0) * 1e3)
    finally:
        pl.close()
    o, v = statistics.median(ours), statistics.median(vtk_times)
    return {"scene": scene.source, "size": list(scene.image.size),
            "triangles": int(sum(ob.mesh.n_triangles for ob in scene.objects)), "repeat": repeat,
            "ours_ms": o, "vtk_ms": v, "vtk_over_ours": v / o}
