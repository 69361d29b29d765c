"""The ``vtk`` reflection model over a run of pixels, in float32, one loop LLVM vectorises.

The same formulas as :func:`renderer.reflection.vtk_model.vtk_lighting`, computed as VTK's
fragment shader computes them — in float32 — over a run of points: each pixel's view-space
position and normal, interpolated first (:func:`renderer.spans.span_points`), then lit in
one loop without calls or early exits (:func:`vtk_light_kernel`), then stored as 8 bits.
The run is a triangle's span, or a row's run of pixels of one object whatever triangles
they show (:func:`renderer.shading.shade_lit_run`): thin triangles, one or two pixels a
row, then still light 8 pixels at a time (a loop over one pixel runs scalar code); ``pow`` is :func:`renderer.float32_math.pow_f32`
(``exp2(p·log2 x)``, as llvmpipe evaluates it). Covers light complexities 0–2 (unlit, a
lone headlight, directional lights; one directional light has a loop of its own, with no
inner loop over lights, so it vectorises); a set with a positional light (complexity 3) is
lit pixel by pixel by the scalar kernel (:func:`vtk_span_applies`).
"""
from __future__ import annotations

import numpy as np

from renderer.float32_math import pow_f32
from renderer.jit import njit
from renderer.min_max import clamp, larger
from renderer.lights import DIRECTIONAL, HEADLIGHT_ONLY, UNLIT
from renderer.spans import span_points

F0, F1, F2, F255 = np.float32(0.0), np.float32(1.0), np.float32(2.0), np.float32(255.0)
HEADLIGHT_FLOOR = np.float32(1e-6)
SPECULAR_FLOOR = np.float32(1e-5)


@njit(cache=True, inline="always")
def vtk_complexity(o, materials, lights):
    """The formula that lights object ``o``: VTK's light complexity, or UNLIT when its
    material's lighting is off."""
    return lights.complexity if materials.lit[o] else UNLIT


@njit(cache=True, inline="always")
def vtk_span_applies(o, materials, lights):
    """True when the span kernel covers object ``o`` under these lights (no positional light)."""
    return vtk_complexity(o, materials, lights) <= DIRECTIONAL


def vtk_spans_apply(o, materials, lights) -> bool:
    """:func:`vtk_span_applies` in Python (for choosing a kernel before shading)."""
    return (lights.complexity if materials.lit[o] else UNLIT) <= DIRECTIONAL


@njit(cache=True, inline="always")
def vtk_normal_only(o, materials, lights):
    """True when the colour depends on nothing but the normal (unlit, or a lone headlight):
    with a constant normal the whole span has one colour."""
    return vtk_complexity(o, materials, lights) <= HEADLIGHT_ONLY


def vtk_normals_only(o, materials, lights) -> bool:
    """:func:`vtk_normal_only` in Python (for choosing a kernel before shading)."""
    return (lights.complexity if materials.lit[o] else UNLIT) <= HEADLIGHT_ONLY


ROUNDER = np.float32(2.0 ** 23)


@njit(cache=True, inline="always")
def to8(v):
    """Linear 0..1 float32 → the framebuffer's 8 bits: round_half_even(clamp(v)·255), the
    rounding done by adding and subtracting 2²³ (float32 addition rounds to nearest, ties
    to even, and at 2²³ its step is 1): the same integer as ``np.rint``, without a call."""
    return np.uint8(np.int32((clamp(v, F0, F1) * F255 + ROUNDER) - ROUNDER))


@njit(cache=True, inline="always")
def store8(colour, count, out):
    """``colour`` (3, ≥ count) linear float32 → ``out`` (≥ count, 3) uint8, C-contiguous (:func:`to8`).

    One loop over the pixels, written into ``out``'s bytes seen as one row (r, g, b side by
    side, byte 3i + c): LLVM vectorises that as a store of three interleaved bytes a pixel.
    Written as ``out[i, c]``, the loop stayed scalar (2.7 ns a pixel on runs of hundreds),
    and packing each pixel into a uint32 first, then unpacking it, took 1.0 ns; this, 0.35
    (runs of 1,024 pixels, one thread, the store alone)."""
    flat = out.reshape(-1)
    for i in range(count):
        j = np.uint64(i)  # unsigned: no wrap-around for a negative index, which keeps a loop scalar
        flat[3 * j], flat[3 * j + 1], flat[3 * j + 2] = to8(colour[0, j]), to8(colour[1, j]), to8(colour[2, j])


@njit(cache=True, inline="always")
def _reflect_dot(lx, ly, lz, nx, ny, nz, vx, vy, vz):
    """(l, n, v) → (n·l, reflect(l, n)·v) in float32, GLSL's reflect(l, n) = l − 2(n·l)n."""
    ndl = nx * lx + ny * ly + nz * lz
    k = F2 * ndl
    return ndl, (lx - k * nx) * vx + (ly - k * ny) * vy + (lz - k * nz) * vz


@njit(cache=True, inline="always")
def _view_vector(px, py, pz):
    """v = normalize(−P), (0, 0, 1) at the eye."""
    plen = np.sqrt(px * px + py * py + pz * pz)
    inv = -F1 / plen if plen > F0 else F0
    return px * inv, py * inv, (pz * inv if plen > F0 else F1)


@njit(cache=True, inline="always")
def vtk_span(o, materials, lights, consts, face, count, points, colour, out):
    """VTK's colour of object ``o`` at the span's ``count`` pixels, stored as 8 bits into
    ``out`` (count, 3): :func:`vtk_span_colours`, then :func:`store8` (an 8-bit store in
    the lighting loop kept it from vectorising, 70 ns a pixel instead of 6)."""
    vtk_span_colours(o, materials, lights, consts, face, count, points, colour)
    store8(colour, count, out)


@njit(cache=True, inline="always")
def vtk_span_colours(o, materials, lights, consts, face, count, points, colour):
    """VTK's linear colour of object ``o`` at the span's ``count`` pixels, into ``colour``
    (3, ≥ count) float32: the span's points interpolated into ``points`` (6, ≥ count)
    (:func:`renderer.spans.span_points`; ``consts`` and ``face`` its set-up,
    :func:`renderer.spans.span_setup`), then lit (:func:`vtk_point_colours`)."""
    span_points(consts, face, count, points, 0)
    vtk_point_colours(o, materials, lights, points, 0, count, colour)


@njit(cache=True, inline="always")
def vtk_point_colours(o, materials, lights, points, first, count, colour):
    """VTK's linear colour of object ``o`` at ``count`` points into ``colour`` (3, ≥ count)
    float32. ``points`` (6, W) float32, columns ``first`` … ``first + count − 1``: view-space
    position and unit normal of each (rows x, y, z, nx, ny, nz), on the viewer's side; they may come from many triangles
    (a row's run of one object, :func:`renderer.shading.shade_lit_run`), so the loop is as
    long as the run, not as a triangle's span. Complexities 0–2 only (:func:`vtk_span_applies`).
    The loops live in :func:`vtk_light_kernel`, compiled once with plain arguments: inlined
    at its call site with the kernel inputs' named tuples, numba took 16 s more to compile
    the shading kernel (``first`` and ``count`` go as int64: a literal 0 or 1 at a call site
    made numba compile it again for that value, 1.3 s each)."""
    amb, dif, spe = materials.ambient[o], materials.diffuse[o], materials.specular[o]
    material = (np.float32(amb[0]), np.float32(amb[1]), np.float32(amb[2]), np.float32(dif[0]), np.float32(dif[1]),
                np.float32(dif[2]), np.float32(spe[0]), np.float32(spe[1]), np.float32(spe[2]),
                np.float32(materials.power[o]))
    shiny = spe[0] != 0.0 or spe[1] != 0.0 or spe[2] != 0.0  # else Ks·Cs·sf is 0 whatever sf
    vtk_light_kernel(vtk_complexity(o, materials, lights), shiny, material, (amb[0] + dif[0], amb[1] + dif[1],
                     amb[2] + dif[2]), lights.direction, lights.intensity_rgb, points, np.int64(first), np.int64(count), colour)


@njit(cache=True, refcounts=False, from_python=False)
def vtk_light_kernel(complexity, shiny, material, unlit, direction, l_col, points, first, count, colour):
    """The loops of :func:`vtk_point_colours`: ``material`` (Amb, Dif, Spe as float32 RGB, then the
    specular power), ``unlit`` Amb + Dif in float64, the lights' directions and colours."""
    a0, a1, a2, d0, d1, d2, s0, s1, s2, power = material
    if complexity == UNLIT:
        r, g, b = np.float32(unlit[0]), np.float32(unlit[1]), np.float32(unlit[2])
        for i in range(count):
            colour[0, i], colour[1, i], colour[2, i] = r, g, b
        return
    if complexity == HEADLIGHT_ONLY:
        c0, c1, c2 = np.float32(l_col[0, 0]), np.float32(l_col[0, 1]), np.float32(l_col[0, 2])
        for i in range(count):
            df = larger(HEADLIGHT_FLOOR, points[5, np.uint64(first + i)])
            sf = pow_f32(df, power) if shiny else F0
            colour[0, i] = a0 + df * d0 * c0 + sf * s0 * c0
            colour[1, i] = a1 + df * d1 * c1 + sf * s1 * c1
            colour[2, i] = a2 + df * d2 * c2 + sf * s2 * c2
        return
    if l_col.shape[0] == 1:  # one directional light: no loop over lights, so this loop vectorises
        lx, ly, lz = (np.float32(direction[0, 0]), np.float32(direction[0, 1]),
                      np.float32(direction[0, 2]))  # VTK's l: the direction the light travels
        c0, c1, c2 = np.float32(l_col[0, 0]), np.float32(l_col[0, 1]), np.float32(l_col[0, 2])
        for i in range(count):
            j = np.uint64(first + i)  # unsigned: no wrap-around, the loop vectorises
            vx, vy, vz = _view_vector(points[0, j], points[1, j], points[2, j])
            ndl, rdv = _reflect_dot(lx, ly, lz, points[3, j], points[4, j], points[5, j], vx, vy, vz)
            df = larger(F0, -ndl)
            sf = pow_f32(larger(SPECULAR_FLOOR, rdv), power) if shiny else F0
            sf = sf if df > F0 else F0
            colour[0, i] = a0 + d0 * (df * c0) + s0 * (sf * c0)
            colour[1, i] = a1 + d1 * (df * c1) + s1 * (sf * c1)
            colour[2, i] = a2 + d2 * (df * c2) + s2 * (sf * c2)
        return
    for i in range(count):
        j = np.uint64(first + i)  # unsigned: no wrap-around, the loop vectorises
        nx, ny, nz = points[3, j], points[4, j], points[5, j]
        vx, vy, vz = _view_vector(points[0, j], points[1, j], points[2, j])
        sd0 = sd1 = sd2 = ss0 = ss1 = ss2 = F0  # Σ df·Lc, Σ sf·Lc
        for li in range(l_col.shape[0]):
            lx, ly, lz = (np.float32(direction[li, 0]), np.float32(direction[li, 1]),
                          np.float32(direction[li, 2]))
            c0, c1, c2 = np.float32(l_col[li, 0]), np.float32(l_col[li, 1]), np.float32(l_col[li, 2])
            ndl, rdv = _reflect_dot(lx, ly, lz, nx, ny, nz, vx, vy, vz)
            df = larger(F0, -ndl)
            sf = pow_f32(larger(SPECULAR_FLOOR, rdv), power) if shiny else F0
            sf = sf if df > F0 else F0
            sd0, sd1, sd2 = sd0 + df * c0, sd1 + df * c1, sd2 + df * c2
            ss0, ss1, ss2 = ss0 + sf * c0, ss1 + sf * c1, ss2 + sf * c2
        colour[0, i] = a0 + d0 * sd0 + s0 * ss0
        colour[1, i] = a1 + d1 * sd1 + s1 * ss1
        colour[2, i] = a2 + d2 * sd2 + s2 * ss2
