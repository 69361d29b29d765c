"""Texture sampling at a fragment: OpenGL's nearest and bilinear filters, repeat and clamp.

Texture space: s to the right, t up, (0, 0) the bottom-left corner of the image, texel
(i, j) covering [i/W, (i+1)/W] × [j/H, (j+1)/H] with its centre at ((i+0.5)/W, (j+0.5)/H).
All of a scene's textures live in one flat uint8 array (``texels``, (Σ H·W, 3), the 8-bit
values VTK uploads), each object's starting at ``offset[o]``, rows from the bottom (see
:mod:`lab.texture`). Colours come out as value/255.

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

import numpy as np
from renderer.jit import njit

NEAREST, LINEAR = 0, 1
REPEAT, CLAMP = 0, 1


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
def sample(texels, offset, width, height, filter_mode, wrap, s, t, out):
    """The filtered texture colour at (s, t) into ``out`` (3,)."""
    if filter_mode == NEAREST:
        i = wrap_index(int(math.floor(s * width)), width, wrap)
        j = wrap_index(int(math.floor(t * height)), height, wrap)
        for c in range(3):
            out[c] = texel(texels, offset, width, i, j, c) / 255.0
        return
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
    for c in range(3):
        t00 = np.int64(texel(texels, offset, width, i0, j0, c))
        t10 = np.int64(texel(texels, offset, width, i1, j0, c))
        t01 = np.int64(texel(texels, offset, width, i0, j1, c))
        t11 = np.int64(texel(texels, offset, width, i1, j1, c))
        h0 = t00 + (((t10 - t00) * wa + 128) >> 8)
        h1 = t01 + (((t11 - t01) * wa + 128) >> 8)
        out[c] = (h0 + (((h1 - h0) * wb + 128) >> 8)) / 255.0
