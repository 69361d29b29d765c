"""Helpers for the mesh-file tests: writing with VTK's writers, and VTK's cells as triangles."""
from __future__ import annotations

import numpy as np

from lab.mesh import fan_triangles, strip_triangles


def vtk_write(writer, mesh, path, **setters):
    """Write ``mesh`` with a VTK writer, calling ``writer.Name(value)`` for each setter (no
    argument when the value is None)."""
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    for name, value in setters.items():
        getattr(writer, name)(*([] if value is None else [value]))
    assert writer.Write() == 1


def vtk_triangles(poly) -> np.ndarray:
    """VTK's polygons fanned and strips cut as VTK's mapper draws them (lab.mesh's functions,
    held to VTK renders in tests/compare/test_parity_mesh_files.py), polygons first."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    def cells(c):
        return vtk_to_numpy(c.GetOffsetsArray()), vtk_to_numpy(c.GetConnectivityArray())

    return np.concatenate([fan_triangles(*cells(poly.GetPolys())), strip_triangles(*cells(poly.GetStrips()))])
