"""Specification of ``lab.meshfiles.vtk_readers``, the ground floor's door to VTK's readers."""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import pyvista as pv

from lab.meshfiles.vtk_readers import SurfaceArrays, VTKReaderError, read_surface, vtk_read_time

ROOT = Path(__file__).resolve().parents[3]


def test_importing_the_door_loads_no_vtk():
    """VTK is imported only when a file is read."""
    code = ("import sys, json, lab.meshfiles, lab.meshfiles.vtk_readers; "
            "print(json.dumps(sorted(m for m in sys.modules if m.startswith(('vtk', 'pyvista')))))")
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert json.loads(done.stdout) == []


def test_arrays_are_vtks_output(tmp_path):
    mesh = pv.Sphere(theta_resolution=8, phi_resolution=6).strip()
    mesh.save(tmp_path / "s.vtp")
    got = read_surface(tmp_path / "s.vtp", "vtkIOXML.vtkXMLPolyDataReader")
    assert isinstance(got, SurfaceArrays)
    ref = pv.read(tmp_path / "s.vtp")
    np.testing.assert_array_equal(got.points, ref.points)
    np.testing.assert_array_equal(got.normals, ref.point_data["Normals"])
    assert len(got.strips[0]) == ref.n_strips + 1 and len(got.polys[1]) == 0
    assert got.tcoords is None and got.n_verts == 0 and got.n_lines == 0


def test_errors_are_captured_not_printed(tmp_path, capfd):
    """Errors of the reader, of the pipeline and of helper objects (the XML parser, which
    writes to VTK's output window) become one exception; nothing reaches stdout or stderr."""
    (tmp_path / "bad.vtp").write_text("hello")
    with pytest.raises(VTKReaderError) as info:
        read_surface(tmp_path / "bad.vtp", "vtkIOXML.vtkXMLPolyDataReader")
    assert str(info.value) == "not valid VTK XML"
    assert capfd.readouterr() == ("", "")


def test_a_warning_is_an_error(tmp_path):
    (tmp_path / "w.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1 7\nf 1//1 2//1 3//1\n")
    with pytest.raises(VTKReaderError, match="line 4: unexpected data at end of line"):
        read_surface(tmp_path / "w.obj", "vtkIOGeometry.vtkOBJReader")


def test_output_window_is_restored(tmp_path):
    from vtkmodules.vtkCommonCore import vtkOutputWindow

    before = vtkOutputWindow.GetInstance()
    (tmp_path / "bad.vtp").write_text("hello")
    with pytest.raises(VTKReaderError):
        read_surface(tmp_path / "bad.vtp", "vtkIOXML.vtkXMLPolyDataReader")
    assert vtkOutputWindow.GetInstance() is before


def test_vtk_read_time(tmp_path):
    pv.Sphere().save(tmp_path / "s.ply")
    assert 0 < vtk_read_time(tmp_path / "s.ply", "vtkIOPLY.vtkPLYReader") < 10


def test_the_door_is_the_only_ground_floor_module_that_imports_vtk():
    """An AST scan of lab/ (the application lab/app aside): vtk, vtkmodules and pyvista are
    imported in lab/meshfiles/vtk_readers.py only."""
    import ast

    found = set()
    for path in sorted((ROOT / "lab").rglob("*.py")):
        if "app" in path.relative_to(ROOT / "lab").parts:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else []
            names += [node.module] if isinstance(node, ast.ImportFrom) and node.module else []
            if any(n.split(".")[0] in ("vtk", "vtkmodules", "pyvista") for n in names):
                found.add(path.relative_to(ROOT).as_posix())
    assert found == {"lab/meshfiles/vtk_readers.py"}
