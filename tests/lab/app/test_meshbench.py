"""The mesh-file load benchmark: its files are the same surface in every format, and it times both readers."""
from __future__ import annotations

import numpy as np

from lab.app.meshbench import main, make_files, time_file
from lab.meshfiles import read_mesh


def test_files_hold_the_same_sphere(tmp_path):
    paths = make_files(tmp_path, level=2)
    assert sorted(p.suffix for p in paths) == [".obj", ".obj", ".ply", ".ply", ".stl", ".stl"]
    meshes = {p.name: read_mesh(p) for p in paths}
    for name, mesh in meshes.items():
        assert mesh.n_triangles == 320, name
        corners = mesh.points[mesh.triangles]
        np.testing.assert_allclose(np.linalg.norm(corners, axis=-1), 1.0, atol=1e-6, err_msg=name)
    split, same = meshes["sphere-split.obj"], meshes["sphere-same.obj"]
    assert split.n_points == 3 * 320 and split.tcoords is not None  # every corner its own point in VTK's reader
    assert same.n_points == 162 and same.point_normals is not None


def test_timing_and_command(tmp_path, capsys):
    path = make_files(tmp_path, level=1)[0]
    t = time_file(path, runs=1)
    assert t["vtk_wall"] > 0 and t["ours_wall"] > 0 and t["triangles"] == 80
    assert main([str(path), "--runs", "1"]) == 0
    assert "sphere-split.obj" in capsys.readouterr().out
