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
from renderer.lights import light_at
from renderer.reflection.materials import MaterialRow, ReflectionModel, textbook_path


def material_row(material) -> MaterialRow:
    """The material's OpenGL colours Ma, Md, Ms and its shininess."""
    return MaterialRow(material.gl_ambient, material.gl_diffuse, material.gl_specular, material.shininess)


@njit(cache=True, inline="always")
def opengl_lighting(n, p, o, materials, lights, out, spec):
    """Fixed-function OpenGL's lit colour of object ``o`` at one point (the scalar kernel),
    clamped to 0..1: all of it in ``out`` (GL_SINGLE_COLOR), or the specular part in ``spec``
    with separate specular (else ``spec`` is zero)."""
    amb, dif, spe, shininess = materials.ambient[o], materials.diffuse[o], materials.specular[o], materials.power[o]
    if lights.local_viewer:
        plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
        vx, vy, vz = -p[0] / plen, -p[1] / plen, -p[2] / plen
    else:
        vx, vy, vz = 0.0, 0.0, 1.0
    for c in range(3):
        out[c] = lights.global_ambient[c] * amb[c]
        spec[c] = 0.0
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
            sf = max(ndh, 0.0) ** shininess
        df = max(ndl, 0.0)
        for c in range(3):
            out[c] += att * (lights.gl_ambient[i, c] * amb[c] + df * lights.gl_diffuse[i, c] * dif[c])
            if lights.separate_specular:
                spec[c] += att * sf * lights.gl_specular[i, c] * spe[c]
            else:
                out[c] += att * sf * lights.gl_specular[i, c] * spe[c]
    for c in range(3):
        out[c] = min(max(out[c], 0.0), 1.0)
        spec[c] = min(max(spec[c], 0.0), 1.0)


MODEL = ReflectionModel(name="opengl", material_row=material_row, shading_path=textbook_path,
                        lighting=opengl_lighting)
