"""Texture sampling at a fragment: OpenGL's nearest and bilinear filters, repeat and clamp.

Texture space: s to the right, t up, (0, 0) the bottom-left corner of the image, texel
(i, j) covering [i/W, (i+1)/W] × [j/H, (j+1)/H] with its centre at ((i+0.5)/W, (j+0.5)/H).
All of a scene's textures live in one flat uint8 array (``texels``, (Σ H·W, 3), the 8-bit
values VTK uploads), each object's starting at ``offset[o]``, rows from the bottom (see
:mod:`lab.texture`): :class:`Textures`, built once per frame by :func:`texture_table`.
Colours come out as value/255.

- nearest: texel (⌊s·W⌋, ⌊t·H⌋);
- linear: the four texels around (s·W − ½, t·H − ½), weighted bilinearly — in llvmpipe's
  fixed point for 8-bit textures: weights truncated to 8 fractional bits, each lerp
  ``a + ((b − a)·w + 128) >> 8`` on 0..255 integers, horizontal then vertical (measured:
  float weights leave 0.5 % of pixels over ΔE 1 against VTK, this 0.02 %);
- repeat wraps an index modulo the size; clamp holds it to [0, size − 1]
  (GL_CLAMP_TO_EDGE). No mipmaps (VTK's default).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from renderer.jit import njit

NEAREST, LINEAR = 0, 1
REPEAT, CLAMP = 0, 1


class Textures(NamedTuple):
    """Every object's texture (index = object), as the kernels read it.

    textured (O,) bool; offset, width, height (O,) int: where its texels start in
    ``texels`` and its size; filter (O,) :data:`NEAREST` or :data:`LINEAR`; wrap (O,)
    :data:`REPEAT` or :data:`CLAMP`; texels (Σ H·W, 3) uint8, all textures one after the other.
    """

    textured: np.ndarray
    offset: np.ndarray
    width: np.ndarray
    height: np.ndarray
    filter: np.ndarray
    wrap: np.ndarray
    texels: np.ndarray


def texture_table(scene) -> Textures:
    """All objects' textures in one flat (Σ H·W, 3) uint8 array (their ``texels_8bit``), and
    per object: textured flag, offset, width, height, filter and wrap codes.

    Only textured objects take rows (the kernels sample nothing for the others). With one
    textured object the flat array is a view of its texels, not a copy: a 2048×1024 texture
    copied every frame cost more than shading the frame."""
    textured, offset, width, height, filt, wrap, chunks = [], [], [], [], [], [], []
    start = 0
    for obj in scene.objects:
        t = obj.texture
        textured.append(t is not None)
        h, w = (t.texels.shape[:2]) if t is not None else (1, 1)
        offset.append(start if t is not None else 0)
        width.append(w)
        height.append(h)
        filt.append(LINEAR if t is not None and t.filter == "linear" else NEAREST)
        wrap.append(CLAMP if t is not None and t.wrap == "clamp" else REPEAT)
        if t is not None:
            chunks.append(t.texels_8bit.reshape(-1, 3))
            start += h * w
    if not chunks:
        texels = np.full((1, 3), 255, np.uint8)
    else:
        texels = chunks[0] if len(chunks) == 1 else np.concatenate(chunks)
    as_int = lambda v: np.array(v, np.int64)  # noqa: E731
    return Textures(np.array(textured, np.bool_), as_int(offset), as_int(width), as_int(height), as_int(filt),
                    as_int(wrap), texels)


@njit(cache=True, inline="always")
def wrap_index(i, size, wrap):
    """An integer texel index wrapped (repeat) or clamped (clamp) into 0..size − 1."""
    if wrap == REPEAT:
        return i % size
    return min(max(i, 0), size - 1)


@njit(cache=True, inline="always")
def texel(texels, offset, width, i, j, c):
    return texels[offset + j * width + i, c]


@njit(cache=True)
def sample(texels, offset, width, height, filter_mode, wrap, s, t):
    """The filtered texture colour at (s, t): ``(r, g, b)``, each value/255."""
    if filter_mode == NEAREST:
        i = wrap_index(int(math.floor(s * width)), width, wrap)
        j = wrap_index(int(math.floor(t * height)), height, wrap)
        return (texel(texels, offset, width, i, j, 0) / 255.0, texel(texels, offset, width, i, j, 1) / 255.0,
                texel(texels, offset, width, i, j, 2) / 255.0)
    u = s * width - 0.5
    v = t * height - 0.5
    i0f = math.floor(u)
    j0f = math.floor(v)
    wa = int(math.floor((u - i0f) * 256.0))  # weights with 8 fractional bits
    wb = int(math.floor((v - j0f) * 256.0))
    i0 = wrap_index(int(i0f), width, wrap)
    i1 = wrap_index(int(i0f) + 1, width, wrap)
    j0 = wrap_index(int(j0f), height, wrap)
    j1 = wrap_index(int(j0f) + 1, height, wrap)
    return (bilinear(texels, offset, width, i0, i1, j0, j1, wa, wb, 0) / 255.0,
            bilinear(texels, offset, width, i0, i1, j0, j1, wa, wb, 1) / 255.0,
            bilinear(texels, offset, width, i0, i1, j0, j1, wa, wb, 2) / 255.0)


@njit(cache=True, inline="always")
def bilinear(texels, offset, width, i0, i1, j0, j1, wa, wb, c):
    """Channel ``c`` of the four texels (i0, j0) … (i1, j1) blended with 8-bit weights ``wa``
    (horizontal) and ``wb`` (vertical), as llvmpipe does: 0..255 integers."""
    t00 = np.int64(texel(texels, offset, width, i0, j0, c))
    t10 = np.int64(texel(texels, offset, width, i1, j0, c))
    t01 = np.int64(texel(texels, offset, width, i0, j1, c))
    t11 = np.int64(texel(texels, offset, width, i1, j1, c))
    h0 = t00 + (((t10 - t00) * wa + 128) >> 8)
    h1 = t01 + (((t11 - t01) * wa + 128) >> 8)
    return h0 + (((h1 - h0) * wb + 128) >> 8)


@njit(cache=True, inline="always")
def sample_texture(textures, o, s, t):
    """Object ``o``'s texture at (s, t): :func:`sample` on its part of ``textures``."""
    return sample(textures.texels, textures.offset[o], textures.width[o], textures.height[o], textures.filter[o],
                  textures.wrap[o], s, t)
