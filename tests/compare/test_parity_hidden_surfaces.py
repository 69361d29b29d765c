"""Hidden-surface removal as a choice: the painter's algorithm fails where objects
interpenetrate, the z-buffer does not; back-face culling changes nothing on a closed convex
mesh and removes the inside of an open one, exactly as VTK's culling does."""
from __future__ import annotations

import dataclasses

import numpy as np

from compare.metrics import compare_frames, failed_bars, measure
from compare.reference import render_reference
from lab.loading import load_scene
from renderer import render


def with_render(scene, **changes):
    return dataclasses.replace(scene, render=dataclasses.replace(scene.render, **changes))


def test_painter_fails_on_interpenetrating_boxes_and_the_zbuffer_passes():
    """Against VTK (z-buffered), the painter's render misses the bars in a ΔE region; the z-buffer render passes."""
    scene = load_scene("painter-fails")
    ref = render_reference(scene)
    painter, de = compare_frames(render(scene), ref)
    assert failed_bars(painter)
    region = de > 5
    assert 500 < region.sum() < 0.5 * (de > 0).size  # a region, not noise and not everything
    assert not failed_bars(measure(render(with_render(scene, hidden_surface="zbuffer")), ref))


def test_no_hidden_surface_removal_is_worse_than_painter():
    """Without any hidden-surface removal (draw order only) more pixels are wrong than with the painter."""
    scene = load_scene("painter-fails")
    ref = render_reference(scene)
    none = measure(render(with_render(scene, hidden_surface="none")), ref)
    painter = measure(render(scene), ref)
    assert none["pixels_over_1"] > painter["pixels_over_1"]


def test_culling_a_closed_convex_mesh_changes_no_pixel():
    """Back faces of a closed convex mesh are always hidden: culling them changes not one byte."""
    scene = load_scene("headlight-icosphere")
    culled = render(with_render(scene, cull_backfaces=True))
    assert np.array_equal(culled.rgb, render(scene).rgb)
    assert not failed_bars(measure(culled, render_reference(with_render(scene, cull_backfaces=True))))


def test_culling_an_open_box_removes_its_inside_as_vtk_does():
    """The open box culled matches VTK culled; unculled, its inner walls appear where the ΔE map shows."""
    scene = load_scene("open-box")
    culled = render(scene)
    assert not failed_bars(measure(culled, render_reference(scene)))
    shown = render(with_render(scene, cull_backfaces=False))
    m, de = compare_frames(culled, shown)
    assert m["coverage_mismatch"] > 0.05  # the inside walls and floor fill pixels the culled render leaves empty
