"""The lesson figures: what each shows is measured, and the figure is written."""
from __future__ import annotations

import numpy as np

from compare.metrics import compare_frames
from compare.reference import render_reference
from lab.loading import load_scene
from lessons.figures import facing, interpolation_figure, interpolation_metrics
from renderer import render


def test_screen_linear_interpolation_differs_on_a_tilted_plane(tmp_path):
    """Gouraud on the grazing floor: screen-linear is measurably not perspective-correct; the figure is written."""
    m = interpolation_figure(tmp_path)
    assert (tmp_path / "interpolation.png").stat().st_size > 10_000
    assert m["tilted"]["pixels_over_1"] > 0.2 and m["tilted"]["delta_e_2000"]["mean"] > 1.0


def test_screen_linear_equals_perspective_on_a_plane_facing_the_camera():
    """With the floor turned to face the camera, w is constant over it and both interpolations agree exactly."""
    m, (screen, perspective, _) = interpolation_metrics(facing(load_scene("tilted-plane")))
    assert screen.coverage.sum() > 10_000
    assert m["max_channel_diff"] == 0


def test_textbook_gouraud_against_vtk_differs_most_on_the_highlight():
    """OpenGL Gouraud vs VTK's per-pixel shading (nearest equivalent material): ΔE is largest where VTK's
    highlight is (the brightest 2 % of its pixels), several times the rest."""
    scene = load_scene("textbook-sphere").with_overrides(model="opengl", shading="gouraud")
    ref = render_reference(scene, reference="vtk-native")
    _, de = compare_frames(render(scene), ref)
    lum = ref.rgb.astype(float).sum(axis=2)
    covered = ref.coverage
    highlight = covered & (lum >= np.percentile(lum[covered], 98))
    assert de[highlight].mean() > 4 * de[covered & ~highlight].mean()


def test_separate_specular_figure_is_written(tmp_path):
    """Single colour against separate specular on the shiny globe: they differ (the
    highlight; where exactly is tested in tests/compare/test_parity_separate_specular.py)."""
    from lessons.figures import separate_specular_figure

    m = separate_specular_figure(tmp_path)
    assert (tmp_path / "separate-specular.png").stat().st_size > 10_000
    assert m["pixels_over_1"] > 0.1 and m["coverage_mismatch"] == 0.0


def test_making_the_figures_again_gives_the_same_bytes_as_the_ones_in_git(tmp_path):
    """No timings (or anything else that changes between runs) inside a figure: two builds are identical,
    and identical to lessons/figures/, so `scanlab lessons figures` leaves git clean."""
    from pathlib import Path

    from lessons.figures import build_figures

    kept = Path(__file__).resolve().parents[2] / "lessons" / "figures"
    names = sorted(build_figures(tmp_path / "a"))
    build_figures(tmp_path / "b")
    for name in names:
        first = (tmp_path / "a" / f"{name}.png").read_bytes()
        assert first == (tmp_path / "b" / f"{name}.png").read_bytes(), name
        assert first == (kept / f"{name}.png").read_bytes(), f"{name}.png differs from git: run scanlab lessons figures"
