"""Mesh files: read by VTK's own readers, written by scanlab (export).

Reading (:func:`read_mesh`, in :mod:`~lab.meshfiles.read`): the surface formats PyVista
reads as one polygon mesh (:data:`~lab.meshfiles.formats.FORMATS`: PLY, OBJ, STL, legacy
VTK, VTK XML PolyData, Movie.BYU, facet, binary marching cubes), each by VTK's reader
through the door :mod:`~lab.meshfiles.vtk_readers` — the only ground-floor module that
imports VTK, and only when a file is read. Both renderers receive exactly the points,
polygons, strips, normals and texture coordinates VTK's reader produced, triangulated as
VTK's mapper draws them (:func:`lab.mesh.fan_triangles`, :func:`lab.mesh.strip_triangles`).
Where VTK's reader misreads or crashes without a word, a check of the format refuses the
file first (``obj_checks``, ``ply_checks``, ``stl_checks``); whatever VTK reports is an
error too. Any problem raises :class:`MeshFileError`, one line starting with the path.

Writing (:func:`write_mesh`, in :mod:`~lab.meshfiles.write`): PLY, OBJ, STL and VTP.
"""
from __future__ import annotations

from lab.meshfiles.read import read_mesh
from lab.meshfiles.validate import MeshFileError
from lab.meshfiles.write import write_mesh

__all__ = ["MeshFileError", "read_mesh", "write_mesh"]
