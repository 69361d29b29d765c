"""Light sets: named groups of lights a sweep swaps into every source (grid key ``lights``).

Each set replaces the scene's own lights. All but ``headlight`` are camera lights (VTK's
``LightTypeToCameraLight``: position and focal point in the camera's frame, (0, 0, 1) at
the camera and (0, 0, 0) at the focal point, lengths in camera distances), so a set lights
the visible side of any source however its camera is placed. Colours are linear 0..1 RGB,
quantised to k/255 as a scene file's are; cone angles are half-angles in degrees.

Add a set by adding an entry to :data:`LIGHT_SETS`; ``scanlab sweep --help`` lists them.

Examples
--------
>>> [light.kind for light in LIGHT_SETS["key-fill"].lights]
['camera', 'camera']
"""
from __future__ import annotations

from typing import NamedTuple

from lab.validation import quantise_colour
from lab.scene import Light, headlight


class LightSet(NamedTuple):
    """A named group of lights and one line saying what it is."""

    lights: tuple[Light, ...]
    description: str


def _camera_light(position, color=(1.0, 1.0, 1.0), **kwargs) -> Light:
    """A camera light aimed at the focal point; ``position`` in camera-frame units."""
    return Light(kind="camera", position=position, color=quantise_colour(color), **kwargs)


LIGHT_SETS: dict[str, LightSet] = {
    "headlight": LightSet((headlight(),), "VTK's default: one white light at the camera"),
    "key": LightSet((_camera_light((-1.0, 1.0, 1.0)),), "one white directional light from the upper left"),
    "key-fill": LightSet((_camera_light((-1.0, 1.0, 1.0), intensity=0.85),
                          _camera_light((1.0, -0.3, 1.0), (0.6, 0.7, 1.0), intensity=0.4)),
                         "a white key light and a dim blue fill from the lower right"),
    "point": LightSet((_camera_light((0.4, 0.5, 0.9), positional=True, attenuation=(1.0, 0.1, 0.0)),),
                      "one positional light near the camera, with linear attenuation"),
    "spot": LightSet((_camera_light((0.3, 0.6, 1.0), positional=True, cone_angle=6.0, exponent=2.0),
                      Light(kind="headlight", intensity=0.2)),
                     "a 6° spot light (exponent 2) aimed at the focal point, its edge across a framed "
                     "object, and a dim headlight"),
    "rgb": LightSet((_camera_light((-1.0, 0.5, 1.0), (1.0, 0.2, 0.2), intensity=0.7),
                     _camera_light((1.0, 0.5, 1.0), (0.2, 1.0, 0.2), intensity=0.7),
                     _camera_light((0.0, -1.0, 1.0), (0.2, 0.2, 1.0), intensity=0.7)),
                    "three coloured directional lights (red, green, blue) from three sides"),
}
"""Light sets by name, in the order ``--help`` lists them."""
