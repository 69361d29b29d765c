"""Load time of mesh files: scanlab's reading against VTK's reader alone, in one process.

    python -m lab.app.meshbench --make DIR     # write 1.3 M-triangle test files into DIR
    python -m lab.app.meshbench FILE ...       # time them

The files (an icosphere of level 8, 1,310,720 triangles, with radial normals and a UV
seam; written here with numpy, not kept in the project): OBJ with ``v``, ``vt`` and ``vn``
numbered apart (every face corner then becomes a point in VTK's reader), OBJ ``f a//a``,
binary and ASCII PLY with normals, binary and ASCII STL.

For each file, interleaved: VTK's reader alone (``SetFileName`` and ``Update``, through
:func:`lab.meshfiles.vtk_readers.vtk_read_time`) and :func:`lab.meshfiles.read_mesh` (the
checks, VTK's reader, triangulation and validation); the best of ``--runs`` of each, as
wall time and as CPU time of this process. The ratio ours / VTK is the figure to judge.
"""
from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from lab import shapes
from lab.atomic import atomic_file
from lab.meshfiles import read_mesh
from lab.meshfiles.formats import format_of
from lab.meshfiles.vtk_readers import vtk_read_time


def _rows(fmt: str, *columns) -> bytes:
    """One line ``fmt % row`` per row of the columns side by side."""
    table = np.column_stack(columns)
    return (((fmt + "\n") * len(table)) % tuple(table.ravel().tolist())).encode()


def make_files(folder: Path, level: int = 8) -> list[Path]:
    """Write the benchmark files into ``folder``; return their paths."""
    folder.mkdir(parents=True, exist_ok=True)
    plain, seamed = shapes.icosphere(level), shapes.icosphere(level, uv=1)
    v = plain.points
    # the seamed sphere's points are the plain one's, then copies along the seam: a copy's
    # v line is its original's (the first point at the same place)
    _, first, inverse = np.unique(seamed.points, axis=0, return_index=True, return_inverse=True)
    v_of = first[inverse.ravel()][seamed.triangles]
    assert v_of.max() < len(v)
    vn_order = np.random.default_rng(1).permutation(len(v))  # vn lines in another order than v
    vn_of = np.argsort(vn_order)[v_of]
    t_of = seamed.triangles
    paths = []

    def write(name, data):
        paths.append(folder / name)
        with atomic_file(paths[-1]) as f:
            f.write(data)

    head = _rows("v %.9f %.9f %.9f", v) + _rows("vt %.9f %.9f", seamed.tcoords) + _rows("vn %.9f %.9f %.9f", v[vn_order])
    corners = np.stack([v_of + 1, t_of + 1, vn_of + 1], axis=-1).reshape(len(t_of), 9)
    write("sphere-split.obj", head + _rows("f %d/%d/%d %d/%d/%d %d/%d/%d", corners))
    same = np.repeat(plain.triangles + 1, 2, axis=1)
    write("sphere-same.obj", _rows("v %.9f %.9f %.9f", v) + _rows("vn %.9f %.9f %.9f", v)
          + _rows("f %d//%d %d//%d %d//%d", same))
    header = (f"ply\nformat {{}} 1.0\nelement vertex {len(v)}\nproperty float x\nproperty float y\nproperty float z\n"
              "property float nx\nproperty float ny\nproperty float nz\n"
              f"element face {plain.n_triangles}\nproperty list uchar int vertex_indices\nend_header\n")
    faces = np.zeros(plain.n_triangles, dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"], faces["v"] = 3, plain.triangles
    write("sphere-binary.ply", header.format("binary_little_endian").encode()
          + np.hstack([v, v]).astype("<f4").tobytes() + faces.tobytes())
    write("sphere-ascii.ply", header.format("ascii").encode() + _rows(" ".join(["%.7g"] * 6), v, v)
          + _rows("3 %d %d %d", plain.triangles))
    p = v[plain.triangles].astype("<f4")
    records = np.zeros(plain.n_triangles, dtype=[("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("a", "<u2")])
    records["v"] = p
    write("sphere-binary.stl", b"scanlab benchmark".ljust(80, b" ") + np.uint32(len(p)).tobytes() + records.tobytes())
    facets = _rows("facet normal 0 0 0\n outer loop\n  vertex %.7g %.7g %.7g\n  vertex %.7g %.7g %.7g\n"
                   "  vertex %.7g %.7g %.7g\n endloop\nendfacet", p.reshape(-1, 9))
    write("sphere-ascii.stl", b"solid scanlab\n" + facets + b"endsolid scanlab\n")
    return paths


def time_file(path: Path, runs: int = 3) -> dict:
    """Best wall and CPU seconds of VTK's reader alone and of ``read_mesh``, interleaved."""
    reader = format_of(path).reader
    best = {"vtk_wall": np.inf, "vtk_cpu": np.inf, "ours_wall": np.inf, "ours_cpu": np.inf}
    for _ in range(runs):
        cpu = time.process_time()
        best["vtk_wall"] = min(best["vtk_wall"], vtk_read_time(path, reader))
        best["vtk_cpu"] = min(best["vtk_cpu"], time.process_time() - cpu)
        wall, cpu = time.perf_counter(), time.process_time()
        mesh = read_mesh(path)
        best["ours_wall"] = min(best["ours_wall"], time.perf_counter() - wall)
        best["ours_cpu"] = min(best["ours_cpu"], time.process_time() - cpu)
    best["triangles"], best["points"] = mesh.n_triangles, mesh.n_points
    return best


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python -m lab.app.meshbench", description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="*", type=Path, help="mesh files to time")
    parser.add_argument("--make", type=Path, metavar="DIR", help="write the benchmark files into DIR first")
    parser.add_argument("--runs", type=int, default=3, help="runs of each reader per file (best is kept)")
    args = parser.parse_args(argv)
    files = list(args.files)
    if args.make:
        files += make_files(args.make)
        print(f"wrote {len(files)} files to {args.make}")
    print(f"{'file':24s} {'MB':>6s} {'triangles':>10s} {'VTK s':>7s} {'ours s':>7s} {'ratio':>6s}  "
          f"{'VTK cpu':>7s} {'ours cpu':>8s} {'ratio':>6s}")
    for path in files:
        t = time_file(path, args.runs)
        print(f"{path.name:24s} {path.stat().st_size / 1e6:6.1f} {t['triangles']:10d} {t['vtk_wall']:7.3f} "
              f"{t['ours_wall']:7.3f} {t['ours_wall'] / t['vtk_wall']:6.2f}  {t['vtk_cpu']:7.3f} {t['ours_cpu']:8.3f} "
              f"{t['ours_cpu'] / t['vtk_cpu']:6.2f}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
