"""Texture sampling at a fragment: OpenGL's nearest and bilinear filters, repeat and clamp.

Texture space: s to the right, t up, (0, 0) the bottom-left corner of the image, texel
(i, j) covering [i/W, (i+1)/W] × [j/H, (j+1)/H] with its centre at ((i+0.5)/W, (j+0.5)/H).
All of a scene's textures live in one flat array (``texels``, (Σ H·W,) uint32, the 8-bit
values VTK uploads), each object's starting at ``offset[o]``, rows from the bottom (see
:mod:`lab.texture`): :class:`Textures`, built once per frame by :func:`texture_table`.
A texel is stored as llvmpipe stores an 8-bit texture, r, g and b in one 32-bit word (bits
0–7, 8–15, 16–23; :func:`pack_texels`), and widened when it is read into 16-bit **lanes**
of a 64-bit integer (:func:`lanes_of`: r in bits 0–7, b in 16–23, g in 32–39), as llvmpipe
widens 8-bit texels to 16-bit lanes to filter them: one load fetches a texel, and the
bilinear blend works on the three lanes at once. (Kept in lanes, 8 bytes a texel, the
2048×1024 earth of ``textured-sphere`` filled 16 MB, and its frames waited on the cache:
4 bytes a texel made them 0.95 of the time, 512² and 1024², docs/performance.md.)
Colours come out as value/255.

- nearest: texel (⌊s·W⌋, ⌊t·H⌋);
- linear: the four texels around (s·W − ½, t·H − ½), weighted bilinearly — in llvmpipe's
  fixed point for 8-bit textures: weights truncated to 8 fractional bits, each lerp
  ``a + ((b − a)·w + 128) >> 8`` on 0..255 integers, horizontal then vertical (measured:
  float weights leave 0.5 % of pixels over ΔE 1 against VTK, this 0.02 %);
- repeat wraps an index modulo the size; clamp holds it to [0, size − 1]
  (GL_CLAMP_TO_EDGE). No mipmaps (VTK's default).

A span of pixels (:func:`modulate_texels`, float32 coordinates) decides filter and wrap
once and runs one straight loop per filter; an index already inside the texture is taken
as it is, without the wrap's ``%``, and a span whose texels all lie inside reads them with
no wrap tests at all. :func:`sample`, one fragment at a time, gives the same values.
"""
from __future__ import annotations

import math
import weakref
from typing import NamedTuple

import numpy as np
from renderer.jit import njit
from renderer.min_max import clamp, larger, smaller

NEAREST, LINEAR = 0, 1
REPEAT, CLAMP = 0, 1


class Textures(NamedTuple):
    """Every object's texture (index = object), as the kernels read it.

    textured (O,) bool; offset, width, height (O,) int: where its texels start in
    ``texels`` and its size; filter (O,) :data:`NEAREST` or :data:`LINEAR`; wrap (O,)
    :data:`REPEAT` or :data:`CLAMP`; texels (Σ H·W,) uint32, all textures one after the other,
    a texel's three 8-bit values in one word (:func:`pack_texels`).
    """

    textured: np.ndarray
    offset: np.ndarray
    width: np.ndarray
    height: np.ndarray
    filter: np.ndarray
    wrap: np.ndarray
    texels: np.ndarray


def texture_table(scene) -> Textures:
    """All objects' textures in one flat (Σ H·W,) uint32 array (their texels packed,
    :func:`packed_texels`), and per object: textured flag, offset, width, height, filter and
    wrap codes.

    Only textured objects take rows (the kernels sample nothing for the others). With one
    textured object the flat array is its packed texels as kept, not a copy: a 2048×1024 texture
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
            chunks.append(packed_texels(t))
            start += h * w
    if not chunks:
        texels = _WHITE
    else:
        texels = chunks[0] if len(chunks) == 1 else np.concatenate(chunks)
    as_int = lambda v: np.array(v, np.int64)  # noqa: E731
    return Textures(np.array(textured, np.bool_), as_int(offset), as_int(width), as_int(height), as_int(filt),
                    as_int(wrap), texels)


LANE = 16
"""Bits per lane: a channel's 8 bits and room for the 8.8 fixed-point product of a lerp."""

_PACKED: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()


def pack_texels(texels_8bit: np.ndarray) -> np.ndarray:
    """(…, 3) uint8 texels → (N,) uint32: r in bits 0–7, g in 8–15, b in 16–23."""
    t = np.asarray(texels_8bit, np.uint8).reshape(-1, 3).astype(np.uint32)
    return t[:, 0] | (t[:, 1] << np.uint32(8)) | (t[:, 2] << np.uint32(16))


_WHITE = pack_texels(np.full((1, 3), 255, np.uint8))
"""The table of a scene without textures: one white texel, which no kernel samples (left writeable:
numba types a read-only array apart, and would compile the shading kernels again for it)."""


def packed_texels(texture) -> np.ndarray:
    """A :class:`lab.texture.Texture`'s 8-bit texels (``texels_8bit``) packed by
    :func:`pack_texels`, rows from the bottom. Worked out once per texture and kept as long
    as the texture lives (it does not depend on the camera)."""
    packed = _PACKED.get(texture)
    if packed is None:
        packed = _PACKED[texture] = pack_texels(texture.texels_8bit)
    return packed


@njit(cache=True, inline="always")
def wrap_index(i, size, wrap):
    """An integer texel index wrapped (repeat) or clamped (clamp) into 0..size − 1."""
    if wrap == REPEAT:
        return i % size
    return clamp(i, 0, size - 1)


UNIT32 = (np.arange(256) / 255.0).astype(np.float32)
"""An 8-bit value v as ``float32(v / 255)``, looked up (the same bits as dividing)."""
LOW8 = np.uint64(0xFF)
RED_BLUE = np.uint64(0x00FF00FF)
"""A packed texel's r and b: already 16 bits apart."""
GREEN = np.uint64(0xFF00)
"""A packed texel's g, moved 24 bits up into the third lane."""
LANES8 = np.uint64(0x000000FF00FF00FF)
"""The low 8 bits of each lane."""
HALF = np.uint64(0x0000008000800080)
"""128 in each lane: the lerp's rounding."""
U8, U16, U24, U32 = np.uint64(8), np.uint64(LANE), np.uint64(24), np.uint64(2 * LANE)


@njit(cache=True, inline="always")
def texel(texels, offset, width, i, j):
    """Texel (i, j) of the texture starting at ``offset``: its three channels in lanes (:func:`lanes_of`)."""
    return lanes_of(texels[np.uint64(offset + j * width + i)])


@njit(cache=True, inline="always")
def lanes_of(packed):
    """A packed texel (:func:`pack_texels`) widened into 16-bit lanes: r and b stay where they
    are (bits 0–7 and 16–23), g moves from bits 8–15 to 32–39. Two masks, a shift and an or."""
    word = np.uint64(packed)
    return (word & RED_BLUE) | ((word & GREEN) << U24)


@njit(cache=True, inline="always")
def channels(lanes):
    """The three 0..255 values ``(r, g, b)`` held in lanes (:func:`lanes_of`: r, b, g from the lowest)."""
    return lanes & LOW8, (lanes >> U32) & LOW8, (lanes >> U16) & LOW8


@njit(cache=True, inline="always")
def wrap_pair(i, size, wrap):
    """Indices ``i`` and ``i + 1`` wrapped or clamped (:func:`wrap_index`); when both already lie
    in 0..size − 1, as they do for most fragments, they are taken as they are (no ``%``)."""
    if i >= 0 and i + 1 < size:
        return i, i + 1
    return wrap_index(i, size, wrap), wrap_index(i + 1, size, wrap)


@njit(cache=True, inline="always")
def wrap_one(i, size, wrap):
    """:func:`wrap_index`, skipping the wrap when ``i`` already lies in 0..size − 1."""
    if i >= 0 and i < size:
        return i
    return wrap_index(i, size, wrap)


@njit(cache=True, inline="always")
def nearest_texel(texels, offset, width, height, wrap, s, t):
    """The nearest filter at (s, t): texel (⌊s·W⌋, ⌊t·H⌋), wrapped, in lanes."""
    i = wrap_one(int(math.floor(s * width)), width, wrap)
    j = wrap_one(int(math.floor(t * height)), height, wrap)
    return texel(texels, offset, width, i, j)


@njit(cache=True, inline="always")
def linear_texel(texels, offset, width, height, wrap, s, t):
    """The linear filter at (s, t), in lanes: the four texels around (u, v) = (s·W − ½, t·H − ½)
    blended by :func:`bilinear`. ``u·256`` is exact (a power of two), so its floor holds the
    left texel column (``>> 8``) and the weight's 8 fractional bits (``& 255``) at once,
    ⌊(u − ⌊u⌋)·256⌋ as llvmpipe's fixed point has it; the same for v."""
    fu = int(math.floor((s * width - 0.5) * 256.0))
    fv = int(math.floor((t * height - 0.5) * 256.0))
    i0, i1 = wrap_pair(fu >> 8, width, wrap)
    j0, j1 = wrap_pair(fv >> 8, height, wrap)
    return bilinear(texel(texels, offset, width, i0, j0), texel(texels, offset, width, i1, j0),
                    texel(texels, offset, width, i0, j1), texel(texels, offset, width, i1, j1), fu & 255, fv & 255)


@njit(cache=True, inline="always")
def lerp8(a, b, w):
    """``a + (((b − a)·w + 128) >> 8)`` in every lane of ``a`` and ``b`` (0..255 each), ``w``
    0..255 (the weight of ``b`` in 256ths): the same integer written
    ``(a·(256 − w) + b·w + 128) >> 8``, which stays within a lane's 16 bits (at most
    255·256 + 128) and never goes negative; the bits that shift in from the next lane are
    masked off."""
    return ((a * np.uint64(256 - w) + b * np.uint64(w) + HALF) >> U8) & LANES8


@njit(cache=True, inline="always")
def bilinear(t00, t10, t01, t11, wa, wb):
    """The four texels (i0, j0), (i1, j0), (i0, j1), (i1, j1) (in lanes) blended as llvmpipe
    does on 0..255 integers: horizontally with weight ``wa``, then vertically with ``wb``
    (8-bit weights of the second texel)."""
    return lerp8(lerp8(t00, t10, wa), lerp8(t01, t11, wa), wb)


@njit(cache=True)
def sample(texels, offset, width, height, filter_mode, wrap, s, t):
    """The filtered texture colour at (s, t): ``(r, g, b)``, each value/255."""
    if filter_mode == NEAREST:
        r, g, b = channels(nearest_texel(texels, offset, width, height, wrap, s, t))
    else:
        r, g, b = channels(linear_texel(texels, offset, width, height, wrap, s, t))
    return r / 255.0, g / 255.0, b / 255.0


@njit(cache=True, inline="always")
def sample_texture(textures, o, s, t):
    """Object ``o``'s texture at (s, t): :func:`sample` on its part of ``textures``."""
    return sample(textures.texels, textures.offset[o], textures.width[o], textures.height[o], textures.filter[o],
                  textures.wrap[o], s, t)


@njit(cache=True, inline="always")
def modulate_texels(textures, o, st, first, count, colour, fixed):
    """``colour`` (3, ≥ count) float32, a span's linear colours, multiplied by object ``o``'s
    texture at the span's texture coordinates, columns ``first`` … ``first + count − 1`` of
    ``st`` (2, W) float32 (:func:`filter_span`; ``fixed`` its scratch, :func:`texel_scratch`)."""
    filter_span(textures.texels, textures.offset[o], textures.width[o], textures.height[o], textures.filter[o],
                textures.wrap[o], st, (first, count), colour, fixed)


@njit(cache=True, from_python=False)
def filter_span(texels, offset, width, height, filter_mode, wrap, st, columns, colour, fixed):
    """The values :func:`sample` gives at the ``columns`` ``(first, count)`` of ``st``, as
    float32, multiplied into ``colour``. Filter and wrap are the object's, chosen once for
    the whole span: one straight loop per filter, the filter inlined. The linear filter
    first works out every pixel's fixed-point texel coordinates (:func:`fixed_coordinates`,
    into rows 0 and 1 of ``fixed``, :func:`texel_scratch`); when the whole
    span's four texels lie inside the texture, as they do but at its edges, they are read
    without a wrap's tests and ``%`` and blended in a loop of their own
    (:func:`linear_inside`). Compiled on its own, called once per span:
    inlined into the general shading kernel too, that kernel took 38 s instead of 31 s to
    compile cold, for no measurable gain."""
    first, count = columns
    if filter_mode == NEAREST:
        for i in range(count):
            j = np.uint64(first + i)
            modulate(colour, i, nearest_texel(texels, offset, width, height, wrap, st[0, j], st[1, j]))
    elif fixed_coordinates(st, width, height, first, count, fixed):
        linear_inside(texels, offset, width, first, count, colour, fixed)
    else:
        for i in range(count):
            j = np.uint64(first + i)
            modulate(colour, i, linear_texel(texels, offset, width, height, wrap, st[0, j], st[1, j]))


@njit(cache=True, inline="always")
def fixed_coordinates(st, width, height, first, count, fixed):
    """The linear filter's (u, v) = (s·W − ½, t·H − ½) of the columns ``first`` …
    ``first + count − 1`` of ``st``, in 256ths (:func:`linear_texel`), into the same
    columns of rows 0 and 1 of ``fixed``; True when all four texels of every pixel lie inside
    the texture (no wrap or clamp needed)."""
    lo_u = lo_v = np.int64(0)
    hi_u = hi_v = np.int64(-1)
    for i in range(count):
        j = np.uint64(first + i)
        fu = np.int64(math.floor((st[0, j] * width - 0.5) * 256.0))
        fv = np.int64(math.floor((st[1, j] * height - 0.5) * 256.0))
        fixed[0, j], fixed[1, j] = fu, fv
        lo_u, hi_u, lo_v, hi_v = smaller(lo_u, fu), larger(hi_u, fu), smaller(lo_v, fv), larger(hi_v, fv)
    return lo_u >= 0 and (hi_u >> 8) + 1 < width and lo_v >= 0 and (hi_v >> 8) + 1 < height


TEXEL_SCRATCH_ROWS = 6
"""Rows of the linear filter's scratch (:func:`filter_span`, :func:`texel_scratch`): the
pixels' fixed-point u and v (:func:`fixed_coordinates`), then their four texels (i0, j0),
(i1, j0), (i0, j1), (i1, j1) as packed words (:func:`gather_texels`)."""


@njit(cache=True, inline="always")
def texel_scratch(width):
    """The scratch :func:`filter_span` fills for a row of ``width`` pixels:
    (:data:`TEXEL_SCRATCH_ROWS`, W) int64. The kernels write all its rows without bounds
    checks: a smaller array is overrun (a test that passed two rows corrupted the process's
    heap, and it crashed later, in LLVM's teardown)."""
    return np.empty((TEXEL_SCRATCH_ROWS, width), np.int64)


@njit(cache=True, inline="always")
def linear_inside(texels, offset, width, first, count, colour, fixed):
    """:func:`linear_texel` at the fixed-point coordinates ``fixed`` (:func:`fixed_coordinates`)
    of a span whose texels all lie inside the texture, multiplied into ``colour``: two loops,
    the texels read into ``fixed`` (:func:`gather_texels`, loads only), then blended and
    multiplied in (:func:`blend_texels`, which LLVM turns into vector code: 8 pixels to a
    register). The same bits as :func:`bilinear` pixel by pixel; measured alone on rows of
    400 pixels of the 2048×1024 earth at 512²-like steps, 9.9 → 5.6 ns a pixel."""
    gather_texels(texels, offset, width, first, count, fixed)
    blend_texels(first, count, colour, fixed)


@njit(cache=True, inline="always")
def gather_texels(texels, offset, width, first, count, fixed):
    """The four texels around each pixel of the span (its texel column ``u >> 8`` and row
    ``v >> 8`` in rows 0 and 1 of ``fixed``, both inside the texture) into rows 2–5 of
    ``fixed``: (i0, j0), (i0 + 1, j0), (i0, j0 + 1), (i0 + 1, j0 + 1), packed words."""
    row = np.uint64(width)
    for i in range(count):
        j = np.uint64(first + i)
        at = np.uint64(offset + (fixed[1, j] >> 8) * width + (fixed[0, j] >> 8))
        fixed[2, j] = np.int64(texels[at])
        fixed[3, j] = np.int64(texels[at + np.uint64(1)])
        fixed[4, j] = np.int64(texels[at + row])
        fixed[5, j] = np.int64(texels[at + row + np.uint64(1)])


RED_BLUE32 = np.uint32(0x00FF00FF)
"""A packed texel's r and b in two 16-bit lanes of a 32-bit word (room for a lerp's product)."""
HALF32 = np.uint32(0x00800080)
"""128 in both lanes of :data:`RED_BLUE32`: the lerp's rounding."""
HALF8 = np.uint32(128)
"""The lerp's rounding for g alone."""
BYTE32, S8, S16 = np.uint32(0xFF), np.uint32(8), np.uint32(16)
F255 = np.float32(255.0)


@njit(cache=True, inline="always")
def lerp32(a, b, w, lanes, rounding):
    """:func:`lerp8` in 32-bit words: ``(a·(256 − w) + b·w + rounding) >> 8``, masked to ``lanes``
    (r and b in two lanes with :data:`RED_BLUE32`, :data:`HALF32`; g alone with 0xFF, 128)."""
    return ((a * (np.uint32(256) - w) + b * w + rounding) >> S8) & lanes


@njit(cache=True, inline="always")
def blend_texels(first, count, colour, fixed):
    """The bilinear blend (:func:`bilinear`) of the texels :func:`gather_texels` read into
    ``fixed``, with each pixel's 8-bit weights (the low bytes of its u and v), multiplied into
    ``colour`` (3, ≥ count). In uint32 words, r and b in two lanes of one, g in another,
    so the loop runs in vector registers; a value v becomes ``float32(v) / 255``, the same
    float32 as :data:`UNIT32` for every 8-bit v (tests/renderer/test_texture_sampling.py)."""
    for i in range(count):
        j = np.uint64(first + i)
        wa, wb = np.uint32(fixed[0, j]) & BYTE32, np.uint32(fixed[1, j]) & BYTE32
        t00, t10 = np.uint32(fixed[2, j]), np.uint32(fixed[3, j])
        t01, t11 = np.uint32(fixed[4, j]), np.uint32(fixed[5, j])
        rb = lerp32(lerp32(t00 & RED_BLUE32, t10 & RED_BLUE32, wa, RED_BLUE32, HALF32),
                    lerp32(t01 & RED_BLUE32, t11 & RED_BLUE32, wa, RED_BLUE32, HALF32), wb, RED_BLUE32, HALF32)
        g = lerp32(lerp32((t00 >> S8) & BYTE32, (t10 >> S8) & BYTE32, wa, BYTE32, HALF8),
                   lerp32((t01 >> S8) & BYTE32, (t11 >> S8) & BYTE32, wa, BYTE32, HALF8), wb, BYTE32, HALF8)
        k = np.uint64(i)
        colour[0, k] *= np.float32(np.int32(rb & BYTE32)) / F255  # from int32: a signed conversion, which
        colour[1, k] *= np.float32(np.int32(g)) / F255            # every instruction set does in vectors
        colour[2, k] *= np.float32(np.int32(rb >> S16)) / F255


@njit(cache=True, inline="always")
def modulate(colour, i, lanes):
    """Pixel ``i``'s colour times the texel in ``lanes`` (each value/255, as float32)."""
    r, g, b = channels(lanes)
    colour[0, i] *= UNIT32[r]
    colour[1, i] *= UNIT32[g]
    colour[2, i] *= UNIT32[b]
