"""The fill rules: which triangle draws a pixel centre lying exactly on an edge two triangles share.

The raster's spans (:func:`renderer.raster.scanline_span`), its edge functions
(:func:`renderer.edge_functions.owns_ties`) and its one-pixel triangles
(:mod:`renderer.one_pixel`) all take the rule as one of these numbers. **Top-left** (OpenGL's,
Direct3D's): a left edge or a bottom edge in window coordinates (y up) owns the centres on
it, a top-left rule in image coordinates (y down). **Bottom-right** hands the ties to the
opposite edges: the deliberately wrong rule of the parity tests.
"""
from __future__ import annotations

TOP_LEFT, BOTTOM_RIGHT = 0, 1
FILL_RULES = {"top-left": TOP_LEFT, "bottom-right": BOTTOM_RIGHT}
"""A fill rule's name (as scenes and options give it) → its number."""
