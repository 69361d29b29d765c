"""Textbook lighting in numpy, written from the formulas alone (not from ``renderer/``).

This module exists to check the renderer's lighting, so it is deliberately an
independent, plain implementation of two published models:

* **OpenGL fixed-function lighting** — *The OpenGL Graphics System: A Specification*
  (versions 1.x; the same text up to 2.1), §2.14.1 "Lighting":

      c = e_cm + a_cm·a_cs
          + Σ_i att_i · spot_i · ( a_cm·a_cli
                                   + (n ⊙ VP_pli)·d_cm·d_cli
                                   + f_i·(n ⊙ h_i)^s_rm · s_cm·s_cli )

  with ``⊙`` the dot product clamped at 0, ``f_i = 1`` if ``n ⊙ VP_pli ≠ 0`` (that is,
  N·L > 0) else 0, ``h_i = normalize(VP_pli + VP_e)`` and ``VP_e = (0,0,1)`` for the
  infinite viewer or the unit vector toward the eye for ``GL_LIGHT_MODEL_LOCAL_VIEWER``.
  Emission ``e_cm`` is taken as 0. Each channel is clamped to [0, 1] at the end.

* **The course slides' "classic" Phong model** (Phong 1975 as taught):

      I = ka·O·A + Σ_l att_l·[N·L > 0]·( kd·O·I_l·(N·L) + ks·I_l·max(R·V, 0)^n )

  with R = 2(N·L)N − L the mirror direction of L, O the object colour, A the ambient
  light and I_l the light colour × intensity; clamped to [0, 1].

Conventions
-----------
* Every vector (points, normals, light positions and directions) is in **view (eye)
  space**: the eye at the origin looking down −z.
* Colours are **linear RGB** in 0..1.
* Normals are **used as given — never flipped** toward the viewer (OpenGL's two-sided
  lighting, ``GL_LIGHT_MODEL_TWO_SIDE``, is off by default). They are only rescaled to
  unit length (a zero normal stays zero and so receives ambient light only).
* L is the unit vector from the point toward the light. A directional light has
  ``L = −direction`` and attenuation 1 (no distance falloff, no spot). A positional light
  has ``L = normalize(position − P)``, ``d = |position − P|`` and
  ``att = 1 / (a0 + a1·d + a2·d²)``; if it is a spot (``cos_cone`` not None),
  ``c = (−L)·direction`` and ``att *= max(c, 0)^exponent`` when ``c ≥ cos_cone``, else 0.
  (For ``cos_cone ≥ 0`` — cone half-angles up to 90° — ``max(c, 0)`` is just ``c``.)
* ``x^0``: numpy gives ``0.0 ** 0.0 == 1.0`` and this module keeps that. So with
  shininess (or n) 0 a lit point (N·L > 0) gets the full specular ``Ls·Ms`` even where
  N·H (or R·V) is 0; unlit points get none, the N·L > 0 gate comes first.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["EyeLight", "unit", "face_points_and_normals", "opengl_colour_parts", "opengl_colours",
           "classic_colours"]


def _vec3(values) -> np.ndarray:
    return np.array(values, dtype=float).reshape(3)


@dataclass
class EyeLight:
    """One light in view space, with both the classic colour and the OpenGL colours.

    ``direction`` is the unit vector the light travels along (from the light toward its
    focal point). ``cos_cone`` is None for no spot, else the cosine of the spot half-angle.
    ``colour`` is colour × intensity (the classic model's I_l); ``ambient``, ``diffuse``
    and ``specular`` are OpenGL's La, Ld, Ls.
    """

    position: np.ndarray = field(default_factory=lambda: np.zeros(3))
    direction: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, -1.0]))
    positional: bool = False
    cos_cone: float | None = None
    exponent: float = 0.0
    attenuation: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))
    colour: np.ndarray = field(default_factory=lambda: np.ones(3))
    ambient: np.ndarray = field(default_factory=lambda: np.zeros(3))
    diffuse: np.ndarray = field(default_factory=lambda: np.ones(3))
    specular: np.ndarray = field(default_factory=lambda: np.ones(3))


def unit(v) -> np.ndarray:
    """``v`` scaled to unit length along its last axis; zero vectors stay zero."""
    v = np.asarray(v, dtype=float)
    length = np.linalg.norm(v, axis=-1, keepdims=True)
    return np.divide(v, length, out=np.zeros_like(v), where=length > 0)


def face_points_and_normals(points, triangles) -> tuple[np.ndarray, np.ndarray]:
    """Centroid (T,3) and unit normal (T,3) of each triangle; normal = (v1−v0)×(v2−v0)."""
    points = np.asarray(points, dtype=float)
    v0, v1, v2 = (points[np.asarray(triangles)[:, k]] for k in range(3))
    return (v0 + v1 + v2) / 3.0, unit(np.cross(v1 - v0, v2 - v0))


def _points_and_normals(P, N) -> tuple[np.ndarray, np.ndarray]:
    P = np.atleast_2d(np.asarray(P, dtype=float))
    N = unit(np.atleast_2d(np.asarray(N, dtype=float)))
    return np.broadcast_arrays(P, N)


def _to_light(light: EyeLight, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """L (M,3), unit, from each point toward the light; and att (M,) with the spot factor."""
    direction = unit(_vec3(light.direction))
    if not light.positional:
        return np.broadcast_to(-direction, P.shape), np.ones(len(P))
    to_light = _vec3(light.position) - P
    d = np.linalg.norm(to_light, axis=1)
    L = unit(to_light)
    a0, a1, a2 = _vec3(light.attenuation)
    att = 1.0 / (a0 + a1 * d + a2 * d * d)
    if light.cos_cone is not None:
        c = -L @ direction
        att = att * np.where(c >= light.cos_cone, np.maximum(c, 0.0) ** light.exponent, 0.0)
    return L, att


def opengl_colour_parts(P, N, ambient, diffuse, specular, shininess, lights, global_ambient=(0.2, 0.2, 0.2),
                        local_viewer=False) -> tuple[np.ndarray, np.ndarray]:
    """OpenGL 1.x fixed-function lighting at view-space points P with normals N, in its two
    parts: the primary colour (ambient + diffuse, global ambient included) and the
    secondary (specular) colour, each (M,3) and *not* clamped."""
    P, N = _points_and_normals(P, N)
    Ma, Md, Ms = _vec3(ambient), _vec3(diffuse), _vec3(specular)
    V = unit(-P) if local_viewer else np.broadcast_to([0.0, 0.0, 1.0], P.shape)
    primary = np.broadcast_to(_vec3(global_ambient) * Ma, P.shape).copy()
    secondary = np.zeros(P.shape)
    for light in lights:
        L, att = _to_light(light, P)
        NL = np.sum(N * L, axis=1)
        H = unit(L + V)
        NH = np.maximum(np.sum(N * H, axis=1), 0.0)
        s = np.where(NL > 0, NH ** float(shininess), 0.0)
        primary += att[:, None] * (_vec3(light.ambient) * Ma + np.maximum(NL, 0.0)[:, None] * (_vec3(light.diffuse) * Md))
        secondary += att[:, None] * s[:, None] * (_vec3(light.specular) * Ms)
    return primary, secondary


def opengl_colours(P, N, ambient, diffuse, specular, shininess, lights, global_ambient=(0.2, 0.2, 0.2),
                   local_viewer=False) -> np.ndarray:
    """OpenGL 1.x fixed-function colour (M,3) at view-space points P with normals N, clamped
    to 0..1 (``GL_SINGLE_COLOR``: both parts of :func:`opengl_colour_parts` summed first)."""
    primary, secondary = opengl_colour_parts(P, N, ambient, diffuse, specular, shininess, lights, global_ambient,
                                             local_viewer)
    return np.clip(primary + secondary, 0.0, 1.0)


def classic_colours(P, N, colour, ka, kd, ks, n, lights, ambient_light=(1.0, 1.0, 1.0)) -> np.ndarray:
    """The course's classic Phong colour (M,3) at view-space points P with normals N."""
    P, N = _points_and_normals(P, N)
    O, A = _vec3(colour), _vec3(ambient_light)
    V = unit(-P)
    I = np.broadcast_to(ka * O * A, P.shape).copy()
    for light in lights:
        L, att = _to_light(light, P)
        NL = np.sum(N * L, axis=1)
        R = 2.0 * NL[:, None] * N - L
        RV = np.maximum(np.sum(R * V, axis=1), 0.0)
        Il = _vec3(light.colour)
        term = kd * NL[:, None] * (O * Il) + ks * (RV ** float(n))[:, None] * Il
        I += np.where(NL > 0, att, 0.0)[:, None] * term
    return np.clip(I, 0.0, 1.0)
