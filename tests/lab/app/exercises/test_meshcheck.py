"""Geometry judged as geometry: a cube (and broken cubes) against what a cube must be."""
import numpy as np
import pytest

from lab import shapes
from lab.app.exercises.meshcheck import Expected, convex_outward, mesh_findings, probe_outward

CUBE = shapes.cube()
EXPECTED = Expected(bounds=np.array([-0.5, 0.5] * 3), area=6.0, volume=1.0, outward=convex_outward(), triangles=12,
                    merged=True)


def codes(points, triangles, expected=EXPECTED):
    return [f.code for f in mesh_findings("cube()", points, triangles, expected)]


def test_the_cube_passes_in_any_point_order_and_corner_rotation():
    order = np.random.default_rng(0).permutation(8)
    inverse = np.argsort(order)
    tris = inverse[CUBE.triangles][:, [1, 2, 0]]
    assert codes(CUBE.points[order], tris) == []


def test_one_flipped_face_is_two_inward_triangles():
    tris = CUBE.triangles.copy()
    tris[:2] = tris[:2, ::-1]
    (finding,) = mesh_findings("cube()", CUBE.points, tris, EXPECTED)
    assert (finding.code, finding.details["count"], finding.details["total"]) == ("faces-inward", 2, 12)


def test_a_missing_triangle_is_a_hole():
    assert codes(CUBE.points, CUBE.triangles[1:]) == ["not-closed"]


def test_unshared_points_at_the_same_places_are_not_merged():
    points = CUBE.points[CUBE.triangles.ravel()]
    assert codes(points, np.arange(36).reshape(12, 3)) == ["points-not-merged"]


def test_unshared_points_a_little_apart_are_cracks():
    points = CUBE.points[CUBE.triangles.ravel()] + np.random.default_rng(1).uniform(-1e-7, 1e-7, (36, 3))
    (finding,) = mesh_findings("cube()", points, np.arange(36).reshape(12, 3), EXPECTED)
    assert finding.code == "cracks" and 1e-8 < finding.details["gap"] < 1e-6


def test_a_sine_of_1e_16_is_no_crack():
    points = CUBE.points[CUBE.triangles.ravel()] + 1e-16
    points[::2] -= 1e-16
    assert codes(points, np.arange(36).reshape(12, 3), Expected(**{**EXPECTED.__dict__, "merged": False})) == []


@pytest.mark.parametrize("scale, shift, code", [(3.0, 0.0, "wrong-scale"), (1.0, 0.5, "not-centred")])
def test_size_and_place(scale, shift, code):
    assert codes(CUBE.points * scale + shift, CUBE.triangles) == [code]


def test_values_that_are_not_a_mesh():
    points = CUBE.points.copy()
    points[3, 1] = np.nan
    assert codes(points, CUBE.triangles) == ["nonfinite-values"]
    assert codes(CUBE.points, CUBE.triangles + 1) == ["index-out-of-range"]
    assert codes(CUBE.points, CUBE.triangles[:0]) == ["no-triangles"]
    assert codes(CUBE.points, np.vstack([CUBE.triangles, [[0, 0, 1]]]))[0] == "degenerate-triangles"


def test_a_face_inside_the_solid_is_internal_and_one_outside_is_stray():
    inside = lambda p: np.all(np.abs(p) < 0.5, axis=1)  # noqa: E731
    expected = Expected(**{**EXPECTED.__dict__, "outward": probe_outward(inside, 0.01), "merged": False})
    middle = np.array([[-0.5, -0.5, 0], [0.5, -0.5, 0], [0.5, 0.5, 0], [-0.5, 0.5, 0]])
    points = np.vstack([CUBE.points, middle])
    both_ways = np.array([[8, 9, 10], [8, 10, 11], [8, 10, 9], [8, 11, 10]])
    found = codes(points, np.vstack([CUBE.triangles, both_ways]), expected)
    assert found == ["internal-faces-kept"]
    ball = lambda p: np.linalg.norm(p, axis=1) < 0.3  # noqa: E731 -- a solid the cube's faces are all outside of
    elsewhere = Expected(**{**EXPECTED.__dict__, "outward": probe_outward(ball, 0.01)})
    assert codes(CUBE.points, CUBE.triangles, elsewhere) == ["stray-faces"]


def test_a_wrong_volume_is_offered_to_the_exercise_first():
    explain = lambda call, volume: []  # noqa: E731
    big = Expected(**{**EXPECTED.__dict__, "volume": 2.0, "explain": explain})
    assert codes(CUBE.points, CUBE.triangles, big) == ["wrong-volume"]
