"""Specification of ``lab.meshfiles``: our VTK-free readers give what VTK reads.

Files are written with pyvista / VTK, read back with ``read_mesh`` and compared with
``pyvista.read``: same points, same triangles in the same order (VTK's own triangulation
for triangles and strips; for quads our fan of VTK's polygons, since the project fans
polygons while ``vtkTriangleFilter`` cuts quads differently), same unit normals, same
texture coordinates (VTK's active ones).
"""
from __future__ import annotations

import ast
import struct
import sys
from pathlib import Path

import numpy as np
import pytest
import pyvista as pv
import vtk

from lab.mesh import fan_triangulate
from lab.meshfiles import MeshFileError, read_mesh

ROOT = Path(__file__).resolve().parents[2]


# ---------------------------------------------------------------------------------------
# Meshes and the reference reading


def sphere(normals=True):
    mesh = pv.Sphere(theta_resolution=12, phi_resolution=9)
    if not normals:
        mesh.point_data.clear()
    return mesh


def cube(normals=True):
    """Quads, with Normals and TCoords (read as VTK's active texture coordinates)."""
    mesh = pv.Cube()
    if not normals:
        mesh.point_data.clear()
    return mesh


def stripped():
    """A sphere made of triangle strips only."""
    mesh = sphere().strip()
    assert mesh.n_strips > 0
    return mesh


def decorated():
    """A sphere with strips, quads and extra data that readers must skip."""
    mesh = sphere().strip() + cube().translate((3, 0, 0))
    mesh.point_data["temperature"] = mesh.points[:, 0]
    mesh.point_data["velocity"] = mesh.points * 2
    mesh.cell_data["cell_id"] = np.arange(mesh.n_cells)
    mesh.field_data["info"] = [1, 2, 3]
    mesh.point_data["uv"] = mesh.points[:, :2]
    mesh.GetPointData().SetTCoords(mesh.GetPointData().GetArray("uv"))
    return mesh


MESHES = {"sphere": sphere, "sphere_no_normals": lambda: sphere(False), "cube": cube,
          "cube_no_normals": lambda: cube(False), "cube_triangles": lambda: cube().triangulate()}


def reference(path, normals=True):
    """(points, triangles, unit normals or None) as VTK reads ``path``."""
    mesh = pv.read(path)
    tri = mesh.triangulate()
    np.testing.assert_array_equal(tri.points, mesh.points)
    triangles = tri.faces.reshape(-1, 4)[:, 1:]
    polys = polygons_of(mesh)
    if any(len(p) != 3 for p in polys):  # VTK ear-cuts quads, the project fans them
        sizes = [len(p) - 2 for p in polys]
        for start, size, p in zip(np.cumsum([0] + sizes), sizes, polys):
            assert set(triangles[start:start + size].ravel()) == set(p)  # same polygon, cut differently
        triangles = np.concatenate([fan_triangulate(polys), triangles[sum(sizes):]])
    n = mesh.point_data.get("Normals") if normals else None
    if n is not None:
        n = np.asarray(n, dtype=np.float64)
        n = n / np.linalg.norm(n, axis=1, keepdims=True)
    return np.asarray(mesh.points, dtype=np.float64), triangles, n


def polygons_of(mesh):
    faces, polys, i = mesh.faces, [], 0
    while i < len(faces):
        polys.append(list(faces[i + 1:i + 1 + faces[i]]))
        i += 1 + faces[i]
    return polys


def assert_reads_like_vtk(path, normals=True):
    got = read_mesh(path)
    points, triangles, n = reference(path, normals)
    np.testing.assert_array_equal(got.points, points)
    np.testing.assert_array_equal(got.triangles, triangles)
    if n is None:
        assert got.point_normals is None
    else:
        np.testing.assert_allclose(got.point_normals, n, atol=1e-6)
    tcoords = pv.read(path).active_texture_coordinates  # VTK's active TCoords, or None
    if tcoords is None:
        assert got.tcoords is None
    else:
        np.testing.assert_array_equal(got.tcoords, np.asarray(tcoords, dtype=np.float64))
    assert got.points.dtype == np.float64 and got.triangles.dtype == np.int64
    return got


# ---------------------------------------------------------------------------------------
# The module itself


def test_readers_use_only_numpy_and_the_standard_library():
    files = sorted((ROOT / "lab" / "meshfiles").glob("*.py"))
    assert files
    for file in files:
        for node in ast.walk(ast.parse(file.read_text())):
            names = [a.name for a in node.names] if isinstance(node, ast.Import) else []
            names += [node.module] if isinstance(node, ast.ImportFrom) and node.module else []
            for name in names:
                top = name.split(".")[0]
                # lab.values and lab.atomic use only the standard library themselves
                assert top in sys.stdlib_module_names or top == "numpy" \
                    or name in ("lab.mesh", "lab.meshfiles", "lab.values", "lab.atomic") \
                    or name.startswith("lab.meshfiles."), f"{file.name} imports {name}"


def test_suffix_is_case_insensitive(tmp_path):
    sphere().save(tmp_path / "lower.ply", binary=True)
    (tmp_path / "UPPER.PLY").write_bytes((tmp_path / "lower.ply").read_bytes())
    upper, lower = read_mesh(tmp_path / "UPPER.PLY"), read_mesh(tmp_path / "lower.ply")
    np.testing.assert_array_equal(upper.triangles, lower.triangles)


# ---------------------------------------------------------------------------------------
# PLY


@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("name", list(MESHES))
def test_ply_reads_like_vtk(tmp_path, name, binary):
    path = tmp_path / f"{name}.ply"
    writer = vtk.vtkPLYWriter()  # pyvista's save would add normals
    writer.SetInputData(MESHES[name]())
    writer.SetFileName(str(path))
    writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
    assert writer.Write() == 1
    mesh = assert_reads_like_vtk(path)
    assert (mesh.point_normals is None) == name.endswith("no_normals")


def test_ply_skips_colours(tmp_path):
    mesh = sphere()
    mesh.point_data["c"] = np.random.default_rng(0).integers(0, 256, (mesh.n_points, 3), dtype=np.uint8)
    mesh.save(tmp_path / "coloured.ply", binary=True, texture="c")
    assert b"red" in (tmp_path / "coloured.ply").read_bytes()[:600]
    assert_reads_like_vtk(tmp_path / "coloured.ply")


def hand_ply(fmt, order):
    """A PLY with mixed quads and triangles, double/short coordinates, extra elements and lists."""
    header = (f"ply\nformat {fmt} 1.0\ncomment hand made\nelement material 1\nproperty list uchar float rgb\n"
              "property uchar id\nelement vertex 5\nproperty double x\nproperty short y\nproperty float z\n"
              "property uchar red\nproperty float s\nproperty float nx\nproperty float ny\nproperty float nz\n"
              "element face 2\nproperty uchar flags\nproperty list uchar uint vertex_indices\n"
              "property list ushort float texcoord\nelement edge 1\nproperty int vertex1\nproperty int vertex2\n"
              "end_header\n")
    verts = [(0.5, 0, 0, 9, 0.1, 0, 0, 2), (1, 0, 0, 9, 0.1, 0, 0, 1), (1, 1, 0, 9, 0.1, 0, 0, 1),
             (0, 1, 0, 9, 0.1, 0, 0, 1), (0, 0, 1, 9, 0.1, 0, 0, 0)]
    faces = [(7, [0, 1, 2, 3], [0.5] * 8), (7, [0, 1, 4], [0.5] * 6)]
    if fmt == "ascii":
        body = "3 1 2 3 4\n" + "".join(" ".join(map(str, v)) + "\n" for v in verts)
        body += "".join(f"{f} {len(i)} {' '.join(map(str, i))} {len(t)} {' '.join(map(str, t))}\n" for f, i, t in faces)
        return (header + body + "0 1\n").encode()
    body = struct.pack(order + "B3fB", 3, 1, 2, 3, 4)
    body += b"".join(struct.pack(order + "dhfBf3f", *v) for v in verts)
    for f, i, t in faces:
        body += struct.pack(order + f"BB{len(i)}IH{len(t)}f", f, len(i), *i, len(t), *t)
    return header.encode() + body + struct.pack(order + "ii", 0, 1)


@pytest.mark.parametrize("fmt, order", [("ascii", ""), ("binary_little_endian", "<"), ("binary_big_endian", ">")])
def test_ply_skips_other_elements_and_properties(tmp_path, fmt, order):
    path = tmp_path / "hand.ply"
    path.write_bytes(hand_ply(fmt, order))
    mesh = read_mesh(path)
    np.testing.assert_array_equal(mesh.points, [[0.5, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1]])
    assert mesh.triangles.tolist() == [[0, 1, 2], [0, 2, 3], [0, 1, 4]]
    np.testing.assert_array_equal(mesh.point_normals, [[0, 0, 1]] * 4 + [[0, 0, 0]])  # unit, zero kept


# ---------------------------------------------------------------------------------------
# OBJ (pyvista splits OBJ vertices, so these are checked by hand)

OBJ = """\
# a unit square made of two quads, with per-point normals
mtllib scene.mtl
o square
v 0 0 0
v 1 0 0
v 2 0 0
v 0 1 0
v 1 1 0
v 2 1 0
vt 0 0
vn 0 0 2
vn 0 0 1
g left
usemtl red
s off
f 1//1 2//1 5//1 4//1
f 2//1 3//2 6//2 5//1
l 1 2
"""


def test_obj_quads_and_normals(tmp_path):
    (tmp_path / "square.obj").write_text(OBJ)
    mesh = read_mesh(tmp_path / "square.obj")
    np.testing.assert_array_equal(mesh.points, [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]])
    assert mesh.triangles.tolist() == [[0, 1, 4], [0, 4, 3], [1, 2, 5], [1, 5, 4]]
    np.testing.assert_array_equal(mesh.point_normals, [[0, 0, 1]] * 6)


def test_obj_index_forms_and_unused_points(tmp_path):
    text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 9 9 9\nvt 0 0\nvn 1 0 0\nvn 0 1 0\nvn 0 0 1\n" \
           "f 1/1/3 2/1/3 3/1/3\nf -4/1/3 -3/1/3 -2/1/3\n"
    (tmp_path / "forms.obj").write_text(text)
    mesh = read_mesh(tmp_path / "forms.obj")
    assert mesh.triangles.tolist() == [[0, 1, 2], [0, 1, 2]]
    np.testing.assert_array_equal(mesh.point_normals, [[0, 0, 1]] * 3 + [[0, 0, 0]])


@pytest.mark.parametrize("faces", ["f 1//1 2//2 3//3\nf 1//2 3//3 4//3\n",  # point 1 has two normals
                                   "f 1//1 2//2 3//3\nf 1 3 4\n",  # a face without normals
                                   "f 1/1 2/1 3/1\nf 1 3 4\n"])
def test_obj_inconsistent_normals_are_dropped(tmp_path, faces):
    text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n" + faces
    (tmp_path / "mixed.obj").write_text(text)
    mesh = read_mesh(tmp_path / "mixed.obj")
    assert mesh.point_normals is None
    assert mesh.triangles.tolist() == [[0, 1, 2], [0, 2, 3]]


# ---------------------------------------------------------------------------------------
# STL


@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("make", [sphere, lambda: cube().triangulate()])
def test_stl_merges_vertices_like_vtk(tmp_path, make, binary):
    path = tmp_path / "mesh.stl"
    make().save(path, binary=binary)
    mesh = assert_reads_like_vtk(path, normals=False)
    assert mesh.point_normals is None
    edges = np.sort(mesh.triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    assert (np.unique(edges, axis=0, return_counts=True)[1] == 2).all()  # closed surface


# ---------------------------------------------------------------------------------------
# Legacy VTK


def write_legacy(mesh, path, binary, version=None):
    writer = vtk.vtkPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    writer.SetFileTypeToBinary() if binary else writer.SetFileTypeToASCII()
    if version:
        writer.SetFileVersion(version)
    assert writer.Write() == 1


@pytest.mark.parametrize("version", [None, 42], ids=["5.1", "4.2"])
@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("make", [*MESHES.values(), stripped, decorated], ids=[*MESHES, "strips", "decorated"])
def test_legacy_vtk_reads_like_vtk(tmp_path, make, binary, version):
    path = tmp_path / "mesh.vtk"
    write_legacy(make(), path, binary, version)
    assert (b"OFFSETS" in path.read_bytes()) == (version is None)
    assert_reads_like_vtk(path)


def test_legacy_vtk_skips_metadata(tmp_path):
    mesh = sphere()
    mesh.point_data["velocity"] = mesh.points
    mesh.GetPointData().GetArray("velocity").SetComponentName(0, "vx")
    path = tmp_path / "meta.vtk"
    write_legacy(mesh, path, binary=False)
    assert b"METADATA" in path.read_bytes()
    assert_reads_like_vtk(path)


STRIP_VTK = """\
# vtk DataFile Version 3.0
a strip of four triangles and one quad
ASCII
DATASET POLYDATA
POINTS 6 float
0 0 0  0 1 0  1 0 0  1 1 0  2 0 0  2 1 0
TRIANGLE_STRIPS 1 7
6 1 0 3 2 5 4
POLYGONS 2 8
4 0 2 3 1
2 4 5
POINT_DATA 6
SCALARS height float 1
LOOKUP_TABLE default
0 1 0 1 0 1
NORMALS n float
0 0 3  0 0 1  0 0 1  0 0 1  0 0 1  0 0 0
"""


def test_legacy_vtk_strip_by_hand(tmp_path):
    (tmp_path / "strip.vtk").write_text(STRIP_VTK)
    mesh = read_mesh(tmp_path / "strip.vtk")
    # polygons first (the 2-point one skipped), then the strip with alternating winding
    assert mesh.triangles.tolist() == [[0, 2, 3], [0, 3, 1], [1, 0, 3], [3, 0, 2], [3, 2, 5], [5, 2, 4]]
    points = mesh.points[mesh.triangles]
    cross = np.cross(points[:, 1] - points[:, 0], points[:, 2] - points[:, 0])
    assert (cross[:, 2] > 0).all()  # all counter-clockwise seen from +z, like the quad
    np.testing.assert_array_equal(mesh.point_normals, [[0, 0, 1]] * 5 + [[0, 0, 0]])


# ---------------------------------------------------------------------------------------
# VTP


def write_vtp(mesh, path, mode, compressor="none", encode=True, header="UInt32", order="little", id32=False):
    writer = vtk.vtkXMLPolyDataWriter()
    writer.SetInputData(mesh)
    writer.SetFileName(str(path))
    {"ascii": writer.SetDataModeToAscii, "binary": writer.SetDataModeToBinary,
     "appended": writer.SetDataModeToAppended}[mode]()
    writer.SetCompressorTypeToZLib() if compressor == "zlib" else writer.SetCompressorTypeToNone()
    writer.SetBlockSize(1024)  # several compressed blocks
    writer.SetEncodeAppendedData(encode)
    writer.SetHeaderTypeToUInt64() if header == "UInt64" else writer.SetHeaderTypeToUInt32()
    writer.SetByteOrderToBigEndian() if order == "big" else writer.SetByteOrderToLittleEndian()
    if id32:
        writer.SetIdTypeToInt32()
    assert writer.Write() == 1


VTP_MODES = {
    "ascii": dict(mode="ascii"),
    "binary": dict(mode="binary"),
    "binary_zlib": dict(mode="binary", compressor="zlib"),
    "binary_zlib_uint64": dict(mode="binary", compressor="zlib", header="UInt64"),
    "binary_big_endian": dict(mode="binary", order="big", id32=True),
    "appended_raw": dict(mode="appended", encode=False),
    "appended_raw_zlib": dict(mode="appended", encode=False, compressor="zlib"),
    "appended_raw_big_uint64": dict(mode="appended", encode=False, order="big", header="UInt64"),
    "appended_base64": dict(mode="appended"),
    "appended_base64_zlib_uint64": dict(mode="appended", compressor="zlib", header="UInt64"),
}


@pytest.mark.parametrize("options", list(VTP_MODES))
@pytest.mark.parametrize("make", [*MESHES.values(), stripped, decorated], ids=[*MESHES, "strips", "decorated"])
def test_vtp_reads_like_vtk(tmp_path, make, options):
    path = tmp_path / "mesh.vtp"
    write_vtp(make(), path, **VTP_MODES[options])
    assert_reads_like_vtk(path)


def test_vtp_pyvista_save(tmp_path):
    sphere().save(tmp_path / "s.vtp")
    assert_reads_like_vtk(tmp_path / "s.vtp")


def test_vtp_several_pieces(tmp_path):
    piece = '<Piece NumberOfPoints="3" NumberOfPolys="1"><PointData Normals="N"><DataArray type="Float32" ' \
            'Name="N" NumberOfComponents="3" format="ascii">0 0 2 0 0 2 0 0 2</DataArray></PointData>' \
            '<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">{} 0 0 1 0 0 0 1 0</DataArray>' \
            '</Points><Polys><DataArray type="Int32" Name="connectivity" format="ascii">0 1 2</DataArray>' \
            '<DataArray type="Int32" Name="offsets" format="ascii">3</DataArray></Polys></Piece>'
    text = f'<?xml version="1.0"?><VTKFile type="PolyData" version="0.1"><PolyData>{piece.format(0)}' \
           f'{piece.format(5)}</PolyData></VTKFile>'
    (tmp_path / "pieces.vtp").write_text(text)
    mesh = read_mesh(tmp_path / "pieces.vtp")
    assert mesh.triangles.tolist() == [[0, 1, 2], [3, 4, 5]]
    assert mesh.points[3].tolist() == [5, 0, 0]
    np.testing.assert_array_equal(mesh.point_normals, [[0, 0, 1]] * 6)


# ---------------------------------------------------------------------------------------
# Errors


def assert_error(path, *words):
    with pytest.raises(MeshFileError) as info:
        read_mesh(path)
    message = str(info.value)
    assert message.startswith(f"{path}: ") and "\n" not in message
    for word in words:
        assert word in message
    return message


@pytest.mark.parametrize("suffix", [".ply", ".obj", ".stl", ".vtk", ".vtp"])
def test_missing_file(tmp_path, suffix):
    assert_error(tmp_path / f"nothing{suffix}")


@pytest.mark.parametrize("suffix", [".ply", ".obj", ".stl", ".vtk", ".vtp", ".PLY"])
def test_garbage(tmp_path, suffix):
    path = tmp_path / f"garbage{suffix}"
    path.write_bytes(bytes(np.random.default_rng(1).integers(0, 256, 3000, dtype=np.uint8)))
    assert_error(path)


def test_unknown_suffix(tmp_path):
    (tmp_path / "mesh.off").write_text("OFF\n")
    assert_error(tmp_path / "mesh.off", "suffix")


@pytest.mark.parametrize("name, text", [
    ("bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"),
    ("bad.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
    ("bad.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                "POLYGONS 1 4\n3 0 1 7\n"),
])
def test_index_out_of_range(tmp_path, name, text):
    (tmp_path / name).write_text(text)
    assert_error(tmp_path / name, "out of range" if not name.endswith(".obj") else "vertex 4")


@pytest.mark.parametrize("name, text, words", [
    ("nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ["NaN"]),
    ("empty.obj", "v 0 0 0\n", ["no triangles"]),
    ("grid.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n", ["POLYDATA"]),
    ("normals.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                    "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 2\nNORMALS n float\n0 0 1 0 0 1\n", ["2 normals for 3 points"]),
    ("short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n",
     ["3 vertices"]),
])
def test_bad_contents(tmp_path, name, text, words):
    (tmp_path / name).write_text(text)
    assert_error(tmp_path / name, *words)
