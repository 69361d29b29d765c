"""Which reference a textbook model's object gets: a replaced shader per pixel, else colours lit in numpy."""
import numpy as np
import pytest

from lab.mesh import Mesh
from lab.scene import SceneObject
from lab.shapes import quad

from compare.lit_reference.reference_kinds import NATIVE, REFERENCES, SHADER, UNLIT, never, textbook_reference

FLAT = quad(1.0)
SMOOTH = Mesh(FLAT.points, FLAT.triangles, point_normals=np.tile([0.0, 0.0, 1.0], (len(FLAT.points), 1)))


@pytest.mark.parametrize("mesh, shading, expected", [(SMOOTH, "phong", SHADER), (SMOOTH, "gouraud", UNLIT),
                                                     (SMOOTH, "flat", UNLIT), (FLAT, "phong", UNLIT)])
def test_phong_with_normals_gets_a_shader_everything_else_unlit_colours(mesh, shading, expected):
    assert textbook_reference(SceneObject(mesh=mesh, shading=shading)) == expected


def test_the_reference_names_are_the_metrics_names():
    assert REFERENCES == ("vtk-native", "vtk-unlit-colours", "vtk-shader-replacement") == (NATIVE, UNLIT, SHADER)
    assert never(None) is False
