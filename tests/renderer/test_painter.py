"""The painter's algorithm: triangles ordered far to near by the window depth of their centroid.

Window depth runs 0 (near) → 1 (far); every order below is worked out by hand from the
three corner depths of each triangle.
"""
import numpy as np

from lab.scene import Camera, Image, Material, RenderSettings, Scene, SceneObject, headlight
from lab.mesh import Mesh
from renderer import render
from renderer.painter import painter_order


def window_triangles(*corner_depths):
    """(K, 3, 3) window triangles, all over the same pixels, with the given corner depths."""
    xy = np.array([[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]])
    return np.array([np.c_[xy, depths] for depths in corner_depths], np.float64)


def test_the_farthest_centroid_is_drawn_first():
    """Centroid depths .2, .8, .5 → order 1 (.8), 2 (.5), 0 (.2)."""
    tris = window_triangles((0.2, 0.2, 0.2), (0.8, 0.8, 0.8), (0.5, 0.5, 0.5))
    assert painter_order(tris).tolist() == [1, 2, 0]


def test_the_depth_of_a_triangle_is_the_mean_of_its_corners():
    """Corners (.1, .2, .9) average .4, farther than a flat .3 although two corners are nearer: 0 first."""
    tris = window_triangles((0.1, 0.2, 0.9), (0.3, 0.3, 0.3))
    assert painter_order(tris).tolist() == [0, 1]


def test_equal_depths_keep_their_draw_order():
    """Centroids .5, .5, .9, .5: the .9 first, then the three .5s in the order given (a stable sort)."""
    tris = window_triangles((0.5,) * 3, (0.4, 0.5, 0.6), (0.9,) * 3, (0.5,) * 3)
    assert painter_order(tris).tolist() == [2, 0, 1, 3]


def crossing_triangles(hidden_surface):
    """Two triangles seen straight down −z (parallel, 16×16, x and y from −1 to 1, none clipped): a red
    one listed first, tilted, z = −x/3 (nearer than z = 0 left of x = 0, farther right of it), and a
    flat green one at z = 0."""
    red = Mesh(np.array([[-0.9, -0.9, 0.3], [-0.9, 0.9, 0.3], [0.9, 0.0, -0.3]]), np.array([[0, 1, 2]]))
    green = Mesh(np.array([[-0.9, -0.9, 0.0], [0.9, -0.9, 0.0], [0.0, 0.9, 0.0]]), np.array([[0, 1, 2]]))
    unlit = lambda colour: Material(color=colour, ambient=1.0, diffuse=0.0, lighting=False)  # noqa: E731
    return Scene(image=Image(size=(16, 16)), camera=Camera(position=(0.0, 0.0, 5.0), parallel=True,
                                                           parallel_scale=1.0),
                 lights=(headlight(),), objects=(SceneObject(mesh=red, material=unlit((1.0, 0.0, 0.0))),
                                                 SceneObject(mesh=green, material=unlit((0.0, 1.0, 0.0)))),
                 render=RenderSettings(hidden_surface=hidden_surface))


def test_one_depth_per_triangle_cannot_order_interpenetrating_surfaces():
    """The triangles cross at x = 0; on the middle row, columns 5 and 10 lie at x = ∓0.3125, inside
    both. The z-buffer shows red at column 5 (z = +0.10, nearer) and green at column 10 (red at −0.10).
    The painter's algorithm takes red's centroid, z = (0.3 + 0.3 − 0.3)/3 = 0.1, as nearer than green's
    0, paints green first and red over it: red at column 10 too, the algorithm's known failure."""
    zbuffer = render(crossing_triangles("zbuffer")).rgb
    painter = render(crossing_triangles("painter")).rgb
    assert zbuffer[8, 5].tolist() == [255, 0, 0] and zbuffer[8, 10].tolist() == [0, 255, 0]
    assert painter[8, 5].tolist() == [255, 0, 0] and painter[8, 10].tolist() == [255, 0, 0]
