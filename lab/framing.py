"""One mesh shown as a whole scene: a built-in shape (``icosphere:level=3``) or a mesh file
given where a scene is expected (``scanlab info suzanne.obj``).

Both are framed the same way (:func:`framed_scene`): a grey-blue material, flat shading, a
camera that frames the mesh as ``vtkRenderer::ResetCamera`` would (:func:`default_camera`)
and one headlight. Shape names and parameters are checked here (:func:`make_shape`), with
one-line :class:`lab.validation.SceneError` messages; a mesh file is read by
:func:`lab.meshfiles.read_mesh`, whose one-line errors become SceneErrors too.
"""
from __future__ import annotations

import inspect
import math
from pathlib import Path

import numpy as np

from lab import shapes
from lab.mesh import Mesh
from lab.scene import Camera, Image, Material, Scene, SceneObject, headlight
from lab.suggest import did_you_mean
from lab.validation import SceneError, quantise_colour
from lab.values import IS_A_FOLDER, MAX_MAGNITUDE, file_problem, real, show


def make_shape(name, params: dict, where=None) -> Mesh:
    """Build a built-in shape by name with keyword parameters, checking both.

    ``where(message)`` makes the exception to raise (so a scene file can name its key).
    """
    err = where or SceneError
    if not isinstance(name, str) or name not in shapes.SHAPES:
        hint = did_you_mean(name, shapes.SHAPES) if isinstance(name, str) else ""
        raise err(f"unknown shape {show(name)}{hint}; valid: {', '.join(shapes.SHAPES)}")
    sig = inspect.signature(shapes.SHAPES[name])
    for key, value in params.items():
        if key not in sig.parameters:
            raise err(f"{name} has no parameter {show(key)}{did_you_mean(str(key), sig.parameters)}; "
                      f"valid: {', '.join(sig.parameters)}")
        default = sig.parameters[key].default
        lo, hi = shapes.PARAM_RANGES.get((name, key), (0, 8))
        if isinstance(default, int) and (not isinstance(value, int) or isinstance(value, bool) or not lo <= value <= hi):
            raise err(f"{name}: {key} must be a whole number in {lo}..{hi}, got {show(value)}")
        if isinstance(default, float) and not 0 < (real(value) or 0) <= MAX_MAGNITUDE:
            raise err(f"{name}: {key} must be a positive number up to {MAX_MAGNITUDE:g}, got {show(value)}")
    return shapes.SHAPES[name](**params)


def parse_shape_spec(spec: str) -> tuple[str, dict]:
    """``"icosphere:level=3,radius=2"`` → ``("icosphere", {"level": 3, "radius": 2.0})``."""
    name, _, rest = spec.partition(":")
    params = {}
    for item in filter(None, rest.split(",")):
        key, eq, value = item.partition("=")
        if not eq:
            raise SceneError(f"{spec}: expected key=value, got {item!r}")
        try:
            params[key.strip()] = int(value)
        except ValueError:
            try:
                params[key.strip()] = float(value)
            except ValueError:
                raise SceneError(f"{spec}: {key}: expected a number, got {value!r}") from None
    return name.strip(), params


def default_camera(bounds: np.ndarray, view_angle: float = 30.0) -> Camera:
    """A camera that frames ``bounds`` the way ``vtkRenderer::ResetCamera`` does.

    Focal point at the bounds' centre; distance = radius / sin(view_angle / 2) with radius
    half the bounds' diagonal; looking from the direction (1, 0.8, 1.6) with y up.
    """
    lo, hi = bounds[0::2], bounds[1::2]
    centre = (lo + hi) / 2.0
    radius = max(float(np.linalg.norm(hi - lo)) / 2.0, 1e-6)
    dist = radius / math.sin(math.radians(view_angle) / 2.0)
    direction = np.array([1.0, 0.8, 1.6]) / np.linalg.norm([1.0, 0.8, 1.6])
    return Camera(position=tuple(centre + dist * direction), focal_point=tuple(centre), view_up=(0.0, 1.0, 0.0),
                  view_angle=view_angle)


def shape_scene(spec: str) -> Scene:
    """A scene of one built-in shape: grey-blue material, default camera, one headlight."""
    name, params = parse_shape_spec(spec)
    mesh = make_shape(name, params, where=lambda m: SceneError(f"{spec}: {m}"))
    return framed_scene(mesh, name, spec)


def framed_scene(mesh: Mesh, name: str, source: str, inputs: tuple[str, ...] = ()) -> Scene:
    """One mesh as a scene, the way a built-in shape or a mesh file given as SCENE is shown:
    grey-blue material (ambient 0.1, diffuse 0.8, specular 0.3, power 20), flat shading,
    :func:`default_camera` around it, one headlight, 512×384 on white."""
    mat = Material(color=quantise_colour((0.6, 0.7, 0.9)), ambient=0.1, diffuse=0.8, specular=0.3,
                   specular_power=20.0)
    obj = SceneObject(mesh=mesh, material=mat, name=name)
    cam = default_camera(obj.world_bounds())
    return Scene(image=Image(), camera=cam, lights=(headlight(),), objects=(obj,), source=source, inputs=inputs)


def mesh_file_scene(path) -> Scene:
    """The scene of one mesh file, framed with a headlight; SceneError if it cannot be read.

    >>> from lab.presets import SCENES_DIR
    >>> mesh_file_scene(SCENES_DIR / "models" / "torus.ply").objects[0].name
    'torus'
    """
    from lab.meshfiles import MeshFileError, read_mesh

    path = Path(path)
    if file_problem(path) == IS_A_FOLDER:
        raise SceneError(f"{path}: is a folder, not a scene file or mesh file")
    try:
        mesh = read_mesh(path)
    except MeshFileError as exc:
        raise SceneError(str(exc)) from None
    return framed_scene(mesh, path.stem, str(path), inputs=(str(path),))
