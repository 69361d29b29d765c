"""Translucency: fragment lists per pixel, and compositing by oit, depth_peeling and sorted.

Every expected value is worked out by hand below, in 8-bit steps where the mode keeps
8-bit (or half-float) buffers: ``unorm8(x) = round_half_even(255·x)`` in float32,
``mul8(a, b) = round(a·b/255)`` as a blend unit does. VTK parity of the same modes is in
``tests/compare/test_parity_translucency.py``.
"""
from dataclasses import replace

import numpy as np
import pytest

from lab.scene import Camera, Image, Light, Material, RenderSettings, Scene, SceneObject
from lab.matrices import model_matrix
from lab.normals import radial_normals
from lab.shapes import cube, icosphere, quad
from renderer import RenderOptions, render
from renderer.pipeline import render_stages
from renderer.raster import DEPTH_CLEAR, DEPTH_MAX
from renderer.spans import whole_lanes
from renderer.translucency import (DEPTH_PEELING, MODES, OIT, SORTED, STRIP_ROWS, batch_scratch, composite_pixel,
                                   depth_order, fragment_lists)
from renderer.window import SUBPIXEL
from .single_thread import one_thread

BLUE = (0, 0, 255)


def composite(mode, colours, alphas, depths, behind, opaque_behind=False):
    """One pixel through :func:`composite_pixel`: fragments in draw order, 8-bit ``behind``."""
    m = len(alphas)
    fragments = np.c_[np.array(colours, float), np.array(alphas, float), np.array(depths, float)]
    out = np.empty(3, np.int64)
    composite_pixel(mode, fragments, m, np.array(behind, np.int64), opaque_behind, out, np.empty(m, np.int64),
                    np.empty(3), np.empty((2, 4), np.int64))
    return tuple(int(c) for c in out)


# --------------------------------------------------------------------------- scratch
@pytest.mark.parametrize("width", [1, 4, 9, 14])
def test_a_strip_of_runs_padded_to_whole_lanes_fits_its_scratch(width):
    """Every way a row's pixels can fall in front of or behind the opaque surface (runs
    parted by gaps), each run's points padded to whole lanes: the worst row, times the
    strip's rows, still fits the batch scratch (runs of 4 between gaps of 1 take 8 points
    for 5 pixels)."""
    worst = 0
    for mask in range(1 << width):
        points, run = 0, 0
        for col in range(width + 1):
            if col < width and mask >> col & 1:
                run += 1
            elif run:
                points, run = points + whole_lanes(run), 0
        worst = max(worst, points)
    points, _, runs = batch_scratch(width)
    assert STRIP_ROWS * worst <= points.shape[1] and STRIP_ROWS * width <= runs.shape[0]
    assert worst > width or width < 4  # padding does take more points than pixels


def test_depth_order_is_nearest_first_and_stable():
    """Depths (0.5, 0.2, 0.5, 0.1): order 3, 1, 0, 2 — the two 0.5s keep their draw order."""
    order = np.empty(4, np.int64)
    depth_order(np.array([0.5, 0.2, 0.5, 0.1]), 4, order)
    assert order.tolist() == [3, 1, 0, 2]


# --------------------------------------------------------------------------- compositing one pixel
@pytest.mark.parametrize("mode, expected", [(OIT, (128, 0, 127)), (DEPTH_PEELING, (128, 0, 127)),
                                            (SORTED, (128, 0, 128))])
def test_one_red_layer_at_half_opacity_over_blue(mode, expected):
    """Red α .5 over blue. sorted, exact: ½·(1, 0, 0) + ½·(0, 0, 1) = (.5, 0, .5) → 127.5 → (128, 0, 128).
    oit: C = ½·red/½ = red, coverage A = 1 − ½ → unorm8 128; red mul8(255, 128) = 128, blue
    mul8(255, 255 − 128) = round(127.5·…) = 127. depth_peeling: front layer red unorm8(½) = 128, alpha
    128; blue behind mul8(255, 127) = 127: the 8-bit blend floors a half step that sorted rounds up."""
    assert composite(mode, [[1, 0, 0]], [0.5], [0.5], BLUE) == expected


@pytest.mark.parametrize("mode, expected", [(OIT, (96, 96, 64)), (DEPTH_PEELING, (128, 64, 63)),
                                            (SORTED, (128, 64, 64))])
@pytest.mark.parametrize("draw_order", ["green first", "red first"])
def test_red_over_green_on_blue(mode, expected, draw_order):
    """Red α .5 in front of green α .5 on blue, in either draw order.
    oit averages, whatever the order: C = (½·red + ½·green)/1 = (.5, .5, 0) → 128; coverage
    1 − ½·½ = .75 → 191; red mul8(128, 191) = 96, green 96, blue mul8(255, 64) = 64.
    sorted, back to front: green over blue (0, .5, .5), red over that (.5, .25, .25) → (128, 64, 64).
    depth_peeling: the same order in 8-bit layers, one LSB below in blue (the parity notes' measurement)."""
    colours, depths = [[0, 1, 0], [1, 0, 0]], [0.6, 0.3]
    if draw_order == "red first":
        colours, depths = colours[::-1], depths[::-1]
    assert composite(mode, colours, [0.5, 0.5], depths, BLUE) == expected


def test_depth_peeling_over_an_opaque_surface_peels_the_front_only_at_first():
    """Over an opaque surface VTK's first peel takes no far fragment, so both layers go through
    the 8-bit front layer: red 128 with coverage 128/255; green weighted by 1 − 128/255 = 127/255:
    255·½·127/255 = 63.5 in real numbers, 63.4999… with float32(128/255), so 63; coverage
    1 − (127/255)·½ → 191.5 → 192, so blue behind keeps 255 − 192 = 63."""
    assert composite(DEPTH_PEELING, [[0, 1, 0], [1, 0, 0]], [0.5, 0.5], [0.6, 0.3], BLUE, True) == (128, 63, 63)
    assert composite(DEPTH_PEELING, [[0, 1, 0], [1, 0, 0]], [0.5, 0.5], [0.6, 0.3], BLUE, False) == (128, 64, 63)


@pytest.mark.parametrize("mode", [OIT, DEPTH_PEELING, SORTED])
def test_opaque_and_invisible_layers(mode):
    """α = 1 hides what is behind: red; α = 0 shows it unchanged: blue."""
    assert composite(mode, [[1, 0, 0]], [1.0], [0.5], BLUE) == (255, 0, 0)
    assert composite(mode, [[1, 0, 0]], [0.0], [0.5], BLUE) == BLUE


def test_sorted_lets_a_highlight_brighter_than_one_shine_through():
    """sorted keeps the lit colour unclamped: 2.0 red at α .5 over black is ½·2 = 1 → 255, not ½ → 128."""
    assert composite(SORTED, [[2.0, 0, 0]], [0.5], [0.5], (0, 0, 0)) == (255, 0, 0)


# --------------------------------------------------------------------------- fragment lists
def triangles(*tris):
    """(fixed, window) arrays for triangles of (x, y, z) vertices in pixel-centre units (see test_raster)."""
    fixed = np.array([[(round(x * SUBPIXEL), round(y * SUBPIXEL)) for x, y, _ in t] for t in tris], np.int64)
    window = np.array([[(x + 0.5, y + 0.5, z) for x, y, z in t] for t in tris], np.float64)
    return fixed, window


# (−0.5, −0.5), (3.5, −0.5), (−0.5, 3.5) in pixel-centre units: the pixel corners (0, 0), (4, 0), (0, 4).
# Centre (i, j) is inside when i + j < 3 (six pixels); on the hypotenuse (i + j = 3), a right edge, it is out.
CORNER = [(-0.5, -0.5), (3.5, -0.5), (-0.5, 3.5)]
INSIDE = np.add.outer(np.arange(4), np.arange(4)) < 3  # [row j, column i]


def test_fragment_lists_count_every_translucent_fragment_in_draw_order():
    """Two copies of the corner triangle at depths .6 then .3 over an empty z-buffer: two fragments in
    each of the six pixels, the first drawn first; starts are the prefix sums of the counts."""
    fixed, window = triangles([(x, y, 0.6) for x, y in CORNER], [(x, y, 0.3) for x, y in CORNER])
    setup, lists = fragment_lists(fixed, window, np.full((4, 4), DEPTH_CLEAR, np.int32))
    assert setup.front.tolist() == [True, True]
    np.testing.assert_array_equal(lists.count, np.where(INSIDE, 2, 0))
    np.testing.assert_array_equal(lists.start.reshape(-1), np.concatenate([[0], np.cumsum(lists.count)[:-1]]))
    assert lists.longest == 2
    first = lists.start[0, 0]
    assert lists.tri[first:first + 2].tolist() == [0, 1]
    assert lists.z[first:first + 2].tolist() == [np.floor(0.6 * DEPTH_MAX + 0.5), np.floor(0.3 * DEPTH_MAX + 0.5)]


def test_fragments_behind_the_opaque_surface_are_dropped_unless_the_depth_test_is_off():
    """An opaque surface at depth .4 everywhere: the copy at .6 is behind it, only the one at .3 stays."""
    fixed, window = triangles([(x, y, 0.6) for x, y in CORNER], [(x, y, 0.3) for x, y in CORNER])
    at_04 = np.full((4, 4), np.floor(0.4 * DEPTH_MAX + 0.5), np.int32)  # the 24-bit integer depth of 0.4
    _, lists = fragment_lists(fixed, window, at_04)
    np.testing.assert_array_equal(lists.count, np.where(INSIDE, 1, 0))
    assert set(lists.tri.tolist()) == {1}
    _, everything = fragment_lists(fixed, window, at_04, depth_test=False)
    np.testing.assert_array_equal(everything.count, np.where(INSIDE, 2, 0))


def test_bands_do_not_change_the_lists():
    """One band of rows or four: the same counts, starts and fragments."""
    fixed, window = triangles([(x, y, 0.6) for x, y in CORNER], [(x, y, 0.3) for x, y in CORNER])
    _, one = fragment_lists(fixed, window, np.full((4, 4), DEPTH_CLEAR, np.int32), n_bands=1)
    _, four = fragment_lists(fixed, window, np.full((4, 4), DEPTH_CLEAR, np.int32), n_bands=4)
    for a, b in zip(one, four):
        assert np.array_equal(a, b)


# --------------------------------------------------------------------------- the whole frame
def two_translucent_squares(mode):
    """16×16, parallel view straight down −z: a green square at z = 0 drawn first, a red one in front
    at z = 0.5, both α .5 and unlit (lighting off: Ka·C + Kd·C = C), on a blue background."""
    def square(colour, z):
        return SceneObject(mesh=quad(3.0), model_to_world=model_matrix(translate=(0.0, 0.0, z)),
                           material=Material(color=colour, ambient=0.0, diffuse=1.0, lighting=False, opacity=0.5))
    return Scene(image=Image(size=(16, 16), background=(0.0, 0.0, 1.0)),
                 camera=Camera(position=(0.0, 0.0, 5.0), parallel=True, parallel_scale=1.0), lights=(),
                 objects=(square((0.0, 1.0, 0.0), 0.0), square((1.0, 0.0, 0.0), 0.5)),
                 render=RenderSettings(transparency=mode))


@pytest.mark.parametrize("mode, expected", [("oit", (96, 96, 64)), ("depth_peeling", (128, 64, 63)),
                                            ("sorted", (128, 64, 64))])
def test_a_frame_of_two_translucent_squares(mode, expected):
    """Every pixel of the frame is the hand-composited red-over-green-on-blue of each mode; the
    translucent squares cover it but write no depth."""
    frame = render(two_translucent_squares(mode))
    assert frame.coverage.all() and (frame.depth == 1.0).all()
    assert {tuple(int(c) for c in p) for p in frame.rgb.reshape(-1, 3)} == {expected}
    assert set(MODES) == {"oit", "depth_peeling", "sorted"}


# --------------------------------------------------------------------------- the fast path against the plain one
def layered_scene(mode="oit", hidden_surface="zbuffer", cull_backfaces=False, wrap="repeat", size=(97, 73)):
    """Every case the fast path has to get right, in one frame of translucent objects:

    - overlapping layers: a shiny phong sphere, front and back faces, inside a flat box;
    - equal depths: two coincident quads of different colours (the tie goes by draw order);
    - many layers per pixel: a stack of eight quads at different depths, crossed by the above;
    - translucent over opaque: an opaque tilted quad cutting through the stack and the sphere,
      so the depth test splits spans into runs (fragments behind it dropped);
    - a textured sphere (seam in view, coordinates past 1 on a textured board) with ``wrap``;
    - a far, finely divided sphere: runs of one or two pixels; a board crossing the near plane.
    """
    from lab.texture import Texture

    def shiny(colour, opacity, specular=0.4):
        return Material(color=colour, specular=specular, specular_power=25.0, opacity=opacity)

    textured = icosphere(level=3, uv=1)
    textured = replace(textured, point_normals=radial_normals(textured.points))
    tex = Texture(np.random.default_rng(3).random((16, 32, 3)), filter="linear", wrap=wrap)
    board = replace(quad(40.0), point_normals=np.tile([0.0, 0.0, 1.0], (4, 1)),
                    tcoords=np.array([[-1.5, -1.5], [2.5, -1.5], [2.5, 2.5], [-1.5, 2.5]]))
    objects = [
        SceneObject(mesh=ball(3), material=shiny((0.9, 0.2, 0.1), 0.5), shading="phong"),
        SceneObject(mesh=cube(1.6), material=shiny((0.9, 0.8, 0.1), 0.6, 0.0), shading="flat",
                    model_to_world=model_matrix(rotate=(10.0, 30.0, 0.0))),
        SceneObject(mesh=quad(1.2), material=shiny((0.1, 0.9, 0.2), 0.5), shading="flat",
                    model_to_world=model_matrix(translate=(-0.5, 0.4, 0.9))),
        SceneObject(mesh=quad(1.2), material=shiny((0.2, 0.1, 0.9), 0.4), shading="flat",
                    model_to_world=model_matrix(translate=(-0.5, 0.4, 0.9))),
        *(SceneObject(mesh=quad(0.9), material=shiny((0.1 * i, 0.9 - 0.1 * i, 0.5), 0.3 + 0.05 * i), shading="flat",
                      model_to_world=model_matrix(translate=(0.45, -0.3, 1.0 - 0.25 * i))) for i in range(8)),
        SceneObject(mesh=quad(2.5), material=Material(color=(0.6, 0.6, 0.6)), shading="flat",
                    model_to_world=model_matrix(rotate=(0.0, 55.0, 0.0), translate=(0.5, -0.2, 0.0))),
        SceneObject(mesh=textured, material=shiny((1.0, 1.0, 1.0), 0.7), shading="phong", texture=tex, model_to_world=model_matrix(scale=(0.5, 0.5, 0.5), rotate=(0.0, 200.0, 0.0),
                                                             translate=(-1.1, -0.6, 0.5))),
        SceneObject(mesh=ball(5), material=shiny((0.9, 0.5, 0.2), 0.5), shading="phong",
                    model_to_world=model_matrix(scale=(0.3, 0.3, 0.3), translate=(1.8, 0.6, -3.0))),
        SceneObject(mesh=board, material=shiny((1.0, 1.0, 1.0), 0.3), shading="phong", texture=tex,
                    model_to_world=model_matrix(rotate=(100.0, 10.0, 0.0), translate=(0.0, -0.5, 0.0))),
    ]
    return Scene(image=Image(size=size, background=(0.1, 0.1, 0.15)),
                 camera=Camera(position=(0.6, 0.9, 3.2), view_angle=40.0, clipping_range=(0.5, 30.0)),
                 lights=(Light(kind="scene", position=(3.0, 4.0, 5.0)),), objects=tuple(objects),
                 render=RenderSettings(transparency=mode, hidden_surface=hidden_surface,
                                       cull_backfaces=cull_backfaces))


def ball(level):
    mesh = icosphere(level=level)
    return replace(mesh, point_normals=radial_normals(mesh.points))


def plain(scene):
    """The plain path: fragment lists composited pixel by pixel, each fragment lit alone."""
    return render(scene, RenderOptions(spans=False))


FAST_CASES = [("oit", "zbuffer", False, "repeat"), ("oit", "zbuffer", False, "clamp"), ("oit", "painter", False, "repeat"),
              ("oit", "zbuffer", True, "repeat"), ("depth_peeling", "zbuffer", False, "clamp"),
              ("sorted", "zbuffer", False, "repeat")]


@pytest.mark.parametrize("mode, hidden, cull, wrap", FAST_CASES, ids=["-".join(map(str, c)) for c in FAST_CASES])
def test_the_fast_path_gives_the_bytes_of_the_plain_path(mode, hidden, cull, wrap):
    """Fragments lit in runs (a triangle's runs on a strip of rows lit together, for the
    untextured objects lit per pixel) and, for ``oit``, summed as they are drawn (no lists):
    the same bytes as lists lit one fragment at a time and composited pixel by pixel."""
    s = layered_scene(mode, hidden, cull, wrap)
    fast = render(s)
    assert fast.coverage.mean() > 0.5
    np.testing.assert_array_equal(fast.rgb, plain(s).rgb)
    np.testing.assert_array_equal(fast.coverage, plain(s).coverage)


def test_the_layered_scene_has_what_it_claims():
    """Many layers (at least twelve fragments on some pixel), coincident fragments (equal depths,
    one after the other in a list), and fragments dropped behind the opaque quad."""
    from renderer.pipeline import render_stages

    s = layered_scene()
    _, stages = render_stages(s)
    tri = stages.tri_fixed[stages.translucent]
    window = stages.tri_window[stages.translucent]
    h, w = s.image.size[1], s.image.size[0]
    _, everything = fragment_lists(tri, window, np.full((h, w), DEPTH_CLEAR, np.int32))
    opaque = np.floor(stages.depth[::-1] * DEPTH_MAX + 0.5).astype(np.int32)  # window rows, as the kernels see them
    _, cut = fragment_lists(tri, window, opaque)
    assert everything.count.max() >= 12
    assert cut.count.sum() < everything.count.sum()
    layered = everything.start[everything.count > 1]
    assert (everything.z[layered] == everything.z[layered + 1]).any()  # the coincident quads


def test_one_thread_and_two_give_the_same_translucent_bytes():
    s = layered_scene(size=(160, 120))
    reference = render(s)
    with one_thread():
        serial = render(s)
    np.testing.assert_array_equal(serial.rgb, reference.rgb)


def grid_quads_scene():
    """Translucent squares and thin tilted quads seen head-on in a parallel view of one world
    unit a pixel: the squares' edges lie on rows and columns of pixel centres (where the fill
    rule decides), half-way between them and a quarter off (the test below checks that some
    horizontal edges lie on a row of centres), and they are 3 to 40 rows tall, so a strip
    holds stretches of a triangle long enough to walk."""
    objects = []
    for i, (x, y, size) in enumerate([(-20.0, -19.5, 12.0), (-4.5, -20.0, 13.0), (10.25, -20.25, 9.0),
                                      (-19.75, 0.5, 3.0), (-12.5, 2.5, 40.0), (6.0, 4.0, 17.5)]):
        objects.append(SceneObject(mesh=quad(size), material=Material(color=(0.2 + 0.1 * i, 0.5, 0.9 - 0.1 * i),
                                                                       opacity=0.5),
                                   shading="flat", model_to_world=model_matrix(translate=(x, y, 0.1 * i))))
    for i, angle in enumerate((3.0, 30.0, 60.0, 89.0)):
        objects.append(SceneObject(mesh=replace(quad(1.0), points=quad(1.0).points * (2.0, 30.0, 1.0)),
                                   material=Material(color=(0.9, 0.3, 0.2), specular=0.3, opacity=0.6),
                                   shading="phong", model_to_world=model_matrix(rotate=(0.0, 0.0, angle),
                                                                                translate=(14.0 - 4 * i, 14.0, 1.0))))
    return Scene(image=Image(size=(64, 64), background=(0.1, 0.1, 0.15)),
                 camera=Camera(position=(0.0, 0.0, 10.0), parallel=True, parallel_scale=32.0,
                               clipping_range=(1.0, 20.0)),
                 lights=(Light(kind="scene", position=(3.0, 4.0, 5.0)),), objects=tuple(objects),
                 render=RenderSettings(transparency="oit"))


@pytest.mark.parametrize("fill_rule", ["top-left", "bottom-right"])
def test_walked_edges_give_the_fragments_of_the_divided_spans(fill_rule):
    """Runs found by walking a triangle's edges down a strip (the fast path) and the plain
    path's spans, one division an edge a row: the same bytes and coverage, with edges on
    rows of pixel centres, for both fill rules."""
    s = grid_quads_scene()
    fixed = render_stages(s)[1].tri_fixed
    on_centres = [t[e, 1] % SUBPIXEL == 0 for t in fixed for e in range(3) if t[e, 1] == t[(e + 1) % 3, 1]]
    assert sum(on_centres) >= 4 and not all(on_centres)
    fast = render(s, RenderOptions(fill_rule=fill_rule))
    slow = render(s, RenderOptions(fill_rule=fill_rule, spans=False))
    assert 0.3 < fast.coverage.mean() < 0.95
    np.testing.assert_array_equal(fast.rgb, slow.rgb)
    np.testing.assert_array_equal(fast.coverage, slow.coverage)
