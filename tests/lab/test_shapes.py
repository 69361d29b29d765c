"""Specification of ``lab.shapes``: the built-in shapes, their sizes, closure and normals.

Menger sponge, icosahedron flake, icosphere, cylinder and cone: counts, surface area and
enclosed volume (divergence theorem), orientation (counter-clockwise from outside) and the
point normals the shapes carry.
"""
from __future__ import annotations

import inspect
import math
import time

import numpy as np
import pytest

from lab.framing import make_shape
from lab.normals import face_normals
from lab.shapes import PHI, SHAPES, cone, cube, cylinder, icosahedron, icosahedron_fractal, icosphere, menger


def area(mesh):
    p = mesh.points[mesh.triangles]
    return np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1).sum() / 2.0


def volume(mesh):
    """Divergence theorem: sum over triangles of v0 · (v1 × v2) / 6."""
    p = mesh.points[mesh.triangles]
    return np.einsum("ij,ij->i", p[:, 0], np.cross(p[:, 1], p[:, 2])).sum() / 6.0


def directed_edge_counts(mesh):
    """(keys of directed edges a→b, their counts, counts of their reverses b→a)."""
    t = mesh.triangles
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    n = mesh.n_points
    keys, counts = np.unique(e[:, 0] * n + e[:, 1], return_counts=True)
    rev = (keys % n) * n + keys // n
    pos = np.searchsorted(keys, rev)
    found = (pos < len(keys)) & (keys[np.minimum(pos, len(keys) - 1)] == rev)
    rev_counts = np.where(found, counts[np.minimum(pos, len(keys) - 1)], 0)
    return keys, counts, rev_counts


def polygon_area(segments, r):
    return segments / 2.0 * r * r * math.sin(2.0 * math.pi / segments)


# --------------------------------------------------------------------------- registry
def test_new_shapes_are_registered_with_loader_compatible_parameters():
    """menger, icosahedron_fractal, cylinder and cone are in SHAPES, with int/float defaults only."""
    for name, fn in [("menger", menger), ("icosahedron_fractal", icosahedron_fractal),
                     ("cylinder", cylinder), ("cone", cone)]:
        assert SHAPES[name] is fn
        for p in inspect.signature(fn).parameters.values():
            assert type(p.default) in (int, float), (name, p.name)


def test_make_shape_builds_menger_with_its_flag():
    """The loader dispatches menger with level and keep_internal given as whole numbers."""
    m = make_shape("menger", {"level": 1, "keep_internal": 1})
    assert m.n_triangles == 20 * 12


# --------------------------------------------------------------------------- menger
@pytest.mark.parametrize("n", range(5))
def test_menger_area_and_volume(n):
    """Level N: area 2·(20/9)^N + 4·(8/9)^N and volume (20/27)^N, to 1e-9 relative."""
    m = menger(level=n)
    assert area(m) == pytest.approx(2 * (20 / 9) ** n + 4 * (8 / 9) ** n, rel=1e-9)
    assert volume(m) == pytest.approx((20 / 27) ** n, rel=1e-9)


@pytest.mark.parametrize("n", range(4))
def test_menger_keep_internal_has_all_faces_and_the_same_volume(n):
    """keep_internal=1: all 6·20^N faces, area 6·20^N·9^-N (larger for N ≥ 1), volume unchanged."""
    m = menger(level=n, keep_internal=1)
    assert m.n_triangles == 12 * 20 ** n
    assert area(m) == pytest.approx(6 * 20 ** n / 9 ** n, rel=1e-9)
    if n >= 1:
        assert area(m) > area(menger(level=n)) + 1.0
    assert volume(m) == pytest.approx((20 / 27) ** n, rel=1e-9)


@pytest.mark.parametrize("n", range(4))
def test_menger_is_closed_and_consistently_oriented(n):
    """Every directed edge occurs exactly once and its reverse exactly once (closed 2-manifold)."""
    m = menger(level=n)
    _, counts, rev_counts = directed_edge_counts(m)
    assert (counts == 1).all()
    assert (rev_counts == 1).all()


@pytest.mark.parametrize("n", range(4))
def test_menger_has_no_duplicate_or_unused_points_and_fills_the_unit_cube(n):
    """Points are distinct, all used, on the 3^-N grid, with bounds ±0.5."""
    m = menger(level=n)
    assert len(np.unique(np.round(m.points * 2 * 3 ** n).astype(np.int64), axis=0)) == m.n_points
    assert np.array_equal(np.unique(m.triangles), np.arange(m.n_points))
    np.testing.assert_allclose(m.bounds(), [-0.5, 0.5] * 3)
    assert m.point_normals is None


def test_menger_level_0_is_the_cube():
    """Level 0 is cube(): the same points, in the same order, and the same triangles."""
    m, c = menger(level=0), cube()
    np.testing.assert_array_equal(m.points, c.points)
    np.testing.assert_array_equal(m.triangles, c.triangles)


def test_menger_level_4_builds_fast():
    """Level 4 (160 000 cubes) builds in under 10 s."""
    t0 = time.perf_counter()
    m = menger(level=4)
    dt = time.perf_counter() - t0
    print(f"menger(level=4): {dt:.3f} s, {m.n_points} points, {m.n_triangles} triangles")
    assert dt < 10.0


# --------------------------------------------------------------------------- icosahedron flake
@pytest.mark.parametrize("n", range(4))
def test_icosahedron_fractal_counts_and_bounds(n):
    """12^N icosahedra, 20·12^N triangles, every point in the unit ball (+1e-12)."""
    m = icosahedron_fractal(level=n)
    assert m.n_points == 12 * 12 ** n
    assert m.n_triangles == 20 * 12 ** n
    assert np.linalg.norm(m.points, axis=1).max() <= 1.0 + 1e-12
    assert volume(m) == pytest.approx(12 ** n * (1 / (1 + PHI)) ** (3 * n) * volume(icosahedron()), rel=1e-9)


def test_icosahedron_fractal_level_0_is_the_icosahedron():
    """Level 0 is icosahedron() of circumradius 1."""
    m, ico = icosahedron_fractal(level=0), icosahedron()
    np.testing.assert_array_equal(m.points, ico.points)
    np.testing.assert_array_equal(m.triangles, ico.triangles)


@pytest.mark.parametrize("n", [1, 2])
def test_icosahedron_fractal_neighbouring_copies_share_an_edge(n):
    """Sibling copies at adjacent vertices share exactly one edge and lie on either side of it; others don't touch."""
    ico = icosahedron()
    e = np.concatenate([ico.triangles[:, [0, 1]], ico.triangles[:, [1, 2]], ico.triangles[:, [2, 0]]])
    adjacent = np.zeros((12, 12), dtype=bool)
    adjacent[e[:, 0], e[:, 1]] = True
    s = 1.0 / (1.0 + PHI)
    midradius = PHI / math.sqrt(1.0 + PHI ** 2)           # of the unit-circumradius icosahedron
    child_r = s ** n                                       # circumradius of one copy
    groups = icosahedron_fractal(level=n).points.reshape(-1, 12, 12, 3)   # (parents, child, vertex, xyz)
    centres = groups.mean(axis=2)
    for i in range(12):
        for j in range(i + 1, 12):
            d = np.linalg.norm(groups[:, i, :, None, :] - groups[:, j, None, :, :], axis=3)  # (parents, 12, 12)
            gap = np.linalg.norm(centres[:, j] - centres[:, i], axis=1)
            if adjacent[i, j]:
                # distance between centres = the two copies' reaches (midradii) along it
                np.testing.assert_allclose(gap, 2 * midradius * child_r, rtol=1e-12)
                assert ((d < 1e-12).sum(axis=(1, 2)) == 2).all()
                u = (centres[:, j] - centres[:, i]) / gap[:, None]
                mid = (centres[:, i] + centres[:, j]) / 2
                side_i = np.einsum("pvk,pk->pv", groups[:, i] - mid[:, None], u)
                side_j = np.einsum("pvk,pk->pv", groups[:, j] - mid[:, None], u)
                assert side_i.max() <= 1e-12 and side_j.min() >= -1e-12
            else:
                assert d.min() > 0.1 * child_r


# --------------------------------------------------------------------------- icosphere
@pytest.mark.parametrize("n", range(6))
def test_icosphere_counts_and_radius(n):
    """20·4^N faces, every vertex at radius 1 (1e-12)."""
    m = icosphere(level=n)
    assert m.n_triangles == 20 * 4 ** n
    np.testing.assert_allclose(np.linalg.norm(m.points, axis=1), 1.0, atol=1e-12)


# --------------------------------------------------------------------------- cylinder and cone
CASES = [(3, 0.5, 1.0), (8, 0.5, 1.0), (32, 0.5, 1.0), (100, 1.3, 0.4), (7, 0.2, 2.5)]


@pytest.mark.parametrize("segments,radius,height", CASES)
def test_cylinder_is_closed_outward_polygon_prism(segments, radius, height):
    """Volume = the polygonal prism's, segments/2·r²·sin(2π/segments)·h; bounds along z ±h/2."""
    m = cylinder(segments=segments, radius=radius, height=height)
    assert m.n_triangles == 4 * segments
    assert volume(m) == pytest.approx(polygon_area(segments, radius) * height, rel=1e-12)
    assert area(m) == pytest.approx(2 * polygon_area(segments, radius)
                                    + segments * 2 * radius * math.sin(math.pi / segments) * height, rel=1e-12)
    np.testing.assert_allclose(m.bounds()[4:], [-height / 2, height / 2])


@pytest.mark.parametrize("segments,radius,height", CASES)
def test_cone_is_closed_outward_polygon_pyramid(segments, radius, height):
    """Volume = the polygonal pyramid's, segments/2·r²·sin(2π/segments)·h/3; apex at +h/2."""
    m = cone(segments=segments, radius=radius, height=height)
    assert m.n_triangles == 2 * segments
    assert volume(m) == pytest.approx(polygon_area(segments, radius) * height / 3, rel=1e-12)
    assert m.points[:, 2].max() == height / 2 and m.points[:, 2].min() == -height / 2


@pytest.mark.parametrize("shape", [cylinder, cone])
@pytest.mark.parametrize("segments,radius,height", CASES)
def test_geometrically_closed_and_normals_agree_with_faces(shape, segments, radius, height):
    """Closed by position (directed edges balance) and every vertex normal is unit, within 90° of its face."""
    m = shape(segments=segments, radius=radius, height=height)
    _, inv = np.unique(m.points, axis=0, return_inverse=True)
    welded = type(m)(m.points, inv.ravel()[m.triangles])
    _, counts, rev_counts = directed_edge_counts(welded)
    assert (counts == 1).all() and (rev_counts == 1).all()
    np.testing.assert_allclose(np.linalg.norm(m.point_normals, axis=1), 1.0, atol=1e-12)
    fn = face_normals(m.points, m.triangles)
    dots = np.einsum("tk,tck->tc", fn, m.point_normals[m.triangles])
    assert dots.min() > 0.0


@pytest.mark.parametrize("shape", [cylinder, cone])
@pytest.mark.parametrize("segments,radius,height", CASES)
def test_caps_are_flat_with_axial_normals(shape, segments, radius, height):
    """Cap triangles' vertex normals are (0, 0, ±1) and equal their face normals; one cap per end of a cylinder."""
    m = shape(segments=segments, radius=radius, height=height)
    fn = face_normals(m.points, m.triangles)
    cap = np.abs(fn[:, 2]) > 1 - 1e-12
    expected = 2 * segments if shape is cylinder else segments
    assert cap.sum() == expected
    np.testing.assert_allclose(m.point_normals[m.triangles[cap]], np.repeat(fn[cap, None, :], 3, axis=1), atol=1e-15)
    assert set(np.unique(np.round(fn[cap, 2]))) == ({-1.0, 1.0} if shape is cylinder else {-1.0})


@pytest.mark.parametrize("segments,radius,height", CASES)
def test_cylinder_side_normals_are_radial(segments, radius, height):
    """Side vertex normals are (cos θ, sin θ, 0) with θ the point's own angle around z."""
    m = cylinder(segments=segments, radius=radius, height=height)
    side = np.abs(m.point_normals[:, 2]) < 0.5
    assert side.sum() == 2 * segments
    p = m.points[side]
    theta = np.arctan2(p[:, 1], p[:, 0])
    np.testing.assert_allclose(m.point_normals[side], np.column_stack([np.cos(theta), np.sin(theta), 0 * theta]),
                               atol=1e-12)
    np.testing.assert_allclose(np.hypot(p[:, 0], p[:, 1]), radius, rtol=1e-12)


@pytest.mark.parametrize("segments,radius,height", CASES)
def test_cone_side_normals_are_tilted_up_by_the_half_angle(segments, radius, height):
    """Side normals are (h cos θ, h sin θ, r)/√(h²+r²): at acos(r/√(h²+r²)) from +z (up by the half-angle)."""
    m = cone(segments=segments, radius=radius, height=height)
    side = m.point_normals[:, 2] > 0
    n = m.point_normals[side]
    np.testing.assert_allclose(n[:, 2], radius / math.hypot(height, radius), rtol=1e-12)
    half_angle = math.atan2(radius, height)
    np.testing.assert_allclose(np.arcsin(n[:, 2]), half_angle, atol=1e-12)   # up from the horizontal
    ring = side & (m.points[:, 2] < 0)
    theta = np.arctan2(m.points[ring, 1], m.points[ring, 0])
    np.testing.assert_allclose(np.arctan2(m.point_normals[ring, 1], m.point_normals[ring, 0]), theta, atol=1e-12)


@pytest.mark.parametrize("segments,radius,height", CASES)
def test_cone_apex_has_one_point_per_side_with_mid_segment_normals(segments, radius, height):
    """`segments` apex points at (0, 0, h/2), distinct normals, each at the middle angle of its triangle's base edge."""
    m = cone(segments=segments, radius=radius, height=height)
    apex = np.flatnonzero(m.points[:, 2] == height / 2)
    assert len(apex) == segments
    np.testing.assert_array_equal(m.points[apex], np.tile([0.0, 0.0, height / 2], (segments, 1)))
    assert len(np.unique(np.round(m.point_normals[apex], 9), axis=0)) == segments
    tris = m.triangles[np.isin(m.triangles, apex).any(axis=1)]
    assert len(tris) == segments and len(np.unique(tris[np.isin(tris, apex)])) == segments
    for t in tris:
        a = t[np.isin(t, apex)][0]
        base = m.points[t[~np.isin(t, apex)]]
        mid = base.mean(axis=0)
        n = m.point_normals[a]
        np.testing.assert_allclose(n[:2] / np.linalg.norm(n[:2]), mid[:2] / np.linalg.norm(mid[:2]), atol=1e-12)


@pytest.mark.parametrize("shape", [cylinder, cone])
def test_too_few_segments_is_an_error(shape):
    """Fewer than 3 segments raises ValueError."""
    with pytest.raises(ValueError, match="segments"):
        shape(segments=2)


def test_a_split_in_four_shares_each_edge_midpoint_and_keeps_the_winding():
    from lab.shapes import split_in_four

    points = np.array([[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]])
    mid, tris = split_in_four(points, np.array([[0, 1, 2], [0, 2, 3]]))
    assert len(mid) == 5 and len(tris) == 8  # the shared diagonal's midpoint made once
    all_points = np.concatenate([points, mid])
    p = all_points[tris]
    normal_z = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])[:, 2]
    assert (normal_z > 0).all()  # every child wound as its counter-clockwise parent
    assert {tuple(m) for m in mid.tolist()} == {(0.5, 0, 0), (1, 0.5, 0), (0.5, 0.5, 0), (0.5, 1, 0), (0, 0.5, 0)}


def test_a_split_in_four_keeps_each_triangles_children_together_in_its_order():
    """Parent i's four children are rows 4i … 4i + 3: each has a corner or the centre of its
    parent, and the list of children keeps the parents' order (neighbours stay neighbours)."""
    from lab.shapes import split_in_four

    points = np.array([[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]])
    parents = np.array([[0, 1, 2], [0, 2, 3], [1, 4, 2]])
    mid, tris = split_in_four(points, parents)
    all_points = np.concatenate([points, mid])
    centres = all_points[tris].mean(axis=1)
    for i, parent in enumerate(parents):
        children = tris[4 * i:4 * i + 4]
        assert children[:3, 0].tolist() == parent.tolist()  # (a, ·, ·), (b, ·, ·), (c, ·, ·)
        np.testing.assert_allclose(centres[4 * i + 3], all_points[parent].mean(axis=0), atol=1e-12)
