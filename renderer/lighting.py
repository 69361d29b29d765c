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
from typing import NamedTuple

import numpy as np
from renderer.jit import njit

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


class ViewLights(NamedTuple):
    """The switched-on lights as arrays in view space; the kernels take it whole.

    complexity : VTK's light complexity of the whole set (:func:`light_complexity`).
    direction (L, 3) unit vectors the light travels along; position (L, 3); colour (L, 3)
    = colour × intensity; positional (L,) bool; cos_cone (L,) cosine of the cone
    half-angle (−2 = no cone); exponent (L,); attenuation (L, 3) constant, linear,
    quadratic; gl_ambient, gl_diffuse, gl_specular (L, 3): the OpenGL model's colours.
    """

    complexity: int
    direction: np.ndarray
    position: np.ndarray
    colour: np.ndarray
    positional: np.ndarray
    cos_cone: np.ndarray
    exponent: np.ndarray
    attenuation: np.ndarray
    gl_ambient: np.ndarray
    gl_diffuse: np.ndarray
    gl_specular: np.ndarray


def light_to_view(light, camera, world_to_view: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A light's position and focal point in view space, by its frame.

    - scene light: world space, carried by ``world_to_view``;
    - headlight: at the eye, aimed at the focal point, so (0, 0, 0) → (0, 0, −d);
    - camera light: (0, 0, 1) is the eye and (0, 0, 0) the focal point, in units of the
      camera distance d, i.e. view = d·(x, y, z − 1) (VTK's light transform
      inverse(view)·scale(d)·translate(0, 0, −1));
    - eye light: already in view (eye) coordinates, as OpenGL keeps a light given right
      after glLoadIdentity.
    """
    if light.kind == "eye":
        return np.asarray(light.position, dtype=np.float64), np.asarray(light.focal_point, dtype=np.float64)
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
               attenuation=np.zeros((n, 3)), gl_ambient=np.zeros((n, 3)), gl_diffuse=np.zeros((n, 3)),
               gl_specular=np.zeros((n, 3)))
    for i, light in enumerate(on):
        pos, foc = light_to_view(light, camera, world_to_view)
        direction = foc - pos
        out["direction"][i] = direction / np.linalg.norm(direction)
        out["position"][i] = pos
        out["colour"][i] = light.colour
        out["gl_ambient"][i] = light.ambient_color
        out["gl_diffuse"][i] = light.gl_diffuse
        out["gl_specular"][i] = light.gl_specular
        out["positional"][i] = light.positional
        if light.positional and light.cone_angle < 90.0:
            out["cos_cone"][i] = math.cos(math.radians(light.cone_angle))
        out["exponent"][i] = light.exponent
        out["attenuation"][i] = light.attenuation
    return ViewLights(complexity=light_complexity(lights), **out)


@njit(cache=True, inline="always")
def reflect_dot(lx, ly, lz, n, vx, vy, vz):
    """reflect(l, n)·v with GLSL's reflect(l, n) = l − 2·(n·l)·n, in scalars."""
    k = 2.0 * (n[0] * lx + n[1] * ly + n[2] * lz)
    return (lx - k * n[0]) * vx + (ly - k * n[1]) * vy + (lz - k * n[2]) * vz


@njit(cache=True, inline="always")
def vtk_lighting(n, p, complexity, amb, dif, spe, power, lights, out):
    """VTK's colour at one fragment (the scalar kernel); writes linear RGB into ``out``.

    n : unit normal on the viewer's side (view space). p : fragment position (view
    space). amb, dif, spe : Ka·Ca, Kd·Cd, Ks·Cs (linear RGB). power : specular power.
    lights : :class:`ViewLights`. Written with scalars only: it runs per pixel.
    """
    l_dir, l_pos, l_col, l_positional = lights.direction, lights.position, lights.colour, lights.positional
    l_cos_cone, l_exponent, l_att = lights.cos_cone, lights.exponent, lights.attenuation
    if complexity == UNLIT:
        for c in range(3):
            out[c] = amb[c] + dif[c]
        return
    shiny = spe[0] != 0.0 or spe[1] != 0.0 or spe[2] != 0.0  # else Ks·Cs·sf is 0 whatever sf: skip the power
    if complexity == HEADLIGHT_ONLY:
        df = max(1e-6, n[2])
        sf = df ** power if shiny else 0.0
        for c in range(3):
            out[c] = amb[c] + df * dif[c] * l_col[0, c] + sf * spe[c] * l_col[0, c]
        return
    plen = math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2])
    vx, vy, vz = (-p[0] / plen, -p[1] / plen, -p[2] / plen) if plen > 0.0 else (0.0, 0.0, 1.0)
    d0 = d1 = d2 = 0.0  # Σ df·Lc
    s0 = s1 = s2 = 0.0  # Σ sf·Lc
    for i in range(l_dir.shape[0]):
        att = 1.0
        lx, ly, lz = l_dir[i, 0], l_dir[i, 1], l_dir[i, 2]
        if complexity == POSITIONAL and l_positional[i]:
            lx, ly, lz = p[0] - l_pos[i, 0], p[1] - l_pos[i, 1], p[2] - l_pos[i, 2]
            dist = math.sqrt(lx * lx + ly * ly + lz * lz)
            lx, ly, lz = lx / dist, ly / dist, lz / dist
            att = 1.0 / (l_att[i, 0] + l_att[i, 1] * dist + l_att[i, 2] * dist * dist)
            if l_cos_cone[i] > -1.5:  # a spot: cut off outside the cone, cos^exponent inside
                cd = lx * l_dir[i, 0] + ly * l_dir[i, 1] + lz * l_dir[i, 2]
                att = att * cd ** l_exponent[i] if cd >= l_cos_cone[i] else 0.0
        df = max(0.0, -att * (n[0] * lx + n[1] * ly + n[2] * lz))
        if df > 0.0:
            sf = att * max(1e-5, reflect_dot(lx, ly, lz, n, vx, vy, vz)) ** power if shiny else 0.0
            d0 += df * l_col[i, 0]
            d1 += df * l_col[i, 1]
            d2 += df * l_col[i, 2]
            s0 += sf * l_col[i, 0]
            s1 += sf * l_col[i, 1]
            s2 += sf * l_col[i, 2]
    out[0] = amb[0] + dif[0] * d0 + spe[0] * s0
    out[1] = amb[1] + dif[1] * d1 + spe[1] * s1
    out[2] = amb[2] + dif[2] * d2 + spe[2] * s2
