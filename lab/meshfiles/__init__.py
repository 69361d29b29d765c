"""Read triangle meshes from PLY, OBJ, STL, legacy VTK and VTP files, without VTK.

Only numpy and the standard library are used, so the scanline renderer can load a scene
with no VTK installed.  Every reader returns a :class:`lab.mesh.Mesh`:

- polygons are fan-triangulated by :func:`lab.mesh.fan_triangulate`; polygons with fewer
  than 3 vertices are skipped;
- triangle strips are split with alternating winding, as VTK's ``vtkTriangleStrip``:
  strip ``v0 v1 v2 v3 v4`` gives ``(0, 1, 2), (2, 1, 3), (2, 3, 4)``;
- polygon triangles come before strip triangles (VTK's cell order);
- point normals are scaled to unit length (zero normals stay zero);
- texture coordinates (s, t) are read as VTK reads them (its active TCoords), at the
  precision of the file; ``Mesh.tcoords`` is None when the file has none.

Supported
---------
PLY (:func:`read_ply`)
    ``ascii``, ``binary_little_endian`` and ``binary_big_endian``.  ``element vertex``
    with x, y, z of any numeric type, optional nx, ny, nz and optional texture
    coordinates u, v (else texture_u, texture_v, else s, t: VTK's order of preference);
    ``element face`` with the list ``vertex_indices`` (or ``vertex_index``).  Other
    elements and properties, list or scalar, are skipped.
OBJ (:func:`read_obj`)
    ``v``, ``vt``, ``vn`` and ``f`` (``i``, ``i/t``, ``i//n``, ``i/t/n``, negative indices).
    Points are the ``v`` rows as given.  Point normals only if every face corner has a
    normal and each point is always paired with the same one (points of no face get zero
    normals); texture coordinates (``vt`` u, v) by the same rule.  VTK's OBJ reader
    duplicates points used with different ``vt``/``vn`` instead; we never split points, so
    such files give no texture coordinates (or normals).  Other statements (``o``, ``g``,
    ``s``, ``usemtl``, ``mtllib``, ``l``) are ignored.
STL (:func:`read_stl`)
    ascii and binary.  Exactly equal vertices are merged (first-occurrence order), so a
    closed STL gives a closed mesh.  No point normals (facet normals are not those), no
    texture coordinates.
Legacy VTK (:func:`read_vtk_legacy`)
    ``DATASET POLYDATA``, ASCII or BINARY (big-endian); POINTS; POLYGONS and
    TRIANGLE_STRIPS in the classic layout (counts inline) and the 5.1 layout (OFFSETS and
    CONNECTIVITY); POINT_DATA NORMALS; the first POINT_DATA TEXTURE_COORDINATES (VTK's
    active one) if it has 2 components.  Other sections and attributes are skipped.
VTP (:func:`read_vtp`)
    VTK XML PolyData: ascii, binary (base64 with UInt32 or UInt64 headers, optionally
    ``vtkZLibDataCompressor``) and appended data (raw or base64), either byte order, one
    or more pieces; Points, Polys, Strips, point normals (``PointData Normals="..."``
    or a 3-component array named ``Normals``) and texture coordinates (the 2-component
    array named by ``PointData TCoords="..."``).

Not supported: colours, vertices and lines (ignored); texture coordinates of 1 or 3
components, and per-face-corner ones (PLY ``texcoord`` lists, OBJ points with several
``vt``), for which VTK splits points (ignored: no texture coordinates); other VTK
datasets; other VTP compressors (LZ4, LZMA); OBJ materials and groups (ignored).

Any problem raises :class:`MeshFileError`, whose one-line message starts with the path.

Writing: :func:`write_mesh` (``write`` module) writes PLY, OBJ, STL and VTP.

Layout: one module per format (``ply``, ``obj``, ``stl``, ``legacy``, ``vtp``), each with its
``read_*`` function; ``_common`` holds the error wrapper, the final checks and the cell
triangulation they share.
"""
from __future__ import annotations

from pathlib import Path

from lab.mesh import Mesh
from lab.meshfiles._common import MeshFileError
from lab.meshfiles.legacy import read_vtk_legacy
from lab.meshfiles.obj import read_obj
from lab.meshfiles.ply import read_ply
from lab.meshfiles.stl import read_stl
from lab.meshfiles.vtp import read_vtp
from lab.meshfiles.write import write_mesh

__all__ = ["MeshFileError", "read_mesh", "read_ply", "read_obj", "read_stl", "read_vtk_legacy", "read_vtp",
           "write_mesh"]


def read_mesh(path) -> Mesh:
    """Read a mesh file, choosing the reader by the suffix (any case).

    Parameters
    ----------
    path : str or os.PathLike, a ``.ply``, ``.obj``, ``.stl``, ``.vtk`` or ``.vtp`` file.

    Returns
    -------
    Mesh

    Raises
    ------
    MeshFileError
        Unknown suffix, missing or unreadable file, or anything wrong in it.
    """
    readers = {".ply": read_ply, ".obj": read_obj, ".stl": read_stl, ".vtk": read_vtk_legacy, ".vtp": read_vtp}
    suffix = Path(path).suffix.lower()
    if suffix not in readers:
        raise MeshFileError(f"{path}: unknown mesh file suffix {suffix!r} (known: {', '.join(readers)})")
    return readers[suffix](path)
