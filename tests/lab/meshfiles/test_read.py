"""Specification of ``lab.meshfiles.read_mesh``: a mesh file as VTK's own reader reads it.

Files are written with VTK's writers (or by hand), read with ``read_mesh`` and compared with
``pyvista.read`` of the same file: the same points (at the precision VTK kept), VTK's
polygons fanned and strips cut as VTK's mapper draws them (polygons first), the same
active normals (made unit length) and the same active 2-component texture coordinates.
"""
from __future__ import annotations

import numpy as np
import pytest
import pyvista as pv
import vtk

from lab.meshfiles import MeshFileError, read_mesh

from ...mesh_files import vtk_triangles, vtk_write


# --------------------------------------------------------------------------- meshes
def sphere(normals=True):
    mesh = pv.Sphere(theta_resolution=12, phi_resolution=9)
    if not normals:
        mesh.point_data.clear()
    return mesh


def cube(normals=True):
    """Quads, with normals and texture coordinates (VTK's active ones)."""
    mesh = pv.Cube()
    if not normals:
        mesh.point_data.clear()
    return mesh


def textured_sphere():
    return sphere().texture_map_to_sphere(inplace=False)


def stripped():
    mesh = sphere().strip()
    assert mesh.n_strips > 0
    return mesh


def decorated():
    """Strips, quads and extra arrays that must not matter."""
    mesh = sphere().strip() + cube().translate((3, 0, 0))
    mesh.point_data["temperature"] = mesh.points[:, 0]
    mesh.cell_data["cell_id"] = np.arange(mesh.n_cells)
    mesh.field_data["info"] = [1, 2, 3]
    mesh.point_data["uv"] = mesh.points[:, :2]
    mesh.GetPointData().SetTCoords(mesh.GetPointData().GetArray("uv"))
    return mesh


MESHES = {"sphere": sphere, "sphere_no_normals": lambda: sphere(False), "cube": cube,
          "cube_no_normals": lambda: cube(False), "strips": stripped, "decorated": decorated}


def assert_reads_like_vtk(path):
    """``read_mesh(path)`` holds exactly what ``pyvista.read(path)`` holds, triangulated as VTK draws it."""
    got, ref = read_mesh(path), pv.read(path)
    np.testing.assert_array_equal(got.points, np.asarray(ref.points, dtype=np.float64))
    np.testing.assert_array_equal(got.triangles, vtk_triangles(ref))
    normals = ref.point_data.active_normals
    if normals is None:
        assert got.point_normals is None
    else:
        n = np.asarray(normals, dtype=np.float64)
        np.testing.assert_allclose(got.point_normals, n / np.linalg.norm(n, axis=1, keepdims=True), atol=1e-15)
    tcoords = ref.active_texture_coordinates
    if tcoords is None or tcoords.shape[1] != 2:
        assert got.tcoords is None
    else:
        np.testing.assert_array_equal(got.tcoords, np.asarray(tcoords, dtype=np.float64))
    assert got.points.dtype == np.float64 and got.triangles.dtype == np.int64
    return got


# --------------------------------------------------------------------------- formats
@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("name", ["sphere", "sphere_no_normals", "cube", "cube_no_normals"])
def test_ply(tmp_path, name, binary):
    vtk_write(vtk.vtkPLYWriter(), MESHES[name](), tmp_path / "m.ply",
              **{"SetFileTypeToBinary" if binary else "SetFileTypeToASCII": None})
    mesh = assert_reads_like_vtk(tmp_path / "m.ply")
    assert (mesh.point_normals is None) == name.endswith("no_normals")


def test_obj_written_by_vtk(tmp_path):
    vtk_write(vtk.vtkOBJWriter(), textured_sphere(), tmp_path / "m.obj")
    assert_reads_like_vtk(tmp_path / "m.obj")


def test_obj_refers_past_its_texture_coordinates(tmp_path):
    """VTK 9.7's OBJ writer, given ``pv.Cube()``, writes 6 ``vt`` lines and faces that use
    ``vt`` 7 and 8. VTK's reader then reads past its texture coordinates (values such as
    4.6e-44 come out); we refuse the file, naming the line."""
    vtk_write(vtk.vtkOBJWriter(), cube(), tmp_path / "cube.obj")
    assert_error(tmp_path / "cube.obj", "line 26", "a face refers to texture coordinate 7, but there are 6")


@pytest.mark.parametrize("binary", [False, True])
def test_stl(tmp_path, binary):
    """VTK's STL reader merges equal points: a closed surface stays closed."""
    sphere().save(tmp_path / "m.stl", binary=binary)
    mesh = assert_reads_like_vtk(tmp_path / "m.stl")
    edges = np.sort(mesh.triangles[:, [0, 1, 1, 2, 2, 0]].reshape(-1, 2), axis=1)
    assert (np.unique(edges, axis=0, return_counts=True)[1] == 2).all()


@pytest.mark.parametrize("version", [None, 42], ids=["5.1", "4.2"])
@pytest.mark.parametrize("binary", [False, True])
@pytest.mark.parametrize("name", list(MESHES))
def test_legacy_vtk(tmp_path, name, binary, version):
    setters = {"SetFileTypeToBinary" if binary else "SetFileTypeToASCII": None}
    if version:
        setters["SetFileVersion"] = version
    vtk_write(vtk.vtkPolyDataWriter(), MESHES[name](), tmp_path / "m.vtk", **setters)
    assert_reads_like_vtk(tmp_path / "m.vtk")


VTP_MODES = {"ascii": {"SetDataModeToAscii": None},
             "binary_zlib": {"SetDataModeToBinary": None, "SetCompressorTypeToZLib": None},
             "appended_raw_big_endian": {"SetDataModeToAppended": None, "SetEncodeAppendedData": False,
                                         "SetByteOrderToBigEndian": None}}


@pytest.mark.parametrize("mode", list(VTP_MODES))
@pytest.mark.parametrize("name", list(MESHES))
def test_vtp(tmp_path, name, mode):
    vtk_write(vtk.vtkXMLPolyDataWriter(), MESHES[name](), tmp_path / "m.vtp", **VTP_MODES[mode])
    assert_reads_like_vtk(tmp_path / "m.vtp")


def test_pyvista_example_globe():
    mesh = assert_reads_like_vtk(__import__("pathlib").Path(pv.__file__).parent / "examples" / "globe.vtk")
    assert mesh.tcoords is not None


def test_suffix_in_any_case(tmp_path):
    sphere().save(tmp_path / "lower.ply")
    (tmp_path / "UPPER.PLY").write_bytes((tmp_path / "lower.ply").read_bytes())
    np.testing.assert_array_equal(read_mesh(tmp_path / "UPPER.PLY").triangles, read_mesh(tmp_path / "lower.ply").triangles)


# --------------------------------------------------------------------------- OBJ splitting
def test_obj_point_with_two_normals_becomes_one_point_per_corner(tmp_path):
    """Point 1 is used with normals 1 and 2: vtkOBJReader then gives every face corner its
    own point, with its own normal, and so do we; no normal is lost."""
    (tmp_path / "two.obj").write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 1 0\n"
                                      "f 1//1 2//1 3//1\nf 1//2 3//1 4//1\n")
    mesh = assert_reads_like_vtk(tmp_path / "two.obj")
    assert mesh.n_points == 6 and mesh.triangles.tolist() == [[0, 1, 2], [3, 4, 5]]
    np.testing.assert_array_equal(mesh.points[[0, 3]], [[0, 0, 0], [0, 0, 0]])
    np.testing.assert_array_equal(mesh.point_normals[[0, 3]], [[0, 0, 1], [0, 1, 0]])


def test_obj_uv_seam_keeps_both_texture_coordinates(tmp_path):
    """Point 1 is used with vt 1 and vt 4 (a UV seam): both are kept, one per corner."""
    (tmp_path / "seam.obj").write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0.5 0.5\n"
                                       "f 1/1 2/2 3/3\nf 1/4 3/3 4/1\n")
    mesh = assert_reads_like_vtk(tmp_path / "seam.obj")
    np.testing.assert_array_equal(mesh.tcoords, [[0, 0], [1, 0], [1, 1], [0.5, 0.5], [1, 1], [0, 0]])


def test_obj_without_splitting_keeps_the_v_rows(tmp_path):
    """Each point always paired with the same vn (``f a//a``): the v rows as they are, quads fanned."""
    (tmp_path / "sq.obj").write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 2\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
                                     "f 1//1 2//2 3//3 4//4\n")
    mesh = assert_reads_like_vtk(tmp_path / "sq.obj")
    assert mesh.n_points == 4 and mesh.triangles.tolist() == [[0, 1, 2], [0, 2, 3]]
    np.testing.assert_array_equal(mesh.point_normals, [[0, 0, 1]] * 4)  # made unit length


def test_obj_material_without_vt_has_no_texture_coordinates(tmp_path):
    """With ``usemtl`` and no ``vt``, vtkOBJReader still makes a texture-coordinate array,
    all −1 (its fill): that is no texture coordinates."""
    (tmp_path / "mtl.obj").write_text("mtllib none.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n")
    assert (np.asarray(pv.read(tmp_path / "mtl.obj").active_texture_coordinates) == -1).all()
    assert read_mesh(tmp_path / "mtl.obj").tcoords is None


# --------------------------------------------------------------------------- refused
def assert_error(path, *words):
    with pytest.raises(MeshFileError) as info:
        read_mesh(path)
    message = str(info.value)
    assert message.startswith(f"{path}: ") and "\n" not in message, message
    for word in words:
        assert word in message, message
    return message


@pytest.mark.parametrize("suffix", [".ply", ".obj", ".stl", ".vtk", ".vtp", ".g", ".facet", ".tri"])
def test_missing_file(tmp_path, suffix):
    assert_error(tmp_path / f"nothing{suffix}", "No such file")


def test_folder(tmp_path):
    (tmp_path / "dir.obj").mkdir()
    assert_error(tmp_path / "dir.obj", "is a folder")


@pytest.mark.parametrize("suffix", [".ply", ".obj", ".stl", ".vtk", ".vtp", ".PLY"])
def test_garbage(tmp_path, suffix, capfd):
    """Random bytes: one line, and nothing printed by VTK."""
    path = tmp_path / f"garbage{suffix}"
    path.write_bytes(bytes(np.random.default_rng(1).integers(0, 256, 3000, dtype=np.uint8)))
    assert_error(path)
    assert capfd.readouterr() == ("", "")


def test_unknown_suffix(tmp_path):
    (tmp_path / "mesh.off").write_text("OFF\n")
    assert_error(tmp_path / "mesh.off", "unknown mesh file suffix '.off'", ".ply, .obj, .stl")


def test_only_vertices_and_lines(tmp_path):
    (tmp_path / "lines.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n")
    assert_error(tmp_path / "lines.obj", "no triangles", "only vertices or lines")


def test_polygon_whose_fan_fails(tmp_path):
    """A concave pentagon whose fan from its first vertex turns a triangle against it: VTK
    cuts it its own way, which we do not reproduce, so the file is refused."""
    (tmp_path / "notch.obj").write_text("v 0 0 0\nv 2 0 0\nv 1 0.5 0\nv 2 2 0\nv 0 2 0\nf 2 3 4 5 1\n")
    assert_error(tmp_path / "notch.obj", "polygon 1 (5 vertices) is concave where a fan from its first vertex fails",
                 "triangulate the file first")


def test_concave_polygon_with_a_sound_fan_is_fanned(tmp_path):
    """The same pentagon from another vertex: its fan is sound, and VTK draws the fan."""
    (tmp_path / "notch.obj").write_text("v 0 0 0\nv 2 0 0\nv 1 0.5 0\nv 2 2 0\nv 0 2 0\nf 1 2 3 4 5\n")
    assert read_mesh(tmp_path / "notch.obj").triangles.tolist() == [[0, 1, 2], [0, 2, 3], [0, 3, 4]]


def test_concave_quad_is_fanned(tmp_path):
    """VTK fans every quad, concave or not; so do we."""
    (tmp_path / "dart.obj").write_text("v 0 0 0\nv 4 0 0\nv 1 1 0\nv 0 4 0\nf 1 2 3 4\n")
    assert read_mesh(tmp_path / "dart.obj").triangles.tolist() == [[0, 1, 2], [0, 2, 3]]


def test_vtk_warning_is_an_error(tmp_path):
    """vtkOBJReader warns about data left at the end of a line and reads on; we stop."""
    (tmp_path / "extra.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1 7\nf 1//1 2//1 3//1\n")
    assert_error(tmp_path / "extra.obj", "line 4", "unexpected data at end of line")


@pytest.mark.parametrize("name, text, words", [
    ("nan.obj", "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", ["NaN"]),
    ("empty.obj", "v 0 0 0\n", ["no triangles"]),
    ("grid.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n", ["only DATASET POLYDATA"]),
    ("index.vtk", "# vtk DataFile Version 3.0\nt\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                  "POLYGONS 1 4\n3 0 1 7\n", ["point index 7 out of range (there are 3 points)"]),
    ("short.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n", []),
])
def test_bad_contents(tmp_path, name, text, words):
    (tmp_path / name).write_text(text)
    assert_error(tmp_path / name, *words)
