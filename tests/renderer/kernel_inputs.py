"""Inputs for the renderer's kernels: a light set and one-object material tables made by
hand, and the tables of every preset (:func:`preset_tables`).

Not a test file: the kernel tests build their :class:`renderer.lights.ViewLights` and
:class:`renderer.reflection.materials.Materials` here, from a few plain values.
"""
from __future__ import annotations

import numpy as np

from renderer.lights import NO_CONE, ViewLights
from renderer.reflection.materials import PIXEL_TWO_SIDED, Materials
from renderer.reflection.registry import CODES


def view_lights(lights=({},), complexity=2, global_ambient=(0.2, 0.2, 0.2), ambient_light=(1.0, 1.0, 1.0),
                local_viewer=False, separate_specular=False) -> ViewLights:
    """A :class:`ViewLights` from one dict per light, keys as its fields (``direction`` is
    normalised; defaults: a white directional light along −z, no cone, attenuation (1, 0, 0);
    the OpenGL colours default to black ambient and white diffuse and specular)."""
    k = len(lights)

    def get(key, default, width=3):
        return np.array([li.get(key, default) for li in lights], dtype=np.float64).reshape(k, width)

    direction = get("direction", (0.0, 0.0, -1.0))
    direction /= np.linalg.norm(direction, axis=1, keepdims=True)
    return ViewLights(direction=direction, position=get("position", (0.0, 0.0, 0.0)),
                      intensity_rgb=get("intensity_rgb", (1.0, 1.0, 1.0)),
                      positional=np.array([li.get("positional", False) for li in lights], np.bool_),
                      cos_cone=get("cos_cone", NO_CONE, 1).reshape(k), exponent=get("exponent", 1.0, 1).reshape(k),
                      attenuation=get("attenuation", (1.0, 0.0, 0.0)), gl_ambient=get("gl_ambient", (0.0, 0.0, 0.0)),
                      gl_diffuse=get("gl_diffuse", (1.0, 1.0, 1.0)), gl_specular=get("gl_specular", (1.0, 1.0, 1.0)),
                      complexity=complexity, global_ambient=np.asarray(global_ambient, np.float64),
                      ambient_light=np.asarray(ambient_light, np.float64), local_viewer=local_viewer,
                      separate_specular=separate_specular)


def materials(ambient, diffuse, specular, power, model="vtk", lit=True, path=PIXEL_TWO_SIDED,
              opacity=1.0) -> Materials:
    """A one-object :class:`Materials` table with the given row (object 0)."""
    row = lambda v: np.broadcast_to(np.asarray(v, np.float64), (1, 3)).copy()  # noqa: E731
    return Materials(model=np.array([CODES[model]]), shading_path=np.array([path]), lit=np.array([lit]),
                     ambient=row(ambient), diffuse=row(diffuse), specular=row(specular),
                     power=np.array([float(power)]), opacity=np.array([float(opacity)]))


def preset_tables():
    """(label, materials, textures, lights) of every preset under every shading and model (the
    tables :func:`renderer.render` hands the shading kernels)."""
    from lab.loading import load_scene
    from lab.presets import SCENES_DIR
    from renderer.camera import world_to_view
    from renderer.lights import view_lights as lights_in_view
    from renderer.reflection.registry import material_table
    from renderer.texture_sampling import texture_table

    for path in sorted(SCENES_DIR.glob("*.toml")):
        scene = load_scene(path)
        for shading in (None, "flat", "gouraud", "phong"):
            for model in (None, "opengl", "classic"):
                s = scene.with_overrides(shading=shading, model=model)
                lights = lights_in_view(s.lights, s.camera, world_to_view(s.camera), s.render)
                yield f"{path.stem}/{shading}/{model}", material_table(s), texture_table(s), lights
