"""The ``opengl`` reflection model: fixed-function OpenGL's lighting, in view space.

OpenGL 1.x specification §2.14.1, the textbook's chapter 17:
``c = Ga·Ma + Σ att·spot·(La·Ma + max(n·L, 0)·Ld·Md + [n·L > 0]·max(n·H, 0)^shininess·Ls·Ms)``
with Blinn's half vector ``H = normalize(L + V)``, ``V = (0, 0, 1)`` (infinite viewer,
OpenGL's default) or ``normalize(−p)`` (local viewer). No emission. ``L`` is the unit vector
from the point toward the light, attenuation and spot cone by
:func:`renderer.lights.light_at`. The normal ``n`` is taken *as given* (no two-sided flip:
OpenGL's default ``GL_LIGHT_MODEL_TWO_SIDE`` is off). Results are clamped to 0..1 per
channel, as OpenGL clamps a lit vertex colour before interpolating it. With
``GL_SEPARATE_SPECULAR_COLOR`` (``separate_specular``) the specular sum is a second colour
of its own (each clamped), which a texture does not modulate: it is added after texturing.

The material row (:func:`material_row`) is Ma, Md, Ms and the shininess; the lights carry
La, Ld, Ls and the light model's Ga, local viewer and separate specular
(:class:`renderer.lights.ViewLights`). Flat lights each triangle once at its centroid,
gouraud each vertex, phong each pixel (:func:`renderer.reflection.materials.textbook_path`).
"""
from __future__ import annotations

import math

from renderer.jit import njit
from renderer.min_max import clamp, larger
from renderer.lights import light_at
from renderer.reflection.materials import MaterialRow, ReflectionModel, textbook_path


def material_row(material) -> MaterialRow:
    """The material's OpenGL colours Ma, Md, Ms and its shininess."""
    return MaterialRow(material.gl_ambient, material.gl_diffuse, material.gl_specular, material.shininess)


@njit(cache=True, inline="always")
def clamp01(x):
    return clamp(x, 0.0, 1.0)


@njit(cache=True, inline="always")
def opengl_lighting(n, p, o, materials, lights):
    """Fixed-function OpenGL's lit colour of object ``o`` at one point (the scalar kernel),
    clamped to 0..1: ``(r, g, b, sr, sg, sb)``, all of it in the primary colour
    (GL_SINGLE_COLOR) with a zero secondary, or the specular part in the secondary colour
    with separate specular."""
    amb, dif, spe, shininess = materials.ambient[o], materials.diffuse[o], materials.specular[o], materials.power[o]
    ga, la, ld, ls = lights.global_ambient, lights.gl_ambient, lights.gl_diffuse, lights.gl_specular
    if lights.local_viewer:
        plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
        vx, vy, vz = -p[0] / plen, -p[1] / plen, -p[2] / plen
    else:
        vx, vy, vz = 0.0, 0.0, 1.0
    r, g, b = ga[0] * amb[0], ga[1] * amb[1], ga[2] * amb[2]
    sr = sg = sb = 0.0
    for i in range(lights.direction.shape[0]):
        lx, ly, lz, att = light_at(lights, i, p)
        if att == 0.0:
            continue
        ndl = n[0] * lx + n[1] * ly + n[2] * lz
        sf = 0.0
        if ndl > 0.0:
            hx, hy, hz = lx + vx, ly + vy, lz + vz
            hl = math.sqrt(hx * hx + hy * hy + hz * hz)
            ndh = (n[0] * hx + n[1] * hy + n[2] * hz) / hl if hl > 0.0 else 0.0
            sf = larger(ndh, 0.0) ** shininess
        df = larger(ndl, 0.0)
        r += att * (la[i, 0] * amb[0] + df * ld[i, 0] * dif[0])
        g += att * (la[i, 1] * amb[1] + df * ld[i, 1] * dif[1])
        b += att * (la[i, 2] * amb[2] + df * ld[i, 2] * dif[2])
        if lights.separate_specular:
            sr += att * sf * ls[i, 0] * spe[0]
            sg += att * sf * ls[i, 1] * spe[1]
            sb += att * sf * ls[i, 2] * spe[2]
        else:
            r += att * sf * ls[i, 0] * spe[0]
            g += att * sf * ls[i, 1] * spe[1]
            b += att * sf * ls[i, 2] * spe[2]
    return clamp01(r), clamp01(g), clamp01(b), clamp01(sr), clamp01(sg), clamp01(sb)


MODEL = ReflectionModel(name="opengl", material_row=material_row, shading_path=textbook_path,
                        lighting=opengl_lighting)
