"""Shading in spans (renderer/spans.py, reflection/vtk_spans.py) gives the same bytes as shading
pixel by pixel, and one thread the same as two, on scenes made to hit the spans' edge cases:
spans of one pixel and of a whole row, triangles cut by the near plane and the viewport, back
faces, parallel projection, screen-linear interpolation, every light complexity the span kernel
covers (and one it leaves to the scalar kernel), flat, gouraud and phong."""
from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from lab.matrices import model_matrix
from lab.normals import radial_normals
from lab.scene import Camera, Image, Light, Material, RenderSettings, Scene, SceneObject, headlight
from lab.normals import angle_weighted_normals
from lab.shapes import cube, cylinder, icosphere, quad
from renderer import RenderOptions, pipeline, render
from renderer.jit import njit
from renderer.pipeline import SceneGeometry
from renderer.shading import EVERYTHING, SPAN_TABLE, fragments, shade, with_span_table
from renderer.spans import (LANES, clipped_vertex, face_toward_viewer, finish_points, span_point_sums, span_points,
                            span_setup, span_tcoords, span_texture_corners, table_weights)
from .assembly import scalar_int64_conversions
from .single_thread import one_thread
from .texture_filters import by_definition

SCENE_LIGHT = Light(kind="scene", position=(3.0, 4.0, 5.0))
LIGHTS = {
    "headlight": (headlight(),),
    "one-scene-light": (SCENE_LIGHT,),
    "two-lights": (SCENE_LIGHT, Light(kind="camera", position=(-1.0, 0.5, 1.0), color=(0.4, 0.6, 1.0))),
    "unlit": (replace(SCENE_LIGHT, on=False),),
    "positional": (replace(SCENE_LIGHT, positional=True),),  # complexity 3: the scalar kernel
}


def ball(level=3):
    mesh = icosphere(level=level)
    return replace(mesh, point_normals=radial_normals(mesh.points))


def scene(shading, lights, camera=None, size=(97, 61), objects=None, interpolation="perspective"):
    objects = objects or (
        SceneObject(mesh=ball(), material=Material(color=(0.6, 0.7, 0.9), specular=0.4, specular_power=30.0),
                    shading=shading),
        # a far, finely divided sphere: spans of one or two pixels
        SceneObject(mesh=ball(5), material=Material(color=(0.9, 0.5, 0.2), specular=0.3), shading=shading,
                    model_to_world=model_matrix(scale=(0.3, 0.3, 0.3), translate=(1.8, 0.6, -3.0))),
        # a large quad crossing the near plane and every side of the viewport, seen from behind
        SceneObject(mesh=replace(quad(40.0), point_normals=np.tile([0.0, 0.0, 1.0], (4, 1))),
                    material=Material(color=(0.3, 0.8, 0.4), specular=0.2), shading=shading,
                    model_to_world=model_matrix(rotate=(100.0, 10.0, 0.0), translate=(0.0, -0.5, 0.0))),
    )
    camera = camera or Camera(position=(0.6, 0.9, 3.2), view_angle=40.0, clipping_range=(0.5, 30.0))
    return Scene(image=Image(size=size, background=(0.1, 0.1, 0.15)), camera=camera, lights=lights,
                 objects=objects, render=RenderSettings(interpolation=interpolation))


CASES = [(shading, light) for shading in ("flat", "phong", "gouraud") for light in LIGHTS]


@pytest.mark.parametrize("shading, light", CASES, ids=[f"{s}-{l}" for s, l in CASES])
def test_spans_give_the_bytes_of_pixel_by_pixel_shading(shading, light):
    s = scene(shading, LIGHTS[light])
    fast = render(s)
    plain = render(s, RenderOptions(spans=False))
    assert fast.coverage.mean() > 0.5  # the scene fills the frame: every kind of span is there
    np.testing.assert_array_equal(fast.rgb, plain.rgb)


@pytest.mark.parametrize("interpolation", ["perspective", "screen"])
def test_parallel_projection_and_screen_linear_interpolation_keep_the_bytes(interpolation):
    s = scene("phong", LIGHTS["one-scene-light"], interpolation=interpolation,
              camera=Camera(position=(0.6, 0.9, 3.2), parallel=True, parallel_scale=1.3, clipping_range=(0.5, 30.0)))
    np.testing.assert_array_equal(render(s).rgb, render(s, RenderOptions(spans=False)).rgb)


def test_spans_as_wide_as_the_image_keep_the_bytes():
    """An axis-aligned cube face filling the frame under a parallel camera: spans of the whole
    row, pixel-aligned edges."""
    s = scene("phong", LIGHTS["one-scene-light"], size=(64, 48),
              objects=(SceneObject(mesh=cube(4.0), shading="flat"),),
              camera=Camera(position=(0.0, 0.0, 5.0), parallel=True, parallel_scale=1.0, clipping_range=(0.5, 30.0)))
    fast = render(s)
    assert fast.coverage.all()
    np.testing.assert_array_equal(fast.rgb, render(s, RenderOptions(spans=False)).rgb)


def thin_and_mixed():
    """Objects of every span way side by side on the same rows: a 400-segment cylinder (phong:
    triangles one or two pixels wide, so a row's run of it crosses many triangles), a flat
    sphere in front of it (the colour held per triangle, or lit once a span under a lone
    headlight, or lit per pixel), a gouraud sphere behind (its run meets the cylinder's)."""
    tube = cylinder(segments=400, radius=0.6, height=2.0)
    tube = replace(tube, point_normals=angle_weighted_normals(tube))
    return (SceneObject(mesh=tube, material=Material(color=(0.7, 0.7, 0.8), specular=0.5, specular_power=40.0),
                        shading="phong", model_to_world=model_matrix(rotate=(75.0, 0.0, 8.0))),
            SceneObject(mesh=ball(2), material=Material(color=(0.9, 0.4, 0.3), specular=0.3), shading="flat",
                        model_to_world=model_matrix(scale=(0.35, 0.35, 0.35), translate=(0.3, 0.2, 0.9))),
            SceneObject(mesh=ball(3), material=Material(color=(0.3, 0.8, 0.5), specular=0.3), shading="gouraud",
                        model_to_world=model_matrix(scale=(0.7, 0.7, 0.7), translate=(-0.9, -0.2, -0.5))))


@pytest.mark.parametrize("light", ["headlight", "one-scene-light", "two-lights", "unlit"])
def test_runs_across_thin_triangles_and_other_objects_keep_the_bytes(light):
    """A row's run of one object is lit in one loop (``shade_lit_run``) whatever triangles it
    crosses, and ends where another object or the background begins: the same bytes as
    pixel by pixel, with one thread and with two."""
    s = scene("phong", LIGHTS[light], size=(120, 90), objects=thin_and_mixed(),
              camera=Camera(position=(0.2, 0.6, 3.4), view_angle=45.0, clipping_range=(0.5, 30.0)))
    fast = render(s)
    np.testing.assert_array_equal(fast.rgb, render(s, RenderOptions(spans=False)).rgb)
    with one_thread():
        np.testing.assert_array_equal(render(s).rgb, fast.rgb)


def weights_span_by_span(k, row, c0, plane, tri_clip, perspective):
    """A span's weights as a span worked them out before the table: from the clipped
    triangle's weight plane and clip w, every float64 operation in the same order."""
    x0, y0, e1x, e1y, e2x, e2y = plane[k, :6]
    inv_a2 = 1.0 / (e1x * e2y - e2x * e1y)
    anchor = np.floor(x0)
    py, px = row + 0.5 - y0, anchor + 0.5 - x0
    l1, l2 = (px * e2y - e2x * py) * inv_a2, (e1x * py - px * e1y) * inv_a2
    b1, b2 = e2y * inv_a2, -e1y * inv_a2
    l0, b0 = 1.0 - l1 - l2, -b1 - b2
    w0, w1, w2 = (1.0 / tri_clip[k, i, 3] for i in range(3)) if perspective else (1.0, 1.0, 1.0)
    return l0 * w0, b0 * w0, l1 * w1, b1 * w1, l2 * w2, b2 * w2, c0 - anchor


def random_clipped_triangles(rng, k=60, n_src=9, n_verts=20, parallel=False):
    """Clipped triangles of random planes, clip w, clipping weights and facing, cut from random
    source triangles of one object (every table a span's set-up reads, nothing more)."""
    plane = np.zeros((k, 11))
    plane[:, :2] = rng.uniform(-5.0, 40.0, (k, 2))
    plane[:, 2:6] = rng.uniform(-30.0, 30.0, (k, 4))
    tri_clip = np.zeros((k, 3, 4))
    tri_clip[:, :, 3] = rng.uniform(0.3, 6.0, (k, 3))
    cb = rng.random((k, 3, 3))
    geo = SceneGeometry(rng.normal(size=(n_verts, 3)), np.zeros((n_verts, 4)), np.zeros(n_verts, np.uint8),
                        rng.normal(size=(n_verts, 3)),
                        rng.integers(0, n_verts, (n_src, 3)), rng.integers(0, 3, n_src), np.zeros(n_verts, np.int64),
                        np.zeros((n_verts, 2)), rng.normal(size=(n_src, 3)), parallel)
    return (plane, rng.random(k) < 0.5, tri_clip, cb / cb.sum(axis=2, keepdims=True), rng.integers(0, n_src, k)), geo


@pytest.mark.parametrize("perspective", [True, False])
@pytest.mark.parametrize("parallel", [False, True])
def test_the_span_table_holds_the_bits_a_span_would_work_out(perspective, parallel):
    """What a span's set-up reads from the span table (gathered once a frame) is, bit for
    bit, what it worked out from the clipped and source triangles' tables span by span: the
    weights on any row from any column, the clipped corners' positions and normals (float32
    of their float64 mix), the plane normal toward the viewer, the facing and the object."""
    rng = np.random.default_rng(5)
    (plane, front, tri_clip, cb, source), geo = random_clipped_triangles(rng, parallel=parallel)
    frags = with_span_table(fragments(np.zeros((1, 1), np.int32), plane, front, tri_clip, cb, source, perspective), geo)
    for k in range(len(source)):
        s = source[k]
        i0, i1, i2 = geo.triangles[s]
        for row, c0 in rng.integers(-3, 50, (5, 2)):
            assert (table_weights(frags.span_weights, k, row, c0)
                    == weights_span_by_span(k, row, c0, plane, tri_clip, perspective)), (k, row, c0)
        corners = [clipped_vertex(geo.verts_view, k, i, cb, i0, i1, i2) for i in range(3)]
        corners += [clipped_vertex(geo.normals_view, k, i, cb, i0, i1, i2) for i in range(3)]
        expected = np.array([*np.concatenate(corners), *face_toward_viewer(geo, s), 1.0 if front[k] else -1.0],
                            np.float32)
        assert frags.span_corners[k].tobytes() == expected.tobytes(), k
        assert frags.span_object[k] == geo.tri_object[s]


@pytest.mark.parametrize("shading", ["phong", "flat"])
@pytest.mark.parametrize("interpolation", ["perspective", "screen"])
def test_the_span_table_read_from_the_clipped_corners_is_the_one_the_written_out_tables_give(shading, interpolation,
                                                                                            monkeypatch):
    """A frame every object of which is lit in spans reads the span table only: the pipeline
    builds it straight from the clipped corners (``span_table_of_corners``, triangles kept
    whole and pieces cut by the near plane and the viewport) and writes out no planes or
    corners; the table is, bit for bit, the one of the written-out tables."""
    won_seen = []
    real = pipeline.shading_fragments

    def spy(won, tri_index, perspective, ws=None, reads=EVERYTHING):
        won_seen.append((won, tri_index.copy(), perspective, reads))
        return real(won, tri_index, perspective, ws, reads)

    monkeypatch.setattr(pipeline, "shading_fragments", spy)
    render(scene(shading, LIGHTS["one-scene-light"], interpolation=interpolation))
    won, tri_index, perspective, reads = won_seen[-1]
    assert reads == SPAN_TABLE and (won.piece >= 0).any() and (won.piece < 0).any()
    written = with_span_table(real(won, tri_index, perspective, None, EVERYTHING), won.geometry)
    direct = real(won, tri_index, perspective, None, SPAN_TABLE)
    assert len(direct.plane) == len(direct.tri_clip) == 0 < len(direct.span_object) == len(written.clip_source)
    for name in ("span_weights", "span_corners", "span_object", "clip_source"):
        assert getattr(direct, name).tobytes() == getattr(written, name).tobytes(), name


def test_a_triangle_kept_whole_takes_its_vertices_values_as_they_are(monkeypatch):
    """Read from the clipped corners, the span table gives every triangle kept whole its source
    vertices' view-space positions and normals as float32, as they are: a zero keeps its sign,
    which mixing them by weights of 1 and 0 would not (−0 + 0·x is +0 for x > 0)."""
    won_seen = []
    real = pipeline.shading_fragments

    def spy(won, tri_index, perspective, ws=None, reads=EVERYTHING):
        won_seen.append((won, tri_index.copy(), perspective))
        return real(won, tri_index, perspective, ws, reads)

    monkeypatch.setattr(pipeline, "shading_fragments", spy)
    render(scene("phong", LIGHTS["one-scene-light"]))
    won, tri_index, perspective = won_seen[-1]
    geo, whole = won.geometry, np.flatnonzero(won.piece < 0)
    first = geo.triangles[won.clip_source[whole[0]]]
    geo.verts_view[first[0], 0], geo.verts_view[first[1], 0] = -0.0, 1.0
    geo.normals_view[first[0], 1], geo.normals_view[first[2], 1] = -0.0, 0.5
    corners = real(won, tri_index, perspective, None, SPAN_TABLE).span_corners
    for k in whole:
        vertices = geo.triangles[won.clip_source[k]]
        assert corners[k, :9].tobytes() == geo.verts_view[vertices].astype(np.float32).tobytes(), k
        assert corners[k, 9:18].tobytes() == geo.normals_view[vertices].astype(np.float32).tobytes(), k
    assert np.signbit(corners[whole[0], 0]) and np.signbit(corners[whole[0], 10])


def test_one_thread_and_two_give_the_same_bytes():
    s = scene("phong", LIGHTS["two-lights"], size=(160, 120))
    reference = render(s)
    with one_thread():
        serial = render(s)
    np.testing.assert_array_equal(serial.rgb, reference.rgb)
    np.testing.assert_array_equal(serial.depth, reference.depth)


def checker(n=16, seed=3):
    """A small random texture: neighbouring texels differ, so a texel chosen one off shows."""
    return np.random.default_rng(seed).random((n, 2 * n, 3))


TEXTURE_CASES = [(f, w, shading) for f in ("nearest", "linear") for w in ("repeat", "clamp")
                 for shading in ("flat", "phong")]


@pytest.mark.parametrize("filter_mode, wrap, shading", TEXTURE_CASES, ids=["-".join(c) for c in TEXTURE_CASES])
def test_textured_spans_give_the_bytes_of_pixel_by_pixel_shading(filter_mode, wrap, shading):
    """Textured objects: lit in the span loop, multiplied by the texels, stored; the same bytes
    as one pixel at a time. A sphere with its longitude seam in view, texture coordinates past
    1 (repeat and clamp differ there), a quad crossing the near plane and the viewport seen
    from behind, a far sphere of one- and two-pixel spans."""
    from lab.texture import Texture

    sphere = icosphere(level=3, uv=1)
    sphere = replace(sphere, point_normals=radial_normals(sphere.points))
    tex = Texture(checker(), filter=filter_mode, wrap=wrap)
    board = replace(quad(40.0), point_normals=np.tile([0.0, 0.0, 1.0], (4, 1)),
                    tcoords=np.array([[-1.5, -1.5], [2.5, -1.5], [2.5, 2.5], [-1.5, 2.5]]))
    material = Material(color=(1.0, 1.0, 1.0), specular=0.4, specular_power=30.0)
    objects = (
        SceneObject(mesh=sphere, material=material, shading=shading, texture=tex,
                    model_to_world=model_matrix(rotate=(0.0, 200.0, 0.0))),
        SceneObject(mesh=sphere, material=material, shading=shading, texture=tex,
                    model_to_world=model_matrix(scale=(0.3, 0.3, 0.3), translate=(1.8, 0.6, -3.0))),
        SceneObject(mesh=board, material=material, shading=shading, texture=tex,
                    model_to_world=model_matrix(rotate=(100.0, 10.0, 0.0), translate=(0.0, -0.5, 0.0))),
    )
    s = scene(shading, LIGHTS["one-scene-light"], objects=objects)
    fast = render(s)
    assert fast.coverage.mean() > 0.5
    np.testing.assert_array_equal(fast.rgb, render(s, RenderOptions(spans=False)).rgb)


EDGE_CASES = [(f, w, i) for f in ("nearest", "linear") for w in ("repeat", "clamp") for i in ("perspective", "screen")]


@pytest.mark.parametrize("filter_mode, wrap, interpolation", EDGE_CASES, ids=["-".join(c) for c in EDGE_CASES])
def test_textured_spans_on_texel_edges_show_the_filter_as_defined(filter_mode, wrap, interpolation, monkeypatch):
    """A quad filling a 64×64 frame under a parallel camera, texture coordinates from −1 to 3
    (four periods; clamp holds three of them to the edge texels) on a 32×16 texture: every
    pixel centre lies exactly on a texel edge across (s·32 an integer) and on a texel centre
    up (t·16 − ½ an integer: the linear filter's weight 0), checked. Unlit white, so each
    pixel shows its texel value: spans of the whole row and pixel by pixel both give the
    filter as defined (:func:`texture_filters.by_definition`), byte for byte."""
    from lab.texture import Texture
    from renderer.texture_sampling import CLAMP, LINEAR, NEAREST, REPEAT

    tex = Texture(checker(16), filter=filter_mode, wrap=wrap)
    board = replace(quad(2.0), point_normals=np.tile([0.0, 0.0, 1.0], (4, 1)),
                    tcoords=np.array([[-1.0, -1.0], [3.0, -1.0], [3.0, 3.0], [-1.0, 3.0]]))
    s = scene("phong", LIGHTS["one-scene-light"], size=(64, 64), interpolation=interpolation,
              objects=(SceneObject(mesh=board, material=Material(color=(1.0, 1.0, 1.0), lighting=False),
                                   shading="phong", texture=tex),),
              camera=Camera(position=(0.0, 0.0, 5.0), parallel=True, parallel_scale=1.0, clipping_range=(0.5, 30.0)))
    seen = []
    monkeypatch.setattr(pipeline, "shade", lambda frags, geo, *a, **k: seen.append((frags, geo)) or
                        shade(frags, geo, *a, **k))
    fast = render(s)
    frags, geo = seen[0]
    frags = with_span_table(frags, geo, textured=True)
    st = np.empty((2, 64), np.float32)
    for row, col in np.ndindex(64, 64):  # window rows, y up
        k = frags.tri_index[row, col]
        span_tcoords(span_setup(k, row, col, frags, geo, False), span_texture_corners(k, frags), 1, st, col)
        assert st[:, col].tolist() == [(col + 0.5) / 16 - 1, (row + 0.5) / 16 - 1]
    codes = (LINEAR if filter_mode == "linear" else NEAREST, CLAMP if wrap == "clamp" else REPEAT)
    texels = tex.texels_8bit.reshape(-1, 3)
    expected = [[by_definition(texels, 32, 16, *codes, (col + 0.5) / 16 - 1, (63 - r + 0.5) / 16 - 1)
                 for col in range(64)] for r in range(64)]  # image rows, top first
    np.testing.assert_array_equal(fast.rgb, expected)
    np.testing.assert_array_equal(render(s, RenderOptions(spans=False)).rgb, expected)


@pytest.mark.parametrize("shading", ["flat", "phong"])
def test_textured_runs_across_triangles_and_objects_keep_the_bytes(shading):
    """A row's run of one textured object is lit, filtered and stored in one go
    (``shade_textured_run``) across its triangles; it ends where another object, an
    untextured one or one with another texture and filter, or the image's edge begins: the
    same bytes as pixel by pixel, with one thread and with two."""
    from lab.texture import Texture

    fine = icosphere(level=4, uv=1)
    fine = replace(fine, point_normals=radial_normals(fine.points))
    material = Material(color=(1.0, 1.0, 1.0), specular=0.4, specular_power=30.0)
    objects = (
        SceneObject(mesh=fine, material=material, shading=shading,
                    texture=Texture(checker(16, seed=5), filter="nearest", wrap="repeat"),
                    model_to_world=model_matrix(translate=(-0.7, 0.0, 0.0))),
        SceneObject(mesh=fine, material=material, shading=shading,
                    texture=Texture(checker(8, seed=6), filter="linear", wrap="clamp"),
                    model_to_world=model_matrix(rotate=(0.0, 90.0, 0.0), translate=(0.9, 0.1, -0.2))),
        SceneObject(mesh=ball(3), material=Material(color=(0.3, 0.8, 0.5), specular=0.3), shading=shading,
                    model_to_world=model_matrix(scale=(0.4, 0.4, 0.4), translate=(0.1, -0.3, 0.9))),
    )
    s = scene(shading, LIGHTS["one-scene-light"], size=(120, 80), objects=objects,
              camera=Camera(position=(0.3, 0.4, 3.0), view_angle=45.0, clipping_range=(0.5, 30.0)))
    fast = render(s)
    assert fast.coverage[:, -1].any()  # some runs end at the image's edge
    np.testing.assert_array_equal(fast.rgb, render(s, RenderOptions(spans=False)).rgb)
    with one_thread():
        np.testing.assert_array_equal(render(s).rgb, fast.rgb)


def test_a_count_rounds_up_to_whole_lanes():
    """round_up_to_lanes: the least multiple of LANES at or above the count (0 stays 0)."""
    from renderer.spans import LANES, round_up_to_lanes

    assert [round_up_to_lanes(n) for n in (0, 1, LANES - 1, LANES, LANES + 1)] == [0, LANES, LANES, LANES, 2 * LANES]


def test_a_span_of_half_a_vector_or_more_is_worked_out_in_whole_vectors():
    """whole_lanes: counts of LANES/2 and more round up to whole vector registers (the points
    past a span's end are the next span's, written over next; the row scratch has room past
    the last column); a thinner span keeps its count, so a one-pixel sliver costs one pixel."""
    from renderer.shading import span_scratch
    from renderer.spans import LANES, whole_lanes

    assert [whole_lanes(n) for n in range(LANES // 2)] == list(range(LANES // 2))
    for n in range(LANES // 2, 5 * LANES):
        assert whole_lanes(n) % LANES == 0 and n <= whole_lanes(n) < n + LANES
    points, _, st, _ = span_scratch(37)
    assert points.shape[1] >= whole_lanes(37) and st.shape[1] >= whole_lanes(37)


@njit
def points_of_span(consts, count, points):
    span_points(consts, False, count, points, 0)


def test_a_spans_pixel_offsets_become_floats_a_vector_at_a_time():
    """The interpolation needs each pixel's offset along the span as a float32: counted as int32,
    eight lanes convert in one instruction (``vcvtdq2ps``); as int64 (the loop's own index),
    AVX2 has no vector instruction and converted them one by one. The kernel holds fewer
    scalar conversions of 64-bit registers than there are lanes."""
    one = np.float32(1.0)
    three = (one, one, one)
    consts = ((one, one, one, one, one, one, one), (three, three, three), (three, three, three), three, one)
    points = np.zeros((6, 2 * LANES), np.float32)
    points_of_span(consts, 2 * LANES, points)
    assert np.isfinite(points).all()
    conversions = scalar_int64_conversions(points_of_span)
    assert len(conversions) < LANES, conversions


@njit
def points_in_two_passes(consts, face, count, points):
    span_point_sums(consts, face, count, points, 3)
    finish_points(points, 3, count, face)


@njit
def points_in_one_pass(consts, face, count, points):
    span_points(consts, face, count, points, 3)


def random_span_consts(rng, sign):
    """A span's float32 constants (``span_setup``'s shape) drawn at random; one corner's normal
    zero, so a pixel near it may have a normal of length zero."""
    f = [np.float32(v) for v in rng.uniform(-2.0, 2.0, 7)]
    f[6] = np.float32(rng.integers(0, 9))  # the first pixel's offset from the anchor: a whole column
    corners = [tuple(np.float32(v) for v in rng.normal(size=3)) for _ in range(7)]
    corners[4] = (np.float32(0.0),) * 3
    return tuple(f), tuple(corners[:3]), tuple(corners[3:6]), corners[6], np.float32(sign)


@pytest.mark.parametrize("face", [False, True])
@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_points_summed_then_finished_over_a_run_are_the_bits_of_a_span(face, sign):
    """A run's points in two passes — each span's weighted sums (``span_point_sums``, no
    division or root), then one loop over the whole run dividing and normalising
    (``finish_points``) — are the bits ``span_points`` gives pixel by pixel: x, y, z and the
    unit normal on the viewer's side, turned by the span's sign, the plane normal as it is
    with ``face``."""
    rng = np.random.default_rng(7)
    for _ in range(40):
        consts = random_span_consts(rng, sign)
        count = int(rng.integers(1, 3 * LANES))
        two, one = np.zeros((8, count + 3 + LANES), np.float32), np.zeros((8, count + 3 + LANES), np.float32)
        points_in_two_passes(consts, face, count, two)
        points_in_one_pass(consts, face, count, one)
        np.testing.assert_array_equal(two[:6, 3:3 + count].view(np.int32), one[:6, 3:3 + count].view(np.int32))


def test_a_run_is_finished_in_vector_registers():
    """``finish_points``'s division and root run on whole vector registers (``vdivps``,
    ``vsqrtps``): what moves them out of the spans of one or two pixels, where they ran one
    pixel at a time."""
    consts = random_span_consts(np.random.default_rng(1), 1.0)
    points_in_two_passes(consts, False, 2 * LANES, np.zeros((8, 3 * LANES + 3), np.float32))
    asm = "\n".join(points_in_two_passes.inspect_asm().values())
    assert "vsqrtps" in asm and "vdivps" in asm
