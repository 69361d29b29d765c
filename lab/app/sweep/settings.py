"""The grid keys: the settings a sweep crosses over every source, one registry entry each.

A grid key reads its values from text (``--grid shading=flat,phong`` or a grid file), checks
them once, at the edge, and turns each into its canonical text (``256X192`` → ``256x192``,
``0.50`` → ``0.5``), so that a case is named the same way however it was typed (a case's
identity is its source and these texts: :mod:`lab.app.sweep.cases`). In the worker, the key
applies its value to a loaded scene.

Keys that change the scene override every object (shading, model, opacity, normals) or the
scene-wide settings (size, interpolation, transparency, hidden surfaces, lights); the key
``reference`` changes only what the scene is compared with (``compare --reference``).

The key ``fault`` exists only when the environment has ``SCANLAB_SWEEP_TEST_FAULTS=1``: it is
for tests, which use it to make a case hang, crash or run out of memory on purpose
(:mod:`lab.app.sweep.faults`).
"""
from __future__ import annotations

import difflib
import os
from dataclasses import dataclass, replace
from typing import Callable

from lab.app.sweep.light_sets import LIGHT_SETS
from lab.loading import MAX_SIZE
from lab.normals import NORMAL_MODES, with_normals
from lab.scene import HIDDEN_SURFACES, INTERPOLATIONS, MODELS, SHADINGS, TRANSPARENCIES, Scene

TEST_FAULTS_ENV = "SCANLAB_SWEEP_TEST_FAULTS"
"""Set to 1 to enable the test-only grid key ``fault``."""

REFERENCES = ("auto", "vtk-native")
"""``auto``: the reference ``scanlab compare`` picks per object; ``vtk-native``: VTK's own shading."""


@dataclass(frozen=True)
class GridKey:
    """One setting a sweep can cross.

    ``values`` is the one-line description ``--help`` prints; ``parse`` turns one value's
    text into its canonical text or raises ValueError with a short reason; ``apply`` returns
    the scene with that value (the scene itself for keys that change no scene).
    """

    values: str
    parse: Callable[[str], str]
    apply: Callable[[Scene, str], Scene]


def _choice(choices) -> Callable[[str], str]:
    def parse(text: str) -> str:
        if text not in choices:
            near = difflib.get_close_matches(text, choices, n=1)
            hint = f" (did you mean {near[0]}?)" if near else ""
            raise ValueError(f"{text!r} is not one of {', '.join(choices)}{hint}")
        return text
    return parse


def _parse_size(text: str) -> str:
    try:
        w, h = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise ValueError(f"expected WIDTHxHEIGHT such as 256x192, got {text!r}") from None
    if not (1 <= w <= MAX_SIZE and 1 <= h <= MAX_SIZE):
        raise ValueError(f"{text!r}: width and height must lie in 1..{MAX_SIZE}")
    return f"{w}x{h}"


def _parse_opacity(text: str) -> str:
    try:
        value = float(text)
    except ValueError:
        raise ValueError(f"expected a number in (0, 1], got {text!r}") from None
    if not 0.0 < value <= 1.0:
        raise ValueError(f"{text!r} is outside (0, 1]")
    return repr(value)


def _render(field: str) -> Callable[[Scene, str], Scene]:
    return lambda scene, value: replace(scene, render=replace(scene.render, **{field: value}))


def _objects(change: Callable) -> Callable[[Scene, str], Scene]:
    """Apply ``change(object, value) -> object`` to every object of the scene."""
    return lambda scene, value: replace(scene, objects=tuple(change(o, value) for o in scene.objects))


def _no_change(scene: Scene, value: str) -> Scene:
    return scene


GRID_KEYS: dict[str, GridKey] = {
    "shading": GridKey(", ".join(SHADINGS), _choice(SHADINGS), lambda s, v: s.with_overrides(shading=v)),
    "model": GridKey(", ".join(MODELS), _choice(MODELS), lambda s, v: s.with_overrides(model=v)),
    "size": GridKey("WIDTHxHEIGHT in pixels, e.g. 256x192", _parse_size,
                    lambda s, v: s.with_overrides(size=tuple(int(x) for x in v.split("x")))),
    "lights": GridKey(", ".join(LIGHT_SETS) + " (replace the scene's lights)", _choice(tuple(LIGHT_SETS)),
                      lambda s, v: replace(s, lights=LIGHT_SETS[v].lights)),
    "interpolation": GridKey(", ".join(INTERPOLATIONS), _choice(INTERPOLATIONS), _render("interpolation")),
    "transparency": GridKey(", ".join(TRANSPARENCIES) + " (with opacity < 1)", _choice(TRANSPARENCIES),
                            _render("transparency")),
    "hidden_surface": GridKey(", ".join(HIDDEN_SURFACES), _choice(HIDDEN_SURFACES), _render("hidden_surface")),
    "opacity": GridKey("a number in (0, 1], every object's", _parse_opacity,
                       _objects(lambda o, v: replace(o, material=replace(o.material, opacity=float(v))))),
    "normals": GridKey(", ".join(NORMAL_MODES) + " (point normals of every mesh)", _choice(NORMAL_MODES),
                       _objects(lambda o, v: replace(o, mesh=with_normals(o.mesh, v)))),
    "reference": GridKey(", ".join(REFERENCES) + " (what ours is compared with)", _choice(REFERENCES), _no_change),
}
"""The grid keys by name, in the order ``--help`` lists them and cases cross them."""


def _fault_key() -> GridKey:
    from lab.app.sweep.faults import FAULTS

    return GridKey(", ".join(FAULTS) + " (tests only)", _choice(tuple(FAULTS)), _no_change)


def grid_keys() -> dict[str, GridKey]:
    """The keys a grid may use here: :data:`GRID_KEYS`, plus ``fault`` when
    ``SCANLAB_SWEEP_TEST_FAULTS=1`` (tests only)."""
    if os.environ.get(TEST_FAULTS_ENV) == "1":
        return {**GRID_KEYS, "fault": _fault_key()}
    return GRID_KEYS


def apply_settings(scene: Scene, settings: dict[str, str]) -> Scene:
    """``scene`` with every setting applied (values already canonical); ``fault`` is left to
    the case's process (:mod:`lab.app.sweep.faults`)."""
    for name, value in settings.items():
        if name != "fault":
            scene = GRID_KEYS[name].apply(scene, value)
    return scene
