"""Write a :class:`lab.mesh.Mesh` as PLY, OBJ, STL or VTP — the exact triangles scanlab draws.

- PLY: binary little-endian, float64 x y z, float64 nx ny nz when the mesh has normals,
  float64 s t when it has texture coordinates, triangles as ``uchar int`` lists.
- OBJ: ``v`` (and ``vt`` and ``vn``, one per point) rows and ``f i i i``, ``f i/i ...``,
  ``f i//i ...`` or ``f i/i/i ...`` faces, 17 significant digits.
- STL: binary, float32 (the format's only precision), facet normals from the geometry;
  STL holds no point normals and no texture coordinates.
- VTP: VTK XML PolyData, inline base64 binary (UInt64 headers), Float64 points, normals
  (``Normals="Normals"``) and texture coordinates (``TCoords="TCoords"``, 2 components),
  Int64 connectivity and offsets.

Every writer goes through a temporary file in the target folder and a rename
(:func:`lab.atomic.atomic_file`), so an interrupted export never leaves half a file.
"""
from __future__ import annotations

import base64
import struct
from pathlib import Path

import numpy as np

from lab.atomic import atomic_file
from lab.mesh import Mesh
from lab.meshfiles.validate import MeshFileError


def write_ply(mesh: Mesh, path) -> None:
    """Binary little-endian PLY with point normals and texture coordinates when the mesh has them."""
    columns, names = [mesh.points], ["x", "y", "z"]
    if mesh.point_normals is not None:
        columns.append(mesh.point_normals)
        names += ["nx", "ny", "nz"]
    if mesh.tcoords is not None:
        columns.append(mesh.tcoords)
        names += ["s", "t"]
    props = "".join(f"property double {name}\n" for name in names)
    header = (f"ply\nformat binary_little_endian 1.0\ncomment written by scanlab\nelement vertex {mesh.n_points}\n"
              f"{props}element face {mesh.n_triangles}\nproperty list uchar int vertex_indices\nend_header\n")
    verts = np.hstack(columns)
    faces = np.zeros(mesh.n_triangles, dtype=[("n", "u1"), ("v", "<i4", (3,))])
    faces["n"], faces["v"] = 3, mesh.triangles
    with atomic_file(path) as f:
        f.write(header.encode("ascii"))
        f.write(np.ascontiguousarray(verts, dtype="<f8").tobytes())
        f.write(faces.tobytes())


def write_obj(mesh: Mesh, path) -> None:
    """Wavefront OBJ: ``v``, ``vt`` (if any), ``vn`` (if any) and ``f`` rows, 1-based; point
    i has ``vt`` i and ``vn`` i."""
    lines = ["# written by scanlab"]
    lines += [f"v {x:.17g} {y:.17g} {z:.17g}" for x, y, z in mesh.points]
    if mesh.tcoords is not None:
        lines += [f"vt {s:.17g} {t:.17g}" for s, t in mesh.tcoords]
    if mesh.point_normals is not None:
        lines += [f"vn {x:.17g} {y:.17g} {z:.17g}" for x, y, z in mesh.point_normals]
    corner = {(False, False): "{0}", (True, False): "{0}/{0}", (False, True): "{0}//{0}",
              (True, True): "{0}/{0}/{0}"}[mesh.tcoords is not None, mesh.point_normals is not None]
    face = f"f {corner} {corner.replace('0', '1')} {corner.replace('0', '2')}"
    lines += [face.format(a, b, c) for a, b, c in mesh.triangles + 1]
    with atomic_file(path) as f:
        f.write(("\n".join(lines) + "\n").encode("ascii"))


def write_stl(mesh: Mesh, path) -> None:
    """Binary STL (float32), one facet per triangle with its geometric normal."""
    p = mesh.points[mesh.triangles]
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    n = np.divide(n, length, out=np.zeros_like(n), where=length > 0)
    rec = np.zeros(mesh.n_triangles, dtype=[("n", "<f4", (3,)), ("v", "<f4", (3, 3)), ("a", "<u2")])
    rec["n"], rec["v"] = n, p
    with atomic_file(path) as f:
        f.write(b"scanlab binary STL".ljust(80, b" "))
        f.write(struct.pack("<I", mesh.n_triangles))
        f.write(rec.tobytes())


def _vtp_array(name: str, values: np.ndarray, vtk_type: str, components: int) -> str:
    raw = np.ascontiguousarray(values).tobytes()
    payload = base64.b64encode(struct.pack("<Q", len(raw)) + raw).decode("ascii")
    comp = f' NumberOfComponents="{components}"' if components > 1 else ""
    return f'<DataArray type="{vtk_type}" Name="{name}"{comp} format="binary">{payload}</DataArray>'


def write_vtp(mesh: Mesh, path) -> None:
    """VTK XML PolyData with inline base64 binary arrays (and point normals and texture
    coordinates if any)."""
    attributes, arrays = "", ""
    if mesh.point_normals is not None:
        attributes += ' Normals="Normals"'
        arrays += _vtp_array("Normals", mesh.point_normals.astype("<f8"), "Float64", 3)
    if mesh.tcoords is not None:
        attributes += ' TCoords="TCoords"'
        arrays += _vtp_array("TCoords", mesh.tcoords.astype("<f8"), "Float64", 2)
    point_data = f"<PointData{attributes}>{arrays}</PointData>" if arrays else ""
    conn = mesh.triangles.astype("<i8").ravel()
    offsets = np.arange(3, 3 * mesh.n_triangles + 1, 3, dtype="<i8")
    xml = ('<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" '
           'header_type="UInt64">\n<PolyData>\n'
           f'<Piece NumberOfPoints="{mesh.n_points}" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" '
           f'NumberOfPolys="{mesh.n_triangles}">\n{point_data}\n'
           f'<Points>{_vtp_array("Points", mesh.points.astype("<f8"), "Float64", 3)}</Points>\n'
           f'<Polys>{_vtp_array("connectivity", conn, "Int64", 1)}{_vtp_array("offsets", offsets, "Int64", 1)}'
           '</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n')
    with atomic_file(path) as f:
        f.write(xml.encode("ascii"))


WRITERS = {".ply": write_ply, ".obj": write_obj, ".stl": write_stl, ".vtp": write_vtp}


def writer_for(path):
    """The writer for ``path``'s suffix (any case); MeshFileError if there is none."""
    suffix = Path(path).suffix.lower()
    if suffix not in WRITERS:
        raise MeshFileError(f"{path}: cannot write {suffix!r} files (known: {', '.join(WRITERS)})")
    return WRITERS[suffix]


def write_mesh(mesh: Mesh, path) -> None:
    """Write ``mesh`` in the format its suffix names (.ply, .obj, .stl, .vtp)."""
    writer_for(path)(mesh, path)
