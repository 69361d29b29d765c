"""The reflection models, found by name: the registry, the per-object material table, the dispatch.

Each model lives in a module of its own (:mod:`~renderer.reflection.vtk_model`,
:mod:`~renderer.reflection.opengl_model`, :mod:`~renderer.reflection.classic_model`) and
registers one :class:`~renderer.reflection.materials.ReflectionModel`: how it fills an
object's material row, which shading path it gives an object, and its lighting kernel.
This module is the one place that knows them all; nothing else in the renderer asks for a
model by name. A model's code is its place in :data:`REFLECTION_MODELS`.

numba cannot call a function chosen at run time, so :func:`reflect` is a hand-written
dispatch on the code: a new model adds its entry below and one branch there.

>>> sorted(REFLECTION_MODELS)
['classic', 'opengl', 'vtk']
"""
from __future__ import annotations

import weakref

import numpy as np

from renderer.jit import njit
from renderer.reflection import classic_model, opengl_model, vtk_model
from renderer.reflection.classic_model import classic_lighting
from renderer.reflection.materials import Materials
from renderer.reflection.opengl_model import opengl_lighting
from renderer.reflection.vtk_model import vtk_lighting
from renderer.reflection.vtk_spans import (store8, vtk_normal_only, vtk_normals_only, vtk_point_colours, vtk_span,
                                          vtk_span_applies, vtk_span_colours, vtk_spans_apply)

REFLECTION_MODELS = {m.name: m for m in (vtk_model.MODEL, opengl_model.MODEL, classic_model.MODEL)}
"""Model name (the scene's ``model``) → its :class:`~renderer.reflection.materials.ReflectionModel`."""

CODES = {name: code for code, name in enumerate(REFLECTION_MODELS)}
"""Model name → the code the kernels see in ``Materials.model``."""

VTK, OPENGL, CLASSIC = CODES["vtk"], CODES["opengl"], CODES["classic"]


@njit(cache=True, inline="always")
def reflect(n, p, o, materials, lights):
    """The lit colour of object ``o`` at view-space point ``p`` with unit normal ``n``, by its
    model: ``(r, g, b, sr, sg, sb)``, the primary and the secondary (separate specular) RGB."""
    model = materials.model[o]
    if model == VTK:
        return vtk_lighting(n, p, o, materials, lights)
    if model == OPENGL:
        return opengl_lighting(n, p, o, materials, lights)
    return classic_lighting(n, p, o, materials, lights)


@njit(cache=True, inline="always")
def span_applies(o, materials, lights):
    """True when object ``o``'s model has a span kernel (:mod:`renderer.spans`) for these
    lights; else shading lights it pixel by pixel with :func:`reflect`. Only the vtk model
    has one (:mod:`~renderer.reflection.vtk_spans`)."""
    return materials.model[o] == VTK and vtk_span_applies(o, materials, lights)


def spans_apply(o, materials, lights) -> bool:
    """:func:`span_applies` in Python (for choosing a kernel before shading)."""
    return bool(materials.model[o] == VTK and vtk_spans_apply(o, materials, lights))


@njit(cache=True, inline="always")
def span_normal_only(o, materials, lights):
    """True when the span kernel's colour depends on the normal alone (one colour for a
    span with a constant normal)."""
    return vtk_normal_only(o, materials, lights)


def spans_normal_only(o, materials, lights) -> bool:
    """:func:`span_normal_only` in Python, for an object that :func:`spans_apply`."""
    return bool(vtk_normals_only(o, materials, lights))


@njit(cache=True, inline="always")
def reflect_span(o, materials, lights, consts, face, count, points, colour, out):
    """The span kernel of object ``o``'s model (only where :func:`span_applies`): the
    span's ``count`` pixels lit and stored as 8 bits into ``out`` (count, 3); ``consts``
    and ``face`` from :func:`renderer.spans.span_setup`; ``points`` (6, ≥ count) and
    ``colour`` (3, ≥ count) float32 scratch."""
    vtk_span(o, materials, lights, consts, face, count, points, colour, out)


@njit(cache=True, inline="always")
def span_colours(o, materials, lights, consts, face, count, points, colour):
    """The span kernel without the store: the span's ``count`` linear colours into
    ``colour`` (3, ≥ count) float32 (for a texture to modulate before
    :func:`store_span` stores them); ``points`` (6, ≥ count) float32 scratch."""
    vtk_span_colours(o, materials, lights, consts, face, count, points, colour)


@njit(cache=True, inline="always")
def light_points(o, materials, lights, points, first, count, colour):
    """Object ``o``'s model (only where :func:`span_applies`) at ``count`` points already
    interpolated (columns ``first`` … of ``points`` (6, W) float32,
    :func:`renderer.spans.span_points`): their linear colours into ``colour`` (3, ≥ count) float32."""
    vtk_point_colours(o, materials, lights, points, first, count, colour)


@njit(cache=True, inline="always")
def store_span(colour, count, out):
    """``colour`` (3, ≥ count) linear float32 → ``out`` (≥ count, 3), C-contiguous, as the
    framebuffer's 8 bits (:func:`renderer.reflection.vtk_spans.store8`): a span, or a run of
    many spans."""
    store8(colour, count, out)


_TABLES: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()
"""Each scene's material table (:func:`material_table`), kept as long as the scene lives."""


def material_table(scene) -> Materials:
    """Every object's row, filled by its reflection model (``material.reflection_model``:
    an unlit object draws VTK's unlit colour).

    A table depends on the scene's objects alone (not on the camera), and a scene is not
    changed in place (a frozen dataclass, compared by identity), so its table is made once
    and given to each of its frames; callers must not write to it (left writeable: numba
    types a read-only array apart and would compile the kernels again for it). Made afresh,
    a frame's table took 15 µs of Python (three objects; kept, 0.2 µs)."""
    table = _TABLES.get(scene)
    if table is None:
        table = _TABLES[scene] = new_material_table(scene.objects)
    return table


def new_material_table(objects) -> Materials:
    """:func:`material_table` of a tuple of scene objects, made afresh."""
    model, path, lit, amb, dif, spe, power = [], [], [], [], [], [], []
    for obj in objects:
        name = obj.material.reflection_model
        room = REFLECTION_MODELS[name]
        row = room.material_row(obj.material)
        model.append(CODES[name])
        path.append(room.shading_path(obj))
        lit.append(obj.material.lighting)
        amb.append(row.ambient), dif.append(row.diffuse), spe.append(row.specular), power.append(row.power)
    as_int = lambda v: np.array(v, np.int64)  # noqa: E731
    as_float = lambda v: np.array(v, np.float64)  # noqa: E731
    return Materials(as_int(model), as_int(path), np.array(lit, np.bool_), as_float(amb), as_float(dif),
                     as_float(spe), as_float(power), as_float([obj.material.opacity for obj in objects]))
