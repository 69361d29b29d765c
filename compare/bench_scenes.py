"""The benchmark set of ``scanlab bench``: named scenes, each drawable at any image size.

Issue 15's default set: icosphere levels 5 and 7 lit by one scene light (phong, VTK's
``pow`` of r·v at every pixel) and by a headlight (flat); Menger sponges of levels 3 and
4 (flat); a cylinder of 1,024 segments (gouraud); the ``translucent-three`` and
``textured-sphere`` presets; a public scanned mesh of 268,686 triangles (the Igea
artefact, from alecjacobson/common-3d-test-models) and the same mesh subdivided once into
1,074,744 triangles. Every scene is built from its name and an image size
(:func:`bench_scene`); anything else ``scanlab`` can load (a preset, a shape spec, a scene
file) may be benchmarked too.

The public mesh is not stored in git: :func:`public_mesh` downloads it once into
:func:`mesh_cache` (``out/bench-meshes/`` beside the sources, gitignored, or
``$SCANLAB_BENCH_MESHES``), converts its triangle strips to triangles and keeps the
result there as ``igea-triangles.npz``. Where nothing can be downloaded, copy ``igea.ply``
into that folder by hand; until then the two mesh scenes are reported as unavailable.
"""
from __future__ import annotations

import os
import urllib.request
from dataclasses import replace
from pathlib import Path

import numpy as np

import lab.atomic
from lab.framing import default_camera
from lab.loading import scene_from_dict
from lab.mesh import Mesh, strip_triangles
from lab.normals import angle_weighted_normals
from lab.scene import Image, Light, Material, Scene, SceneObject
from lab.shapes import split_in_four

IGEA_URL = "https://raw.githubusercontent.com/alecjacobson/common-3d-test-models/master/data/igea.ply"
"""A public scanned model (134,345 vertices, one PLY ``tristrips`` element)."""

DEFAULT_SIZES = ((512, 512), (1024, 1024))


class MeshUnavailable(RuntimeError):
    """The public mesh is neither cached nor downloadable here."""


def mesh_cache() -> Path:
    """Where downloaded benchmark meshes live: ``$SCANLAB_BENCH_MESHES``, else
    ``out/bench-meshes`` in the source tree (``out/`` is gitignored)."""
    override = os.environ.get("SCANLAB_BENCH_MESHES")
    return Path(override) if override else Path(__file__).resolve().parents[1] / "out" / "bench-meshes"


def strips_to_triangles(strips: np.ndarray) -> np.ndarray:
    """PLY triangle strips (vertex indices, −1 between strips) → (T, 3) triangles, wound as
    :func:`lab.mesh.strip_triangles` winds a strip (every triangle keeps the strip's winding);
    triangles with a repeated vertex (the strips' joins) are dropped."""
    strips = np.asarray(strips, np.int64)
    breaks = np.flatnonzero(strips < 0)
    connectivity = strips[strips >= 0]
    offsets = np.concatenate([[0], breaks - np.arange(len(breaks)), [len(connectivity)]])
    tri = strip_triangles(offsets, connectivity)
    keep = (tri[:, 0] != tri[:, 1]) & (tri[:, 1] != tri[:, 2]) & (tri[:, 0] != tri[:, 2])
    return tri[keep]


def read_strip_ply(data: bytes) -> Mesh:
    """A binary little-endian PLY of float x, y, z vertices and one ``tristrips`` element
    (``list int int vertex_indices``), as the Igea file is."""
    mark = data.find(b"end_header\n")
    end = mark + len(b"end_header\n")
    header = data[:end].decode("ascii", "replace").splitlines() if mark >= 0 else []
    if "format binary_little_endian 1.0" not in header:
        raise MeshUnavailable("the public mesh is not the binary PLY expected")
    n_vertices = next(int(line.split()[2]) for line in header if line.startswith("element vertex"))
    points = np.frombuffer(data, "<f4", n_vertices * 3, end).reshape(-1, 3).astype(np.float64)
    at = end + n_vertices * 12
    count = int(np.frombuffer(data, "<i4", 1, at)[0])
    strips = np.frombuffer(data, "<i4", count, at + 4)
    return Mesh(points, strips_to_triangles(strips))


def public_mesh() -> Mesh:
    """The Igea mesh as triangles, from the cache, downloaded once if missing."""
    cache = mesh_cache()
    converted = cache / "igea-triangles.npz"
    if converted.exists():
        with np.load(converted) as f:
            return Mesh(f["points"], f["triangles"])
    source = cache / "igea.ply"
    if not source.exists():
        try:
            with urllib.request.urlopen(IGEA_URL, timeout=30) as response:
                data = response.read()
        except OSError as exc:
            raise MeshUnavailable(f"cannot download the public mesh ({exc}); copy igea.ply into {cache}") from None
        cache.mkdir(parents=True, exist_ok=True)
        with lab.atomic.atomic_file(source) as f:
            f.write(data)
    mesh = read_strip_ply(source.read_bytes())
    cache.mkdir(parents=True, exist_ok=True)
    with lab.atomic.atomic_file(converted) as f:
        np.savez(f, points=mesh.points, triangles=mesh.triangles)
    return mesh


def subdivide(mesh: Mesh) -> Mesh:
    """Every triangle split into four at its edge midpoints (:func:`lab.shapes.split_in_four`),
    the points left where they are: 4× the triangles, the same surface."""
    mid, triangles = split_in_four(mesh.points, mesh.triangles)
    return Mesh(np.concatenate([mesh.points, mid]), triangles)


def _mesh_scene(mesh: Mesh, name: str, size) -> Scene:
    """A scanned mesh with angle-weighted point normals, phong, one scene light, the
    default camera (the whole mesh in view)."""
    mesh = replace(mesh, point_normals=angle_weighted_normals(mesh))
    obj = SceneObject(mesh=mesh, material=Material(color=(0.8, 0.75, 0.7), ambient=0.1, diffuse=0.8, specular=0.3,
                                                   specular_power=20.0), shading="phong", name=name)
    light = Light(kind="scene", position=(3.0, 4.0, 5.0))
    return Scene(image=Image(size=tuple(size)), camera=default_camera(obj.world_bounds()), lights=(light,),
                 objects=(obj,), source=name)


def _shape_scene(name: str, size, obj: dict, light: dict, camera: dict) -> Scene:
    return scene_from_dict({"image": {"size": list(size), "background": [1.0, 1.0, 1.0]}, "camera": camera,
                            "light": [light], "object": [obj]}, source=name, allow_large=True)


SCENE_LIGHT = {"kind": "scene", "position": [3.0, 4.0, 5.0]}
HEADLIGHT = {"kind": "headlight"}
SPHERE_CAMERA = {"position": [1.2, 1.0, 2.6], "focal_point": [0.0, 0.0, 0.0], "view_up": [0.0, 1.0, 0.0],
                 "view_angle": 30.0}
SPONGE_CAMERA = {"position": [1.6, 1.3, 2.2], "focal_point": [0.0, 0.0, 0.0], "view_up": [0.0, 1.0, 0.0],
                 "view_angle": 30.0}
MATERIAL = {"color": [0.6, 0.7, 0.9], "ambient": 0.1, "diffuse": 0.8, "specular": 0.3, "specular_power": 20.0}


def _icosphere(level: int, phong: bool):
    def build(size):
        obj = {"shape": "icosphere", "params": {"level": level}, **MATERIAL}
        if phong:
            obj.update(normals="radial", shading="phong")
        name = f"ico{level}-{'phong' if phong else 'flat'}"
        return _shape_scene(name, size, obj, SCENE_LIGHT if phong else HEADLIGHT, SPHERE_CAMERA)
    return build


def _menger(level: int):
    def build(size):
        obj = {"shape": "menger", "params": {"level": level}, **MATERIAL, "color": [0.85, 0.6, 0.3]}
        return _shape_scene(f"menger{level}", size, obj, HEADLIGHT, SPONGE_CAMERA)
    return build


def _cylinder(size):
    obj = {"shape": "cylinder", "params": {"segments": 1024}, "normals": "computed", "crease_angle": 60.0,
           "shading": "gouraud", **MATERIAL, "rotate": [60.0, 0.0, 20.0]}
    return _shape_scene("cylinder1024", size, obj, SCENE_LIGHT, {**SPHERE_CAMERA, "position": [1.6, 1.3, 3.4]})


def _preset(name: str):
    def build(size):
        from lab.loading import load_scene

        return load_scene(name, allow_large=True).with_overrides(size=size)
    return build


def _real(subdivisions: int):
    def build(size):
        mesh = public_mesh()
        for _ in range(subdivisions):
            mesh = subdivide(mesh)
        return _mesh_scene(mesh, "igea-1m" if subdivisions else "igea-270k", size)
    return build


BENCH_SCENES = {
    "ico5-phong": _icosphere(5, True),
    "ico5-flat": _icosphere(5, False),
    "ico7-phong": _icosphere(7, True),
    "ico7-flat": _icosphere(7, False),
    "menger3": _menger(3),
    "menger4": _menger(4),
    "cylinder1024": _cylinder,
    "translucent-three": _preset("translucent-three"),
    "textured-sphere": _preset("textured-sphere"),
    "igea-270k": _real(0),
    "igea-1m": _real(1),
}
"""Name → builder(size) of the default benchmark set (issue 15), in the order reported."""


def bench_scene(name: str, size) -> Scene:
    """The scene ``name`` of :data:`BENCH_SCENES` at ``size`` (W, H), or anything
    :func:`lab.loading.load_scene` reads, resized."""
    if name in BENCH_SCENES:
        return BENCH_SCENES[name](tuple(size))
    from lab.loading import load_scene

    return load_scene(name, allow_large=True).with_overrides(size=tuple(size))
