"""The ``vtk`` reflection model: VTK's (non-PBR) lighting, per fragment, in view space.

Which formula runs depends on the whole *set* of lights, as in VTK's OpenGL2 mapper
("light complexity", :func:`renderer.lights.light_complexity`):

0. no light switched on, or the object's lighting off: ``Amb + Dif`` (unlit);
1. exactly one light on and it is a headlight (of any intensity — measured):
   ``df = max(1e-6, n.z)``, ``sf = df^p`` (a fixed half-vector (0, 0, 1)),
   ``Amb + df·Dif·Lc + sf·Spe·Lc``;
2. otherwise, no positional light: per light ``df = max(0, n·(−l))``,
   ``sf = sign(df)·max(1e-5, reflect(l, n)·v)^p`` (Phong's reflection vector);
3. any positional light (switched on or not): as 2, with ``l`` from the light to the
   point, attenuation and spot cone (:func:`renderer.lights.light_at`).

``Amb = Ka·C``, ``Dif = Kd·C``, ``Spe = Ks·Cs`` (:func:`material_row`; the specular power
is clamped at :data:`VTK_MAX_SPECULAR_POWER`, as ``vtkProperty`` clamps it),
``Lc = colour × intensity``, ``l`` the direction the light travels, ``v = normalize(−P)``
(a local viewer, also under parallel projection). Lighting is per fragment whatever the
shading (VTK has no per-vertex lighting) and two-sided (:func:`shading_path`). Source:
VTK 9.7 ``vtkOpenGLPolyDataMapper::ReplaceShaderLight`` and
``vtkOpenGLRenderer::UpdateLights``; measured in ``shared/docs/vtk-parity.md``.
"""
from __future__ import annotations

import math

import numpy as np

from renderer.jit import njit
from renderer.min_max import larger
from renderer.lights import HEADLIGHT_ONLY, UNLIT, light_at
from renderer.reflection.materials import (PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED, MaterialRow, ReflectionModel,
                                           smooth)

VTK_MAX_SPECULAR_POWER = 128.0
"""``vtkProperty::SetSpecularPower`` clamps to [0, 128]: a larger power in the vtk model
draws as 128 (measured: 1000 is read back as 128.0). The classic model keeps any power."""


def material_row(material) -> MaterialRow:
    """Ka·C, Kd·C, Ks·Cs and the specular power, at most :data:`VTK_MAX_SPECULAR_POWER`."""
    colour = np.asarray(material.color)
    return MaterialRow(material.ambient * colour, material.diffuse * colour,
                       material.specular * np.asarray(material.effective_specular_color),
                       min(material.specular_power, VTK_MAX_SPECULAR_POWER))


def shading_path(obj) -> int:
    """Per pixel always: the interpolated normal, two-sided, when the object is smooth;
    else the plane normal turned toward the viewer."""
    return PIXEL_TWO_SIDED if smooth(obj) else PIXEL_FACE_NORMAL


@njit(cache=True, inline="always")
def reflect_dot(lx, ly, lz, n, vx, vy, vz):
    """reflect(l, n)·v with GLSL's reflect(l, n) = l − 2·(n·l)·n, in scalars."""
    k = 2.0 * (n[0] * lx + n[1] * ly + n[2] * lz)
    return (lx - k * n[0]) * vx + (ly - k * n[1]) * vy + (lz - k * n[2]) * vz


@njit(cache=True, inline="always")
def vtk_lighting(n, p, o, materials, lights):
    """VTK's colour of object ``o`` at one fragment (the scalar kernel): linear
    ``(r, g, b, 0, 0, 0)`` (VTK has one colour, so the secondary colour is zero).

    n : unit normal on the viewer's side (view space). p : fragment position (view
    space). materials : :class:`~renderer.reflection.materials.Materials` (row ``o``:
    Ka·C, Kd·C, Ks·Cs, specular power). lights : :class:`~renderer.lights.ViewLights`.
    Written with scalars only: it runs per pixel. A positional light implies complexity 3
    (:func:`~renderer.lights.light_complexity`), so every light goes through
    :func:`~renderer.lights.light_at`.
    """
    amb, dif, spe, power = materials.ambient[o], materials.diffuse[o], materials.specular[o], materials.power[o]
    l_col = lights.intensity_rgb
    complexity = lights.complexity if materials.lit[o] else UNLIT
    if complexity == UNLIT:
        return amb[0] + dif[0], amb[1] + dif[1], amb[2] + dif[2], 0.0, 0.0, 0.0
    shiny = spe[0] != 0.0 or spe[1] != 0.0 or spe[2] != 0.0  # else Ks·Cs·sf is 0 whatever sf: skip the power
    if complexity == HEADLIGHT_ONLY:
        df = larger(1e-6, n[2])
        sf = df ** power if shiny else 0.0
        return (amb[0] + df * dif[0] * l_col[0, 0] + sf * spe[0] * l_col[0, 0],
                amb[1] + df * dif[1] * l_col[0, 1] + sf * spe[1] * l_col[0, 1],
                amb[2] + df * dif[2] * l_col[0, 2] + sf * spe[2] * l_col[0, 2], 0.0, 0.0, 0.0)
    plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
    vx, vy, vz = (-p[0] / plen, -p[1] / plen, -p[2] / plen) if plen > 0.0 else (0.0, 0.0, 1.0)
    d0 = d1 = d2 = 0.0  # Σ df·Lc
    s0 = s1 = s2 = 0.0  # Σ sf·Lc
    for i in range(l_col.shape[0]):
        to_x, to_y, to_z, att = light_at(lights, i, p)
        lx, ly, lz = -to_x, -to_y, -to_z  # VTK's l: the direction the light travels
        df = larger(0.0, -att * (n[0] * lx + n[1] * ly + n[2] * lz))
        if df > 0.0:
            sf = att * larger(1e-5, reflect_dot(lx, ly, lz, n, vx, vy, vz)) ** power if shiny else 0.0
            d0 += df * l_col[i, 0]
            d1 += df * l_col[i, 1]
            d2 += df * l_col[i, 2]
            s0 += sf * l_col[i, 0]
            s1 += sf * l_col[i, 1]
            s2 += sf * l_col[i, 2]
    return (amb[0] + dif[0] * d0 + spe[0] * s0, amb[1] + dif[1] * d1 + spe[1] * s1, amb[2] + dif[2] * d2 + spe[2] * s2,
            0.0, 0.0, 0.0)


MODEL = ReflectionModel(name="vtk", material_row=material_row, shading_path=shading_path, lighting=vtk_lighting)
