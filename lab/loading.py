"""Loading scenes: TOML scene files and built-in shape names → :class:`lab.scene.Scene`.

All validation happens here, at the edge, every value read through
:class:`lab.validation.Table` (as the CSG parser reads its tree); a problem raises
:class:`SceneError` whose one-line message names the file and the key. Colours are quantised to k/255 on loading
(VTK's ``vtkColor`` keeps no more), so both renderers start from the same numbers.
"""
from __future__ import annotations

import errno
import os
import tomllib
from dataclasses import replace
from pathlib import Path

import numpy as np

from lab import shapes
from lab.mesh import Mesh
from lab.presets import preset_names, preset_path
from lab.scene import (HIDDEN_SURFACES, INTERPOLATIONS, LIGHT_KINDS, LIGHT_RANGES, MATERIAL_RANGES, MODELS, SHADINGS,
                       TRANSPARENCIES, Camera, Image, Light, Material, RenderSettings, Scene, SceneObject, headlight)
from lab.framing import make_shape, mesh_file_scene, shape_scene
from lab.matrices import model_matrix
from lab.suggest import did_you_mean
from lab.values import IS_A_FOLDER, file_problem, show
from lab.validation import SceneError, Table, quantise_colour

MAX_SIZE = 8192
"""Largest image width and height without ``--allow-large`` (pixels)."""
LARGE_SIZE = 65536
"""Largest image width and height with ``--allow-large`` (pixels)."""
CSG_SEGMENTS = 128


def size_problem(size, allow_large: bool = False) -> str | None:
    """What is wrong with an image size (width, height) in pixels, or None.

    Both must be whole numbers from 1 to MAX_SIZE, or to LARGE_SIZE with ``allow_large``.
    """
    limit = LARGE_SIZE if allow_large else MAX_SIZE
    w, h = size
    if any(x != int(x) or x < 1 for x in size):
        return f"expected two whole numbers of at least 1, got {w:g}x{h:g}"
    if w > limit or h > limit:
        hint = "" if allow_large else f" (--allow-large lifts it to {LARGE_SIZE}x{LARGE_SIZE})"
        return f"{int(w)}x{int(h)} is beyond the limit of {limit}x{limit} pixels{hint}"
    return None


# --------------------------------------------------------------------------- sections
def _image(src, table, allow_large=False) -> Image:
    s = Table(src, "image", table, {"size", "background"})
    size = s.vector("size", (512, 384), 2)
    problem = size_problem(size, allow_large)
    if problem:
        raise s.error("size", problem)
    return Image(size=(int(size[0]), int(size[1])), background=s.colour("background", (1.0, 1.0, 1.0)))


def _camera(src, table) -> Camera:
    s = Table(src, "camera", table, {"position", "focal_point", "view_up", "view_angle",
                                     "clipping_range", "parallel", "parallel_scale"})
    pos = s.vector("position", (0.0, 0.0, 1.0))
    foc = s.vector("focal_point", (0.0, 0.0, 0.0))
    up = s.vector("view_up", (0.0, 1.0, 0.0))
    d = np.subtract(pos, foc)
    if np.linalg.norm(d) == 0:
        raise s.error("position", "equals focal_point; the view direction is undefined")
    if np.linalg.norm(np.cross(up, d)) <= 1e-12 * np.linalg.norm(d) * max(np.linalg.norm(up), 1e-300):
        raise s.error("view_up", "is parallel to the view direction (or zero)")
    rng = s.vector("clipping_range", None, 2)
    if rng is not None and not (0 < rng[0] < rng[1]):
        raise s.error("clipping_range", f"needs 0 < near < far, got {list(rng)}")
    return Camera(position=pos, focal_point=foc, view_up=up,
                  view_angle=s.number("view_angle", 30.0, 0.0, 180.0, True, True),
                  clipping_range=rng, parallel=s.flag("parallel", False),
                  parallel_scale=s.number("parallel_scale", 1.0, 0.0, lo_open=True))


def _light(src, i, table) -> Light:
    s = Table(src, f"light[{i}]", table, {"kind", "position", "focal_point", "color", "intensity", "positional",
                                           "cone_angle", "exponent", "attenuation", "on", "ambient_color",
                                           "diffuse_color", "specular_color"})
    kind = s.choice("kind", "scene", LIGHT_KINDS)
    att = s.vector("attenuation", (1.0, 0.0, 0.0), 3, 0.0)
    if sum(att) <= 0:
        raise s.error("attenuation", "needs at least one positive coefficient")
    position, focal, positional = _light_position(s, table)
    return Light(kind=kind, position=position, focal_point=focal, positional=positional,
                 ambient_color=s.colour("ambient_color", (0.0, 0.0, 0.0)),
                 diffuse_color=s.colour("diffuse_color", None), specular_color=s.colour("specular_color", None),
                 color=s.colour("color", (1.0, 1.0, 1.0)),
                 intensity=s.number("intensity", 1.0, *LIGHT_RANGES["intensity"]),
                 cone_angle=s.number("cone_angle", 90.0, 0.0, 180.0, lo_open=True),
                 exponent=s.number("exponent", 1.0, *LIGHT_RANGES["exponent"]),
                 attenuation=att, on=s.flag("on", True))


def _light_position(s: Table, table: dict):
    """(position, focal_point, positional) from 3 values, or OpenGL's 4 = [x, y, z, w]."""
    raw = table.get("position", (0.0, 0.0, 1.0))
    if isinstance(raw, list) and len(raw) == 4:
        x, y, z, w = s.vector("position", None, 4)
        if "positional" in table or "focal_point" in table:
            raise s.error("position", "a 4-value position [x, y, z, w] sets 'positional' and the focal point "
                                      "itself (w = 0: directional toward the origin; w ≠ 0: point light)")
        if w == 0.0:
            if (x, y, z) == (0.0, 0.0, 0.0):
                raise s.error("position", "a directional light [x, y, z, 0] needs a nonzero direction")
            return (x, y, z), (0.0, 0.0, 0.0), False
        return (x / w, y / w, z / w), (0.0, 0.0, 0.0), True
    return s.vector("position", (0.0, 0.0, 1.0)), s.vector("focal_point", (0.0, 0.0, 0.0)), \
        s.flag("positional", False)


MATERIAL_DEFAULTS = {"ambient": 0.0, "diffuse": 1.0, "specular": 0.0, "specular_power": 1.0, "opacity": 1.0,
                     "shininess": 0.0}
"""A material's numbers when an object does not give them (ranges: lab.scene.MATERIAL_RANGES)."""
OBJECT_KEYS = {"mesh", "shape", "params", "color", "ambient", "diffuse", "specular", "specular_power",
               "specular_color", "opacity", "shading", "scale", "rotate", "translate", "lighting", "name",
               "model", "ambient_color", "diffuse_color", "shininess", "normals", "crease_angle", "csg",
               "texture", "texture_filter", "texture_wrap", "matrix"}


def _object(src, base: Path | None, i, table, inputs: list) -> SceneObject:
    """One ``[[object]]``; the files it reads (mesh, texture) are appended to ``inputs``."""
    s = Table(src, f"object[{i}]", table, OBJECT_KEYS)
    sources = [k for k in ("mesh", "shape", "csg") if k in table]
    if len(sources) != 1:
        raise s.error("mesh", "give exactly one of 'mesh' (a file), 'shape' (a built-in shape) or 'csg' (a tree)")
    if "csg" in table:
        mesh, name = _csg(s, table["csg"]), "csg"
    elif "mesh" in table:
        mesh = _mesh_file(s, base, table["mesh"], inputs)
        name = Path(str(table["mesh"])).stem
    else:
        params = table.get("params", {})
        if not isinstance(params, dict):
            raise s.error("params", f"expected a table like {{ level = 3 }}, got {show(params)}")
        mesh = make_shape(table["shape"], params, where=lambda m: s.error("shape", m))
        name = str(table["shape"])
    number = {k: s.number(k, default, *MATERIAL_RANGES[k]) for k, default in MATERIAL_DEFAULTS.items()}
    mat = Material(color=s.colour("color", (1.0, 1.0, 1.0)), **number, specular_color=s.colour("specular_color", None),
                   lighting=s.flag("lighting", True), model=s.choice("model", "vtk", MODELS),
                   ambient_color=s.colour("ambient_color", None), diffuse_color=s.colour("diffuse_color", None))
    mesh = _normals(s, mesh, table)
    texture = _texture(s, base, mesh, table, inputs)
    if "matrix" in table:
        m = _matrix(s, table)
    else:
        m = model_matrix(scale=s.vector("scale", (1.0, 1.0, 1.0)), rotate=s.vector("rotate", (0.0, 0.0, 0.0)),
                         translate=s.vector("translate", (0.0, 0.0, 0.0)))
    if abs(np.linalg.det(m[:3, :3])) < 1e-300:
        raise s.error("matrix" if "matrix" in table else "scale", "a zero scale flattens the object")
    return SceneObject(mesh=mesh, material=mat, shading=s.choice("shading", "flat", SHADINGS),
                       model_to_world=m, name=str(table.get("name", name)), texture=texture)


def _matrix(s: Table, table: dict) -> np.ndarray:
    """``matrix``: the model-to-world matrix itself, 4 rows of 4 numbers for row vectors
    (``P_world = [P, 1] @ M``, translation in the last row, last column 0, 0, 0, 1), as
    :mod:`lab.scene_writer` writes an arbitrary (sheared, mirrored) transform exactly."""
    if any(k in table for k in ("scale", "rotate", "translate")):
        raise s.error("matrix", "give either 'matrix' or scale/rotate/translate, not both")
    rows = table["matrix"]
    if not isinstance(rows, list) or len(rows) != 4:
        raise s.error("matrix", f"expected 4 rows of 4 numbers, got {show(rows)}")
    m = np.array([Table(s.source, f"{s.where}.matrix", {"row": r}, {"row"}).vector("row", None, 4)
                  for r in rows])
    if not np.array_equal(m[:, 3], [0.0, 0.0, 0.0, 1.0]):
        raise s.error("matrix", f"the last column must be 0, 0, 0, 1 (an affine transform), got {m[:, 3].tolist()}")
    return m


def _texture(s: Table, base: Path | None, mesh: Mesh, table: dict, inputs: list):
    """The object's texture image and sampling rules, or None."""
    from lab.texture import FILTERS, WRAPS, load_texture

    filt = s.choice("texture_filter", "nearest", FILTERS)
    wrap = s.choice("texture_wrap", "repeat", WRAPS)
    if "texture" not in table:
        return None
    value = table["texture"]
    if not isinstance(value, str):
        raise s.error("texture", f"expected an image file name, got {show(value)}")
    if mesh.tcoords is None:
        raise s.error("texture", "the mesh has no texture coordinates (a mesh file with them, or a built-in "
                                 "icosphere, cylinder or cone with params uv = 1)")
    try:
        path = resolve_path(base, value)
        inputs.append(path)
        return load_texture(path, filt, wrap)
    except ValueError as exc:
        raise s.error("texture", str(exc)) from None


def _csg(s: Table, tree) -> Mesh:
    """Mesh a CSG tree (``[object.csg]``) once, here, with manifold3d (see :mod:`lab.csg`).

    Quadrics get CSG_SEGMENTS segments per circle: a CSG result is often a small
    difference of large volumes, so the tessellation must be fine (at 64 the preset's
    volume is 2 % off the implicit one, at 128 0.6 %).
    """
    from lab import csg

    if not isinstance(tree, dict):
        raise s.error("csg", f"expected a table such as {{ op = \"union\", children = [...] }}, got {show(tree)}")
    node = csg.from_dict(tree, where=f"{s.where}.csg", source=s.source)  # errors name the path in the tree
    try:
        return csg.to_mesh(node, segments=CSG_SEGMENTS)
    except ValueError as exc:  # a primitive that encloses no finite region
        raise s.error("csg", str(exc)) from None


def _normals(s: Table, mesh: Mesh, table: dict) -> Mesh:
    """Apply the object's ``normals`` choice once, here, so both renderers get the result."""
    from lab.normals import NORMAL_MODES, with_normals

    mode = s.choice("normals", "file", NORMAL_MODES)
    crease = s.number("crease_angle", 180.0, 0.0, 180.0) if "crease_angle" in table else None
    if crease is not None and mode != "computed":
        raise s.error("crease_angle", "only applies with normals = \"computed\"")
    return with_normals(mesh, mode, crease, source=s.source)


def _render(src, table) -> RenderSettings:
    s = Table(src, "render", table, {"interpolation", "global_ambient", "local_viewer", "ambient",
                                     "hidden_surface", "cull_backfaces", "transparency",
                                     "separate_specular"})
    return RenderSettings(interpolation=s.choice("interpolation", "perspective", INTERPOLATIONS),
                          hidden_surface=s.choice("hidden_surface", "zbuffer", HIDDEN_SURFACES),
                          cull_backfaces=s.flag("cull_backfaces", False),
                          transparency=s.choice("transparency", "oit", TRANSPARENCIES),
                          global_ambient=s.colour("global_ambient", (0.2, 0.2, 0.2)),
                          local_viewer=s.flag("local_viewer", False), ambient=s.colour("ambient", (1.0, 1.0, 1.0)),
                          separate_specular=s.flag("separate_specular", False))


PYVISTA_EXAMPLES = "pyvista-examples:"


def resolve_path(base: Path | None, value: str) -> Path:
    """A scene file's path: relative to the scene file, or ``pyvista-examples:NAME`` for a
    file PyVista bundles (its ``examples`` folder, found without importing PyVista)."""
    if value.startswith(PYVISTA_EXAMPLES):
        import importlib.util

        spec = importlib.util.find_spec("pyvista")
        if spec is None or spec.origin is None:
            raise ValueError(f"{value}: PyVista is not installed, so its example files are not here")
        folder = Path(spec.origin).parent / "examples"
        name = value[len(PYVISTA_EXAMPLES):]
        path = folder / name
        if file_problem(path) is not None:
            known = sorted(p.name for p in folder.iterdir() if p.is_file() and not p.name.endswith((".py", ".pyc")))
            raise ValueError(f"{value}: PyVista has no example file {name!r}{did_you_mean(name, known)}; "
                             f"its files: {', '.join(known)}")
        return path
    path = Path(value) if base is None else base / value
    if file_problem(path) == IS_A_FOLDER:
        raise ValueError(f"{path}: is a folder, not a file")
    return path


def _mesh_file(s: Table, base: Path | None, value, inputs: list) -> Mesh:
    from lab.meshfiles import MeshFileError, read_mesh

    if not isinstance(value, str):
        raise s.error("mesh", f"expected a file name, got {show(value)}")
    try:
        path = resolve_path(base, value)
        inputs.append(path)
        return read_mesh(path)
    except (MeshFileError, ValueError) as exc:
        raise s.error("mesh", str(exc)) from None


# --------------------------------------------------------------------------- entry point
def load_scene(path_or_name, allow_large: bool = False) -> Scene:
    """Load a scene file (TOML), a preset name from ``lab/scenes``, a shape spec, or a
    mesh file (any other existing file: :func:`lab.framing.mesh_file_scene`).

    ``allow_large`` lifts the image size limit (MAX_SIZE × MAX_SIZE pixels).

    Examples
    --------
    >>> load_scene("icosphere:level=1").objects[0].mesh.n_triangles
    80
    """
    text = str(path_or_name)
    path = Path(text)
    if path.suffix.lower() != ".toml":
        preset = preset_path(text)
        if file_problem(preset) is None:
            path = preset
        elif text.partition(":")[0] in shapes.SHAPES:
            return shape_scene(text)
        elif file_problem(path) == os.strerror(errno.ENOENT):
            hint = did_you_mean(text.partition(":")[0], [*preset_names(), *shapes.SHAPES]) if len(text) <= 200 else ""
            raise SceneError(f"{text if len(text) <= 200 else text[:199] + '…'}: no such scene file, preset or shape"
                             f"{hint} (shapes: {', '.join(shapes.SHAPES)}; presets: `scanlab scenes`)")
        elif file_problem(path) in (None, IS_A_FOLDER):

            return mesh_file_scene(path)
    problem = file_problem(path)
    if problem:
        raise SceneError(f"{path}: cannot read: {problem}")
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise SceneError(f"{path}: cannot read: {exc.strerror or exc}") from None
    scene = parse_scene(raw, source=str(path), base=path.parent, allow_large=allow_large)
    return replace(scene, inputs=(str(path),) + scene.inputs)


def parse_scene(raw: bytes, source: str = "<scene>", base: Path | None = None, allow_large: bool = False) -> Scene:
    """Parse the bytes of a scene file named ``source`` (relative paths start at ``base``).

    Raises SceneError for anything wrong, from UTF-8 and TOML syntax (with line and
    column) to every key; :mod:`lab.app.fuzz` checks that nothing else escapes.
    """
    try:
        data = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise SceneError(f"{source}: not a UTF-8 text file (byte {exc.start})") from None
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{source}: TOML syntax error: {exc}") from None
    except ValueError as exc:  # tomllib's int(): Python converts at most 4300 digits
        raise SceneError(f"{source}: TOML: a number too long to read ({show(str(exc), 80)})") from None
    except RecursionError:
        raise SceneError(f"{source}: TOML: arrays or tables nested too deeply") from None
    return scene_from_dict(data, source=source, base=base, allow_large=allow_large)


def scene_from_dict(data: dict, source: str = "<scene>", base: Path | None = None,
                    allow_large: bool = False) -> Scene:
    """Build a validated :class:`Scene` from parsed TOML (docs/scene-files.md lists the keys).

    ``allow_large`` lifts the image size limit of MAX_SIZE × MAX_SIZE pixels (up to
    LARGE_SIZE on each side).
    """
    Table(source, "", data, {"image", "camera", "light", "object", "render"})

    def table(key, want):
        v = data.get(key, want())
        if not isinstance(v, type(want())) or (isinstance(v, list) and not all(isinstance(t, dict) for t in v)):
            kind = "a table [" + key + "]" if want is dict else "tables [[" + key + "]]"
            raise SceneError(f"{source}: {key}: expected {kind}")
        return v

    inputs: list[Path] = []
    objects = tuple(_object(source, base, i, t, inputs) for i, t in enumerate(table("object", list)))
    if not objects:
        raise SceneError(f"{source}: object: the scene has no [[object]]")
    lights = tuple(_light(source, i, t) for i, t in enumerate(table("light", list))) or (headlight(),)
    return Scene(image=_image(source, table("image", dict), allow_large), camera=_camera(source, table("camera", dict)),
                 lights=lights, objects=objects, source=source, render=_render(source, table("render", dict)),
                 inputs=tuple(str(p) for p in inputs))
