"""Hypothesis strategies: random valid scenes and random triangle soups.

- :func:`scene_dicts`: what a scene file may hold — a camera (perspective or parallel,
  fitted or explicit clipping range), 1–3 lights of every kind, 1–3 built-in shapes with
  random transforms, materials, shading, normals and models, back-face culling on or off.
  Built with :func:`lab.loading.scene_from_dict`, so every scene is one the loader accepts.
- :func:`soup_scenes`: a handful of random points, often repeated or collinear, joined by
  random triangles (degenerate ones included, any winding), split between two objects of
  different colours, some triangles drawn again in the second (depth ties), in front of a
  random camera; :func:`aligned_soup_scenes`: soups with corners on pixel centres, where
  the fill rule decides.

Images are small (16–80 pixels a side): the properties are about geometry, not size.
"""
from __future__ import annotations

import numpy as np
from hypothesis import assume
from hypothesis import strategies as st

from lab.loading import SceneError, scene_from_dict
from lab.mesh import Mesh
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject, headlight

coord = st.floats(-2.0, 2.0, allow_nan=False, width=32)
unit = st.floats(0.0, 1.0, allow_nan=False, width=32)
vec3 = st.tuples(coord, coord, coord).map(list)
colour = st.tuples(unit, unit, unit).map(list)
sizes = st.tuples(st.integers(16, 80), st.integers(16, 80)).map(list)


@st.composite
def directions(draw):
    """A unit vector, not too close to the y axis (so view_up = +y stays valid)."""
    v = np.array(draw(st.tuples(*[st.floats(-1, 1, allow_nan=False)] * 3)))
    n = np.linalg.norm(v)
    assume(n > 0.1)
    v = v / n
    assume(abs(v[1]) < 0.98)
    return v


@st.composite
def cameras(draw, reach: float = 1.0):
    """A camera looking at a focal point near the origin from 2–10 units (× ``reach``)."""
    focal = np.array(draw(st.tuples(coord, coord, coord))) * 0.5
    dist = draw(st.floats(2.0, 10.0)) * reach
    position = focal + dist * draw(directions())
    cam = {"position": position.tolist(), "focal_point": focal.tolist(), "view_up": [0.0, 1.0, 0.0],
           "view_angle": draw(st.floats(10.0, 80.0))}
    if draw(st.booleans()):
        cam.update(parallel=True, parallel_scale=draw(st.floats(0.5, 3.0)))
    if draw(st.booleans()):
        near = draw(st.floats(0.05, dist))
        cam["clipping_range"] = [near, near + draw(st.floats(0.5, 20.0))]
    return cam


@st.composite
def lights(draw):
    light = {"kind": draw(st.sampled_from(["scene", "camera", "headlight"])), "position": draw(vec3),
             "focal_point": draw(vec3), "color": draw(colour), "intensity": draw(st.floats(0.0, 2.0)),
             "on": draw(st.booleans())}
    assume(np.linalg.norm(np.subtract(light["position"], light["focal_point"])) > 1e-3)
    if draw(st.booleans()):
        light.update(positional=True, cone_angle=draw(st.floats(5.0, 120.0)), exponent=draw(st.floats(0.0, 4.0)),
                     attenuation=[1.0, draw(st.floats(0.0, 0.5)), draw(st.floats(0.0, 0.2))])
    return light


SHAPES = {
    "cube": st.fixed_dictionaries({}),
    "quad": st.fixed_dictionaries({}),
    "icosahedron": st.fixed_dictionaries({}),
    "icosphere": st.fixed_dictionaries({"level": st.integers(0, 2)}),
    "cylinder": st.fixed_dictionaries({"segments": st.integers(3, 16)}),
    "cone": st.fixed_dictionaries({"segments": st.integers(3, 16)}),
}


@st.composite
def objects(draw):
    shape = draw(st.sampled_from(sorted(SHAPES)))
    obj = {"shape": shape, "params": draw(SHAPES[shape]), "color": draw(colour), "ambient": draw(unit),
           "diffuse": draw(unit), "specular": draw(unit), "specular_power": draw(st.floats(0.0, 200.0)),
           "shading": draw(st.sampled_from(["flat", "gouraud", "phong"])),
           "normals": draw(st.sampled_from(["file", "computed", "face", "radial"])),
           "model": draw(st.sampled_from(["vtk", "vtk", "opengl", "classic"])),
           "lighting": draw(st.booleans()),
           "scale": draw(st.tuples(*[st.floats(0.2, 2.0)] * 3).map(list)),
           "rotate": draw(st.tuples(*[st.floats(-180.0, 180.0)] * 3).map(list)),
           "translate": draw(vec3)}
    if obj["model"] == "opengl":
        obj["shininess"] = draw(st.floats(0.0, 128.0))
    return obj


@st.composite
def scene_dicts(draw):
    data = {"image": {"size": draw(sizes), "background": draw(colour)}, "camera": draw(cameras()),
            "object": draw(st.lists(objects(), min_size=1, max_size=3)),
            "light": draw(st.lists(lights(), min_size=1, max_size=3)),
            "render": {"cull_backfaces": draw(st.booleans())}}
    return data


def scenes():
    """Random valid scenes, through the loader."""
    def build(data):
        try:
            return scene_from_dict(data, source="<hypothesis>")
        except SceneError as exc:  # the strategy should only make valid scenes: say which key
            raise AssertionError(f"the strategy made an invalid scene: {exc}") from None
    return scene_dicts().map(build)


@st.composite
def soup_scenes(draw):
    """Random triangles over a few random points: repeats, collinear triples, zero area, any winding."""
    grid = st.sampled_from([-1.0, -0.5, 0.0, 0.5, 1.0])  # shared values make collinear and repeated points
    value = st.one_of(grid, coord)
    n_points = draw(st.integers(3, 12))
    points = np.array(draw(st.lists(st.tuples(value, value, value), min_size=n_points, max_size=n_points)))
    index = st.integers(0, n_points - 1)
    triangles = np.array(draw(st.lists(st.tuples(index, index, index), min_size=1, max_size=30)))
    cam = draw(cameras())
    camera = Camera(position=tuple(cam["position"]), focal_point=tuple(cam["focal_point"]), view_up=(0.0, 1.0, 0.0),
                    view_angle=cam["view_angle"], parallel=cam.get("parallel", False),
                    parallel_scale=cam.get("parallel_scale", 1.0),
                    clipping_range=tuple(cam["clipping_range"]) if "clipping_range" in cam else None)
    light = draw(st.sampled_from([headlight(), Light(kind="scene", position=(2.0, 3.0, 4.0))]))
    w, h = draw(sizes)
    # two objects of different colours over the same points: where their triangles coincide,
    # the depth tie decides the colour, so the order of drawing shows in the image
    split = draw(st.integers(0, len(triangles)))
    copies = draw(st.lists(st.integers(0, len(triangles) - 1), max_size=6))  # coincident copies: depth ties
    triangles = np.concatenate([triangles, triangles[copies].reshape(-1, 3)])
    objects = tuple(SceneObject(mesh=Mesh(points, part), material=Material(color=c, ambient=0.1, diffuse=0.8,
                                                                           specular=0.3, specular_power=10.0))
                    for part, c in ((triangles[:split], (0.8, 0.6, 0.2)), (triangles[split:], (0.2, 0.5, 0.9)))
                    if len(part))
    return Scene(image=Image(size=(w, h), background=(0.2, 0.3, 0.4)), camera=camera, lights=(light,),
                 objects=objects, source="<soup>")


@st.composite
def aligned_soup_scenes(draw):
    """Random triangles whose corners sit exactly on pixel centres (parallel camera along −z):
    their edges pass through many pixel centres, so the fill rule decides those pixels."""
    w, h = draw(sizes)
    n_points = draw(st.integers(3, 10))
    cols = np.array(draw(st.lists(st.integers(-4, w + 3), min_size=n_points, max_size=n_points)))
    rows = np.array(draw(st.lists(st.integers(-4, h + 3), min_size=n_points, max_size=n_points)))
    z = np.array(draw(st.lists(st.sampled_from([-1.0, -0.5, 0.0, 0.5, 1.0]), min_size=n_points,
                               max_size=n_points)))
    scale = 1.0  # half the view height: a pixel is 2/h world units
    points = np.column_stack([((cols + 0.5) * 2.0 / w - 1.0) * scale * w / h, ((rows + 0.5) * 2.0 / h - 1.0) * scale,
                              z])
    index = st.integers(0, n_points - 1)
    triangles = np.array(draw(st.lists(st.tuples(index, index, index), min_size=1, max_size=20)))
    camera = Camera(position=(0.0, 0.0, 5.0), focal_point=(0.0, 0.0, 0.0), parallel=True, parallel_scale=scale,
                    clipping_range=(1.0, 10.0))
    split = draw(st.integers(0, len(triangles)))
    objects = tuple(SceneObject(mesh=Mesh(points, part), material=Material(color=c))
                    for part, c in ((triangles[:split], (0.8, 0.6, 0.2)), (triangles[split:], (0.2, 0.5, 0.9)))
                    if len(part))
    return Scene(image=Image(size=(w, h), background=(0.2, 0.3, 0.4)), camera=camera, lights=(headlight(),),
                 objects=objects, source="<aligned soup>")


def any_scene():
    """Random valid scenes, random soups and pixel-aligned soups."""
    return st.one_of(scenes(), soup_scenes(), aligned_soup_scenes())
