"""The raster exercise's test meshes and its pixel classifier.

Hundreds of window-space triangles in small meshes, made the same way every time
(seeded): fans around a shared point, grids and Delaunay triangulations whose shared
edges run through pixel centres, a clockwise copy, tiny and huge triangles, zero-area
ones, and one mesh whose corners lie off the 1/256 grid (where snapping matters). The
triangles of one mesh never overlap, so under the right rule every pixel is drawn at
most once, and a pixel drawn by two triangles of a mesh is a *duplicate*.

:func:`classify` sorts every pixel of a mesh: correct, missing, duplicated, unexpected.
:func:`edge_function_masks` is a slow numpy reference of the tie rules, in fixed point:
the top-left rule (equal to :func:`renderer.coverage.triangle_coverage`, which the tests
check) and the mistaken ones the diagnoses name.

Window coordinates: pixels, y up, pixel (x, y) centred at (x + 0.5, y + 0.5);
masks are indexed ``mask[y, x]`` (row 0 at the bottom).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

SUBPIXEL = 256


@dataclass(frozen=True)
class RasterMesh:
    """Triangles (K, 3, 2) in window coordinates, in a ``width`` × ``height`` window.
    ``on_grid``: every corner is a multiple of 1/256 pixel (snapping changes nothing)."""

    name: str
    name_ja: str
    width: int
    height: int
    triangles: np.ndarray
    on_grid: bool = True


def _fan(centre, radius, count, step, phase=0.0):
    angles = phase + 2 * np.pi * np.arange(count) / count
    rim = np.round((np.asarray(centre) + radius * np.column_stack([np.cos(angles), np.sin(angles)])) / step) * step
    return np.array([[centre, rim[k], rim[(k + 1) % count]] for k in range(count)])


def _grid(x0, y0, nx, ny, step):
    tris = []
    for i in range(nx):
        for j in range(ny):
            a, b = (x0 + i * step, y0 + j * step), (x0 + (i + 1) * step, y0 + j * step)
            c, d = (x0 + (i + 1) * step, y0 + (j + 1) * step), (x0 + i * step, y0 + (j + 1) * step)
            tris += [[a, b, c], [a, c, d]] if (i + j) % 2 else [[a, b, d], [b, c, d]]
    return np.array(tris, dtype=np.float64)


def _delaunay(points):
    from scipy.spatial import Delaunay

    tris = points[Delaunay(points).simplices]
    area = (tris[:, 1, 0] - tris[:, 0, 0]) * (tris[:, 2, 1] - tris[:, 0, 1]) - \
        (tris[:, 2, 0] - tris[:, 0, 0]) * (tris[:, 1, 1] - tris[:, 0, 1])
    tris[area < 0] = tris[area < 0][:, [0, 2, 1]]  # counter-clockwise
    return tris


def _tiny(rng, cells_x, cells_y):
    tris = []
    for i in range(cells_x):
        for j in range(cells_y):
            base = np.array([3 * i + 1.5, 3 * j + 1.5])
            corners = base + np.round(rng.uniform(-0.8, 0.8, (3, 2)) * 4) / 4
            if (i + j) % 3 == 0:
                corners[0] = base + 0.0  # a corner on a pixel centre
            tris.append(corners)
    tris = np.array(tris)
    area = (tris[:, 1, 0] - tris[:, 0, 0]) * (tris[:, 2, 1] - tris[:, 0, 1]) - \
        (tris[:, 2, 0] - tris[:, 0, 0]) * (tris[:, 1, 1] - tris[:, 0, 1])
    return tris[area != 0]


def raster_meshes() -> list[RasterMesh]:
    """The exercise's meshes (about 400 triangles), the same on every call."""
    rng = np.random.default_rng(14)
    half = np.round(rng.uniform(0, 1, (30, 2)) * [48, 40]) / 2
    frame = np.array([[0.5, 0.5], [23.5, 0.5], [23.5, 19.5], [0.5, 19.5]])
    fine = np.round(rng.uniform(0.25, 0.75, (28, 2)) * [24, 20] * SUBPIXEL) / SUBPIXEL
    off = rng.uniform(0.5, 23.5, (30, 2)) * [1.0, 19.0 / 23.0] + rng.uniform(1e-4, 1e-3, (30, 2))
    grid = _grid(0.5, 0.5, 7, 6, 3.0)
    huge = np.array([[[-2999.5, -2999.5], [3000.5, -2999.5], [3000.5, 3000.5]],
                     [[-2999.5, -2999.5], [3000.5, 3000.5], [-2999.5, 3000.5]]])
    sliver = _fan((2.5, 10.5), 21.0, 40, 0.5, phase=-0.45)[:11]
    flat = np.array([[[1.5, 1.5], [5.5, 5.5], [9.5, 9.5]], [[2.0, 7.5], [12.0, 7.5], [20.0, 7.5]],
                     [[3.5, 3.5], [3.5, 3.5], [8.25, 2.0]], [[15.5, 2.5], [15.5, 9.5], [15.5, 18.5]]])
    return [
        RasterMesh("fan around a pixel centre", "画素中心まわりの扇", 24, 20, _fan((12.5, 10.5), 8.0, 12, 0.5)),
        RasterMesh("fan around a pixel corner", "画素の角まわりの扇", 24, 20, _fan((12.0, 10.0), 7.5, 7, 0.25, 0.3)),
        RasterMesh("grid through pixel centres", "画素中心を通る格子", 24, 20, grid),
        RasterMesh("grid, clockwise", "格子（時計回り）", 24, 20, grid[:, [0, 2, 1]]),
        RasterMesh("Delaunay on the half-pixel grid", "半画素格子上のドロネー分割", 24, 20,
                 _delaunay(np.concatenate([frame, half]))),
        RasterMesh("Delaunay on the 1/256 grid", "1/256 格子上のドロネー分割", 24, 20,
                 _delaunay(np.concatenate([frame, fine]))),
        RasterMesh("thin slivers", "細長い三角形", 24, 20, sliver),
        RasterMesh("tiny triangles", "小さな三角形", 24, 21, _tiny(rng, 8, 7)),
        RasterMesh("huge triangles", "巨大な三角形", 24, 20, huge),
        RasterMesh("zero-area triangles", "面積 0 の三角形", 24, 20, flat),
        RasterMesh("corners off the 1/256 grid", "1/256 格子外の頂点", 24, 20,
                 _delaunay(np.concatenate([frame + 1e-3, off])), on_grid=False),
    ]


def to_fixed(window_xy: np.ndarray) -> np.ndarray:
    """Window x, y → int64 fixed point, pixel centre (i, j) at (256·i, 256·j) (round half even)."""
    return np.rint((np.asarray(window_xy, np.float64) - 0.5) * SUBPIXEL).astype(np.int64)


def edge_function_masks(tri_window: np.ndarray, width: int, height: int, rule: str = "top-left",
                        snap: bool = True) -> np.ndarray:
    """(height, width) coverage of one triangle by its three edge functions (slow numpy reference).

    The triangle is made counter-clockwise; E(P) = dx·(Y − ya) − dy·(X − xa) for each edge
    a → b is > 0 inside. ``rule``: "top-left" (a centre with E = 0 counts for a left edge,
    dy < 0, or a bottom edge, dy = 0 and dx > 0), "inclusive" (every E ≥ 0), "exclusive"
    (every E > 0). ``snap`` False evaluates at the corners as given (float), not snapped.
    A triangle of zero area covers nothing.
    """
    if snap:
        v = to_fixed(tri_window).astype(np.float64)
        xs, ys = np.arange(width) * float(SUBPIXEL), np.arange(height) * float(SUBPIXEL)
    else:
        v = np.asarray(tri_window, np.float64)
        xs, ys = np.arange(width) + 0.5, np.arange(height) + 0.5
    area = (v[1, 0] - v[0, 0]) * (v[2, 1] - v[0, 1]) - (v[2, 0] - v[0, 0]) * (v[1, 1] - v[0, 1])
    if area == 0:
        return np.zeros((height, width), bool)
    if area < 0:
        v = v[[0, 2, 1]]
    X, Y = np.meshgrid(xs, ys)
    inside = np.ones((height, width), bool)
    for e in range(3):
        (xa, ya), (xb, yb) = v[e], v[(e + 1) % 3]
        dx, dy = xb - xa, yb - ya
        E = dx * (Y - ya) - dy * (X - xa)
        if rule == "inclusive":
            inside &= E >= 0
        elif rule == "exclusive":
            inside &= E > 0
        else:
            owned = dy < 0 or (dy == 0 and dx > 0)
            inside &= (E > 0) | ((E == 0) & owned)
    return inside


CLASSES = ("correct", "missing", "duplicated", "unexpected")


def classify(reference: np.ndarray, student: np.ndarray) -> dict[str, np.ndarray]:
    """Pixel classes of one mesh from its per-triangle masks (K, H, W), reference and student.

    correct: both draw it once; missing: the reference draws it, the student does not;
    duplicated: two or more of the student's triangles draw it; unexpected: the student
    draws it once where the reference draws nothing.
    """
    ref, stu = reference.sum(axis=0), student.sum(axis=0)
    return {"correct": (ref >= 1) & (stu == 1), "missing": (ref >= 1) & (stu == 0), "duplicated": stu >= 2,
            "unexpected": (ref == 0) & (stu == 1)}
