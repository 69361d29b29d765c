"""Specification of ``lab.meshfiles.formats``: the formats read, each by VTK's reader.

Besides PLY, OBJ, STL, VTK and VTP (tests/lab/meshfiles/test_read.py), the further surface
formats PyVista reads come with VTK's readers: Movie.BYU, facet, binary marching cubes.
"""
from __future__ import annotations

import importlib

import numpy as np
import pytest
import pyvista as pv
import vtk

from lab.meshfiles import read_mesh
from lab.meshfiles.formats import FORMATS, format_of


def test_every_reader_is_a_vtk_class_pyvista_uses():
    from pyvista.core.utilities.reader import CLASS_READERS

    for suffix, fmt in FORMATS.items():
        module, name = fmt.reader.rsplit(".", 1)
        assert hasattr(importlib.import_module(f"vtkmodules.{module}"), name)
        vtk_class = getattr(CLASS_READERS[suffix], "_vtk_class_name", "")
        assert vtk_class in (name, "vtkDataSetReader"), suffix  # pyvista reads .vtk with the generic reader


def test_suffix_in_any_case():
    assert format_of("a/b/M.PlY") is FORMATS[".ply"] and format_of("x.off") is None


WRITERS = {".g": (vtk.vtkBYUWriter, "SetGeometryFileName"), ".facet": (vtk.vtkFacetWriter, "SetFileName"),
           ".tri": (vtk.vtkMCubesWriter, "SetFileName")}


@pytest.mark.parametrize("suffix", list(WRITERS))
def test_further_formats_read_like_vtk(tmp_path, suffix):
    sphere = pv.Sphere(theta_resolution=10, phi_resolution=8)
    writer_class, setter = WRITERS[suffix]
    writer = writer_class()
    writer.SetInputData(sphere)
    getattr(writer, setter)(str(tmp_path / f"s{suffix}"))
    writer.Write()
    mesh, ref = read_mesh(tmp_path / f"s{suffix}"), pv.read(tmp_path / f"s{suffix}")
    np.testing.assert_array_equal(mesh.points, np.asarray(ref.points, dtype=np.float64))
    np.testing.assert_array_equal(mesh.triangles, ref.faces.reshape(-1, 4)[:, 1:])
    assert mesh.n_triangles == sphere.n_cells
