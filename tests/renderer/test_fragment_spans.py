"""A span's linear colours (renderer/fragment_spans.py): a run of a triangle's fragments gets,
bit for bit, the colours its pixels get one at a time, and the colours the opaque pass lights.

One perspective triangle in view space (vertex clip w 3, 4 and 2.5), runs of 24 pixels on
every row it spans, for each way a run can be lit: the span kernel (face normal, two-sided;
unlit, headlight, directional lights; textured nearest and linear, repeat and clamp) and the
pixel-by-pixel fallback (a positional light, the opengl model, flat and gouraud colours).
"""
import numpy as np
import pytest

from renderer.fragment_spans import span_linear_colours
from renderer.lit_colours import LitColours
from renderer.pipeline import SceneGeometry
from renderer.raster import screen_weights, set_up
from renderer.reflection.materials import FACE_COLOUR, PIXEL_AS_GIVEN, PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED, VERTEX_COLOUR
from renderer.plane_normals import face_normals
from renderer.shading import fragment_colour
from renderer.shading import fragments as make_fragments
from renderer.shading import with_span_table
from renderer.texture_sampling import CLAMP, LINEAR, NEAREST, REPEAT, Textures, pack_texels, texel_scratch
from renderer.window import SUBPIXEL

from .kernel_inputs import materials, view_lights

WINDOW = np.array([[[2.3, 1.7, 0.4], [40.6, 5.2, 0.5], [12.1, 30.4, 0.6]]])
RUN = 24


def geometry():
    verts = np.array([[-1.0, -1.0, -3.0], [1.2, -0.8, -4.0], [-0.2, 1.1, -2.5]])
    normals = verts / np.linalg.norm(verts, axis=1, keepdims=True) + [0.0, 0.0, 0.3]
    tris = np.array([[0, 1, 2]])
    plane = np.empty((1, 3))
    face_normals(verts, tris, plane)
    return SceneGeometry(verts, np.c_[verts, [3.0, 4.0, 2.5]], np.zeros(3, np.uint8), normals, tris, np.zeros(1, np.int64),
                         np.zeros(3, np.int64), np.array([[-0.3, 0.1], [1.6, 0.2], [0.4, 1.3]]), plane, False)


def fragments(geo):
    fixed = np.rint(WINDOW[..., :2] * SUBPIXEL).astype(np.int64) - SUBPIXEL // 2
    setup = set_up(fixed, WINDOW, 32, False)
    return with_span_table(make_fragments(np.empty((0, 0), np.int32), setup.plane, setup.front,
                                          geo.verts_clip[None].copy(), np.eye(3)[None].copy(), np.zeros(1, np.int64), True),
                           geo, textured=True)


def textures(filter_mode, wrap):
    texels = (np.random.default_rng(7).random((8 * 16, 3)) * 255).astype(np.uint8)
    return Textures(np.array([filter_mode is not None]), np.zeros(1, np.int64), np.array([16]), np.array([8]),
                    np.array([LINEAR if filter_mode == "linear" else NEAREST]),
                    np.array([CLAMP if wrap == "clamp" else REPEAT]), pack_texels(texels))


LIGHTS = {"unlit": view_lights(complexity=0), "headlight": view_lights(complexity=1),
          "directional": view_lights(({"direction": (-0.3, -0.5, -1.0)}, {"direction": (0.4, 0.1, -1.0)})),
          "one-directional": view_lights(({"direction": (-0.3, -0.5, -1.0)},)),
          "positional": view_lights(({"position": (1.0, 2.0, 1.0), "positional": True},), complexity=3)}
SPAN_KERNEL = [(path, light, tex) for path in (PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED) for light in LIGHTS
               for tex in ((None, "repeat"), ("nearest", "repeat"), ("linear", "clamp"))]
FALLBACK = [(path, model) for path in (FACE_COLOUR, VERTEX_COLOUR, PIXEL_AS_GIVEN) for model in ("opengl", "classic")]


def colours_of_runs(path, lights, model="vtk", texture=(None, "repeat"), run=RUN):
    """Every row's pixels 0 … 47 lit in runs of ``run``: (rows, 3, 48) float32."""
    geo = geometry()
    frags = fragments(geo)
    lit = LitColours(np.random.default_rng(1).random((3, 6)), np.random.default_rng(2).random((1, 6)))
    inputs = (materials((0.1, 0.15, 0.2), (0.6, 0.5, 0.4), (0.5, 0.5, 0.5), 20.0, model=model, path=path),
              textures(*texture), lights, lit)
    out = np.empty((32, 3, 2 * RUN), np.float32)
    # texture coordinates go to their own columns of a row's scratch (as points do in the shading kernels)
    points, colour, st = np.empty((6, RUN), np.float32), np.empty((3, RUN), np.float32), np.empty((2, 2 * RUN), np.float32)
    fixed = texel_scratch.py_func(2 * RUN)
    for row in range(32):
        for c0 in range(0, 2 * RUN, run):
            span_linear_colours(0, row, c0, run, frags, geo, inputs, (points, colour, st, fixed))
            out[row, :, c0:c0 + run] = colour[:, :run]
    return out, (frags, geo, inputs)


@pytest.mark.parametrize("path, light, texture", SPAN_KERNEL, ids=[f"{p}-{li}-{t[0]}-{t[1]}" for p, li, t in SPAN_KERNEL])
def test_a_run_gives_the_bits_of_its_pixels_one_at_a_time(path, light, texture):
    long, _ = colours_of_runs(path, LIGHTS[light], texture=texture)
    single, _ = colours_of_runs(path, LIGHTS[light], texture=texture, run=1)
    np.testing.assert_array_equal(long, single)


@pytest.mark.parametrize("path, light, texture", SPAN_KERNEL, ids=[f"{p}-{li}-{t[0]}-{t[1]}" for p, li, t in SPAN_KERNEL])
def test_a_run_is_lit_as_the_scalar_kernel_lights_it_up_to_float32(path, light, texture):
    """The span kernel computes in float32 (as VTK's shaders do); the float64 scalar kernel
    agrees to 1e-5, far below an 8-bit step."""
    long, (frags, geo, inputs) = colours_of_runs(path, LIGHTS[light], texture=texture)
    for row in range(0, 32, 3):
        for col in range(0, 2 * RUN, 5):
            l1, l2 = screen_weights(0, row, col, frags.plane)
            expected = fragment_colour(0, l1, l2, frags, geo, *inputs)
            np.testing.assert_allclose(long[row, :, col], expected, rtol=0, atol=1e-5)


@pytest.mark.parametrize("path, model", FALLBACK)
def test_other_paths_are_the_scalar_kernel_in_float32(path, model):
    """No span kernel: every pixel is the float64 scalar colour, rounded to float32."""
    long, (frags, geo, inputs) = colours_of_runs(path, LIGHTS["directional"], model=model, texture=("linear", "repeat"))
    for row in range(32):
        for col in range(2 * RUN):
            l1, l2 = screen_weights(0, row, col, frags.plane)
            expected = np.float32(fragment_colour(0, l1, l2, frags, geo, *inputs))
            assert long[row, :, col].tolist() == expected.tolist()
