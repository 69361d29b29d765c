"""The reference for the ``classic`` model: the course's Phong illumination in numpy and in GLSL.

Written from the course slides (Phong 1975 as taught), not from ``renderer/``:

    I = ka·O·A + Σ_l att_l·[N·L > 0]·( kd·O·I_l·(N·L) + ks·I_l·max(R·V, 0)^n )

with R = 2(N·L)N − L the mirror direction of L, V = normalize(−P), O the object colour,
A the ambient light and I_l the light colour × intensity; clamped to [0, 1]. One colour: no
separate specular. Vectors and lights follow :mod:`compare.lit_reference.eye_space`.

For ``--reference vtk-native`` (:func:`vtk_property`) VTK's material maps one to one.
"""
from __future__ import annotations

import numpy as np

from compare.lit_reference.eye_space import glsl_light_vector, glsl_vec3, light_vector, points_and_normals, unit, vec3
from compare.lit_reference.reference_kinds import LitReference, never, textbook_reference


def classic_colours(P, N, colour, ka, kd, ks, n, lights, ambient_light=(1.0, 1.0, 1.0)) -> np.ndarray:
    """The course's classic Phong colour (M,3) at view-space points P with normals N."""
    P, N = points_and_normals(P, N)
    O, A = vec3(colour), vec3(ambient_light)
    V = unit(-P)
    I = np.broadcast_to(ka * O * A, P.shape).copy()
    for light in lights:
        L, att = light_vector(light, P)
        NL = np.sum(N * L, axis=1)
        R = 2.0 * NL[:, None] * N - L
        RV = np.maximum(np.sum(R * V, axis=1), 0.0)
        Il = vec3(light.intensity_rgb)
        term = kd * NL[:, None] * (O * Il) + ks * (RV ** float(n))[:, None] * Il
        I += np.where(NL > 0, att, 0.0)[:, None] * term
    return np.clip(I, 0.0, 1.0)


def lit(points, normals, obj, scene, lights) -> tuple[np.ndarray, None]:
    """``obj``'s colours at view-space points (no secondary colour)."""
    m = obj.material
    return classic_colours(points, normals, np.asarray(m.color), m.ambient, m.diffuse, m.specular, m.specular_power,
                           lights, ambient_light=np.asarray(scene.render.ambient)), None


def glsl(obj, scene, lights) -> str:
    """The classic model per fragment in GLSL, into ``c``."""
    m, o = obj.material, np.asarray(obj.material.color)
    body = f"  vec3 V = normalize(-P);\n  vec3 c = {glsl_vec3(m.ambient * o)} * {glsl_vec3(scene.render.ambient)};\n"
    for li in lights:
        body += ("  {\n" + glsl_light_vector(li) +
                 "    ndl = dot(n, L);\n"
                 "    if (att > 0.0 && ndl > 0.0) {\n"
                 "      vec3 R = 2.0 * ndl * n - L;\n"
                 f"      float sf = pow(max(dot(R, V), 0.0), {m.specular_power:.9g});\n"
                 f"      c += att * {glsl_vec3(li.intensity_rgb)} * ({glsl_vec3(m.diffuse * o)} * ndl"
                 f" + {m.specular:.9g} * sf);\n"
                 "    }\n  }\n")
    return body


def vtk_property(obj, scene) -> dict:
    """One to one: ``O·A``, Ka; O, Kd; white, Ks; n."""
    m = obj.material
    return dict(ambient_color=np.asarray(m.color) * np.asarray(scene.render.ambient), ambient=m.ambient,
                diffuse_color=np.asarray(m.color), diffuse=m.diffuse, specular_color=np.ones(3),
                specular=m.specular, power=m.specular_power)


REFERENCE = LitReference(name="classic", reference=textbook_reference, vtk_property=vtk_property, lit=lit, glsl=glsl,
                         separate_specular=never)
