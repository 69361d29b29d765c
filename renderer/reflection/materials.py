"""What a reflection model gets and gives: the per-object material table, the shading paths.

Every object has one row of :class:`Materials`, filled by its reflection model
(:mod:`renderer.reflection.registry`): the model's code, the shading path it chose for the
object, and its colours in the model's own terms (:class:`MaterialRow`). The scene-wide
light-model settings are not here: they travel with the lights
(:class:`renderer.lights.ViewLights`).

A **shading path** says where an object's colour is lit and with which normal; the
shading kernels (:mod:`renderer.shading`, :mod:`renderer.lit_colours`) follow the path and
never ask which model it is:

- :data:`PIXEL_FACE_NORMAL`: per pixel, with the triangle's plane normal turned toward
  the viewer (perspective: n·P ≤ 0; parallel: n.z ≥ 0);
- :data:`PIXEL_TWO_SIDED`: per pixel, with the interpolated vertex normal, negated on back
  faces (two-sided lighting);
- :data:`FACE_COLOUR`: once per triangle (flat, at its centroid), the colour held over it;
- :data:`VERTEX_COLOUR`: once per vertex, the colours interpolated (Gouraud);
- :data:`PIXEL_AS_GIVEN`: per pixel, with the interpolated vertex normal as given, never
  flipped (Phong).
"""
from __future__ import annotations

from typing import Callable, NamedTuple

import numpy as np

PIXEL_FACE_NORMAL, PIXEL_TWO_SIDED, FACE_COLOUR, VERTEX_COLOUR, PIXEL_AS_GIVEN = 0, 1, 2, 3, 4


def any_flat(materials) -> bool:
    """True when some object is shaded flat (:data:`PIXEL_FACE_NORMAL` or :data:`FACE_COLOUR`):
    only such a frame reads its triangles' plane normals and holds colours per triangle."""
    path = materials.shading_path
    return bool(((path == PIXEL_FACE_NORMAL) | (path == FACE_COLOUR)).any())


def any_face_colour(materials) -> bool:
    """True when some object holds one colour per triangle (:data:`FACE_COLOUR`): the frame
    lights each of its triangles (:func:`renderer.lit_colours.light_faces`), shown or not,
    so it reads every triangle's plane normal."""
    return bool((materials.shading_path == FACE_COLOUR).any())


def smooth(obj) -> bool:
    """True when ``obj`` is shaded with its vertex normals: a gouraud or phong object that has
    them (without point normals every shading falls back to flat)."""
    return obj.shading != "flat" and obj.mesh.point_normals is not None


def textbook_path(obj) -> int:
    """Where the textbook's pipeline lights (fixed-function OpenGL, the course): flat once per
    triangle, gouraud once per vertex, phong per pixel with the normal as given."""
    if not smooth(obj):
        return FACE_COLOUR
    return VERTEX_COLOUR if obj.shading == "gouraud" else PIXEL_AS_GIVEN


class MaterialRow(NamedTuple):
    """One object's colours in its model's terms: ``ambient``, ``diffuse``, ``specular``
    (3,) linear RGB and ``power`` (the specular exponent)."""

    ambient: np.ndarray
    diffuse: np.ndarray
    specular: np.ndarray
    power: float


class Materials(NamedTuple):
    """The per-object material table (index = object), as the kernels read it.

    model (O,) int: the reflection model's code (:data:`renderer.reflection.registry.CODES`);
    shading_path (O,) int: see the module docstring; lit (O,) bool: the material's
    ``lighting`` (False: VTK's unlit ``Amb + Dif``); ambient, diffuse, specular (O, 3) and
    power (O,): :class:`MaterialRow` of each object; opacity (O,) 0..1.
    """

    model: np.ndarray
    shading_path: np.ndarray
    lit: np.ndarray
    ambient: np.ndarray
    diffuse: np.ndarray
    specular: np.ndarray
    power: np.ndarray
    opacity: np.ndarray


class ReflectionModel(NamedTuple):
    """What a reflection model registers (:data:`renderer.reflection.registry.REFLECTION_MODELS`).

    name : the scene file's ``model`` value.
    material_row : :class:`lab.scene.Material` → :class:`MaterialRow`.
    shading_path : :class:`lab.scene.SceneObject` → its shading path.
    lighting : the scalar kernel ``lighting(n, p, o, materials, lights)``: the lit colour
        of object ``o`` at view-space point ``p`` with unit normal ``n`` (3-tuples or arrays),
        ``(r, g, b, sr, sg, sb)``: the primary colour and the secondary (separately added
        specular) colour, linear RGB.
    """

    name: str
    material_row: Callable
    shading_path: Callable
    lighting: Callable
