"""VTK's (non-PBR) reflection model, in view space: lights, their frames and the formulas.

All vectors here live in **view space** (eye at the origin, looking down −z). Colours
are linear 0..1 RGB. Which formula runs depends on the whole *set* of lights, as in
VTK's OpenGL2 mapper ("light complexity"):

0. no light switched on, or the object's lighting off: ``Amb + Dif`` (unlit);
1. exactly one light on and it is a headlight (of any intensity — measured): ``df = max(1e-6, n.z)``,
   ``sf = df^p`` (a fixed half-vector (0, 0, 1)), ``Amb + df·Dif·Lc + sf·Spe·Lc``;
2. otherwise, no positional light: per light ``df = max(0, n·(−l))``,
   ``sf = sign(df)·max(1e-5, reflect(l, n)·v)^p`` (Phong's reflection vector);
3. any positional light (switched on or not): as 2, with ``l`` from the light to the
   point, attenuation ``1/(a0 + a1·d + a2·d²)`` and a spot cone ``c^exponent``.

``Amb = Ka·Ca``, ``Dif = Kd·Cd``, ``Spe = Ks·Cs``, ``Lc = colour × intensity``, ``l`` the
direction the light travels, ``v = normalize(−P)`` (a local viewer, also under parallel
projection). Source: VTK 9.7 ``vtkOpenGLPolyDataMapper::ReplaceShaderLight`` and
``vtkOpenGLRenderer::UpdateLights``; measured in ``shared/docs/vtk-parity.md``.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

UNLIT, HEADLIGHT_ONLY, DIRECTIONAL, POSITIONAL = 0, 1, 2, 3


def light_complexity(lights) -> int:
    """VTK's light complexity (0–3) of a light set; switched-off lights still count."""
    complexity, n_on = UNLIT, 0
    for light in lights:
        if light.on:
            n_on += 1
            complexity = max(complexity, HEADLIGHT_ONLY)
        # A lone headlight keeps the simple formula whatever its intensity (measured
        # against VTK 9.7: headlight-dimmed preset).
        if complexity == HEADLIGHT_ONLY and (n_on > 1 or light.kind != "headlight"):
            complexity = DIRECTIONAL
        if complexity < POSITIONAL and light.positional:
            return POSITIONAL
    return complexity


@dataclass(frozen=True)
class ViewLights:
    """The switched-on lights as arrays in view space, for the kernels.

    direction (L, 3) unit vectors the light travels along; position (L, 3); colour (L, 3)
    = colour × intensity; positional (L,) bool; cos_cone (L,) cosine of the cone
    half-angle (−2 = no cone); exponent (L,); attenuation (L, 3) constant, linear,
    quadratic.
    """

    complexity: int
    direction: np.ndarray
    position: np.ndarray
    colour: np.ndarray
    positional: np.ndarray
    cos_cone: np.ndarray
    exponent: np.ndarray
    attenuation: np.ndarray


def light_to_view(light, camera, world_to_view: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A light's position and focal point in view space, by its frame.

    - scene light: world space, carried by ``world_to_view``;
    - headlight: at the eye, aimed at the focal point, so (0, 0, 0) → (0, 0, −d);
    - camera light: (0, 0, 1) is the eye and (0, 0, 0) the focal point, in units of the
      camera distance d, i.e. view = d·(x, y, z − 1) (VTK's light transform
      inverse(view)·scale(d)·translate(0, 0, −1)).
    """
    d = float(np.linalg.norm(np.subtract(camera.position, camera.focal_point)))
    if light.kind == "scene":
        pos = np.append(light.position, 1.0) @ world_to_view
        foc = np.append(light.focal_point, 1.0) @ world_to_view
        return pos[:3], foc[:3]
    if light.kind == "headlight":
        return np.zeros(3), np.array([0.0, 0.0, -d])
    shift = np.array([0.0, 0.0, -1.0])
    return d * (np.asarray(light.position) + shift), d * (np.asarray(light.focal_point) + shift)


def view_lights(lights, camera, world_to_view: np.ndarray) -> ViewLights:
    """Gather the switched-on lights in view space (see :class:`ViewLights`)."""
    on = [li for li in lights if li.on]
    n = len(on)
    out = dict(direction=np.zeros((n, 3)), position=np.zeros((n, 3)), colour=np.zeros((n, 3)),
               positional=np.zeros(n, np.bool_), cos_cone=np.full(n, -2.0), exponent=np.zeros(n),
               attenuation=np.zeros((n, 3)))
    for i, light in enumerate(on):
        pos, foc = light_to_view(light, camera, world_to_view)
        direction = foc - pos
        out["direction"][i] = direction / np.linalg.norm(direction)
        out["position"][i] = pos
        out["colour"][i] = np.asarray(light.color) * light.intensity
        out["positional"][i] = light.positional
        if light.positional and light.cone_angle < 90.0:
            out["cos_cone"][i] = math.cos(math.radians(light.cone_angle))
        out["exponent"][i] = light.exponent
        out["attenuation"][i] = light.attenuation
    return ViewLights(complexity=light_complexity(lights), **out)


@njit(cache=True)
def reflect(i, n):
    """GLSL reflect: i − 2·(n·i)·n."""
    return i - 2.0 * (n[0] * i[0] + n[1] * i[1] + n[2] * i[2]) * n


@njit(cache=True)
def vtk_lighting(n, p, complexity, amb, dif, spe, power,
                 l_dir, l_pos, l_col, l_positional, l_cos_cone, l_exponent, l_att, out):
    """VTK's colour at one fragment (the scalar kernel); writes RGB into ``out``.

    n : unit normal facing the viewer's side (view space). p : fragment position
    (view space). amb, dif, spe : Ka·Ca, Kd·Cd, Ks·Cs. power : specular power.
    """
    if complexity == 0:
        for c in range(3):
            out[c] = amb[c] + dif[c]
        return
    if complexity == 1:
        df = max(1e-6, n[2])
        sf = df ** power
        for c in range(3):
            out[c] = amb[c] + df * dif[c] * l_col[0, c] + sf * spe[c] * l_col[0, c]
        return
    plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
    v = -p / plen if plen > 0.0 else np.array([0.0, 0.0, 1.0])
    diffuse = np.zeros(3)
    specular = np.zeros(3)
    for i in range(l_dir.shape[0]):
        att = 1.0
        if complexity == 3 and l_positional[i]:
            lv = p - l_pos[i]
            dist = math.sqrt(lv[0] * lv[0] + lv[1] * lv[1] + lv[2] * lv[2])
            lv = lv / dist
            att = 1.0 / (l_att[i, 0] + l_att[i, 1] * dist + l_att[i, 2] * dist * dist)
            if l_cos_cone[i] > -1.5:
                cd = lv[0] * l_dir[i, 0] + lv[1] * l_dir[i, 1] + lv[2] * l_dir[i, 2]
                if cd >= l_cos_cone[i]:
                    att *= cd ** l_exponent[i]
                else:
                    att = 0.0
        else:
            lv = l_dir[i].copy()
        df = max(0.0, att * -(n[0] * lv[0] + n[1] * lv[1] + n[2] * lv[2]))
        r = reflect(lv, n)
        rv = max(1e-5, r[0] * v[0] + r[1] * v[1] + r[2] * v[2])
        sf = (1.0 if df > 0.0 else 0.0) * att * rv ** power
        for c in range(3):
            diffuse[c] += df * l_col[i, c]
            specular[c] += sf * l_col[i, c]
    for c in range(3):
        out[c] = amb[c] + dif[c] * diffuse[c] + spe[c] * specular[c]
