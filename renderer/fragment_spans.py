"""A span's linear colours: a run of one triangle's fragments on a row, lit but not yet stored.

Translucent fragments (:mod:`renderer.translucency`) are blended, not stored, so they need
the colour *before* the framebuffer's 8-bit store: linear RGB, unclamped (a highlight
brighter than 1 still counts). :func:`span_linear_colours` gives it for a run of
neighbouring pixels of one clipped triangle, lit the way the opaque pass lights them
(:func:`renderer.shading.shade_span`):

- an object whose reflection model has a span kernel
  (:func:`renderer.reflection.registry.span_applies`) is interpolated and lit in one
  float32 loop over the run (:mod:`renderer.spans`), as VTK's fragment shader computes in
  float32; a texture multiplies it (:func:`renderer.shading.modulate_span`); a flat
  untextured triangle whose colour depends on the normal alone is lit once;
- anything else goes pixel by pixel through :func:`renderer.shading.fragment_colour`
  (float64), then float32.

A pixel gets the same bits whichever run it is lit in (the span weights are anchored at the
triangle's first vertex, :mod:`renderer.spans`), so runs of one pixel give the same colours
as long runs: the plain path the tests compare with.
"""
from __future__ import annotations

import numpy as np

from renderer.jit import njit
from renderer.raster import screen_weights
from renderer.reflection.materials import PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED
from renderer.reflection.registry import light_points, span_applies, span_colours, span_normal_only
from renderer.shading import fragment_colour, modulate_span
from renderer.spans import span_points, span_setup


@njit(cache=True, inline="always")
def span_linear_colours(k, row, c0, count, frags, geo, inputs, scratch):
    """The linear colours of clipped triangle ``k``'s pixels ``c0 … c0 + count − 1`` on
    ``row`` into the colour of ``scratch`` (points (6, ≥ count), colour (3, ≥ count)
    float32, texture coordinates (2, W) float32 at the pixels' columns, W the row's
    width: :func:`renderer.shading.span_scratch`;
    see the module docstring). ``frags``: a
    :class:`renderer.shading.Fragments` whose ``plane`` is the triangles' set-up (its
    ``tri_index`` is not read); ``inputs``: ``(materials, textures, lights, lit)``."""
    materials, textures, lights, lit = inputs
    points, colour, _, _ = scratch
    s = frags.clip_source[k]
    o = geo.tri_object[s]
    path = materials.shading_path[o]
    textured = textures.textured[o]
    face = path == PIXEL_FACE_NORMAL
    if (face or path == PIXEL_TWO_SIDED) and span_applies(o, materials, lights):
        consts = span_setup(k, row, c0, frags, geo, face)
        constant = face and not textured and span_normal_only(o, materials, lights)
        span_colours(o, materials, lights, consts, face, 1 if constant else count, points, colour)
        if textured:
            modulate_span(k, consts, c0, count, frags, textures, o, scratch)
        if constant:
            for i in range(1, count):
                colour[0, i], colour[1, i], colour[2, i] = colour[0, 0], colour[1, 0], colour[2, 0]
        return
    pixel_by_pixel(k, row, c0, count, frags, geo, inputs, colour)


@njit(cache=True, inline="always")
def lit_in_batches(o, materials, textures, lights):
    """True when object ``o``'s fragments can be lit many runs at a time
    (:func:`batch_points`, then :func:`light_batch`): untextured and lit at every pixel by
    its model's span kernel (not a colour held along a span). A triangle's runs on the rows
    of a strip are then lit in one loop instead of one loop a run (a run is ten pixels or
    so: too short for the loop's vector body)."""
    path = materials.shading_path[o]
    face = path == PIXEL_FACE_NORMAL
    return (not textures.textured[o] and (face or path == PIXEL_TWO_SIDED) and span_applies(o, materials, lights)
            and not (face and span_normal_only(o, materials, lights)))


@njit(cache=True, inline="always")
def batch_points(k, row, c0, count, frags, geo, face, points, at):
    """The interpolated points of a run (clipped triangle ``k``'s pixels ``c0 … c0 + count −
    1`` on ``row``) into columns ``at`` … of a batch's ``points`` (6, N) float32
    (:func:`renderer.spans.span_points`): the points :func:`span_linear_colours` lights."""
    span_points(span_setup(k, row, c0, frags, geo, face), face, count, points, at)


@njit(cache=True, inline="always")
def light_batch(o, materials, lights, points, count, colour):
    """The linear colours of a batch's first ``count`` points (:func:`batch_points`) of object
    ``o`` into ``colour`` (3, ≥ count) float32, in one loop: each the colour
    :func:`span_linear_colours` gives its pixel."""
    light_points(o, materials, lights, points, 0, count, colour)


@njit(cache=True, from_python=False)
def pixel_by_pixel(k, row, c0, count, frags, geo, inputs, colour):
    """The fallback of :func:`span_linear_colours`: each pixel's
    :func:`renderer.shading.fragment_colour` (float64), as float32. Compiled on its own, not
    inlined into the kernels that call it: it is the biggest function of the shading code
    (every reflection model), and the fast path rarely needs it."""
    materials, textures, lights, lit = inputs
    for i in range(count):
        l1, l2 = screen_weights(k, row, c0 + i, frags.plane)
        r, g, b = fragment_colour(k, l1, l2, frags, geo, materials, textures, lights, lit)
        colour[0, i], colour[1, i], colour[2, i] = np.float32(r), np.float32(g), np.float32(b)
