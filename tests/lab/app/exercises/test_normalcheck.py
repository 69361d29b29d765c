"""Point normals of the cylinder and the cone, judged point by point."""
import numpy as np

from lab import shapes
from lab.app.exercises.catalogue.cone import round_shape as cone_shape
from lab.app.exercises.catalogue.cylinder import round_shape as cylinder_shape
from lab.app.exercises.normalcheck import normal_findings
from lab.app.exercises.exercise_registry import Case

CYL = Case((12, 0.5, 1.0), "cylinder(12, 0.5, 1)")
CONE = Case((12, 0.5, 1.0), "cone(12, 0.5, 1)")


def codes(mesh, normals, case, shape):
    return [f.code for f in normal_findings(case.call, mesh.points, mesh.triangles, normals, shape(case))]


def test_the_built_in_shapes_pass():
    assert codes(shapes.cylinder(12, 0.5, 1.0), shapes.cylinder(12, 0.5, 1.0).point_normals, CYL, cylinder_shape) == []
    assert codes(shapes.cone(12, 0.5, 1.0), shapes.cone(12, 0.5, 1.0).point_normals, CONE, cone_shape) == []


def test_scaled_normals_are_not_unit():
    mesh = shapes.cylinder(12, 0.5, 1.0)
    assert codes(mesh, mesh.point_normals * 2, CYL, cylinder_shape) == ["normals-not-unit"]


def test_flipped_side_normals_point_inward_and_flipped_caps_are_wrong_caps():
    mesh = shapes.cylinder(12, 0.5, 1.0)
    side = np.abs(mesh.point_normals[:, 2]) < 0.5
    flipped = np.where(side[:, None], -mesh.point_normals, mesh.point_normals)
    assert codes(mesh, flipped, CYL, cylinder_shape) == ["normals-inward"]
    assert codes(mesh, np.where(side[:, None], mesh.point_normals, -mesh.point_normals), CYL,
                 cylinder_shape) == ["cap-normals-wrong"]


def test_cylinder_normals_on_a_cone_are_not_tilted():
    mesh = shapes.cone(12, 0.5, 1.0)
    flat = mesh.point_normals.copy()
    ring = np.abs(mesh.points[:, 2] + 0.5) < 1e-12
    side_ring = ring & (mesh.point_normals[:, 2] > 0)
    flat[side_ring] = np.column_stack([mesh.points[side_ring, :2] / 0.5, np.zeros(side_ring.sum())])
    assert codes(mesh, flat, CONE, cone_shape) == ["cone-normals-not-tilted"]


def test_an_apex_normal_anywhere_within_its_segment_passes_and_straight_up_does_not():
    mesh = shapes.cone(12, 0.5, 1.0)
    apex = np.flatnonzero(np.abs(mesh.points[:, 2] - 0.5) < 1e-12)
    averaged = mesh.point_normals.copy()
    averaged[apex] *= [1.0, 1.0, 1.2]
    averaged[apex] /= np.linalg.norm(averaged[apex], axis=1, keepdims=True)
    assert codes(mesh, averaged, CONE, cone_shape) == []
    up = mesh.point_normals.copy()
    up[apex] = [0.0, 0.0, 1.0]
    assert codes(mesh, up, CONE, cone_shape) == ["side-normals-wrong"]
