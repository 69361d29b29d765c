"""The state model of the live lab: everything its controls set, and the one edge where it
becomes something to draw.

:class:`Controls` holds the values exactly as the browser sent them (a number typed into a
field arrives as text; a slider sends a number). :func:`to_render` is the only place they
are read: every value is checked there, with the scene loader's ranges, and the result is
a :class:`Render` (the intact :class:`lab.scene.Scene` VTK draws, our
:class:`renderer.RenderOptions` and the "break it" entry) or :class:`Problems`, one
:class:`Problem` per field, which the page shows beside the field (never a traceback).

Conventions: colours travel as ``#rrggbb`` (8-bit sRGB codes read as linear 0..1 values
k/255, as the scene files' colours are quantised); vectors as lists of three numbers in
world space (a camera light's in the camera's frame, see :class:`lab.scene.Light`);
angles in degrees. A field's *path* names it in :class:`Problems`: ``camera.view_angle``,
``lights.1.intensity``, ``materials.0.opacity``, ``shape_params.level``.

The state is the trame state's keys (:data:`KEYS`); lists of lights and materials are
plain dicts so the page can bind its fields to them.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace
from typing import NamedTuple

import numpy as np

from lab.scene import (HIDDEN_SURFACES, INTERPOLATIONS, LIGHT_KINDS, LIGHT_RANGES, MATERIAL_RANGES, MODELS, SHADINGS,
                       TRANSPARENCIES, Camera, Light, Scene)
from lab.values import MAX_MAGNITUDE
from renderer.breakages import BREAKAGES, apply_breakage
from renderer.pipeline import RenderOptions

SIZES = ("256x256", "512x512", "640x480", "800x600", "scene")
"""Image sizes on offer; "scene" keeps the scene's own."""
DEFAULT_SIZE = "512x512"
AS_SCENE = "scene"
"""Shading or model: each object's own, as the scene says."""
NO_BREAKAGE = "none"
"""No rule broken."""
MAX_LIGHTS = 8



class Problem(NamedTuple):
    """Why a field's value cannot be used: a ``code`` the page words in its language
    (:mod:`lab.app.live.wording`) and the numbers or text the words need."""

    code: str
    args: tuple = ()


class Problems(Exception):
    """Fields that cannot be used: ``found`` maps each field's path to its :class:`Problem`."""

    def __init__(self, found: dict[str, Problem]):
        super().__init__("; ".join(f"{path}: {p.code}" for path, p in found.items()))
        self.found = found


@dataclass(frozen=True)
class Controls:
    """What the controls set, as sent (unchecked). See the module docstring."""

    source: str = "preset:course-phong"
    shape_params: dict = field(default_factory=dict)
    size: str = DEFAULT_SIZE
    shading: str = AS_SCENE
    model: str = AS_SCENE
    interpolation: str = "perspective"
    hidden_surface: str = "zbuffer"
    cull_backfaces: bool = False
    transparency: str = "oit"
    separate_specular: bool = False
    materials: list = field(default_factory=list)
    lights: list = field(default_factory=list)
    camera: dict = field(default_factory=dict)
    breakage: str = NO_BREAKAGE

    @classmethod
    def from_state(cls, state) -> "Controls":
        """The controls among a state's keys (a mapping or a trame ``State``)."""
        return cls(**{k: state[k] for k in KEYS})

    def to_state(self) -> dict:
        return {k: getattr(self, k) for k in KEYS}


KEYS = tuple(f.name for f in fields(Controls))
"""The state keys the controls own: a change of any of them asks for new images."""


class Render(NamedTuple):
    """Checked controls: the intact ``scene`` (VTK's, and the one saved), our ``options`` and
    the ``breakage`` name ("" for none)."""

    scene: Scene
    options: RenderOptions
    breakage: str

    def ours(self) -> tuple[Scene, RenderOptions]:
        """What our renderer draws: the scene and options with the breakage applied."""
        if not self.breakage:
            return self.scene, self.options
        return apply_breakage(self.breakage, self.scene, self.options)


# --------------------------------------------------------------------------- from a scene
def hex_colour(rgb) -> str:
    """Linear 0..1 RGB (on the k/255 grid) → ``#rrggbb``."""
    return "#" + "".join(f"{round(float(c) * 255):02x}" for c in rgb)


def _same(values) -> str:
    values = set(values)
    return values.pop() if len(values) == 1 else AS_SCENE


def light_controls(light: Light) -> dict:
    """A light as the page edits it (the OpenGL-only colours carried along unseen)."""
    extra = {k: None if v is None else list(v) for k, v in (("ambient_color", light.ambient_color),
                                                           ("diffuse_color", light.diffuse_color),
                                                           ("specular_color", light.specular_color))}
    return {"kind": light.kind, "position": list(light.position), "focal_point": list(light.focal_point),
            "color": hex_colour(light.color), "intensity": light.intensity, "positional": light.positional,
            "cone_angle": light.cone_angle, "exponent": light.exponent, "attenuation": list(light.attenuation),
            "on": light.on, **extra}


def new_light() -> dict:
    """The light "Add" makes: a white scene light up, right and in front of the origin."""
    return light_controls(Light(kind="scene", position=(1.0, 1.0, 1.0)))


def camera_controls(camera: Camera) -> dict:
    return {"position": list(camera.position), "focal_point": list(camera.focal_point),
            "view_up": list(camera.view_up), "view_angle": camera.view_angle, "parallel": camera.parallel,
            "parallel_scale": camera.parallel_scale}


def controls_for(scene: Scene, source: str, shape_params: dict | None = None, keep: Controls | None = None) -> Controls:
    """The controls showing ``scene`` as loaded; ``keep`` carries over the size and the
    breakage (the choices that are not the scene's)."""
    r = scene.render
    materials = [{"color": hex_colour(o.material.color), **{k: getattr(o.material, k) for k in MATERIAL_RANGES}}
                 for o in scene.objects]
    return Controls(source=source, shape_params=dict(shape_params or {}),
                    size=keep.size if keep else DEFAULT_SIZE, breakage=keep.breakage if keep else NO_BREAKAGE,
                    shading=_same(o.shading for o in scene.objects),
                    model=_same(o.material.model for o in scene.objects),
                    interpolation=r.interpolation, hidden_surface=r.hidden_surface, cull_backfaces=r.cull_backfaces,
                    transparency=r.transparency, separate_specular=r.separate_specular, materials=materials,
                    lights=[light_controls(li) for li in scene.lights], camera=camera_controls(scene.camera))


# --------------------------------------------------------------------------- the edge
class _Reader:
    """Reads raw values, collecting a :class:`Problem` per bad field instead of stopping."""

    def __init__(self):
        self.found: dict[str, Problem] = {}

    def number(self, path: str, raw, lo=-MAX_MAGNITUDE, hi=MAX_MAGNITUDE, lo_open=False, hi_open=False):
        value = _as_number(raw)
        if value is None:
            self.found[path] = Problem("number")
        elif value < lo or value > hi or (lo_open and value == lo) or (hi_open and value == hi):
            self.found[path] = Problem("range", (f"{lo:g}", f"{hi:g}", "(" if lo_open else "[", ")" if hi_open else "]"))
        else:
            return value
        return None

    def vector(self, path: str, raw, lo=-MAX_MAGNITUDE, hi=MAX_MAGNITUDE):
        if not isinstance(raw, (list, tuple)) or len(raw) != 3:
            self.found[path] = Problem("vector")
            return None
        values = [self.number(f"{path}.{i}", v, lo, hi) for i, v in enumerate(raw)]
        return None if None in values else tuple(values)

    def choice(self, path: str, raw, choices, blank: str | None = None):
        """One of ``choices``; ``blank`` (a word meaning "none of them") gives ""."""
        if blank is not None and raw == blank:
            return ""
        if isinstance(raw, str) and raw in choices:
            return raw
        self.found[path] = Problem("choice", (str(raw)[:40],))
        return None

    def flag(self, path: str, raw):
        if isinstance(raw, bool):
            return raw
        self.found[path] = Problem("flag")
        return None

    def colour(self, path: str, raw):
        """``#rrggbb`` (or ``#rrggbbaa``, the alpha ignored) → k/255 triple."""
        if isinstance(raw, str) and len(raw) in (7, 9) and raw[0] == "#":
            try:
                return tuple(int(raw[i:i + 2], 16) / 255.0 for i in (1, 3, 5))
            except ValueError:
                pass
        self.found[path] = Problem("colour")
        return None

    def optional_colour(self, path: str, raw):
        """A colour kept from the scene file, or None (a list of three numbers in 0..1)."""
        if raw is None:
            return None
        c = self.vector(path, raw, 0.0, 1.0)
        return None if c is None else tuple(round(x * 255.0) / 255.0 for x in c)


def _as_number(raw) -> float | None:
    """A finite number from a number or a text field's text; None if it is not one."""
    if isinstance(raw, bool):
        return None
    if isinstance(raw, str):
        try:
            raw = float(raw.strip().replace(",", "."))
        except ValueError:
            return None
    if isinstance(raw, (int, float)) and math.isfinite(raw):
        return float(raw)
    return None


def to_render(controls: Controls, base: Scene) -> Render:
    """The controls checked and applied to ``base`` (the scene as loaded): a :class:`Render`,
    or :class:`Problems` naming every field that cannot be used."""
    read = _Reader()
    size = _size(read, controls.size, base)
    shading = read.choice("shading", controls.shading, SHADINGS, blank=AS_SCENE)
    model = read.choice("model", controls.model, MODELS, blank=AS_SCENE)
    render = replace(base.render, interpolation=read.choice("interpolation", controls.interpolation, INTERPOLATIONS),
                     hidden_surface=read.choice("hidden_surface", controls.hidden_surface, HIDDEN_SURFACES),
                     cull_backfaces=read.flag("cull_backfaces", controls.cull_backfaces),
                     transparency=read.choice("transparency", controls.transparency, TRANSPARENCIES),
                     separate_specular=read.flag("separate_specular", controls.separate_specular))
    objects = _objects(read, controls.materials, base, shading, model)
    lights = _lights(read, controls.lights)
    camera = _camera(read, controls.camera, base.camera)
    breakage = read.choice("breakage", controls.breakage, BREAKAGES, blank=NO_BREAKAGE)
    if read.found:
        raise Problems(read.found)
    scene = replace(base, image=replace(base.image, size=size), render=render, objects=objects, lights=lights,
                    camera=camera)
    return Render(scene, RenderOptions(), breakage)


def _size(read: _Reader, raw, base: Scene):
    if read.choice("size", raw, SIZES) is None:
        return None
    if raw == "scene":
        return base.image.size
    w, h = raw.split("x")
    return int(w), int(h)


def _objects(read: _Reader, materials, base: Scene, shading, model) -> tuple:
    if not isinstance(materials, list) or len(materials) != len(base.objects):
        read.found["materials"] = Problem("objects", (len(base.objects),))
        return base.objects
    objects = []
    for i, (raw, obj) in enumerate(zip(materials, base.objects)):
        if not isinstance(raw, dict):
            read.found[f"materials.{i}"] = Problem("objects", (len(base.objects),))
            continue
        values = {k: read.number(f"materials.{i}.{k}", raw.get(k), lo, hi) for k, (lo, hi) in MATERIAL_RANGES.items()}
        colour = read.colour(f"materials.{i}.color", raw.get("color"))
        material = replace(obj.material, color=colour, **values)
        if model:
            material = replace(material, model=model)
        objects.append(replace(obj, material=material, shading=shading or obj.shading))
    return tuple(objects)


def _lights(read: _Reader, lights) -> tuple:
    if not isinstance(lights, list) or len(lights) > MAX_LIGHTS:
        read.found["lights"] = Problem("lights", (MAX_LIGHTS,))
        return ()
    out = []
    for i, raw in enumerate(lights):
        p = f"lights.{i}"
        if not isinstance(raw, dict):
            read.found[p] = Problem("lights", (MAX_LIGHTS,))
            continue
        attenuation = read.vector(f"{p}.attenuation", raw.get("attenuation"), 0.0)
        if attenuation is not None and sum(attenuation) <= 0:
            read.found[f"{p}.attenuation"] = Problem("attenuation")
        out.append(Light(kind=read.choice(f"{p}.kind", raw.get("kind"), LIGHT_KINDS),
                         position=read.vector(f"{p}.position", raw.get("position")),
                         focal_point=read.vector(f"{p}.focal_point", raw.get("focal_point")),
                         color=read.colour(f"{p}.color", raw.get("color")),
                         intensity=read.number(f"{p}.intensity", raw.get("intensity"), *LIGHT_RANGES["intensity"]),
                         positional=read.flag(f"{p}.positional", raw.get("positional")),
                         cone_angle=read.number(f"{p}.cone_angle", raw.get("cone_angle"), 0.0, 180.0, lo_open=True),
                         exponent=read.number(f"{p}.exponent", raw.get("exponent"), *LIGHT_RANGES["exponent"]),
                         attenuation=attenuation, on=read.flag(f"{p}.on", raw.get("on")),
                         ambient_color=read.optional_colour(f"{p}.ambient_color", raw.get("ambient_color"))
                         or (0.0, 0.0, 0.0),
                         diffuse_color=read.optional_colour(f"{p}.diffuse_color", raw.get("diffuse_color")),
                         specular_color=read.optional_colour(f"{p}.specular_color", raw.get("specular_color"))))
    return tuple(out)


def _camera(read: _Reader, raw, base: Camera) -> Camera:
    if not isinstance(raw, dict):
        read.found["camera"] = Problem("vector")
        return base
    position = read.vector("camera.position", raw.get("position"))
    focal = read.vector("camera.focal_point", raw.get("focal_point"))
    up = read.vector("camera.view_up", raw.get("view_up"))
    if position is not None and focal is not None and up is not None:
        d = np.subtract(position, focal)
        if np.linalg.norm(d) == 0:
            read.found["camera.position"] = Problem("camera_at_focus")
        elif np.linalg.norm(np.cross(up, d)) <= 1e-12 * np.linalg.norm(d) * max(np.linalg.norm(up), 1e-300):
            read.found["camera.view_up"] = Problem("camera_up")
    return replace(base, position=position, focal_point=focal, view_up=up,
                   view_angle=read.number("camera.view_angle", raw.get("view_angle"), 0.0, 180.0, True, True),
                   parallel=read.flag("camera.parallel", raw.get("parallel")),
                   parallel_scale=read.number("camera.parallel_scale", raw.get("parallel_scale"), 0.0,
                                              lo_open=True))
