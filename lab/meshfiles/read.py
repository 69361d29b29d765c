"""``read_mesh``: a mesh file, read by VTK's own reader, as the :class:`~lab.mesh.Mesh` both
renderers draw.

The steps, in order (any problem raises :class:`MeshFileError` naming the file):

1. the suffix names the format (:data:`lab.meshfiles.formats.FORMATS`), and the path is a
   regular file (not a folder, device or pipe);
2. the format's check reads the bytes and refuses what VTK's reader would misread or
   crash on (OBJ indices past the end, PLY strips or short binary data, short STL);
3. VTK's reader reads the file (:mod:`lab.meshfiles.vtk_readers`, the only door to VTK on
   the ground floor); anything it reports is an error;
4. polygons become fans and strips become triangles as VTK's mapper draws them
   (:func:`lab.mesh.fan_triangles`, :func:`lab.mesh.strip_triangles`), polygons first;
   vertex and line cells are not drawn; point normals and 2-component texture
   coordinates are kept as VTK's reader gave them (an OBJ point used with several ``vt``
   or ``vn`` is one point per face corner there), except texture coordinates that are all
   −1, vtkOBJReader's fill for an OBJ with a material (``usemtl``) but no ``vt``: none;
5. :func:`lab.meshfiles.validate.make_mesh` checks the result, in one place.
"""
from __future__ import annotations

import mmap
from pathlib import Path

import numpy as np

from lab.mesh import Mesh, fan_triangles, strip_triangles, unfanned_polygons
from lab.meshfiles.formats import FORMATS, format_of
from lab.meshfiles.validate import MeshFileError, make_mesh
from lab.meshfiles.vtk_readers import read_surface
from lab.values import IS_A_FOLDER, file_problem


def read_mesh(path) -> Mesh:
    """Read a mesh file, choosing VTK's reader by the suffix (any case).

    Parameters
    ----------
    path : str or os.PathLike; a suffix of :data:`lab.meshfiles.formats.FORMATS`
        (``.ply .obj .stl .vtk .vtp .g .facet .tri``).

    Returns
    -------
    Mesh

    Raises
    ------
    MeshFileError
        One line, ``"<path>: <what is wrong>"``: unknown suffix, missing or unreadable
        file, anything VTK's reader reports, or anything wrong in what it read.
    """
    problem = file_problem(path)
    if problem == IS_A_FOLDER:  # before the suffix: a folder named "models" has none
        raise MeshFileError(f"{path}: cannot read file: {problem}")
    fmt = format_of(path)
    if fmt is None:
        raise MeshFileError(f"{path}: unknown mesh file suffix {Path(path).suffix!r} (known: {', '.join(FORMATS)})")
    if problem:
        raise MeshFileError(f"{path}: cannot read file: {problem}")
    try:
        data = _contents(path) if fmt.check else None
        after = fmt.check(data) if fmt.check else None
        arrays = read_surface(path, fmt.reader)
        if after:
            after(arrays)
        return _mesh(arrays)
    except OSError as exc:
        raise MeshFileError(f"{path}: cannot read file: {exc.strerror or exc}") from None
    except ValueError as exc:  # the checks', VTK's and make_mesh's one-line messages
        raise MeshFileError(f"{path}: {exc}") from None


def _contents(path):
    """The file's bytes for the checks, mapped rather than copied (an ``mmap``; ``b""`` for
    an empty file)."""
    with open(path, "rb") as f:
        try:
            return mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_READ)
        except ValueError:  # an empty file cannot be mapped
            return b""


def _mesh(arrays) -> Mesh:
    """The Mesh of what VTK read: fans of the polygons, then the strips' triangles."""
    unfanned = unfanned_polygons(arrays.points, *arrays.polys)
    if len(unfanned):
        size = np.diff(arrays.polys[0])[unfanned[0]]
        raise ValueError(f"polygon {unfanned[0] + 1} ({size} vertices) is concave where a fan from its first vertex "
                         f"fails: VTK's renderer cuts such a polygon its own way, which scanlab does not reproduce "
                         f"({len(unfanned)} such polygons; triangulate the file first)")
    triangles = fan_triangles(*arrays.polys)
    if len(arrays.strips[1]):
        triangles = np.concatenate([triangles, strip_triangles(*arrays.strips)])
    if len(triangles) == 0 and (arrays.n_verts or arrays.n_lines):
        raise ValueError("no triangles (the file holds only vertices or lines)")
    tcoords = arrays.tcoords if arrays.tcoords is not None and arrays.tcoords.shape[1:] == (2,) else None
    if tcoords is not None and (tcoords == -1).all():  # vtkOBJReader's fill for a material without any vt
        tcoords = None
    return make_mesh(arrays.points, triangles, arrays.normals, tcoords)
