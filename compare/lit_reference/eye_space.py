"""View-space lights and vectors for the lit references, in numpy, written apart from ``renderer/``.

The references for the textbook models (:mod:`compare.lit_reference.opengl_lit`,
:mod:`compare.lit_reference.classic_lit`) light points with formulas written here from
their published sources alone; this module holds what they share: the light as VTK
placed it (:class:`EyeLight`), the light vector and attenuation in numpy
(:func:`light_vector`) and in GLSL (:func:`glsl_light_vector`, for the replaced phong
shader), unit vectors and face centroids.

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
* ``x^0``: numpy gives ``0.0 ** 0.0 == 1.0`` and the references keep that. So with
  shininess (or n) 0 a lit point (N·L > 0) gets the full specular even where N·H (or R·V)
  is 0; unlit points get none, the N·L > 0 gate comes first.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

__all__ = ["EyeLight", "vec3", "unit", "face_points_and_normals", "points_and_normals", "light_vector", "glsl_vec3",
           "glsl_light_vector"]


def vec3(values) -> np.ndarray:
    return np.array(values, dtype=float).reshape(3)


@dataclass
class EyeLight:
    """One light in view space, with both the classic colour and the OpenGL colours.

    ``direction`` is the unit vector the light travels along (from the light toward its
    focal point). ``cos_cone`` is None for no spot, else the cosine of the spot half-angle.
    ``intensity_rgb`` is colour × intensity (the classic model's I_l); ``ambient``,
    ``diffuse`` and ``specular`` are OpenGL's La, Ld, Ls.
    """

    position: np.ndarray = field(default_factory=lambda: np.zeros(3))
    direction: np.ndarray = field(default_factory=lambda: np.array([0.0, 0.0, -1.0]))
    positional: bool = False
    cos_cone: float | None = None
    exponent: float = 0.0
    attenuation: np.ndarray = field(default_factory=lambda: np.array([1.0, 0.0, 0.0]))
    intensity_rgb: np.ndarray = field(default_factory=lambda: np.ones(3))
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


def points_and_normals(P, N) -> tuple[np.ndarray, np.ndarray]:
    """P (M,3) and unit N (M,3), broadcast against each other."""
    P = np.atleast_2d(np.asarray(P, dtype=float))
    N = unit(np.atleast_2d(np.asarray(N, dtype=float)))
    return np.broadcast_arrays(P, N)


def light_vector(light: EyeLight, P: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """L (M,3), unit, from each point toward the light; and att (M,) with the spot factor."""
    direction = unit(vec3(light.direction))
    if not light.positional:
        return np.broadcast_to(-direction, P.shape), np.ones(len(P))
    to_light = vec3(light.position) - P
    d = np.linalg.norm(to_light, axis=1)
    L = unit(to_light)
    a0, a1, a2 = vec3(light.attenuation)
    att = 1.0 / (a0 + a1 * d + a2 * d * d)
    if light.cos_cone is not None:
        c = -L @ direction
        att = att * np.where(c >= light.cos_cone, np.maximum(c, 0.0) ** light.exponent, 0.0)
    return L, att


def glsl_vec3(v) -> str:
    """A GLSL ``vec3`` constant, 9 significant digits."""
    return "vec3(" + ", ".join(f"{float(x):.9g}" for x in v) + ")"


def glsl_light_vector(li: EyeLight) -> str:
    """GLSL that sets ``L`` (toward the light) and ``att`` for one light, at the fragment ``P``
    (:func:`light_vector` in GLSL)."""
    if not li.positional:
        return f"    L = -{glsl_vec3(li.direction)}; att = 1.0;\n"
    a0, a1, a2 = (float(x) for x in li.attenuation)
    code = (f"    L = {glsl_vec3(li.position)} - P; dist = length(L); L = L / dist;\n"
            f"    att = 1.0 / ({a0:.9g} + {a1:.9g} * dist + {a2:.9g} * dist * dist);\n")
    if li.cos_cone is not None:
        code += (f"    cs = dot(-L, {glsl_vec3(li.direction)});\n"
                 f"    att = cs >= {li.cos_cone:.9g} ? att * pow(cs, {float(li.exponent):.9g}) : 0.0;\n")
    return code
