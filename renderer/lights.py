"""The switched-on lights in view space, the scene-wide light model, and one light seen from a point.

Every reflection model (:mod:`renderer.reflection`) reads its lights from one
:class:`ViewLights`: the switched-on lights as arrays in **view space** (eye at the
origin, looking down −z), together with the scene-wide light-model settings (OpenGL's
``glLightModel``: global ambient, local viewer, separate specular; the classic model's
ambient light A; VTK's light complexity). Colours are linear 0..1 RGB.

Where each light is (:func:`light_to_view`) follows its frame: scene lights in world
space, headlights at the eye, camera lights in the camera's frame, eye lights in view
space. How much of a positional light reaches a point (:func:`light_at`) is written once,
for every model: attenuation ``1/(a0 + a1·d + a2·d²)`` and, inside a spot cone,
``cos^exponent`` of the angle off the spot's axis, zero outside.

VTK's light complexity (:func:`light_complexity`), which chooses VTK's formula
(:mod:`renderer.reflection.vtk_model`): 0 no light switched on; 1 exactly one light on
and it is a headlight (of any intensity — measured); 2 otherwise, no positional light; 3
any positional light (switched on or not). Source: VTK 9.7
``vtkOpenGLRenderer::UpdateLights``; measured in ``shared/docs/vtk-parity.md``.
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from lab.scene import RenderSettings
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


NO_CONE = -2.0
"""``ViewLights.cos_cone`` of a light that is not a spot (directional, or a point light with
a cone of 90° or more): below every cosine, so it can never be mistaken for a cone."""


class ViewLights(NamedTuple):
    """The switched-on lights as arrays in view space, and the scene-wide light model; the
    kernels take it whole.

    direction (L, 3) unit vectors the light travels along; position (L, 3);
    intensity_rgb (L, 3) = colour × intensity; positional (L,) bool; cos_cone (L,) cosine
    of the cone half-angle (:data:`NO_CONE` = not a spot); exponent (L,); attenuation
    (L, 3) constant, linear, quadratic; gl_ambient, gl_diffuse, gl_specular (L, 3): the
    OpenGL model's colours.

    The light model, scene-wide (``[render]``): complexity, VTK's light complexity of the
    whole set (:func:`light_complexity`); global_ambient (3,), OpenGL's light-model
    ambient; ambient_light (3,), the classic model's A; local_viewer and
    separate_specular, OpenGL's ``GL_LIGHT_MODEL_LOCAL_VIEWER`` and
    ``GL_SEPARATE_SPECULAR_COLOR``.
    """

    direction: np.ndarray
    position: np.ndarray
    intensity_rgb: np.ndarray
    positional: np.ndarray
    cos_cone: np.ndarray
    exponent: np.ndarray
    attenuation: np.ndarray
    gl_ambient: np.ndarray
    gl_diffuse: np.ndarray
    gl_specular: np.ndarray
    complexity: int
    global_ambient: np.ndarray
    ambient_light: np.ndarray
    local_viewer: bool
    separate_specular: bool


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


def view_lights(lights, camera, world_to_view: np.ndarray, settings: RenderSettings = RenderSettings()) -> ViewLights:
    """Gather the switched-on lights in view space and the light model of ``settings`` (the
    scene's ``[render]``), see :class:`ViewLights`."""
    on = [li for li in lights if li.on]
    n = len(on)
    out = dict(direction=np.zeros((n, 3)), position=np.zeros((n, 3)), intensity_rgb=np.zeros((n, 3)),
               positional=np.zeros(n, np.bool_), cos_cone=np.full(n, NO_CONE), exponent=np.zeros(n),
               attenuation=np.zeros((n, 3)), gl_ambient=np.zeros((n, 3)), gl_diffuse=np.zeros((n, 3)),
               gl_specular=np.zeros((n, 3)))
    for i, light in enumerate(on):
        pos, foc = light_to_view(light, camera, world_to_view)
        direction = foc - pos
        out["direction"][i] = direction / np.linalg.norm(direction)
        out["position"][i] = pos
        out["intensity_rgb"][i] = light.intensity_rgb
        out["gl_ambient"][i] = light.ambient_color
        out["gl_diffuse"][i] = light.gl_diffuse
        out["gl_specular"][i] = light.gl_specular
        out["positional"][i] = light.positional
        if light.positional and light.cone_angle < 90.0:
            out["cos_cone"][i] = math.cos(math.radians(light.cone_angle))
        out["exponent"][i] = light.exponent
        out["attenuation"][i] = light.attenuation
    return ViewLights(**out, complexity=light_complexity(lights),
                      global_ambient=np.asarray(settings.global_ambient, np.float64),
                      ambient_light=np.asarray(settings.ambient, np.float64), local_viewer=bool(settings.local_viewer),
                      separate_specular=bool(settings.separate_specular))


@njit(cache=True, inline="always")
def light_at(lights, i, p):
    """Light ``i`` as seen from view-space point ``p`` (the scalar kernel every model shares):
    ``(Lx, Ly, Lz, att)``.

    ``L`` is the unit vector from ``p`` toward the light: ``−direction`` for a directional
    light, with ``att = 1``; ``(position − p)/d`` for a positional one, ``d = |position − p|``,
    with ``att = 1/(a0 + a1·d + a2·d²)``, times ``c^exponent`` inside a spot cone
    (``c = −L·direction``, the cosine of the angle off the spot's axis, at least
    ``cos_cone``) and zero outside it. VTK's ``l`` (from the light to the point) is exactly
    ``−L``: the negation is exact in floating point, so one formula serves both sides.
    """
    if not lights.positional[i]:
        return -lights.direction[i, 0], -lights.direction[i, 1], -lights.direction[i, 2], 1.0
    lx, ly, lz = lights.position[i, 0] - p[0], lights.position[i, 1] - p[1], lights.position[i, 2] - p[2]
    d = math.sqrt(lx * lx + ly * ly + lz * lz)
    lx, ly, lz = lx / d, ly / d, lz / d
    a = lights.attenuation[i]
    att = 1.0 / (a[0] + a[1] * d + a[2] * d * d)
    if lights.cos_cone[i] != NO_CONE:  # a spot: cut off outside the cone, cos^exponent inside
        c = -(lx * lights.direction[i, 0] + ly * lights.direction[i, 1] + lz * lights.direction[i, 2])
        att = att * c ** lights.exponent[i] if c >= lights.cos_cone[i] else 0.0
    return lx, ly, lz, att
