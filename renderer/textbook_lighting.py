"""The textbook's reflection models, in view space: fixed-function OpenGL and the course's.

Both take a unit normal ``n`` *as given* (no two-sided flip: OpenGL's default
``GL_LIGHT_MODEL_TWO_SIDE`` is off, and in the course a face turned away from the light
gets ambient only), a view-space point ``p`` and the switched-on lights
(:class:`renderer.lighting.ViewLights`). ``L`` is the unit vector from the point toward
the light: ``−direction`` for a directional light, ``normalize(position − p)`` for a
point light. Positional lights are attenuated by ``1/(a0 + a1·d + a2·d²)`` and, inside a
spot cone, weighted by ``(−L·direction)^exponent`` (zero outside). Results are clamped to
0..1 per channel, as OpenGL clamps a lit vertex colour before interpolating it.

- **opengl** (:func:`opengl_lighting`; OpenGL 1.x specification §2.14.1, the textbook's
  chapter 17): ``c = Ga·Ma + Σ att·spot·(La·Ma + max(n·L, 0)·Ld·Md
  + [n·L > 0]·max(n·H, 0)^shininess·Ls·Ms)`` with Blinn's half vector
  ``H = normalize(L + V)``, ``V = (0, 0, 1)`` (infinite viewer, OpenGL's default) or
  ``normalize(−p)`` (local viewer). No emission. With ``GL_SEPARATE_SPECULAR_COLOR``
  (``separate``) the specular sum is a second colour of its own (each clamped), which a
  texture does not modulate: it is added after texturing.
- **classic** (:func:`classic_lighting`; the course's slides):
  ``I = Ka·O·A + Σ att·spot·[L·N > 0]·(Kd·O·I·(L·N) + Ks·I·max(R·V, 0)^n)``, with
  ``R = 2(L·N)N − L`` and ``V = normalize(−p)``; specular only where the light reaches
  the front of the surface.

Every kernel writes a *primary* colour ``out`` and a *secondary* (specular) colour
``spec``; ``spec`` is zero except for the opengl model with separate specular.

Material arrays follow :func:`renderer.pipeline.object_table`: for opengl
``amb, dif, spe, power`` = Ma, Md, Ms, shininess; for classic ``Ka·O``, ``Kd·O``,
``Ks·(1, 1, 1)``, n.
"""
from __future__ import annotations

import math

import numpy as np
from renderer.jit import njit, prange


@njit(cache=True, inline="always")
def light_vector(lights, i, p):
    """(Lx, Ly, Lz, attenuation·spot) for light ``i`` at view-space point ``p``."""
    if not lights.positional[i]:
        return -lights.direction[i, 0], -lights.direction[i, 1], -lights.direction[i, 2], 1.0
    lx, ly, lz = lights.position[i, 0] - p[0], lights.position[i, 1] - p[1], lights.position[i, 2] - p[2]
    d = math.sqrt(lx * lx + ly * ly + lz * lz)
    lx, ly, lz = lx / d, ly / d, lz / d
    a = lights.attenuation[i]
    att = 1.0 / (a[0] + a[1] * d + a[2] * d * d)
    if lights.cos_cone[i] > -1.5:
        c = -(lx * lights.direction[i, 0] + ly * lights.direction[i, 1] + lz * lights.direction[i, 2])
        att = att * c ** lights.exponent[i] if c >= lights.cos_cone[i] else 0.0
    return lx, ly, lz, att


@njit(cache=True, inline="always")
def opengl_lighting(n, p, amb, dif, spe, shininess, global_ambient, local_viewer, separate, lights, out, spec):
    """Fixed-function OpenGL's lit colour at one point (the scalar kernel), clamped to 0..1:
    all of it in ``out`` (GL_SINGLE_COLOR), or the specular part in ``spec`` if ``separate``."""
    if local_viewer:
        plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
        vx, vy, vz = -p[0] / plen, -p[1] / plen, -p[2] / plen
    else:
        vx, vy, vz = 0.0, 0.0, 1.0
    for c in range(3):
        out[c] = global_ambient[c] * amb[c]
        spec[c] = 0.0
    for i in range(lights.direction.shape[0]):
        lx, ly, lz, att = light_vector(lights, i, p)
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
            if separate:
                spec[c] += att * sf * lights.gl_specular[i, c] * spe[c]
            else:
                out[c] += att * sf * lights.gl_specular[i, c] * spe[c]
    for c in range(3):
        out[c] = min(max(out[c], 0.0), 1.0)
        spec[c] = min(max(spec[c], 0.0), 1.0)


@njit(cache=True, inline="always")
def classic_lighting(n, p, amb, dif, spe, power, ambient_light, lights, out, spec):
    """The course's ``Ka·O·A + Σ (Kd·O·I·(L·N) + Ks·I·(R·V)^n)`` at one point, clamped to
    0..1, in ``out`` (``spec`` is zeroed: the course has one colour)."""
    plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
    vx, vy, vz = -p[0] / plen, -p[1] / plen, -p[2] / plen
    for c in range(3):
        out[c] = amb[c] * ambient_light[c]
        spec[c] = 0.0
    for i in range(lights.direction.shape[0]):
        lx, ly, lz, att = light_vector(lights, i, p)
        ndl = n[0] * lx + n[1] * ly + n[2] * lz
        if att == 0.0 or ndl <= 0.0:
            continue
        rx, ry, rz = 2.0 * ndl * n[0] - lx, 2.0 * ndl * n[1] - ly, 2.0 * ndl * n[2] - lz
        sf = max(rx * vx + ry * vy + rz * vz, 0.0) ** power
        for c in range(3):
            out[c] += att * lights.colour[i, c] * (dif[c] * ndl + spe[c] * sf)
    for c in range(3):
        out[c] = min(max(out[c], 0.0), 1.0)


OPENGL, CLASSIC = 1, 2  # model codes (0 = vtk, in renderer.lighting)


@njit(cache=True, inline="always")
def textbook_lighting(model, n, p, amb, dif, spe, power, global_ambient, local_viewer, separate, ambient_light, lights,
                      out, spec):
    """Dispatch to :func:`opengl_lighting` or :func:`classic_lighting` by model code."""
    if model == OPENGL:
        opengl_lighting(n, p, amb, dif, spe, power, global_ambient, local_viewer, separate, lights, out, spec)
    else:
        classic_lighting(n, p, amb, dif, spe, power, ambient_light, lights, out, spec)


@njit(cache=True, parallel=True)
def light_vertices(verts_view, normals_view, vert_object, obj_model, obj_amb, obj_dif, obj_spe, obj_power,
                   global_ambient, local_viewer, separate, ambient_light, lights, colours):
    """Gouraud's first half: a lit colour per vertex (the loop kernel), normals normalised.

    ``colours`` (N, 6): primary RGB, then secondary (specular) RGB. Only vertices of
    objects whose model is opengl or classic are lit; others keep whatever ``colours`` held.
    """
    for v in prange(verts_view.shape[0]):
        o = vert_object[v]
        if obj_model[o] == 0:
            continue
        n = normals_view[v].copy()
        length = math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2])
        if length > 0.0:
            n /= length
        textbook_lighting(obj_model[o], n, verts_view[v], obj_amb[o], obj_dif[o], obj_spe[o], obj_power[o],
                          global_ambient, local_viewer, separate, ambient_light, lights, colours[v, :3],
                          colours[v, 3:])


@njit(cache=True, parallel=True)
def light_faces(verts_view, triangles, face_normals, tri_object, obj_model, obj_amb, obj_dif, obj_spe, obj_power,
                global_ambient, local_viewer, separate, ambient_light, lights, colours):
    """Flat shading's colour per triangle (the loop kernel): its unit plane normal
    (``face_normals``, (v1 − v0) × (v2 − v0) normalised), lit at one representative point,
    the centroid. ``colours`` (T, 6): primary RGB, then secondary RGB."""
    for t in prange(triangles.shape[0]):
        o = tri_object[t]
        if obj_model[o] == 0:
            continue
        centroid = np.empty(3)
        for c in range(3):
            centroid[c] = (verts_view[triangles[t, 0], c] + verts_view[triangles[t, 1], c]
                           + verts_view[triangles[t, 2], c]) / 3.0
        textbook_lighting(obj_model[o], face_normals[t], centroid, obj_amb[o], obj_dif[o], obj_spe[o], obj_power[o],
                          global_ambient, local_viewer, separate, ambient_light, lights, colours[t, :3],
                          colours[t, 3:])
