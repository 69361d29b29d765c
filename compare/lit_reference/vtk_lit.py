"""The reference for the ``vtk`` model: VTK itself, with the scene's material as it is.

Nothing is lit here: VTK draws the object with its own lighting (``"vtk-native"``), from
the ``vtkProperty`` values of :func:`vtk_property`. An object with ``lighting = false``
belongs here whatever its ``model``: it draws VTK's unlit ``Ka·C + Kd·C``.
"""
from __future__ import annotations

from compare.lit_reference.reference_kinds import NATIVE, LitReference, never


def native(obj) -> str:
    """VTK draws it with its own shading."""
    return NATIVE


def vtk_property(obj, scene) -> dict:
    """The scene's values: colour for ambient and diffuse, the specular colour, Ka, Kd, Ks and
    the specular power (which VTK clamps at 128)."""
    m = obj.material
    return dict(ambient_color=m.color, ambient=m.ambient, diffuse_color=m.color, diffuse=m.diffuse,
                specular_color=m.effective_specular_color, specular=m.specular, power=m.specular_power)


REFERENCE = LitReference(name="vtk", reference=native, vtk_property=vtk_property, lit=None, glsl=None,
                         separate_specular=never)
