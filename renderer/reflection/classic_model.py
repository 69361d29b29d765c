"""The ``classic`` reflection model: the course's Phong illumination, in view space.

The course's slides: ``I = Ka·O·A + Σ att·spot·[L·N > 0]·(Kd·O·I·(L·N) + Ks·I·max(R·V, 0)^n)``,
with ``R = 2(L·N)N − L`` the mirror direction of ``L``, ``V = normalize(−p)``, ``O`` the
object colour, ``A`` the ambient light (the scene's ``[render] ambient``) and ``I`` the
light's colour × intensity. ``L`` is the unit vector from the point toward the light,
attenuation and spot cone by :func:`renderer.lights.light_at`. Specular only where the
light reaches the front of the surface; the normal is taken as given, never flipped; the
result is clamped to 0..1. One colour: no separate specular.

The material row (:func:`material_row`) is ``Ka·O``, ``Kd·O``, ``Ks·(1, 1, 1)`` and ``n``.
Flat lights each triangle once at one representative point, its centroid; gouraud each
vertex; phong each pixel (:func:`renderer.reflection.materials.textbook_path`).
"""
from __future__ import annotations

import math

import numpy as np

from renderer.jit import njit
from renderer.min_max import clamp, larger
from renderer.lights import light_at
from renderer.reflection.materials import MaterialRow, ReflectionModel, textbook_path


def material_row(material) -> MaterialRow:
    """Ka·O, Kd·O, Ks·(1, 1, 1) and n (any power: no clamp)."""
    colour = np.asarray(material.color)
    return MaterialRow(material.ambient * colour, material.diffuse * colour, np.full(3, material.specular),
                       material.specular_power)


@njit(cache=True, inline="always")
def classic_lighting(n, p, o, materials, lights):
    """The course's ``Ka·O·A + Σ (Kd·O·I·(L·N) + Ks·I·(R·V)^n)`` for object ``o`` at one point
    (the scalar kernel), clamped to 0..1: ``(r, g, b, 0, 0, 0)`` (the course has one colour)."""
    amb, dif, spe, power = materials.ambient[o], materials.diffuse[o], materials.specular[o], materials.power[o]
    a, li = lights.ambient_light, lights.intensity_rgb
    plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
    vx, vy, vz = -p[0] / plen, -p[1] / plen, -p[2] / plen
    r, g, b = amb[0] * a[0], amb[1] * a[1], amb[2] * a[2]
    for i in range(lights.direction.shape[0]):
        lx, ly, lz, att = light_at(lights, i, p)
        ndl = n[0] * lx + n[1] * ly + n[2] * lz
        if att == 0.0 or ndl <= 0.0:
            continue
        rx, ry, rz = 2.0 * ndl * n[0] - lx, 2.0 * ndl * n[1] - ly, 2.0 * ndl * n[2] - lz
        sf = larger(rx * vx + ry * vy + rz * vz, 0.0) ** power
        r += att * li[i, 0] * (dif[0] * ndl + spe[0] * sf)
        g += att * li[i, 1] * (dif[1] * ndl + spe[1] * sf)
        b += att * li[i, 2] * (dif[2] * ndl + spe[2] * sf)
    return clamp(r, 0.0, 1.0), clamp(g, 0.0, 1.0), clamp(b, 0.0, 1.0), 0.0, 0.0, 0.0


MODEL = ReflectionModel(name="classic", material_row=material_row, shading_path=textbook_path,
                        lighting=classic_lighting)
