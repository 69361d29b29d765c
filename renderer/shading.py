"""Stage 7, visibility buffer → 8-bit RGB: per-fragment weights, normals, positions and colours.

For each covered pixel the screen-space weights from :mod:`renderer.raster` are made
perspective-correct (divide by clip w, renormalise), carried back through clipping to the
source triangle, and used to interpolate what the object's **shading path**
(:mod:`renderer.reflection.materials`) needs; then :func:`unorm8` stores the colour. All
vectors in view space. By path:

- ``PIXEL_FACE_NORMAL``: the triangle's plane normal (v1 − v0) × (v2 − v0), turned toward
  the viewer (perspective: so that n·P ≤ 0 at its first vertex; parallel: n.z ≥ 0;
  :func:`renderer.spans.face_toward_viewer`), lit per pixel;
- ``PIXEL_TWO_SIDED``: the perspective-correct interpolation of the (unnormalised)
  view-space vertex normals, normalised, negated on back faces, lit per pixel;
- ``PIXEL_AS_GIVEN``: the same interpolated normal, never flipped, lit per pixel;
- ``FACE_COLOUR``: the triangle's lit colour (:mod:`renderer.lit_colours`);
- ``VERTEX_COLOUR``: its vertices' lit colours, interpolated.

Rows are shaded in **spans**, runs of pixels showing one triangle (:func:`shade_span`): a
colour that cannot change along the span is worked out once; a model with a span kernel
(the vtk model, :mod:`renderer.reflection.vtk_spans`) lights the whole span in float32,
vectorised (:mod:`renderer.spans`), and a row's run of one such object is lit in one loop
across its triangles (:func:`shade_lit_run`, :func:`shade_textured_run`); anything else is lit pixel by pixel through
:func:`renderer.reflection.registry.reflect`, which picks the object's reflection model. A texture multiplies the lit colour (VTK, GL_MODULATE); the
secondary colour (separate specular, zero unless asked for) is added after it.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from renderer.jit import njit, prange
from renderer.min_max import larger

from renderer.bands import one_band_at_a_time, shading_bands
from renderer.float32_math import unorm8
from renderer.held_colours import all_held, held_colour_table, paint_rows
from renderer.lit_colours import face_colour
from renderer.raster import EMPTY, screen_weights
from renderer.reflection.materials import FACE_COLOUR, PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED, VERTEX_COLOUR
from renderer.reflection.registry import (light_points, reflect, reflect_span, span_applies, span_colours,
                                         span_normal_only, spans_apply, store_span)
from renderer.spans import (CORNERS, LANES, TEXTURED_CORNERS, SpanTable, face_toward_viewer, finish_points,
                            span_point_sums, span_points, span_setup, span_table, span_table_of_corners, span_tcoords,
                            span_texture_corners, span_textured_points, whole_lanes)
from renderer.texture_sampling import modulate_texels, sample_texture, texel_scratch
from renderer.workspace import empty, thread_workspace


@njit(cache=True)
def _to_8bit(flat, out):
    for i in range(flat.shape[0]):
        out[i] = unorm8(flat[i])


def to_8bit(rgb: np.ndarray) -> np.ndarray:
    """Apply :func:`unorm8` to every value of a float array; returns uint8 of the same shape."""
    flat = np.ascontiguousarray(rgb, dtype=np.float64).reshape(-1)
    out = np.empty(flat.shape, np.uint8)
    _to_8bit(flat, out)
    return out.reshape(np.shape(rgb))


@njit(cache=True, inline="always")
def fragment_weights(frags, k, l1, l2):
    """Weights ``(w0, w1, w2)`` of the *source* triangle's vertices at a fragment of clipped
    triangle ``k``: :func:`source_weights` with its vertices' clip w and clipping weights.

    ``l1, l2`` are screen-space weights of clipped triangle ``k``'s vertices 1 and 2.
    """
    return source_weights(l1, l2, clip_ws(frags.tri_clip, k), clip_weights(frags.clip_bary, k), frags.perspective)


@njit(cache=True, inline="always")
def clip_ws(tri_clip, k):
    """Clip w of clipped triangle ``k``'s three vertices."""
    return tri_clip[k, 0, 3], tri_clip[k, 1, 3], tri_clip[k, 2, 3]


@njit(cache=True, inline="always")
def clip_weights(cb, k):
    """Clipped triangle ``k``'s vertices' weights in the source triangle, one 9-tuple: vertex 0's
    three weights, then vertex 1's, then vertex 2's."""
    return (cb[k, 0, 0], cb[k, 0, 1], cb[k, 0, 2], cb[k, 1, 0], cb[k, 1, 1], cb[k, 1, 2],
            cb[k, 2, 0], cb[k, 2, 1], cb[k, 2, 2])


@njit(cache=True, inline="always")
def source_weights(l1, l2, w, cb, perspective):
    """Weights ``(w0, w1, w2)`` of the *source* triangle's vertices from the screen-space weights
    ``l1, l2`` of a clipped triangle's vertices 1 and 2.

    Perspective-correct (``perspective``, what GPUs and VTK do): each is divided by that
    vertex's clip w (``w``, a 3-tuple) and the three renormalised. Otherwise they stay
    screen-linear, as the course's scanline slides interpolate. Then they are mapped
    through the clipped vertices' own weights in the source triangle (``cb``, a 9-tuple,
    :func:`clip_weights`).
    """
    l0 = 1.0 - l1 - l2
    if perspective:
        b0, b1, b2 = l0 / w[0], l1 / w[1], l2 / w[2]
        s = b0 + b1 + b2
        b0, b1, b2 = b0 / s, b1 / s, b2 / s
    else:
        b0, b1, b2 = l0, l1, l2
    return (b0 * cb[0] + b1 * cb[3] + b2 * cb[6],
            b0 * cb[1] + b1 * cb[4] + b2 * cb[7],
            b0 * cb[2] + b1 * cb[5] + b2 * cb[8])


class Fragments(NamedTuple):
    """The visibility buffer and the clipped triangles it points into (window rows, y up).

    tri_index (H, W) clipped triangle per pixel (:data:`renderer.raster.EMPTY` = none);
    plane (K, ≥ 6) the triangles' set-up (the first six columns of
    :class:`renderer.raster.TriangleSetup`'s, :func:`renderer.raster.weight_planes`), from which
    the screen-space weights of a pixel are worked out (:func:`renderer.raster.screen_weights`);
    front (K,); tri_clip (K, 3, 4); clip_bary (K, 3, 3) weights in the source triangle;
    clip_source (K,) source triangle; perspective: weights made perspective-correct (else
    screen-linear, see :func:`fragment_weights`); span_weights, span_corners, span_object: the
    same triangles' span table (the fields of :class:`renderer.spans.SpanTable`, flat here:
    numba passes no tuple inside a tuple into a parallel loop), what their spans start from,
    gathered once (:func:`with_span_table`; empty until then, :func:`fragments`).
    """

    tri_index: np.ndarray
    plane: np.ndarray
    front: np.ndarray
    tri_clip: np.ndarray
    clip_bary: np.ndarray
    clip_source: np.ndarray
    perspective: bool
    span_weights: np.ndarray
    span_corners: np.ndarray
    span_object: np.ndarray


def fragments(tri_index, plane, front, tri_clip, clip_bary, clip_source, perspective) -> Fragments:
    """:class:`Fragments` of these clipped triangles, their span table still empty
    (:func:`with_span_table` fills it, where a frame is shaded in spans)."""
    return Fragments(tri_index, plane, front, tri_clip, clip_bary, clip_source, bool(perspective),
                     np.empty((0, 11)), np.empty((0, CORNERS), np.float32), np.empty(0, np.int64))


def with_span_table(frags: Fragments, geo, ws=None, name: str = "fragments", clipped=None,
                    textured: bool = False) -> Fragments:
    """``frags`` with their span table (:func:`renderer.spans.span_table`) in workspace buffers
    named after ``name``, built where the kernels need it (a frame painted from held colours
    neither builds nor compiles it); read from ``clipped`` (:class:`renderer.spans.CornerTables`)
    if given (:func:`renderer.spans.span_table_of_corners`: the same table, read from no planes
    or written-out corners); ``textured``: with the corners' texture coordinates
    (:data:`renderer.spans.TEXTURED_CORNERS`)."""
    k = len(frags.clip_source)
    columns = TEXTURED_CORNERS if textured else CORNERS
    table = SpanTable(empty(ws, f"{name}.span_weights", (k, 11)), empty(ws, f"{name}.span_corners", (k, columns), np.float32),
                      empty(ws, f"{name}.span_object", k, np.int64))
    if k and clipped is not None:
        span_table_of_corners(clipped, frags.perspective, geo, *table)
    elif k:
        span_table(frags.plane, frags.front, frags.tri_clip, frags.clip_bary, frags.clip_source, frags.perspective,
                   geo, *table)
    return frags._replace(span_weights=table.weights, span_corners=table.corners, span_object=table.object)


class ShadingInputs(NamedTuple):
    """What shading reads besides the geometry and the fragments: ``materials``
    (:class:`renderer.reflection.materials.Materials`), ``textures``
    (:class:`renderer.texture_sampling.Textures`), ``lights``
    (:class:`renderer.lights.ViewLights`) and ``lit`` (:class:`renderer.lit_colours.LitColours`)."""

    materials: tuple
    textures: tuple
    lights: tuple
    lit: tuple


@njit(cache=True, inline="always")
def interpolate(w, a, i0, i1, i2, first=0):
    """``w0·a[i0] + w1·a[i1] + w2·a[i2]`` over columns ``first .. first + 2`` of ``a``, as a 3-tuple."""
    return (w[0] * a[i0, first] + w[1] * a[i1, first] + w[2] * a[i2, first],
            w[0] * a[i0, first + 1] + w[1] * a[i1, first + 1] + w[2] * a[i2, first + 1],
            w[0] * a[i0, first + 2] + w[1] * a[i1, first + 2] + w[2] * a[i2, first + 2])


@njit(cache=True, inline="always")
def normalise(x, y, z):
    """(x, y, z) scaled to unit length; a zero vector stays zero."""
    length = math.sqrt(x * x + y * y + z * z)
    if length > 0.0:
        return x / length, y / length, z / length
    return x, y, z


@njit(cache=True, inline="always")
def fragment_colour(k, l1, l2, frags, geo, materials, textures, lights, lit):
    """The linear colour ``(r, g, b)`` of one fragment of clipped triangle ``k`` with
    screen-space weights ``l1, l2`` (of its vertices 1 and 2), by its object's shading path
    (see the module docstring). Only the clipped-triangle tables of ``frags`` (front,
    tri_clip, clip_bary, clip_source) are read. Scalars and tuples only: it runs per pixel
    (measured: writing into the rows of a scratch array instead, taken as views per fragment,
    made shading 1.5× slower on ``course-phong``).
    """
    tris = geo.triangles
    w = fragment_weights(frags, k, l1, l2)
    s = frags.clip_source[k]
    o = geo.tri_object[s]
    i0, i1, i2 = tris[s, 0], tris[s, 1], tris[s, 2]
    path = materials.shading_path[o]
    if path == FACE_COLOUR:
        r, g, b = lit.face[s, 0], lit.face[s, 1], lit.face[s, 2]
        sr, sg, sb = lit.face[s, 3], lit.face[s, 4], lit.face[s, 5]
    elif path == VERTEX_COLOUR:
        r, g, b = interpolate(w, lit.vertex, i0, i1, i2)
        sr, sg, sb = interpolate(w, lit.vertex, i0, i1, i2, 3)
    else:
        p = interpolate(w, geo.verts_view, i0, i1, i2)
        if path == PIXEL_FACE_NORMAL:
            nx, ny, nz = face_toward_viewer(geo, s)
        else:
            nx, ny, nz = interpolate(w, geo.normals_view, i0, i1, i2)
            nx, ny, nz = normalise(nx, ny, nz)
            if path == PIXEL_TWO_SIDED and not frags.front[k]:
                nx, ny, nz = -nx, -ny, -nz
        r, g, b, sr, sg, sb = reflect((nx, ny, nz), p, o, materials, lights)
    if textures.textured[o]:  # the texture multiplies the lit colour (VTK, GL_MODULATE) ...
        ts = w[0] * geo.tcoords[i0, 0] + w[1] * geo.tcoords[i1, 0] + w[2] * geo.tcoords[i2, 0]
        tt = w[0] * geo.tcoords[i0, 1] + w[1] * geo.tcoords[i1, 1] + w[2] * geo.tcoords[i2, 1]
        tr, tg, tb = sample_texture(textures, o, ts, tt)
        r, g, b = r * tr, g * tg, b * tb
    return r + sr, g + sg, b + sb  # ... and the separate specular colour (zero unless asked for) comes after it


@njit(cache=True, inline="always")
def copy_along(rgb, row, c0, c1):
    """Pixel c0's colour copied to c0 + 1 … c1 − 1 of ``row``."""
    for col in range(c0 + 1, c1):
        rgb[row, col, 0], rgb[row, col, 1], rgb[row, col, 2] = rgb[row, c0, 0], rgb[row, c0, 1], rgb[row, c0, 2]


@njit(cache=True, inline="always")
def store(rgb, row, col, r, g, b):
    rgb[row, col, 0] = unorm8(r)
    rgb[row, col, 1] = unorm8(g)
    rgb[row, col, 2] = unorm8(b)


@njit(cache=True, inline="always")
def modulate_span(k, consts, c0, count, frags, textures, o, scratch):
    """The span's linear colours (the colour of ``scratch`` (3, ≥ count) float32,
    :func:`span_scratch`) multiplied by object ``o``'s texture (VTK, GL_MODULATE). The
    pixels' texture coordinates are interpolated in float32 from the span's ``consts``
    (:func:`renderer.spans.span_setup`) and clipped triangle ``k``'s corners
    (:func:`renderer.spans.span_tcoords`, the bits :func:`shade_textured_run` gives them),
    into the row scratch ``st`` at their columns c0 … c0 + count − 1; then the whole span is
    filtered in one loop (:func:`renderer.texture_sampling.modulate_texels`)."""
    _, colour, st, fixed = scratch
    span_tcoords(consts, span_texture_corners(k, frags), count, st, c0)
    modulate_texels(textures, o, st, c0, count, colour, fixed)


@njit(cache=True, inline="always")
def hold_face_colour(s, row, c0, c1, lit, rgb):
    """Source triangle ``s``'s lit colour (primary + secondary, :mod:`renderer.lit_colours`)
    stored along the pixels c0 … c1 − 1 of ``row``."""
    r, g, b = face_colour(lit, s)
    store(rgb, row, c0, r, g, b)
    copy_along(rgb, row, c0, c1)


@njit(cache=True, inline="always")
def light_span(o, row, c0, c1, consts, face, materials, lights, scratch, rgb):
    """Object ``o``'s span kernel over the pixels c0 … c1 − 1 of ``row`` (``consts``, ``face``
    from :func:`renderer.spans.span_setup`), stored as 8 bits; when the colour cannot change
    along the span (a flat triangle whose model's colour depends on the normal alone), it is
    worked out at the first pixel and stored along it. ``scratch``: :func:`span_scratch`."""
    points, colour, _, _ = scratch
    constant = face and span_normal_only(o, materials, lights)
    count = 1 if constant else c1 - c0
    reflect_span(o, materials, lights, consts, face, count, points, colour, rgb[row, c0:c0 + count])
    if constant:
        copy_along(rgb, row, c0, c1)


@njit(cache=True, inline="always")
def object_of(k, frags, geo):
    """The object of clipped triangle ``k`` (read from the span table: one lookup, not two)."""
    return frags.span_object[k]


@njit(cache=True, inline="always")
def lit_per_pixel(o, materials, lights):
    """True when object ``o`` (one that :func:`span_covers`) is lit at every pixel by its
    model's span kernel: not FACE_COLOUR, and not a flat triangle whose colour depends on the
    normal alone (that is worked out once a span, :func:`light_span`)."""
    path = materials.shading_path[o]
    return path != FACE_COLOUR and not (path == PIXEL_FACE_NORMAL and span_normal_only(o, materials, lights))


@njit(cache=True, inline="always")
def span_scratch(width):
    """Scratch of a row: ``(points (8, W + 7), colour (3, W))`` float32 (see :func:`shade_lit_run`:
    the sums of :func:`renderer.spans.span_point_sums` in eight rows, six of them the points after),
    ``st`` (2, W + 7) float32, a span's texture coordinates (:func:`modulate_span`), and
    ``fixed``, the texels' fixed-point coordinates and the texels read
    (:func:`renderer.texture_sampling.texel_scratch`, :func:`renderer.texture_sampling.filter_span`). The points and
    coordinates have room for a span's whole vector lanes (:func:`renderer.spans.whole_lanes`)
    past the row's last column."""
    w = larger(width, 1)
    return (np.empty((8, w + LANES - 1), np.float32), np.empty((3, w), np.float32),
            np.empty((2, w + LANES - 1), np.float32), texel_scratch(w))


@njit(cache=True, inline="always")
def shade_lit_run(k, row, col, end, frags, geo, inputs, scratch, rgb):
    """Colour the **run** of pixels of ``row`` from ``col`` that show object ``o`` (clipped
    triangle ``k``'s), for an object that :func:`lit_per_pixel`: the spans of as many triangles
    as follow one another (the first ends at ``end``), each span's weighted sums into its
    columns (:func:`renderer.spans.span_point_sums`), then the whole run made points — divided
    by the weights' sum, normals made unit — in one loop (:func:`renderer.spans.finish_points`),
    lit in one loop (:func:`renderer.reflection.registry.light_points`) and stored. Returns the
    run's end.

    The same bytes as lighting each span on its own (:func:`light_span`): a pixel's point
    comes from its own triangle's span set-up either way, and the model's loop computes each
    pixel alone. But a run of thin triangles (one or two pixels a row: 1,024-segment
    cylinders, large meshes) lights its pixels 8 at a time instead of one by one in scalar
    code, and divides and takes roots 8 at a time too (the points in one pass, span by span:
    the 1,024-segment cylinder's shading at 1024² 3.23–3.35 ms against 3.07–3.16 in two,
    the 1M-triangle scan's 4.99 against 4.71; spans of six pixels, the level-5 icosphere's,
    the same). ``inputs``: ``(materials, lights)``; ``scratch``: :func:`span_scratch`,
    the points at the pixels' own columns."""
    materials, lights = inputs
    points, colour, _, _ = scratch
    o = object_of(k, frags, geo)
    face = materials.shading_path[o] == PIXEL_FACE_NORMAL
    start = col
    while k != EMPTY:  # whole lanes: the sums past a span's end are the next span's, written over next
        span_point_sums(span_setup(k, row, col, frags, geo, face), face, whole_lanes(end - col), points, col)
        col = end
        k, end = next_span_of(o, row, col, frags, geo)
    finish_points(points, start, col - start, face)
    light_points(o, materials, lights, points, start, col - start, colour)
    store_span(colour, col - start, rgb[row, start:col])
    return col


@njit(cache=True, inline="always")
def next_span_of(o, row, col, frags, geo):
    """The span that starts at ``col`` on ``row`` (its triangle and end, :func:`span_end`) if
    it shows object ``o``; else (EMPTY, col): a run of one object ends there."""
    if col == frags.tri_index.shape[1]:
        return EMPTY, col
    k = frags.tri_index[row, col]
    if k == EMPTY or object_of(k, frags, geo) != o:
        return EMPTY, col
    return k, span_end(frags.tri_index, row, col, True)


@njit(cache=True, inline="always")
def textured_run(o, materials, textures, lights):
    """True when object ``o`` is textured and lit per pixel by its model's span kernel: then
    :func:`shade_textured_run` colours whole runs of it (else :func:`shade_span`)."""
    path = materials.shading_path[o]
    return textures.textured[o] and (path == PIXEL_FACE_NORMAL or path == PIXEL_TWO_SIDED) and span_applies(
        o, materials, lights)


@njit(cache=True, inline="always")
def shade_textured_run(k, row, col, end, frags, geo, inputs, scratch, rgb):
    """:func:`shade_lit_run` for a :func:`textured_run` object: each span of the run gives its
    points and its texture coordinates (:func:`span_tcoords`) at their columns, then the
    whole run is lit in one loop, multiplied by its texels in one loop
    (:func:`renderer.texture_sampling.modulate_texels`) and stored. The same bytes as
    :func:`shade_span` span by span (each pixel's point, coordinates and texel are its own
    triangle's), with the lighting and the texture filter run over a whole row of the
    object instead of spans a few pixels long. Returns the run's end. ``inputs``:
    ``(materials, textures, lights, lit)``. Kept apart from :func:`shade_lit_run`, whose
    kernel (:func:`shade_rows_lit_spans`) then compiles no texture code."""
    materials, textures, lights, _ = inputs
    points, colour, st, fixed = scratch
    o = object_of(k, frags, geo)
    face = materials.shading_path[o] == PIXEL_FACE_NORMAL
    start = col
    while k != EMPTY:  # whole lanes: the values past a span's end are the next span's, written over next
        span_textured_points(span_setup(k, row, col, frags, geo, face), span_texture_corners(k, frags), face,
                             whole_lanes(end - col), points, st, col)
        col = end
        k, end = next_span_of(o, row, col, frags, geo)
    light_points(o, materials, lights, points, start, col - start, colour)
    modulate_texels(textures, o, st, start, col - start, colour, fixed)
    store_span(colour, col - start, rgb[row, start:col])
    return col


@njit(cache=True, inline="always")
def span_covers(o, materials, textures, lights):
    """True when object ``o`` can be shaded by :func:`shade_rows_lit_spans`: untextured, and
    either FACE_COLOUR or lit per pixel (PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED) by a model with a
    span kernel for these lights (:func:`shade_span`'s first way, or its second untextured).
    :func:`spans_cover_all` is its Python twin."""
    path = materials.shading_path[o]
    return not textures.textured[o] and (path == FACE_COLOUR or (
        (path == PIXEL_FACE_NORMAL or path == PIXEL_TWO_SIDED) and span_applies(o, materials, lights)))


def spans_cover_all(materials, textures, lights) -> bool:
    """True when :func:`span_covers` holds for every object (the same rule in Python, for
    :func:`shade` to choose its kernel; ``tests/renderer/test_shading.py`` checks the two agree)."""
    return all(not textures.textured[o] and (path == FACE_COLOUR or (
        path in (PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED) and spans_apply(o, materials, lights)))
        for o, path in enumerate(materials.shading_path))


@njit(cache=True, inline="always")
def shade_span(k, row, c0, c1, frags, geo, inputs, scratch, rgb):
    """Colour the pixels c0 … c1 − 1 of ``row``, all showing clipped triangle ``k``;
    ``inputs`` is ``(materials, textures, lights, lit)`` (as :class:`ShadingInputs`).

    Three ways, the first that applies: an untextured FACE_COLOUR triangle holds one colour
    (:func:`hold_face_colour`); an object whose model has a span kernel
    (:func:`renderer.reflection.registry.span_applies`) is interpolated and lit in one
    float32 loop over the span (:mod:`renderer.spans`): untextured, stored by
    :func:`light_span`; textured, multiplied by its texels (:func:`modulate_span`), then
    stored; anything else goes pixel by pixel through :func:`fragment_colour`. (One
    :func:`renderer.spans.span_setup` for both span ways: the parallel loop this is inlined
    into compiled in 52 s instead of 29 s with one for each.) ``scratch``: :func:`span_scratch`.
    """
    materials, textures, lights, lit = inputs
    s = frags.clip_source[k]
    o = geo.tri_object[s]
    path = materials.shading_path[o]
    textured = textures.textured[o]
    if path == FACE_COLOUR and not textured:
        hold_face_colour(s, row, c0, c1, lit, rgb)
        return
    face = path == PIXEL_FACE_NORMAL
    if (face or path == PIXEL_TWO_SIDED) and span_applies(o, materials, lights):
        consts = span_setup(k, row, c0, frags, geo, face)
        if textured:
            points, colour, _, _ = scratch
            span_colours(o, materials, lights, consts, face, c1 - c0, points, colour)
            modulate_span(k, consts, c0, c1 - c0, frags, textures, o, scratch)
            store_span(colour, c1 - c0, rgb[row, c0:c1])
        else:
            light_span(o, row, c0, c1, consts, face, materials, lights, scratch, rgb)
        return
    for col in range(c0, c1):
        l1, l2 = screen_weights(k, row, col, frags.plane)
        r, g, b = fragment_colour(k, l1, l2, frags, geo, materials, textures, lights, lit)
        store(rgb, row, col, r, g, b)


@njit(cache=True, inline="always")
def span_end(tri_index, row, col, spans):
    """The end (exclusive) of the run of pixels from ``col`` on ``row`` that show the same
    triangle; ``spans`` False: ``col + 1``."""
    k, end, width = tri_index[row, col], col + 1, tri_index.shape[1]
    while spans and end < width and tri_index[row, end] == k:
        end += 1
    return end


@njit(cache=True, inline="always")
def fill_colour(rgb, row, c0, c1, colour):
    """The 8-bit ``colour`` (3,) stored along the pixels c0 … c1 − 1 of ``row`` (the background,
    or a colour held per triangle)."""
    for c in range(c0, c1):
        rgb[row, c, 0], rgb[row, c, 1], rgb[row, c, 2] = colour[0], colour[1], colour[2]


@njit(cache=True, parallel=True)
def shade_rows(frags, geo, materials, textures, lights, lit, background, n_bands, spans, rgb):
    """Colour every covered pixel and store 8-bit RGB (the loop kernel), every shading path.

    Each row is walked in spans of pixels that show the same triangle (:func:`shade_span`),
    a textured object lit per pixel in runs of its spans (:func:`shade_textured_run`);
    an empty pixel gets the 8-bit ``background``. ``spans`` False cuts every span to one
    pixel (the plain path the tests compare the spans with: the same bytes). Rows are
    independent and each pixel is written once, so a parallel loop gives the same bytes as
    a serial one, whatever the number of bands ``n_bands`` the rows are dealt to
    (:mod:`renderer.bands`). The walk is written out in the parallel loop: as a call to a
    kernel compiled on its own, frames were 5–25 % slower (ico5, textured-sphere; one
    thread); as an inlined function, this kernel took 8 s longer to compile.
    """
    height, width = frags.tri_index.shape
    for band in prange(n_bands):
        inputs = (materials, textures, lights, lit)  # made inside the parallel loop: numba passes no tuple into it
        scratch = span_scratch(width)
        for row in range(band, height, n_bands):
            col = 0
            while col < width:
                k, end = frags.tri_index[row, col], span_end(frags.tri_index, row, col, spans)
                if k == EMPTY:
                    fill_colour(rgb, row, col, end, background)
                elif spans and textured_run(object_of(k, frags, geo), materials, textures, lights):
                    end = shade_textured_run(k, row, col, end, frags, geo, inputs, scratch, rgb)
                else:
                    shade_span(k, row, col, end, frags, geo, inputs, scratch, rgb)
                col = end


@njit(cache=True, parallel=True)
def shade_rows_lit_spans(frags, geo, materials, lights, held, background, n_bands, rgb):
    """:func:`shade_rows` for a frame whose every object :func:`span_covers`, two ways: runs of
    one object lit per pixel (:func:`shade_lit_run`); colours held per triangle (``held`` (K, 3)
    uint8, :mod:`renderer.held_colours`: flat under a headlight, and FACE_COLOUR) copied along
    their spans. The same bytes as :func:`shade_rows`, which takes the same ways span by
    span, without the pixel-by-pixel models and textures: a frame that needs no more compiles
    no more (:func:`shade` chooses). A fresh process drawing a phong icosphere compiled its
    shading in 8 s instead of 27.5 s (CPU)."""
    height, width = frags.tri_index.shape
    for band in prange(n_bands):
        inputs = (materials, lights)  # made inside the parallel loop: numba passes no tuple into it
        scratch = span_scratch(width)
        for row in range(band, height, n_bands):
            col = 0
            while col < width:
                k, end = frags.tri_index[row, col], span_end(frags.tri_index, row, col, True)
                if k == EMPTY:
                    fill_colour(rgb, row, col, end, background)
                elif lit_per_pixel(object_of(k, frags, geo), materials, lights):
                    end = shade_lit_run(k, row, col, end, frags, geo, inputs, scratch, rgb)
                else:  # held per triangle, or FACE_COLOUR
                    fill_colour(rgb, row, col, end, held[k])
                col = end


def painted_from_held(inputs: ShadingInputs, spans: bool = True) -> bool:
    """True when :func:`shade` paints the frame from its held colours (every object
    :func:`renderer.held_colours.all_held`, :func:`renderer.held_colours.paint_rows`): it
    then reads the fragments' visibility buffer and source triangles only, not their planes,
    corners or span table (:func:`renderer.pipeline.shading_fragments` leaves them empty)."""
    return (spans and spans_cover_all(inputs.materials, inputs.textures, inputs.lights)
            and all_held(inputs.materials, inputs.lights))


HELD, SPAN_TABLE, EVERYTHING = "source triangles", "span table", "everything"


def fragment_reads(inputs: ShadingInputs, spans: bool = True) -> str:
    """What :func:`shade` reads of the fragments' tables: :data:`HELD`, their source triangles
    (:func:`painted_from_held`); :data:`SPAN_TABLE`, those and the span table (every object
    :func:`span_covers`: :func:`shade_rows_lit_spans`); else :data:`EVERYTHING`."""
    if painted_from_held(inputs, spans):
        return HELD
    return SPAN_TABLE if spans and spans_cover_all(inputs.materials, inputs.textures, inputs.lights) else EVERYTHING


@njit(cache=True, parallel=True)
def paint_background(background, rgb):
    """Every pixel of ``rgb`` (H, W, 3) uint8 the 8-bit ``background`` (3,): the shading of a
    frame without triangles, the bytes the kernels give its empty pixels, rows in parallel
    (:func:`fill_colour`). (numpy broadcasting the three values over each pixel took 1.5 ms at
    512²; one row filled and copied to every row, 18 µs for the row and one thread for the copy.)"""
    for row in prange(rgb.shape[0]):
        fill_colour(rgb, row, 0, rgb.shape[1], background)


def shade(frags: Fragments, geo, inputs: ShadingInputs, background: np.ndarray, rgb: np.ndarray,
          n_bands: int | None = None, spans: bool = True, reads: str | None = None) -> None:
    """Shade the visibility buffer ``frags`` into ``rgb`` (H, W, 3) uint8, window rows (the
    Python wrapper). ``background`` is the 8-bit clear colour; ``n_bands`` defaults to
    :func:`renderer.bands.shading_bands`; ``spans=False`` shades pixel by pixel (the plain
    path, for tests); ``reads``: :func:`fragment_reads` of ``inputs`` and ``spans`` when the
    caller has it (the pipeline chose the fragments' tables by it), else worked out here; a
    frame without triangles is painted with the background (:func:`paint_background`)."""
    if len(frags.clip_source) == 0:  # no triangle (nothing opaque): the background everywhere, no threads started
        paint_background(background, rgb)
        return
    height = frags.tri_index.shape[0]
    n_bands = shading_bands(height) if n_bands is None else max(1, min(int(n_bands), height))
    reads = fragment_reads(inputs, spans) if reads is None else reads
    if reads == HELD:
        held = held_colour_table(frags, geo, inputs.materials, inputs.lights, inputs.lit, thread_workspace())
        with one_band_at_a_time():
            paint_rows(frags.tri_index, held, background, n_bands, rgb)
    elif reads == SPAN_TABLE:
        held = held_colour_table(frags, geo, inputs.materials, inputs.lights, inputs.lit, thread_workspace())
        if len(frags.span_object) != len(frags.clip_source):  # none yet; outside one_band_at_a_time
            frags = with_span_table(frags, geo, thread_workspace())
        with one_band_at_a_time():
            shade_rows_lit_spans(frags, geo, inputs.materials, inputs.lights, held, background, n_bands, rgb)
    else:
        frags = with_span_table(frags, geo, thread_workspace(), textured=bool(inputs.textures.textured.any()))
        with one_band_at_a_time():
            shade_rows(frags, geo, inputs.materials, inputs.textures, inputs.lights, inputs.lit, background, n_bands,
                       bool(spans), rgb)
