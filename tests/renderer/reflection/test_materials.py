"""What every reflection model shares: when an object is smooth, and where the textbook's pipeline lights it."""
import numpy as np
import pytest

from lab.mesh import Mesh
from lab.scene import SceneObject
from lab.shapes import quad
from renderer.reflection.materials import (FACE_COLOUR, PIXEL_AS_GIVEN, PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED, VERTEX_COLOUR,
                                          any_face_colour, any_flat, smooth, textbook_path)

FLAT = quad(1.0)
WITH_NORMALS = Mesh(FLAT.points, FLAT.triangles, point_normals=np.tile([0.0, 0.0, 1.0], (len(FLAT.points), 1)))


@pytest.mark.parametrize("mesh, shading, expected", [
    (WITH_NORMALS, "gouraud", True), (WITH_NORMALS, "phong", True), (WITH_NORMALS, "flat", False),
    (FLAT, "gouraud", False), (FLAT, "phong", False)])
def test_smooth_needs_vertex_normals_and_a_smooth_shading(mesh, shading, expected):
    assert smooth(SceneObject(mesh=mesh, shading=shading)) is expected


@pytest.mark.parametrize("mesh, shading, expected", [
    (WITH_NORMALS, "flat", FACE_COLOUR), (WITH_NORMALS, "gouraud", VERTEX_COLOUR),
    (WITH_NORMALS, "phong", PIXEL_AS_GIVEN), (FLAT, "gouraud", FACE_COLOUR), (FLAT, "phong", FACE_COLOUR)])
def test_the_textbook_lights_faces_vertices_or_pixels(mesh, shading, expected):
    """flat → once per triangle; gouraud → per vertex; phong → per pixel; without normals, flat."""
    assert textbook_path(SceneObject(mesh=mesh, shading=shading)) == expected


@pytest.mark.parametrize("paths, flat", [((PIXEL_FACE_NORMAL,), True), ((VERTEX_COLOUR, FACE_COLOUR), True),
                                         ((PIXEL_TWO_SIDED, VERTEX_COLOUR, PIXEL_AS_GIVEN), False), ((), False)])
def test_a_frame_is_flat_when_some_object_is_lit_with_its_plane_normal_or_holds_a_colour_per_triangle(paths, flat):
    from types import SimpleNamespace

    assert any_flat(SimpleNamespace(shading_path=np.array(paths, np.int64))) is flat


@pytest.mark.parametrize("paths, every", [((PIXEL_FACE_NORMAL,), False), ((VERTEX_COLOUR, FACE_COLOUR), True),
                                          ((PIXEL_TWO_SIDED, PIXEL_AS_GIVEN), False), ((), False)])
def test_a_frame_lights_every_triangle_when_some_object_holds_a_colour_per_triangle(paths, every):
    """FACE_COLOUR lights each of its object's triangles, shown or not: that frame reads every
    plane normal; one lit per pixel with its plane normal reads only those of what it shows."""
    from types import SimpleNamespace

    assert any_face_colour(SimpleNamespace(shading_path=np.array(paths, np.int64))) is every
