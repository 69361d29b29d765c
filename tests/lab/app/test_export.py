"""Export writes the exact triangles and normals both renderers draw, in formats VTK reads too."""
from __future__ import annotations

import numpy as np
import pytest

from lab.app.cli import main
from lab.loading import load_scene
from lab.meshfiles import MeshFileError, read_mesh, write_mesh


@pytest.mark.parametrize("suffix", [".ply", ".obj", ".vtp", ".stl"])
def test_round_trip_is_exact(suffix, tmp_path):
    """Our reader (VTK's) gets back the very points, triangles and normals we wrote, at the
    precision VTK's reader keeps: float32 for STL (the format's) and for PLY (vtkPLYReader
    reads doubles into float32), doubles for OBJ points and VTP; OBJ ``vn`` as float32."""
    mesh = load_scene("torus-mesh").world_mesh()
    path = tmp_path / f"t{suffix}"
    write_mesh(mesh, path)
    back = read_mesh(path)
    if suffix == ".stl":
        np.testing.assert_array_equal(back.points[back.triangles], mesh.points[mesh.triangles].astype(np.float32))
        assert back.point_normals is None
        return
    single = suffix == ".ply"
    np.testing.assert_array_equal(back.points, mesh.points.astype(np.float32) if single else mesh.points)
    np.testing.assert_array_equal(back.triangles, mesh.triangles)
    np.testing.assert_allclose(back.point_normals, mesh.point_normals, atol=1e-7 if suffix in (".ply", ".obj") else 1e-15)


@pytest.mark.parametrize("suffix", [".ply", ".obj", ".vtp", ".stl"])
def test_vtk_reads_the_export(suffix, tmp_path):
    """VTK (pyvista.read) sees the same triangles in every exported format."""
    pv = pytest.importorskip("pyvista")
    mesh = load_scene("directional-cubes").world_mesh()
    path = tmp_path / f"c{suffix}"
    write_mesh(mesh, path)
    v = pv.read(path)
    assert v.n_cells == mesh.n_triangles
    faces = v.faces.reshape(-1, 4)[:, 1:]
    np.testing.assert_allclose(v.points[faces], mesh.points[mesh.triangles], atol=1e-6)


def test_export_command_and_unknown_suffix(tmp_path, capsys):
    """scanlab export writes the file and says so; an unknown suffix is a one-line error, status 2."""
    assert main(["export", "icosphere:level=2", "-o", str(tmp_path / "s.ply")]) == 0
    assert "320 triangles" in capsys.readouterr().out
    assert main(["export", "cube", "-o", str(tmp_path / "s.xyz")]) == 2
    assert not (tmp_path / "s.xyz").exists()
    with pytest.raises(MeshFileError):
        write_mesh(load_scene("cube").world_mesh(), tmp_path / "x.3ds")


def test_info_reports_area_volume_and_closedness(capsys):
    """scanlab info of the unit cube: 8 points, 12 triangles, area 6, volume 1, closed."""
    assert main(["info", "cube"]) == 0
    out = capsys.readouterr().out
    assert "8 points, 12 triangles" in out and "area 6," in out and "volume 1," in out and "oriented: yes" in out


def test_menger_level_4_builds_and_exports_in_under_10_s(tmp_path):
    """menger:level=4 (160,000 cubes): load and write binary PLY in under 10 s, and read back the same count."""
    import time

    t0 = time.perf_counter()
    assert main(["export", "menger:level=4", "-o", str(tmp_path / "m4.ply")]) == 0
    elapsed = time.perf_counter() - t0
    print(f"menger level 4 build + export: {elapsed:.2f} s")
    assert elapsed < 10.0
    back = read_mesh(tmp_path / "m4.ply")
    assert back.n_triangles == load_scene("menger:level=4").objects[0].mesh.n_triangles
