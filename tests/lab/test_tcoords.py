"""Specification of texture coordinates (``Mesh.tcoords``) wherever a mesh is made.

- readers give VTK's active texture coordinates (compared with ``pyvista.read``: same
  points, VTK's cells triangulated as its mapper draws them, same tcoords), or None;
- writers write them (PLY ``s t``, OBJ ``vt``, VTP ``TCoords``) and read back unchanged
  (to float32 where VTK's reader keeps float32: PLY, OBJ ``vt``);
- normals keep them (split points copy their source point's);
- shapes: ``icosphere``, ``cylinder`` and ``cone`` with ``uv=1`` (seams, poles, same surface).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import pyvista as pv
import vtk

from lab import shapes
from lab.framing import make_shape
from lab.measure import enclosed_volume, surface_area
from lab.mesh import Mesh, fan_triangles
from lab.meshfiles import MeshFileError, read_mesh, write_mesh
from lab.normals import NORMAL_MODES, split_at_creases, with_normals

from ..mesh_files import vtk_triangles, vtk_write

GLOBE = Path(pv.__file__).parent / "examples" / "globe.vtk"


# ---------------------------------------------------------------------------------------
# Reading: the same as VTK


def textured_sphere():
    """pyvista's sphere with vtkTextureMapToSphere's coordinates (and normals)."""
    mesh = pv.Sphere(theta_resolution=12, phi_resolution=9).texture_map_to_sphere(inplace=False)
    assert mesh.active_texture_coordinates is not None
    return mesh


def assert_like_pyvista(path):
    """Our reading of ``path`` has pyvista's points, triangles and active tcoords."""
    ref = pv.read(path)
    got = read_mesh(path)
    np.testing.assert_array_equal(got.points, np.asarray(ref.points, dtype=np.float64))
    np.testing.assert_array_equal(got.triangles, vtk_triangles(ref))
    assert ref.active_texture_coordinates is not None
    np.testing.assert_array_equal(got.tcoords, np.asarray(ref.active_texture_coordinates, dtype=np.float64))
    assert got.tcoords.dtype == np.float64 and got.tcoords.shape == (got.n_points, 2)
    return got


def test_globe_reads_like_pyvista():
    assert GLOBE.is_file()
    mesh = assert_like_pyvista(GLOBE)
    assert mesh.n_points == 540 and mesh.tcoords.min() >= 0 and mesh.tcoords.max() <= 1


LEGACY = {"ascii_5.1": {"SetFileTypeToASCII": None}, "binary_5.1": {"SetFileTypeToBinary": None},
          "ascii_4.2": {"SetFileTypeToASCII": None, "SetFileVersion": 42},
          "binary_4.2": {"SetFileTypeToBinary": None, "SetFileVersion": 42}}


@pytest.mark.parametrize("strips", [False, True], ids=["polys", "strips"])
@pytest.mark.parametrize("options", list(LEGACY))
def test_legacy_vtk_tcoords(tmp_path, options, strips):
    mesh = textured_sphere().strip() if strips else textured_sphere()
    vtk_write(vtk.vtkPolyDataWriter(), mesh, tmp_path / "s.vtk", **LEGACY[options])
    assert b"TEXTURE_COORDINATES" in (tmp_path / "s.vtk").read_bytes()
    assert_like_pyvista(tmp_path / "s.vtk")


VTP = {"pyvista": None, "ascii": {"SetDataModeToAscii": None},
       "binary_zlib": {"SetDataModeToBinary": None, "SetCompressorTypeToZLib": None},
       "appended_raw_big": {"SetDataModeToAppended": None, "SetEncodeAppendedData": False,
                            "SetByteOrderToBigEndian": None}}


@pytest.mark.parametrize("options", list(VTP))
def test_vtp_tcoords(tmp_path, options):
    path = tmp_path / "s.vtp"
    if VTP[options] is None:
        textured_sphere().save(path)
    else:
        vtk_write(vtk.vtkXMLPolyDataWriter(), textured_sphere(), path, **VTP[options])
    assert b'TCoords="Texture Coordinates"' in path.read_bytes()
    assert_like_pyvista(path)


@pytest.mark.parametrize("binary", [False, True])
def test_ply_written_by_vtk(tmp_path, binary):
    path = tmp_path / "s.ply"
    vtk_write(vtk.vtkPLYWriter(), textured_sphere(), path,
              **{"SetFileTypeToBinary" if binary else "SetFileTypeToASCII": None})
    assert b"property float u\nproperty float v\n" in path.read_bytes()  # VTK writes u v
    assert_like_pyvista(path)


def ply_text(names, rows):
    props = "".join(f"property double {n}\n" for n in names)
    return ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            f"{props}element face 1\nproperty list uchar int vertex_indices\nend_header\n"
            + "".join(f"{i} {i % 2} 0 {' '.join(map(str, r))}\n" for i, r in enumerate(rows)) + "3 0 1 2\n")


@pytest.mark.parametrize("names", [("u", "v"), ("s", "t"), ("texture_u", "texture_v"),
                                   ("s", "t", "u", "v"), ("u", "v", "s", "t"), ("s", "t", "texture_u", "texture_v"),
                                   ("texture_u", "texture_v", "u", "v"), ("texture_s", "texture_t"), ("u", "t")])
def test_ply_tcoord_names_like_vtk(tmp_path, names):
    """u v, texture_u texture_v, s t: the pairs VTK's PLY reader accepts, in its order of preference."""
    rows = [[0.125 * (i + 1) + 0.01 * j for j in range(len(names))] for i in range(3)]  # exact in float32
    (tmp_path / "t.ply").write_text(ply_text(names, rows))
    ref = pv.read(tmp_path / "t.ply").active_texture_coordinates
    got = read_mesh(tmp_path / "t.ply").tcoords
    if ref is None:
        assert got is None and names in [("texture_s", "texture_t"), ("u", "t")]
    else:
        np.testing.assert_allclose(got, ref, rtol=1e-7)  # VTK keeps float32, we keep the file's doubles


def test_ply_face_texcoord_lists_as_vtk_reads_them(tmp_path):
    """Per-corner ``texcoord`` lists of faces: VTK's PLY reader turns them into point texture
    coordinates; we take what it gives."""
    text = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\n"
            "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 6 0 0 1 0 0 1\n")
    (tmp_path / "f.ply").write_text(text)
    mesh = assert_like_pyvista(tmp_path / "f.ply")
    np.testing.assert_array_equal(mesh.tcoords, [[0, 0], [1, 0], [0, 1]])


def test_obj_written_by_vtk(tmp_path):
    """vtkOBJWriter writes ``f a/a/a``: each point one vt, so VTK splits nothing either."""
    vtk_write(vtk.vtkOBJWriter(), textured_sphere(), tmp_path / "s.obj")
    assert_like_pyvista(tmp_path / "s.obj")


OBJ_SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 5 5 5\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0\n"


@pytest.mark.parametrize("faces, points", [
    ("f 1/1 2/2 3/3 4/4\n", 5),                          # each corner's vt index is its v index: v rows kept
    ("vn 0 0 1\nf 1/1/1 2/2/1 3/3/1\nf 1/1/1 3/3/1 4/4/1\n", 6),  # vn 1 at every corner: a point per corner
    ("f 1/1 2/2 3/3\nf 1/4 3/3 4/4\n", 6),              # point 1 with vt 1 and vt 4: a UV seam
])
def test_obj_tcoords_as_vtk_splits_points(tmp_path, faces, points):
    """Where a face corner's vt (or vn) index differs from its v index, vtkOBJReader gives
    every face corner its own point; each keeps its own (s, t)."""
    (tmp_path / "sq.obj").write_text(OBJ_SQUARE + faces)
    mesh = assert_like_pyvista(tmp_path / "sq.obj")
    assert mesh.n_points == points
    faces_ = [line.split()[1:] for line in faces.splitlines() if line.startswith("f")]
    vt = np.array([int(c.split("/")[1]) - 1 for f in faces_ for c in f])
    offsets = np.concatenate([[0], np.cumsum([len(f) for f in faces_])])
    corner_of_triangles = fan_triangles(offsets, np.arange(len(vt)))  # the face corner behind each triangle corner
    table = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0]])
    np.testing.assert_array_equal(mesh.tcoords[mesh.triangles], table[vt[corner_of_triangles]])


def test_obj_tcoord_index_out_of_range(tmp_path):
    (tmp_path / "bad.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/9\n")
    with pytest.raises(MeshFileError, match="line 5: a face refers to texture coordinate 9, but there are 1"):
        read_mesh(tmp_path / "bad.obj")


def test_legacy_first_point_tcoords_are_the_active_ones(tmp_path):
    """Cell TEXTURE_COORDINATES, then two point ones: VTK makes the first point ones active."""
    mesh = textured_sphere()
    reversed_uv = np.asarray(mesh.active_texture_coordinates)[:, ::-1].copy()
    mesh.point_data["other"] = reversed_uv
    mesh.cell_data["cell_uv"] = np.zeros((mesh.n_cells, 2), dtype=np.float32)
    mesh.GetCellData().SetTCoords(mesh.GetCellData().GetArray("cell_uv"))
    path = tmp_path / "two.vtk"
    vtk_write(vtk.vtkPolyDataWriter(), mesh, path, SetFileTypeToASCII=None)
    # make "other" (written as 2-component SCALARS) the first point TEXTURE_COORDINATES
    data = path.read_text()
    assert "SCALARS other float 2\nLOOKUP_TABLE default\n" in data
    data = data.replace("SCALARS other float 2\nLOOKUP_TABLE default\n", "TEXTURE_COORDINATES other 2 float\n")
    assert data.index("CELL_DATA") < data.index("TEXTURE_COORDINATES cell_uv") < data.index("POINT_DATA") \
        < data.index("TEXTURE_COORDINATES other") < data.index("TEXTURE_COORDINATES Texture")
    path.write_text(data)
    got = assert_like_pyvista(path)
    np.testing.assert_allclose(got.tcoords, reversed_uv, atol=1e-6)  # ascii: 6 digits


def test_three_component_tcoords_are_ignored(tmp_path):
    mesh = pv.Sphere(theta_resolution=6, phi_resolution=5)
    mesh.point_data["uvw"] = np.asarray(mesh.points, dtype=np.float32)
    mesh.GetPointData().SetTCoords(mesh.GetPointData().GetArray("uvw"))
    vtk_write(vtk.vtkPolyDataWriter(), mesh, tmp_path / "s.vtk")
    mesh.save(tmp_path / "s.vtp")
    for path in (tmp_path / "s.vtk", tmp_path / "s.vtp"):
        assert pv.read(path).active_texture_coordinates.shape == (mesh.n_points, 3)
        assert read_mesh(path).tcoords is None


def test_vtp_tcoords_only_if_named(tmp_path):
    """A 2-component array called TCoords, not named by the TCoords attribute, is not VTK's."""
    mesh = pv.Sphere(theta_resolution=6, phi_resolution=5)
    mesh.point_data["TCoords"] = np.asarray(mesh.points[:, :2], dtype=np.float32)
    mesh.save(tmp_path / "s.vtp")
    assert pv.read(tmp_path / "s.vtp").active_texture_coordinates is None
    assert read_mesh(tmp_path / "s.vtp").tcoords is None


def test_files_without_tcoords(tmp_path):
    mesh = pv.Sphere(theta_resolution=6, phi_resolution=5)
    for suffix in (".vtk", ".vtp", ".ply", ".stl"):
        mesh.save(tmp_path / f"s{suffix}")
        assert read_mesh(tmp_path / f"s{suffix}").tcoords is None


def test_stl_has_no_tcoords(tmp_path):
    textured_sphere().save(tmp_path / "s.stl")
    assert read_mesh(tmp_path / "s.stl").tcoords is None


def test_bad_tcoords_are_an_error(tmp_path):
    text = ("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
            "property float u\nproperty float v\nelement face 1\nproperty list uchar int vertex_indices\n"
            "end_header\n0 0 0 0 nan\n1 0 0 0 0\n0 1 0 0 0\n3 0 1 2\n")
    (tmp_path / "nan.ply").write_text(text)
    with pytest.raises(MeshFileError, match="texture coordinates contain NaN"):
        read_mesh(tmp_path / "nan.ply")


# ---------------------------------------------------------------------------------------
# Writing: round trips


def textured(normals):
    """An icosphere with tcoords (seam and pole copies), with or without normals."""
    mesh = shapes.icosphere(level=2, uv=1)
    return with_normals(mesh, "radial") if normals else mesh


FLOAT32 = {".ply": ("points", "normals", "tcoords"), ".obj": ("normals", "tcoords"), ".vtp": ()}
"""What VTK's reader of each format keeps as float32: vtkPLYReader everything, vtkOBJReader
``vt`` and ``vn`` (its points are doubles), vtkXMLPolyDataReader nothing (the file's Float64)."""


@pytest.mark.parametrize("normals", [False, True], ids=["no_normals", "normals"])
@pytest.mark.parametrize("suffix", [".ply", ".obj", ".vtp"])
def test_round_trip(tmp_path, suffix, normals):
    """What we write reads back the same: same points, triangles and texture coordinates,
    exact where VTK's reader keeps doubles and rounded to float32 where it keeps float32."""
    mesh = textured(normals)
    path = tmp_path / f"m{suffix}"
    write_mesh(mesh, path)
    back = read_mesh(path)

    def kept(name, values):
        return values.astype(np.float32).astype(np.float64) if name in FLOAT32[suffix] else values

    np.testing.assert_array_equal(back.points, kept("points", mesh.points))
    np.testing.assert_array_equal(back.triangles, mesh.triangles)
    np.testing.assert_array_equal(back.tcoords, kept("tcoords", mesh.tcoords))
    if normals:
        unit = kept("normals", mesh.point_normals)
        np.testing.assert_allclose(back.point_normals, unit / np.linalg.norm(unit, axis=1, keepdims=True), atol=1e-15)
    else:
        assert back.point_normals is None
    assert pv.read(path).n_points == mesh.n_points


def test_written_forms(tmp_path):
    mesh = textured(False)
    write_mesh(mesh, tmp_path / "m.ply")
    write_mesh(mesh, tmp_path / "m.obj")
    write_mesh(with_normals(mesh, "radial"), tmp_path / "n.obj")
    write_mesh(mesh, tmp_path / "m.vtp")
    assert b"property double s\nproperty double t\n" in (tmp_path / "m.ply").read_bytes()
    obj = (tmp_path / "m.obj").read_text().splitlines()
    assert sum(line.startswith("vt ") for line in obj) == mesh.n_points
    a, b, c = mesh.triangles[0] + 1
    assert f"f {a}/{a} {b}/{b} {c}/{c}" in obj
    assert f"f {a}/{a}/{a} {b}/{b}/{b} {c}/{c}/{c}" in (tmp_path / "n.obj").read_text().splitlines()
    assert b'TCoords="TCoords"' in (tmp_path / "m.vtp").read_bytes()


def test_stl_drops_tcoords(tmp_path):
    write_mesh(textured(False), tmp_path / "m.stl")
    assert read_mesh(tmp_path / "m.stl").tcoords is None


def test_no_tcoords_written_when_none(tmp_path):
    mesh = shapes.icosphere(level=1)
    for suffix in (".ply", ".obj", ".vtp"):
        write_mesh(mesh, tmp_path / f"m{suffix}")
        assert read_mesh(tmp_path / f"m{suffix}").tcoords is None
    assert "vt " not in (tmp_path / "m.obj").read_text()


# ---------------------------------------------------------------------------------------
# Normals keep texture coordinates


def source_of(new: Mesh, old: Mesh) -> np.ndarray:
    """Index into ``old`` of each point of ``new``, matched by position (positions unique in ``old``)."""
    keys = {tuple(p): i for i, p in enumerate(old.points)}
    assert len(keys) == old.n_points
    return np.array([keys[tuple(p)] for p in new.points])


def test_split_at_creases_copies_tcoords():
    cube = shapes.cube()
    mesh = Mesh(cube.points, cube.triangles, None, cube.points[:, :2] + 0.5 * cube.points[:, 2:])
    split = split_at_creases(mesh, 30.0)
    assert split.n_points == 24  # each corner of the cube split in three
    np.testing.assert_array_equal(split.tcoords, mesh.tcoords[source_of(split, mesh)])
    smooth = split_at_creases(mesh, 180.0)
    np.testing.assert_array_equal(smooth.tcoords, mesh.tcoords)


@pytest.mark.parametrize("mode", NORMAL_MODES)
@pytest.mark.parametrize("crease", [None, 20.0])
def test_every_normal_mode_keeps_tcoords(mode, crease):
    mesh = shapes.cone(segments=12, uv=1)
    out = with_normals(mesh, mode, crease)
    if out.n_points == mesh.n_points:
        np.testing.assert_array_equal(out.tcoords, mesh.tcoords)
    else:  # split: copies carry their source point's tcoords
        assert mode == "computed" and crease is not None
        np.testing.assert_array_equal(out.points[out.triangles], mesh.points[mesh.triangles])
        np.testing.assert_array_equal(out.tcoords[out.triangles], mesh.tcoords[mesh.triangles])
    assert with_normals(shapes.icosphere(1), mode, crease).tcoords is None


# ---------------------------------------------------------------------------------------
# Shapes with uv=1


def s_spread(mesh: Mesh, triangles=None) -> np.ndarray:
    st = mesh.tcoords[mesh.triangles if triangles is None else triangles]
    return st[:, :, 0].max(axis=1) - st[:, :, 0].min(axis=1)


def assert_same_surface(a: Mesh, b: Mesh):
    """Same triangles, corner by corner (positions and normals), hence same area and volume."""
    assert a.n_triangles == b.n_triangles
    np.testing.assert_array_equal(a.points[a.triangles], b.points[b.triangles])
    if a.point_normals is not None:
        np.testing.assert_array_equal(a.point_normals[a.triangles], b.point_normals[b.triangles])
    assert surface_area(a) == pytest.approx(surface_area(b), rel=1e-12)
    assert enclosed_volume(a) == pytest.approx(enclosed_volume(b), rel=1e-12)


@pytest.mark.parametrize("level", [1, 2, 3, 4])
def test_icosphere_uv(level):
    plain, mesh = shapes.icosphere(level, radius=2.0), shapes.icosphere(level, radius=2.0, uv=1)
    assert plain.tcoords is None
    assert_same_surface(plain, mesh)
    np.testing.assert_array_equal(mesh.points[:plain.n_points], plain.points)  # copies come after
    s, t = mesh.tcoords.T
    # no triangle interpolates across the seam: every triangle's s spread is < 0.5
    assert s_spread(mesh).max() < 0.5
    assert s.min() >= 0.0 and s.max() < 1.5 and t.min() >= 0.0 and t.max() <= 1.0
    # the convention: t from the latitude (+y up), s from the longitude atan2(x, z), up to whole turns
    x, y, z = mesh.points.T
    np.testing.assert_allclose(t, 0.5 + np.arcsin(np.clip(y / 2.0, -1, 1)) / np.pi, atol=1e-12)
    away = np.hypot(x, z) > 1e-9
    turns = s[away] - (0.5 + np.arctan2(x[away], z[away]) / (2 * np.pi))
    np.testing.assert_allclose(turns, np.round(turns), atol=1e-12)
    # seam (x = 0, z < 0): each point on it is split, used with s = 0 and with s = 1
    seam = away & (np.abs(x) < 1e-12) & (z < 0)
    seam_places = {tuple(p) for p in mesh.points[seam]}
    assert len(seam_places) == 2 ** (level + 1) - 1  # the half meridian's points between the poles
    for place in seam_places:
        copies = np.all(mesh.points == place, axis=1)
        assert sorted(s[copies]) == [0.0, 1.0]
    # poles: one point per triangle around each, with t = 1 (north) or 0 (south), s the
    # mean of the two other vertices of its triangle
    for sign, pole_t in ((1, 1.0), (-1, 0.0)):
        at_pole = np.flatnonzero(np.all(np.isclose(mesh.points, [0, 2.0 * sign, 0], atol=1e-12), axis=1))
        tris = np.flatnonzero(np.isin(mesh.triangles, at_pole).any(axis=1))
        assert len(at_pole) == len(tris) == 6  # an edge midpoint of the icosahedron: valence 6
        np.testing.assert_array_equal(t[at_pole], pole_t)
        for tri in mesh.triangles[tris]:
            pole, others = tri[np.isin(tri, at_pole)], tri[~np.isin(tri, at_pole)]
            assert s[pole[0]] == pytest.approx(s[others].mean(), abs=1e-15)
    # only points are split: each copy is at the place of an original point
    assert mesh.n_points > plain.n_points


def test_icosphere_uv_level_0():
    """No pole vertices: the poles lie on edges, whose two triangles span half the image."""
    plain, mesh = shapes.icosphere(0), shapes.icosphere(0, uv=1)
    assert_same_surface(plain, mesh)
    assert s_spread(mesh).max() == pytest.approx(0.5)


@pytest.mark.parametrize("segments", [3, 8, 32])
@pytest.mark.parametrize("make", [shapes.cylinder, shapes.cone])
def test_cylinder_and_cone_uv(make, segments):
    plain, mesh = make(segments=segments, radius=0.7, height=1.3), make(segments=segments, radius=0.7, height=1.3, uv=1)
    assert plain.tcoords is None
    assert_same_surface(plain, mesh)
    s, t = mesh.tcoords.T
    assert s.min() == 0.0 and s.max() == 1.0 and t.min() == 0.0 and t.max() == 1.0
    p = mesh.points
    side = mesh.point_normals[:, 2] > -1.0 + 1e-12
    side &= (mesh.point_normals[:, 2] < 1.0 - 1e-12) if make is shapes.cylinder else True
    side_tris = mesh.triangles[side[mesh.triangles].all(axis=1)]
    assert len(side_tris) == (2 if make is shapes.cylinder else 1) * segments
    assert s_spread(mesh, side_tris).max() == pytest.approx(1.0 / segments)  # no triangle across the seam
    # side: s = θ/2π (θ of the normal, in [0, 2π]: 2π at the seam column), t = (z + h/2)/h
    theta = np.arctan2(mesh.point_normals[side, 1], mesh.point_normals[side, 0]) % (2 * np.pi)
    turns = s[side] - theta / (2 * np.pi)
    np.testing.assert_allclose(turns, np.round(turns), atol=1e-12)
    assert set(np.round(turns)) <= {0.0, 1.0}
    np.testing.assert_allclose(t[side], (p[side, 2] + 0.65) / 1.3, atol=1e-12)
    # one seam column: s = 1 at the place of s = 0
    seam = side & (s == 1.0)
    assert seam.sum() == (2 if make is shapes.cylinder else 1)
    # caps: planar
    np.testing.assert_allclose(s[~side], 0.5 + p[~side, 0] / 1.4, atol=1e-12)
    np.testing.assert_allclose(t[~side], 0.5 + p[~side, 1] / 1.4, atol=1e-12)
    assert mesh.n_points == plain.n_points + (2 if make is shapes.cylinder else 1)


def test_uv_through_the_loader():
    mesh = make_shape("icosphere", {"level": 2, "uv": 1})
    assert mesh.tcoords is not None
    assert make_shape("cylinder", {"uv": 1}).tcoords is not None
    assert make_shape("cone", {"uv": 0}).tcoords is None
    with pytest.raises(Exception, match="uv"):
        make_shape("cone", {"uv": 2})


def test_csg_meshes_have_no_tcoords():
    from lab import csg

    mesh = csg.to_mesh(csg.sphere(0.5), segments=16)
    assert mesh.tcoords is None
