"""The reference for the ``opengl`` model: fixed-function OpenGL lighting in numpy and in GLSL.

Written from *The OpenGL Graphics System: A Specification* (versions 1.x; the same text
up to 2.1), §2.14.1 "Lighting", not from ``renderer/``:

    c = e_cm + a_cm·a_cs
        + Σ_i att_i · spot_i · ( a_cm·a_cli
                                 + (n ⊙ VP_pli)·d_cm·d_cli
                                 + f_i·(n ⊙ h_i)^s_rm · s_cm·s_cli )

with ``⊙`` the dot product clamped at 0, ``f_i = 1`` if ``n ⊙ VP_pli ≠ 0`` (that is,
N·L > 0) else 0, ``h_i = normalize(VP_pli + VP_e)`` and ``VP_e = (0,0,1)`` for the
infinite viewer or the unit vector toward the eye for ``GL_LIGHT_MODEL_LOCAL_VIEWER``.
Emission ``e_cm`` is taken as 0. Each channel is clamped to [0, 1] at the end; with
``GL_SEPARATE_SPECULAR_COLOR`` the specular sum is a colour of its own, clamped on its own
and added after the texture. Vectors and lights follow :mod:`compare.lit_reference.eye_space`.

For ``--reference vtk-native`` (:func:`vtk_property`) VTK's nearest material stands in.
"""
from __future__ import annotations

import numpy as np

from compare.lit_reference.eye_space import glsl_light_vector, glsl_vec3, light_vector, points_and_normals, unit, vec3
from compare.lit_reference.reference_kinds import LitReference, textbook_reference


def opengl_colour_parts(P, N, ambient, diffuse, specular, shininess, lights, global_ambient=(0.2, 0.2, 0.2),
                        local_viewer=False) -> tuple[np.ndarray, np.ndarray]:
    """OpenGL 1.x fixed-function lighting at view-space points P with normals N, in its two
    parts: the primary colour (ambient + diffuse, global ambient included) and the
    secondary (specular) colour, each (M,3) and *not* clamped."""
    P, N = points_and_normals(P, N)
    Ma, Md, Ms = vec3(ambient), vec3(diffuse), vec3(specular)
    V = unit(-P) if local_viewer else np.broadcast_to([0.0, 0.0, 1.0], P.shape)
    primary = np.broadcast_to(vec3(global_ambient) * Ma, P.shape).copy()
    secondary = np.zeros(P.shape)
    for light in lights:
        L, att = light_vector(light, P)
        NL = np.sum(N * L, axis=1)
        H = unit(L + V)
        NH = np.maximum(np.sum(N * H, axis=1), 0.0)
        s = np.where(NL > 0, NH ** float(shininess), 0.0)
        primary += att[:, None] * (vec3(light.ambient) * Ma + np.maximum(NL, 0.0)[:, None] * (vec3(light.diffuse) * Md))
        secondary += att[:, None] * s[:, None] * (vec3(light.specular) * Ms)
    return primary, secondary


def opengl_colours(P, N, ambient, diffuse, specular, shininess, lights, global_ambient=(0.2, 0.2, 0.2),
                   local_viewer=False) -> np.ndarray:
    """OpenGL 1.x fixed-function colour (M,3) at view-space points P with normals N, clamped
    to 0..1 (``GL_SINGLE_COLOR``: both parts of :func:`opengl_colour_parts` summed first)."""
    primary, secondary = opengl_colour_parts(P, N, ambient, diffuse, specular, shininess, lights, global_ambient,
                                             local_viewer)
    return np.clip(primary + secondary, 0.0, 1.0)


def lit(points, normals, obj, scene, lights) -> tuple[np.ndarray, np.ndarray | None]:
    """``obj``'s colours at view-space points: clamped RGB, and the separate specular colour
    (clamped on its own) when the scene asks for it, else None."""
    m, r = obj.material, scene.render
    args = (points, normals, m.gl_ambient, m.gl_diffuse, m.gl_specular, m.shininess, lights)
    if r.separate_specular:  # GL_SEPARATE_SPECULAR_COLOR: each part clamped on its own
        rgb, secondary = (np.clip(part, 0.0, 1.0) for part in opengl_colour_parts(
            *args, global_ambient=np.asarray(r.global_ambient), local_viewer=r.local_viewer))
        return rgb, secondary
    return opengl_colours(*args, global_ambient=np.asarray(r.global_ambient), local_viewer=r.local_viewer), None


def glsl(obj, scene, lights) -> str:
    """The opengl model per fragment in GLSL: ``c`` the primary colour, the specular sum in
    ``secondary``, joined to ``c`` unless the scene keeps it separate."""
    m, r = obj.material, scene.render
    ma, md, ms = glsl_vec3(m.gl_ambient), glsl_vec3(m.gl_diffuse), glsl_vec3(m.gl_specular)
    viewer = "normalize(-P)" if r.local_viewer else "vec3(0.0, 0.0, 1.0)"
    body = f"  vec3 V = {viewer};\n  vec3 c = {glsl_vec3(r.global_ambient)} * {ma};\n"
    for li in lights:
        body += ("  {\n" + glsl_light_vector(li) +
                 "    ndl = dot(n, L);\n    float sf = 0.0;\n"
                 f"    if (ndl > 0.0) {{ sf = pow(max(dot(n, normalize(L + V)), 0.0), {m.shininess:.9g}); }}\n"
                 f"    c += att * ({glsl_vec3(li.ambient)} * {ma} + max(ndl, 0.0) * {glsl_vec3(li.diffuse)} * {md});\n"
                 f"    secondary += att * sf * {glsl_vec3(li.specular)} * {ms};\n  }}\n")
    if not r.separate_specular:
        body += "  c += secondary;\n"
    return body


def vtk_property(obj, scene) -> dict:
    """VTK's nearest equivalent, so that what remains is the difference of the models, not of
    the numbers: the ambient ``(Ga + ΣLa)·Ma`` becomes VTK's ambient colour, ``Md`` and ``Ms``
    its diffuse and specular colours (coefficients 1), and shininess/4 its specular power
    (Phong's (r·v)^p is close to Blinn's (n·h)^(4p))."""
    m = obj.material
    la = sum((np.asarray(li.ambient_color) for li in scene.lights if li.on), np.zeros(3))
    amb = np.clip((np.asarray(scene.render.global_ambient) + la) * m.gl_ambient, 0.0, 1.0)
    return dict(ambient_color=amb, ambient=1.0, diffuse_color=m.gl_diffuse, diffuse=1.0,
                specular_color=m.gl_specular, specular=1.0, power=m.shininess / 4.0)


def separate_specular(scene) -> bool:
    """OpenGL's ``GL_SEPARATE_SPECULAR_COLOR``, as the scene's ``[render]`` sets it."""
    return bool(scene.render.separate_specular)


REFERENCE = LitReference(name="opengl", reference=textbook_reference, vtk_property=vtk_property, lit=lit, glsl=glsl,
                         separate_specular=separate_specular)
