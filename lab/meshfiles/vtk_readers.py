"""The file-reading door: VTK's own readers turn a surface file into arrays.

This is the only ground-floor module that imports VTK (``vtkmodules``), and it imports it
only inside its functions, when a mesh file is actually read: a scene of built-in shapes
never loads VTK. It hands back what the reader produced, untouched, as numpy
arrays (:class:`SurfaceArrays`); :mod:`lab.meshfiles.read` triangulates and checks them.

Everything VTK says while reading (errors and warnings of the reader, of its pipeline and
of helper objects such as the XML parser) is captured instead of printed, and any of it
makes the read fail with :class:`VTKReaderError`, whose message is one line
(:func:`lab.meshfiles.messages.one_line`): a file VTK warns about is not drawn as VTK half
read it.
"""
from __future__ import annotations

import contextlib
import importlib
from dataclasses import dataclass

import numpy as np

from lab.meshfiles.messages import one_line


class VTKReaderError(ValueError):
    """VTK's reader failed or complained; the message is one line, without the path."""


@dataclass(frozen=True)
class SurfaceArrays:
    """What a VTK reader produced, as numpy arrays, at the precision VTK kept.

    ``polys`` and ``strips`` are VTK cell arrays ``(offsets, connectivity)``: cell i is
    ``connectivity[offsets[i]:offsets[i + 1]]``. ``normals`` and ``tcoords`` are the
    output's *active* point normals and texture coordinates (the ones VTK's mapper draws
    with), or None; ``tcoords`` may have 1, 2 or 3 components. ``n_verts`` and
    ``n_lines`` count the vertex and line cells, which scanlab does not draw.
    """

    points: np.ndarray
    polys: tuple[np.ndarray, np.ndarray]
    strips: tuple[np.ndarray, np.ndarray]
    normals: np.ndarray | None
    tcoords: np.ndarray | None
    n_verts: int
    n_lines: int


def _numpy(array) -> np.ndarray | None:
    from vtkmodules.util.numpy_support import vtk_to_numpy

    if array is None:
        return None
    values = vtk_to_numpy(array)
    return values.reshape(len(values), -1) if values.ndim == 1 and array.GetNumberOfComponents() > 1 else values


def _cells(cell_array) -> tuple[np.ndarray, np.ndarray]:
    """(offsets, connectivity) of a vtkCellArray, as int64 arrays."""
    if not (cell_array.IsStorage64Bit() or cell_array.IsStorage32Bit()):
        cell_array.ConvertTo64BitStorage()
    return (np.asarray(_numpy(cell_array.GetOffsetsArray()), dtype=np.int64),
            np.asarray(_numpy(cell_array.GetConnectivityArray()), dtype=np.int64))


@contextlib.contextmanager
def _captured(*objects):
    """Collect what VTK says while the block runs: the objects' error and warning events,
    and whatever else reaches VTK's output window (kept off stderr meanwhile)."""
    from vtkmodules.vtkCommonCore import vtkCommand, vtkLogger, vtkOutputWindow, vtkStringOutputWindow

    reports: list[str] = []

    def observe(_obj, _event, text=None):
        reports.append(str(text or ""))

    observe.CallDataType = 13  # VTK_STRING: the observer receives the message text
    for obj in objects:
        obj.AddObserver(vtkCommand.ErrorEvent, observe)
        obj.AddObserver(vtkCommand.WarningEvent, observe)
    window, previous = vtkStringOutputWindow(), vtkOutputWindow.GetInstance()
    verbosity = vtkLogger.GetCurrentVerbosityCutoff()
    vtkOutputWindow.SetInstance(window)
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    try:
        yield reports
    finally:
        vtkLogger.SetStderrVerbosity(verbosity)
        vtkOutputWindow.SetInstance(previous)
        reports.extend(t for t in window.GetOutput().split("\n\n") if t.strip())


def _new_reader(reader: str, path):
    """An instance of VTK's reader class ``reader`` (``"module.Class"`` under ``vtkmodules``)
    set to read ``path``."""
    module, name = reader.rsplit(".", 1)
    vtk_reader = getattr(importlib.import_module(f"vtkmodules.{module}"), name)()
    setter = getattr(vtk_reader, "SetGeometryFileName", None) or vtk_reader.SetFileName  # BYU names it so
    setter(str(path))
    return vtk_reader


def read_surface(path, reader: str) -> SurfaceArrays:
    """Read ``path`` with the VTK reader class ``reader`` and return its output's arrays.

    Parameters
    ----------
    path : str or os.PathLike, the file (VTK's reader opens it itself).
    reader : ``"module.Class"`` under ``vtkmodules``, e.g. ``"vtkIOPLY.vtkPLYReader"``.

    Raises
    ------
    VTKReaderError
        The reader failed, reported an error or a warning, or produced no polygon data.
    """
    vtk_reader = _new_reader(reader, path)
    with _captured(vtk_reader, vtk_reader.GetExecutive()) as reports:
        ok = vtk_reader.GetExecutive().Update()
    message = one_line(reports)
    if message or not ok:
        raise VTKReaderError(message or "VTK's reader failed without saying why")
    output = vtk_reader.GetOutputDataObject(0)
    if output is None or not output.IsA("vtkPolyData"):
        raise VTKReaderError("the file holds no polygon data")
    points = output.GetPoints()
    point_data = output.GetPointData()
    return SurfaceArrays(
        points=np.zeros((0, 3)) if points is None else _numpy(points.GetData()).reshape(-1, 3),
        polys=_cells(output.GetPolys()), strips=_cells(output.GetStrips()),
        normals=_numpy(point_data.GetNormals()), tcoords=_numpy(point_data.GetTCoords()),
        n_verts=output.GetNumberOfVerts(), n_lines=output.GetNumberOfLines())


def vtk_read_time(path, reader: str) -> float:
    """Seconds VTK's reader alone takes to read ``path`` (``Update`` of a reader set to the
    file), for the load-time benchmark against :func:`lab.meshfiles.read_mesh`."""
    import time

    vtk_reader = _new_reader(reader, path)
    start = time.perf_counter()
    vtk_reader.Update()
    return time.perf_counter() - start
