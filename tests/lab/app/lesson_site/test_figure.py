"""lab/app/lesson_site/figure.py: variant labels name only what differs, in the page's language."""
from lab.loading import load_scene
from lab.app.lesson_site.figure import AXES, describe, variant_labels


def test_labels_name_only_the_axes_that_differ():
    flat = describe(load_scene("cylinder-cone").with_overrides(shading="flat"))
    phong = describe(load_scene("cylinder-cone").with_overrides(shading="phong"))
    assert variant_labels([flat, phong]) == ["flat", "Phong"]
    assert variant_labels([flat, flat]) == ["figure", "figure"]


def test_every_axis_describes_every_preset_in_json_values():
    for name in ("camera-lights", "translucent-two", "separate-specular", "spot-attenuation", "textbook-icosahedron"):
        d = describe(load_scene(name))
        assert set(d) == set(AXES) and all(isinstance(v, (str, int)) for v in d.values())
    assert describe(load_scene("spot-attenuation"))["lights"] == "spot+directional"
    assert describe(load_scene("textbook-icosahedron"))["colour"] == "white+red"
