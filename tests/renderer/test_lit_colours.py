"""Stage 7a: lit colours once per vertex (Gouraud) and once per triangle (flat), only where an object's path asks.

One triangle at z = −2 in view space, facing the eye, under a light straight down −z, the
classic model with Ka·O = .1, Kd·O = (.3, .5, .7), Ks = 0, ambient light 1: a lit point
whose unit normal is (0, 0, 1) gets .1 + (.3, .5, .7) = (.4, .6, .8).
"""
import numpy as np

from renderer.lit_colours import lit_colours
from renderer.pipeline import SceneGeometry
from renderer.reflection.materials import FACE_COLOUR, PIXEL_TWO_SIDED, VERTEX_COLOUR

from .kernel_inputs import materials, view_lights

LIT = [0.4, 0.6, 0.8]


def geometry(normals):
    verts = np.array([[0.0, 0.0, -2.0], [1.0, 0.0, -2.0], [0.0, 1.0, -2.0]])
    return SceneGeometry(verts, np.c_[verts, np.ones(3)], np.zeros(3, np.uint8), np.asarray(normals, float), np.array([[0, 1, 2]]),
                         np.zeros(1, np.int64), np.zeros(3, np.int64), np.zeros((3, 2)), np.array([[0.0, 0, 1]]), False)


def lit(path, normals=((0, 0, 2.0),) * 3):
    table = materials(0.1, (0.3, 0.5, 0.7), 0, 1, model="classic", path=path)
    return lit_colours(geometry(normals), table, view_lights([{"direction": (0, 0, -1)}], ambient_light=(1, 1, 1)))


def test_vertex_colours_light_each_vertex_with_its_normal_normalised():
    """VERTEX_COLOUR: normals (0, 0, 2) are normalised first, so every vertex gets (.4, .6, .8), secondary 0;
    a zero normal stays zero: ambient only, .1."""
    colours = lit(VERTEX_COLOUR).vertex
    np.testing.assert_allclose(colours, [LIT + [0, 0, 0]] * 3)
    dark = lit(VERTEX_COLOUR, normals=((0, 0, 2.0), (0, 0, 0), (0, 0, 1.0))).vertex
    np.testing.assert_allclose(dark[1], [0.1, 0.1, 0.1, 0, 0, 0])


def test_face_colours_light_the_triangle_once_with_its_plane_normal():
    """FACE_COLOUR: the plane normal (0, 0, 1), whatever the vertex normals: (.4, .6, .8)."""
    colours = lit(FACE_COLOUR, normals=((0, 0, -1.0),) * 3).face
    np.testing.assert_allclose(colours, [LIT + [0, 0, 0]])


def test_objects_lit_per_pixel_get_no_lit_colours():
    """PIXEL_TWO_SIDED objects are left alone: the rows are not written (NaN stays where it was put)."""
    from renderer.workspace import Workspace

    ws = Workspace()
    ws.array("shade.vert_colour", (3, 6))[:] = np.nan
    ws.array("shade.face_colour", (1, 6))[:] = np.nan
    table = materials(0.1, 0.3, 0, 1, path=PIXEL_TWO_SIDED)
    colours = lit_colours(geometry(((0, 0, 1.0),) * 3), table, view_lights(), ws)
    assert np.isnan(colours.vertex).all() and np.isnan(colours.face).all()
