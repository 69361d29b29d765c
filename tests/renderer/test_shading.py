"""Stage 7, shading: a fragment's weights, its normal by shading path, texture and separate specular, 8 bits.

Tiny hand-made visibility buffers of one triangle in view space; every expected colour is
worked out by hand in the test's docstring (8 bits: ``round_half_even(255·c)`` in float32).
"""
import numpy as np
import pytest
from numba import njit

from renderer.lit_colours import LitColours
from renderer.pipeline import SceneGeometry
from renderer.reflection.materials import (FACE_COLOUR, PIXEL_AS_GIVEN, PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED,
                                           VERTEX_COLOUR)
from renderer.raster import screen_weights
from renderer.plane_normals import face_normals
from renderer.shading import ShadingInputs, fragment_weights, shade, span_covers, spans_cover_all, to_8bit
from renderer.shading import fragments as make_fragments
from renderer.shading import with_span_table
from renderer.spans import span_setup, span_tcoords, span_texture_corners, span_textured_points
from renderer.texture_sampling import NEAREST, REPEAT, Textures, pack_texels

from .kernel_inputs import materials, preset_tables, view_lights

BACKGROUND = np.array([10, 20, 30], np.uint8)
UNTEXTURED = Textures(np.array([False]), np.zeros(1, np.int64), np.ones(1, np.int64), np.ones(1, np.int64),
                      np.array([NEAREST]), np.array([REPEAT]), pack_texels(np.full((1, 3), 255, np.uint8)))


def triangle(verts_view, normals=None, w=(1.0, 1.0, 1.0), parallel=False):
    """SceneGeometry of one triangle (object 0) with view-space corners ``verts_view``, vertex
    ``normals`` (zeros if None) and clip w per corner."""
    verts = np.asarray(verts_view, np.float64)
    clip = np.c_[verts, np.asarray(w)]
    normals = np.zeros((3, 3)) if normals is None else np.asarray(normals, np.float64)
    tris = np.array([[0, 1, 2]])
    plane = np.empty((1, 3))
    face_normals(verts, tris, plane)
    return SceneGeometry(verts, clip, np.zeros(len(verts), np.uint8), normals, tris, np.zeros(1, np.int64), np.zeros(3, np.int64), np.zeros((3, 2)),
                         plane, parallel)


def fragments(geo, bary, front=True, perspective=False, clip_bary=None):
    """Every pixel of a (H, W) image covered by the triangle, with screen-space weights ``bary`` (H, W, 2).

    Each pixel gets a clipped copy of the triangle of its own whose set-up plane (vertex 0 at
    the pixel's centre minus (l1, l2), edges (1, 0) and (0, 1)) gives exactly those weights there."""
    bary = np.asarray(bary, np.float64)
    height, width = bary.shape[:2]
    n = height * width
    rows, cols = np.divmod(np.arange(n), width)
    plane = np.zeros((n, 11))
    plane[:, 0] = cols + 0.5 - bary[..., 0].reshape(-1)
    plane[:, 1] = rows + 0.5 - bary[..., 1].reshape(-1)
    plane[:, 2], plane[:, 5] = 1.0, 1.0
    cb = np.eye(3) if clip_bary is None else np.asarray(clip_bary, np.float64)
    return make_fragments(np.arange(n, dtype=np.int32).reshape(height, width), plane, np.full(n, front),
                           np.repeat(geo.verts_clip[None], n, axis=0), np.repeat(cb[None], n, axis=0),
                           np.zeros(n, np.int64), perspective)


def shade_all(frags, geo, mats, lit=None, textures=UNTEXTURED, lights=None, n_bands=None):
    rgb = np.full(frags.tri_index.shape + (3,), 7, np.uint8)
    lit = lit if lit is not None else LitColours(np.zeros((3, 6)), np.zeros((1, 6)))
    shade(frags, geo, ShadingInputs(mats, textures, lights if lights is not None else view_lights(complexity=1), lit),
          BACKGROUND, rgb, n_bands)
    return rgb


# --------------------------------------------------------------------------- weights and normals
def test_screen_linear_weights_are_the_rasteriser_weights():
    """l1 = l2 = 1/3 with clip w (1, 2, 4), screen-linear: (1/3, 1/3, 1/3) whatever w."""
    frags = fragments(triangle(np.eye(3), w=(1, 2, 4)), [[[1 / 3, 1 / 3]]])
    np.testing.assert_allclose(fragment_weights(frags, 0, 1 / 3, 1 / 3), [1 / 3, 1 / 3, 1 / 3])


def test_perspective_weights_divide_by_clip_w_and_renormalise():
    """l = (1/3, 1/3, 1/3), w = (1, 2, 4): (1/3, 1/6, 1/12) / (7/12) = (4/7, 2/7, 1/7)."""
    frags = fragments(triangle(np.eye(3), w=(1, 2, 4)), [[[1 / 3, 1 / 3]]], perspective=True)
    np.testing.assert_allclose(fragment_weights(frags, 0, 1 / 3, 1 / 3), [4 / 7, 2 / 7, 1 / 7])


def test_weights_are_carried_back_through_clipping():
    """Clipped vertex 1 is the midpoint of source vertices 0 and 1; (l0, l1, l2) = (.5, .25, .25) →
    .5·(1, 0, 0) + .25·(.5, .5, 0) + .25·(0, 0, 1) = (.625, .125, .25)."""
    frags = fragments(triangle(np.eye(3)), [[[0.25, 0.25]]], clip_bary=[[1, 0, 0], [0.5, 0.5, 0], [0, 0, 1]])
    np.testing.assert_allclose(fragment_weights(frags, 0, 0.25, 0.25), [0.625, 0.125, 0.25])


@njit
def pixel_tcoords(k, row, col, frags, geo):
    """A pixel's texture coordinates the way :func:`fragment_colour` works them out."""
    l1, l2 = screen_weights(k, row, col, frags.plane)
    w = fragment_weights(frags, k, l1, l2)
    s, tc = frags.clip_source[k], geo.tcoords
    i0, i1, i2 = geo.triangles[s, 0], geo.triangles[s, 1], geo.triangles[s, 2]
    return (w[0] * tc[i0, 0] + w[1] * tc[i1, 0] + w[2] * tc[i2, 0],
            w[0] * tc[i0, 1] + w[1] * tc[i1, 1] + w[2] * tc[i2, 1])


@pytest.mark.parametrize("perspective", [True, False])
def test_a_spans_texture_coordinates_are_its_pixels_own_in_float32(perspective):
    """A span's texture coordinates (``span_tcoords``: float32, interpolated as positions are,
    as llvmpipe interpolates them) are the bits each of its pixels gets as a span of its own
    and the bits ``span_textured_points`` writes beside the points; and they are the float64
    interpolation ``fragment_colour`` works out, to float32's precision: 40 clipped
    triangles of random shape, clip w (0.3 … 6) and clipping weights, spans starting
    anywhere on 30 rows."""
    rng = np.random.default_rng(11)
    n_src, k_clip = 12, 40
    tris = rng.integers(0, 30, (n_src, 3))
    geo = triangle(np.zeros((3, 3)))._replace(
        verts_view=rng.normal(size=(30, 3)), normals_view=rng.normal(size=(30, 3)), triangles=tris,
        tri_object=np.zeros(n_src, np.int64), face_normals=np.zeros((n_src, 3)), tcoords=rng.uniform(-2.0, 3.0, (30, 2)))
    plane = np.zeros((k_clip, 11))
    plane[:, :2] = rng.uniform(0.0, 40.0, (k_clip, 2))
    plane[:, 2:6] = rng.uniform(-30.0, 30.0, (k_clip, 4))
    tri_clip = np.zeros((k_clip, 3, 4))
    tri_clip[:, :, 3] = rng.uniform(0.3, 6.0, (k_clip, 3))
    cb = rng.random((k_clip, 3, 3))
    frags = make_fragments(np.zeros((1, 1), np.int32), plane, np.ones(k_clip, np.bool_), tri_clip,
                            cb / cb.sum(axis=2, keepdims=True), rng.integers(0, n_src, k_clip), perspective)
    frags = with_span_table(frags, geo, textured=True)
    st, alone, beside, points = np.empty((2, 64), np.float32), np.empty((2, 64), np.float32), \
        np.empty((2, 64), np.float32), np.empty((6, 64), np.float32)
    worst = 0.0
    for k in range(k_clip):
        corners = span_texture_corners(k, frags)
        for row in range(30):
            c0, count = int(rng.integers(0, 40)), int(rng.integers(1, 25))
            span_tcoords(span_setup(k, row, c0, frags, geo, False), corners, count, st, c0)
            span_textured_points(span_setup(k, row, c0, frags, geo, False), corners, False, count, points, beside, c0)
            for col in range(c0, c0 + count):
                span_tcoords(span_setup(k, row, col, frags, geo, False), corners, 1, alone, col)
                expected = np.array(pixel_tcoords(k, row, col, frags, geo))
                if np.abs(expected).max() < 10.0:  # inside or near the triangle: weights of a sane size
                    worst = max(worst, np.abs(st[:, col] - expected).max())
            assert st[:, c0:c0 + count].tobytes() == alone[:, c0:c0 + count].tobytes(), (k, row, c0)
            assert st[:, c0:c0 + count].tobytes() == beside[:, c0:c0 + count].tobytes(), (k, row, c0)
    assert 0.0 < worst < 2e-4


# --------------------------------------------------------------------------- colours by path
def test_vertex_colours_are_interpolated():
    """VERTEX_COLOUR, vertices lit red, green, blue; screen weights l1 = l2 = .25 → (.5, .25, .25) →
    (127.5, 63.75, 63.75) → (128, 64, 64); an empty pixel shows the background."""
    geo = triangle([[0, 0, -2], [1, 0, -2], [0, 1, -2]])
    frags = fragments(geo, [[[0.25, 0.25], [0.0, 0.0]]])
    frags = frags._replace(tri_index=np.array([[0, -1]], np.int32))
    lit = LitColours(np.c_[np.eye(3), np.zeros((3, 3))], np.zeros((1, 6)))
    rgb = shade_all(frags, geo, materials(0, 0, 0, 1, path=VERTEX_COLOUR), lit)
    assert rgb.tolist() == [[[128, 64, 64], [10, 20, 30]]]


def test_a_face_colour_is_held_and_its_secondary_colour_added():
    """FACE_COLOUR: primary (.2, .4, .6) + secondary (.2, 0, 0) = (.4, .4, .6) → (102, 102, 153) at any weights."""
    geo = triangle([[0, 0, -2], [1, 0, -2], [0, 1, -2]])
    lit = LitColours(np.zeros((3, 6)), np.array([[0.2, 0.4, 0.6, 0.2, 0.0, 0.0]]))
    rgb = shade_all(fragments(geo, [[[0.1, 0.7], [0.5, 0.5]]]), geo, materials(0, 0, 0, 1, path=FACE_COLOUR), lit)
    assert rgb.tolist() == [[[102, 102, 153]] * 2]


def test_the_texture_modulates_the_primary_colour_and_not_the_secondary():
    """Texel (128, 255, 255) times primary (1, .5, .5) = (128/255, .5, .5), plus secondary (.2, 0, 0):
    red 128 + 51 = 179, green and blue 127.5 → 128."""
    geo = triangle([[0, 0, -2], [1, 0, -2], [0, 1, -2]])
    lit = LitColours(np.zeros((3, 6)), np.array([[1.0, 0.5, 0.5, 0.2, 0.0, 0.0]]))
    textured = UNTEXTURED._replace(textured=np.array([True]), texels=pack_texels(np.array([[128, 255, 255]], np.uint8)))
    rgb = shade_all(fragments(geo, [[[0.2, 0.2]]]), geo, materials(0, 0, 0, 1, path=FACE_COLOUR), lit, textured)
    assert rgb.tolist() == [[[179, 128, 128]]]


# Under a lone headlight (VTK's complexity 1) df = max(1e-6, n.z): a normal toward the eye gives
# Amb + Dif = (.1, .1, .1) + (.3, .5, .7) = (.4, .6, .8) → (102, 153, 204); a normal away gives
# Amb + 1e-6·Dif → (26, 26, 26).
AMB, DIF = (0.1, 0.1, 0.1), (0.3, 0.5, 0.7)
TOWARD, AWAY = [102, 153, 204], [26, 26, 26]
CLOCKWISE = [[0, 0, -2], [0, 1, -2], [1, 0, -2]]  # seen from the eye: plane normal (0, 0, −1), away from it


@pytest.mark.parametrize("parallel", [False, True])
def test_the_face_normal_path_turns_the_plane_normal_toward_the_viewer(parallel):
    """PIXEL_FACE_NORMAL: the plane normal (0, 0, −1) of a clockwise triangle is flipped toward the eye."""
    geo = triangle(CLOCKWISE, parallel=parallel)
    rgb = shade_all(fragments(geo, [[[0.25, 0.25]]]), geo, materials(AMB, DIF, 0, 1, path=PIXEL_FACE_NORMAL))
    assert rgb.tolist() == [[TOWARD]]


@pytest.mark.parametrize("front, expected", [(True, AWAY), (False, TOWARD)])
def test_the_two_sided_path_negates_the_normal_on_back_faces(front, expected):
    """PIXEL_TWO_SIDED: vertex normals (0, 0, −1) used as they are on a front face, negated on a back face."""
    geo = triangle(CLOCKWISE, normals=[[0, 0, -1]] * 3)
    rgb = shade_all(fragments(geo, [[[0.25, 0.25]]], front=front), geo,
                    materials(AMB, DIF, 0, 1, path=PIXEL_TWO_SIDED))
    assert rgb.tolist() == [[expected]]


@pytest.mark.parametrize("front", [True, False])
def test_the_as_given_path_never_flips_the_normal(front):
    """PIXEL_AS_GIVEN, the classic model, light toward −z from the eye: normals (0, 0, −1) face away
    from it on either face, so ambient only, Ka·O·A = (.4, .4, .4) → 102."""
    geo = triangle(CLOCKWISE, normals=[[0, 0, -1]] * 3)
    rgb = shade_all(fragments(geo, [[[0.25, 0.25]]], front=front), geo,
                    materials((0.4, 0.4, 0.4), DIF, 0, 1, model="classic", path=PIXEL_AS_GIVEN),
                    lights=view_lights([{"direction": (0, 0, -1)}]))
    assert rgb.tolist() == [[[102, 102, 102]]]


def test_bands_of_rows_do_not_change_a_byte():
    """7×5 pixels with random weights: one band, three, or one per row give the same bytes, and every
    pixel is written (none keeps the fill value 7)."""
    geo = triangle([[0, 0, -2], [1, 0, -2], [0, 1, -2]])
    bary = np.random.default_rng(3).random((7, 5, 2)) / 2
    lit = LitColours(np.c_[np.eye(3), np.zeros((3, 3))], np.zeros((1, 6)))
    frames = [shade_all(fragments(geo, bary), geo, materials(0, 0, 0, 1, path=VERTEX_COLOUR), lit, n_bands=n)
              for n in (1, 3, 7, None)]
    assert all(np.array_equal(frames[0], f) for f in frames[1:])
    assert not (frames[0] == 7).all(axis=-1).any()


def test_to_8bit_rounds_half_to_even_in_float32():
    """127.5 → 128, 63.75 → 64, 0.5/255 → 0, 1.5/255 → 2."""
    assert to_8bit(np.array([0.5, 0.25, 0.5 / 255, 1.5 / 255])).tolist() == [128, 64, 0, 2]


# --------------------------------------------------------------------------- which kernel shades a frame

@njit
def covered_by_kernel(materials, textures, lights):
    return [span_covers(o, materials, textures, lights) for o in range(materials.model.shape[0])]


def test_the_kernel_choice_in_python_agrees_with_the_kernels_own_rule():
    """``spans_cover_all`` (Python, chooses the kernel) says yes exactly when the kernels' own
    ``span_covers`` holds for every object, on every preset × shading × model; both answers occur."""
    answers = set()
    for label, mats, textures, lights in preset_tables():
        answer = spans_cover_all(mats, textures, lights)
        assert answer == all(covered_by_kernel(mats, textures, lights)), label
        answers.add(answer)
    assert answers == {True, False}


def test_each_frame_reaches_only_the_kernel_its_objects_need(monkeypatch):
    """A flat icosphere under a headlight (every triangle one held colour) is painted from the
    table by ``paint_rows``; under a scene light (lit per pixel) by ``shade_rows_lit_spans``; a
    textured sphere by the general ``shade_rows``. Each gives the bytes of pixel-by-pixel shading."""
    from dataclasses import replace

    import renderer.shading as shading
    from lab.framing import shape_scene
    from lab.loading import load_scene
    from lab.scene import Light
    from renderer import RenderOptions, render

    flat = shape_scene("icosphere:level=2").with_overrides(shading="flat")
    scenes = [flat, replace(flat, lights=(Light(kind="scene", position=(3.0, 4.0, 5.0)),)),
              load_scene("textured-sphere")]
    plain = [render(scene, RenderOptions(spans=False)).rgb for scene in scenes]
    calls = []
    for name in ("shade_rows", "shade_rows_lit_spans", "paint_rows"):
        kernel = getattr(shading, name)
        monkeypatch.setattr(shading, name, lambda *a, _k=kernel, _n=name: calls.append(_n) or _k(*a))
    for scene, expected in zip(scenes, plain):
        np.testing.assert_array_equal(render(scene).rgb, expected)
    assert calls == ["paint_rows", "shade_rows_lit_spans", "shade_rows"]


def test_a_frame_without_triangles_is_the_background_the_kernels_paint():
    """With no triangle at all, :func:`shade` paints every pixel the background without a
    kernel (:func:`paint_background`): the bytes the kernels give a frame whose pixels are
    all empty."""
    geo = triangle([[0, 0, -2], [1, 0, -2], [0, 1, -2]])
    frags = fragments(geo, np.zeros((6, 5, 2)))
    empty_rows = frags._replace(tri_index=np.full((6, 5), -1, np.int32))  # one triangle, on no pixel
    none = make_fragments(np.full((6, 5), -1, np.int32), frags.plane[:0], frags.front[:0], frags.tri_clip[:0],
                          frags.clip_bary[:0], frags.clip_source[:0], False)
    mats = materials(0.4, 0.6, 0, 1, path=PIXEL_FACE_NORMAL)
    by_kernel, painted = shade_all(empty_rows, geo, mats), shade_all(none, geo, mats)
    np.testing.assert_array_equal(painted, by_kernel)
    assert (painted == BACKGROUND).all()
