"""Light sets: each is a valid set of the scene's lights, and VTK draws it as we do."""
from __future__ import annotations

import pytest

from lab.app.sweep.light_sets import LIGHT_SETS
from lab.app.sweep.run_case import run_one_case
from lab.app.sweep.settings import apply_settings
from lab.loading import load_scene


def test_every_light_set_has_lights_and_a_description_and_colours_on_the_k_over_255_grid():
    for name, light_set in LIGHT_SETS.items():
        assert light_set.lights and light_set.description, name
        for light in light_set.lights:
            assert all(abs(c * 255 - round(c * 255)) < 1e-9 for c in light.color), name


@pytest.mark.parametrize("name", list(LIGHT_SETS))
def test_both_renderers_draw_every_light_set_alike(name):
    """Parity against a real VTK render, gouraud-shaded, within the parity bars."""
    scene = apply_settings(load_scene("icosphere:level=2"), {"lights": name, "shading": "gouraud", "size": "96x72"})
    assert scene.lights == LIGHT_SETS[name].lights
    outcome = run_one_case(scene, name)
    assert outcome.failed_bars == [], outcome.metrics
    assert outcome.metrics["shared_pixels"] > 1000, "the sphere is in view"
