"""The lit references, found by model name: the compare side's registry of reflection models.

Each model's reference lives in a module of its own (:mod:`~compare.lit_reference.vtk_lit`,
:mod:`~compare.lit_reference.opengl_lit`, :mod:`~compare.lit_reference.classic_lit`) and
registers a :class:`~compare.lit_reference.reference_kinds.LitReference`. Nothing else in
``compare/`` asks for a model by name: it looks the object's model up here.

>>> sorted(LIT_REFERENCES)
['classic', 'opengl', 'vtk']
"""
from __future__ import annotations

from compare.lit_reference import classic_lit, opengl_lit, vtk_lit

LIT_REFERENCES = {r.name: r for r in (vtk_lit.REFERENCE, opengl_lit.REFERENCE, classic_lit.REFERENCE)}
"""Model name (the scene's ``model``) → its :class:`~compare.lit_reference.reference_kinds.LitReference`."""


def lit_reference(obj):
    """The :class:`~compare.lit_reference.reference_kinds.LitReference` of ``obj``'s reflection
    model (``material.reflection_model``: an unlit object is VTK's)."""
    return LIT_REFERENCES[obj.material.reflection_model]
