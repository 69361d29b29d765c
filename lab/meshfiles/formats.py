"""The mesh file formats scanlab reads: each suffix, its VTK reader and its checks.

The readers are VTK's own; a format's ``check`` (if any) guards what that reader gets
wrong without saying so (:mod:`~lab.meshfiles.obj_checks`, :mod:`~lab.meshfiles.ply_checks`,
:mod:`~lab.meshfiles.stl_checks`). These are the surface formats PyVista reads as one
polygon mesh (``pyvista.read``); glTF, 3DS and VRML (scenes of several parts) are not read.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from lab.meshfiles import obj_checks, ply_checks, stl_checks


@dataclass(frozen=True)
class MeshFormat:
    """A file format: its name, VTK's reader (``module.Class`` under ``vtkmodules``) and,
    if VTK's reader needs guarding, ``check(data)``: it raises ValueError for a file VTK
    would misread and may return a second check, run on what VTK read."""

    suffix: str
    name: str
    reader: str
    check: Callable | None = None


FORMATS = {f.suffix: f for f in (
    MeshFormat(".ply", "PLY (Stanford polygon file, ASCII or binary)", "vtkIOPLY.vtkPLYReader", ply_checks.check),
    MeshFormat(".obj", "Wavefront OBJ", "vtkIOGeometry.vtkOBJReader", obj_checks.check),
    MeshFormat(".stl", "STL (ASCII or binary)", "vtkIOGeometry.vtkSTLReader", stl_checks.check),
    MeshFormat(".vtk", "legacy VTK, DATASET POLYDATA (ASCII or binary)", "vtkIOLegacy.vtkPolyDataReader"),
    MeshFormat(".vtp", "VTK XML PolyData", "vtkIOXML.vtkXMLPolyDataReader"),
    MeshFormat(".g", "Movie.BYU geometry", "vtkIOGeometry.vtkBYUReader"),
    MeshFormat(".facet", "facet (VTK's facet format)", "vtkFiltersHybrid.vtkFacetReader"),
    MeshFormat(".tri", "binary marching cubes triangles", "vtkIOGeometry.vtkMCubesReader"),
)}
"""Every format read, by suffix (matched in any case)."""


def format_of(path) -> MeshFormat | None:
    """The format ``path``'s suffix names (any case), or None."""
    return FORMATS.get(Path(path).suffix.lower())
