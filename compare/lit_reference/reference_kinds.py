"""The kinds of reference VTK can draw, and the record each reflection model registers.

- :data:`NATIVE` (``"vtk-native"``): VTK's own shading (the vtk model; any model with
  ``--reference vtk-native``, through VTK's nearest material);
- :data:`UNLIT` (``"vtk-unlit-colours"``): colours lit in numpy per vertex or per triangle,
  drawn by VTK unlit;
- :data:`SHADER` (``"vtk-shader-replacement"``): VTK's fragment lighting replaced by GLSL of
  the model's formula (per-pixel textbook lighting).
"""
from __future__ import annotations

from typing import Callable, NamedTuple

NATIVE, UNLIT, SHADER, NONE = "vtk-native", "vtk-unlit-colours", "vtk-shader-replacement", "none"
REFERENCES = (NATIVE, UNLIT, SHADER)


class LitReference(NamedTuple):
    """What a reflection model registers on the compare side
    (:data:`compare.lit_reference.lit_registry.LIT_REFERENCES`).

    name : the scene file's ``model`` value.
    reference : ``SceneObject`` → the kind of reference that draws it (:data:`REFERENCES`).
    vtk_property : ``(SceneObject, Scene)`` → the ``vtkProperty`` values (a dict: ambient_color,
        ambient, diffuse_color, diffuse, specular_color, specular, power) that draw the object
        with VTK's own lighting: the model's own, or VTK's nearest equivalent.
    lit : ``(points, normals, obj, scene, lights)`` → (rgb, secondary or None), the model's
        colours at view-space points, in numpy; None for a model VTK draws natively.
    glsl : ``(obj, scene, lights)`` → GLSL that sets ``vec3 c`` (and adds to ``secondary``)
        from ``n``, ``P``, ``L``, ``att``: the model per fragment; None for a native model.
    separate_specular : ``Scene`` → whether the model's specular colour is added after the
        texture (OpenGL's ``GL_SEPARATE_SPECULAR_COLOR``).
    """

    name: str
    reference: Callable
    vtk_property: Callable
    lit: Callable | None
    glsl: Callable | None
    separate_specular: Callable


def textbook_reference(obj) -> str:
    """The reference of a textbook model (lit per triangle, per vertex, or per pixel): a
    replaced shader for phong with vertex normals, else colours lit in numpy, drawn unlit."""
    if obj.shading == "phong" and obj.mesh.point_normals is not None:
        return SHADER
    return UNLIT


def never(scene) -> bool:
    """For models with one colour: no separate specular."""
    return False
