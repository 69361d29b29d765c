"""Coverage agrees with VTK on random valid scenes and random triangle soups (hypothesis).

Colours are the parity tests' business (``test_parity*.py``); here the claim is about
geometry only: whatever the scene, the pixels we draw are the pixels VTK draws, within
the coverage bar. Random scenes have small images (16–80 px a side, at most 6400 pixels),
where the bar of 0.02 % allows at most one pixel. Examples are fewer than in the
renderer's properties, since each one is a VTK render (profiles: ``tests/conftest.py``).
"""
from __future__ import annotations

from hypothesis import given, settings

from compare.metrics import PARITY_BARS, measure
from compare.reference import render_reference
from renderer import render

from ..scene_strategies import any_scene

VTK_EXAMPLES = max(10, settings.default.max_examples * 3 // 4)


@settings(max_examples=VTK_EXAMPLES)
@given(any_scene())
def test_coverage_matches_vtk(scene):
    """Coverage mismatch within the bar (0.02 % of the pixels)."""
    m = measure(render(scene), render_reference(scene))
    assert m["coverage_mismatch"] <= PARITY_BARS["coverage_mismatch"], m
