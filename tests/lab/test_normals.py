"""Specification of ``lab.normals``: the vertex normals both renderers shade with.

Angle-weighted vertex normals (Thürmer & Wüthrich 1998), split at creases by the
"within the angle of this face" rule, and the four normal modes of a scene.
"""
from __future__ import annotations

import time

import numpy as np
import pytest

from lab.mesh import Mesh
from lab.normals import (
    NORMAL_MODES,
    angle_weighted_normals,
    face_normals,
    split_at_creases,
    with_normals,
)
from lab.shapes import cube, icosphere

AXES = np.array([[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]], dtype=float)


def unit(v):
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)


def flat_grid(nx=6, ny=5, seed=1):
    """A z = 0 grid of nx × ny points, jittered in x and y, quads cut into two triangles
    (alternating diagonals), counter-clockwise seen from +z."""
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.arange(nx, dtype=float), np.arange(ny, dtype=float), indexing="xy")
    pts = np.column_stack([x.ravel(), y.ravel(), np.zeros(nx * ny)])
    pts[:, :2] += rng.uniform(-0.2, 0.2, size=(nx * ny, 2))
    tris = []
    for r in range(ny - 1):
        for c in range(nx - 1):
            a, b, d, e = r * nx + c, r * nx + c + 1, (r + 1) * nx + c + 1, (r + 1) * nx + c
            tris += [(a, b, d), (a, d, e)] if (r + c) % 2 else [(a, b, e), (b, d, e)]
    return Mesh(pts, np.array(tris))


# ---------------------------------------------------------------------------------------
# Face normals


def test_face_normals_are_unit_outward_and_zero_for_degenerate_triangles():
    """face_normals is the unit (v1 − v0) × (v2 − v0), and zero for a collinear triangle."""
    pts = [[0, 0, 0], [2, 0, 0], [0, 3, 0], [4, 0, 0]]
    n = face_normals(pts, [[0, 1, 2], [0, 2, 1], [0, 1, 3]])
    np.testing.assert_array_equal(n, [[0, 0, 1], [0, 0, -1], [0, 0, 0]])


# ---------------------------------------------------------------------------------------
# Smooth surfaces


def test_icosphere_computed_normals_are_radial_and_unit():
    """On a unit icosphere (level 3) the computed normals are unit and within 1e-2 of radial."""
    mesh = icosphere(level=3)
    out = with_normals(mesh, "computed")
    radial = mesh.points / np.linalg.norm(mesh.points, axis=1, keepdims=True)
    np.testing.assert_array_equal(out.points, mesh.points)
    np.testing.assert_allclose(np.linalg.norm(out.point_normals, axis=1), 1.0, atol=1e-12)
    assert np.abs(out.point_normals - radial).max() < 1e-2


def test_icosphere_radial_normals_are_the_normalised_positions_exactly():
    """'radial' normals are exactly points / |points|, points and triangles untouched."""
    mesh = icosphere(level=3)
    out = with_normals(mesh, "radial")
    np.testing.assert_array_equal(out.point_normals, mesh.points / np.linalg.norm(mesh.points, axis=1, keepdims=True))
    np.testing.assert_array_equal(out.points, mesh.points)
    np.testing.assert_array_equal(out.triangles, mesh.triangles)


def test_no_crease_reached_keeps_the_points_in_their_order():
    """A crease wider than any dihedral angle splits nothing: same points, same order, smooth normals."""
    mesh = icosphere(level=3)
    out = split_at_creases(mesh, 40.0)
    np.testing.assert_array_equal(out.points, mesh.points)
    np.testing.assert_array_equal(out.triangles, mesh.triangles)
    np.testing.assert_allclose(out.point_normals, angle_weighted_normals(mesh), atol=1e-12)


def test_flat_grid_normals_are_all_plus_z():
    """On a flat grid every computed normal is (0, 0, 1), smooth or split at creases."""
    mesh = flat_grid()
    for crease in (None, 0.0, 30.0):
        out = with_normals(mesh, "computed", crease_angle=crease)
        assert out.n_points == mesh.n_points
        np.testing.assert_allclose(out.point_normals, np.tile([0.0, 0.0, 1.0], (mesh.n_points, 1)), atol=1e-12)


# ---------------------------------------------------------------------------------------
# The cube: smooth, then split at its edges


def test_cube_smooth_normals_are_the_diagonals():
    """Without a crease the cube keeps its 8 points, normals along ±(1, 1, 1)/√3."""
    mesh = cube()
    out = with_normals(mesh, "computed")
    assert out.n_points == 8
    np.testing.assert_allclose(out.point_normals, np.sign(mesh.points) / np.sqrt(3.0), atol=1e-12)


def test_cube_split_at_30_degrees_has_24_points_with_face_normals():
    """With crease 30 the cube has 24 points, each normal an axis equal to its triangles' face normal."""
    mesh = cube()
    out = with_normals(mesh, "computed", crease_angle=30.0)
    assert out.n_points == 24
    assert len(np.unique(out.points, axis=0)) == 8
    assert all(np.isclose(AXES @ n, 1.0).sum() == 1 for n in out.point_normals)
    fn = face_normals(out.points, out.triangles)
    for corner in range(3):
        np.testing.assert_allclose(out.point_normals[out.triangles[:, corner]], fn, atol=1e-12)


def test_cube_split_keeps_triangle_count_order_and_winding():
    """Splitting keeps the triangles: same count and order, same corner positions, same face normals."""
    mesh = cube()
    out = split_at_creases(mesh, 30.0)
    assert out.n_triangles == mesh.n_triangles
    np.testing.assert_array_equal(out.points[out.triangles], mesh.points[mesh.triangles])
    np.testing.assert_allclose(face_normals(out.points, out.triangles), face_normals(mesh.points, mesh.triangles),
                               atol=1e-12)


# ---------------------------------------------------------------------------------------
# Angle weighting


def test_angle_weighting_not_area_or_count():
    """A vertex whose one face is cut in two gets the angle-weighted normal, not the area or count one.

    Vertex O = (0, 0, 0) meets two faces at right angles along the y axis:
    face A = triangle (O, (1,0,0), (0,1,0)), normal +z, angle 90° at O, area 1/2;
    face B, in the x = 0 plane with normal +x, is the triangle (O, (0,1,0), (0,0,3)) cut
    at M = (0, 1/2, 3/2) into (O, (0,1,0), M) and (O, M, (0,0,3)): angles at O of
    atan(3) and 90° − atan(3), summing to 90°; area 3/2 in all.
    Angle weights: 90°·z + 90°·x → (1, 0, 1)/√2.
    Area weights would give (3, 0, 1)/√10; counting triangles, (2, 0, 1)/√5.
    """
    pts = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0.5, 1.5], [0, 0, 3]]
    mesh = Mesh(pts, [[0, 1, 2], [0, 2, 3], [0, 3, 4]])
    np.testing.assert_allclose(face_normals(mesh.points, mesh.triangles), [[0, 0, 1], [1, 0, 0], [1, 0, 0]],
                               atol=1e-15)
    expected = unit([1, 0, 1])
    for out in (angle_weighted_normals(mesh), split_at_creases(mesh, 180.0).point_normals):
        np.testing.assert_allclose(out[0], expected, atol=1e-12)
        assert not np.allclose(out[0], unit([3, 0, 1]), atol=1e-3)   # area weights
        assert not np.allclose(out[0], unit([2, 0, 1]), atol=1e-3)   # count weights


def test_crease_rule_is_within_angle_of_this_face():
    """Each corner gathers the faces within the crease of its own face, not a chain of neighbours.

    Three triangles meet at O = (0, 0, 0), with normals (0, −sin a, cos a) for tilts
    a = 0°, 25°, 50°. With crease 30° the middle face gathers all three faces, each outer
    face only itself and the middle one (50° apart from the other): three normals, so O
    becomes three points, each the angle-weighted sum of its own face set.
    """
    tilt = np.radians([0.0, 25.0, 50.0])
    pts = [[0.0, 0.0, 0.0]]
    for k, a in enumerate(tilt):
        pts += [[1.0 + k, 0.0, 0.0], [0.5 + k, np.cos(a), np.sin(a)]]
    mesh = Mesh(pts, [[0, 1, 2], [0, 3, 4], [0, 5, 6]])
    fn = face_normals(mesh.points, mesh.triangles)
    np.testing.assert_allclose(fn, np.column_stack([np.zeros(3), -np.sin(tilt), np.cos(tilt)]), atol=1e-15)

    out = split_at_creases(mesh, 30.0)
    assert out.n_points == mesh.n_points + 2
    np.testing.assert_array_equal(out.points[:3], 0.0)          # O, split three ways, first
    np.testing.assert_array_equal(out.triangles[:, 0], [0, 1, 2])
    e1, e2 = mesh.points[mesh.triangles[:, 1]], mesh.points[mesh.triangles[:, 2]]
    w = np.arctan2(np.linalg.norm(np.cross(e1, e2), axis=1), np.einsum("ij,ij->i", e1, e2))  # angles at O
    expected = [unit(w[0] * fn[0] + w[1] * fn[1]), unit(w @ fn), unit(w[1] * fn[1] + w[2] * fn[2])]
    np.testing.assert_allclose(out.point_normals[:3], expected, atol=1e-12)


# ---------------------------------------------------------------------------------------
# Modes


def test_face_mode_drops_the_point_normals():
    """'face' gives point_normals None (faceted shading), points and triangles unchanged."""
    mesh = with_normals(cube(), "computed")
    out = with_normals(mesh, "face")
    assert out.point_normals is None
    np.testing.assert_array_equal(out.points, mesh.points)
    np.testing.assert_array_equal(out.triangles, mesh.triangles)


def test_file_mode_keeps_the_mesh_and_its_normals():
    """'file' returns the mesh as is, with its own normals (or none)."""
    own = np.tile([0.0, 1.0, 0.0], (8, 1))
    mesh = Mesh(cube().points, cube().triangles, own)
    out = with_normals(mesh, "file")
    assert out is mesh
    np.testing.assert_array_equal(out.point_normals, own)
    assert with_normals(cube(), "file").point_normals is None


def test_unknown_mode_raises_naming_the_source():
    """An unknown mode raises ValueError naming the source and the valid modes."""
    with pytest.raises(ValueError, match=r"scenes/demo\.toml.*'smooth'") as info:
        with_normals(cube(), "smooth", source="scenes/demo.toml")
    assert all(mode in str(info.value) for mode in NORMAL_MODES)


# ---------------------------------------------------------------------------------------
# Speed


def test_split_at_creases_is_fast():
    """An icosphere of level 5 (20480 triangles) is split at crease 40 in under 1 s."""
    mesh = icosphere(level=5)
    assert mesh.n_triangles == 20480
    start = time.perf_counter()
    out = with_normals(mesh, "computed", crease_angle=40.0)
    elapsed = time.perf_counter() - start
    assert out.n_triangles == 20480
    assert elapsed < 1.0, f"{elapsed:.2f} s"
