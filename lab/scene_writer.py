"""Writing a scene back to a scene file: the loader's inverse.

:func:`write_scene` writes ``NAME.toml`` and, beside it in ``NAME-files/``, each object's
mesh (VTK XML PolyData, float64: points, point normals and texture coordinates exactly)
and texture (PNG, the 8-bit texels). Loading the file again gives the same numbers:
every float is written with ``repr`` (shortest round-trip form), colours are already on
the k/255 grid the loader quantises to (a colour that is not, such as a PyVista light
kit's warmth, moves by less than half a level), meshes are written in model space with
the object's model-to-world matrix under ``matrix`` (so any affine transform survives,
not only scale/rotate/translate), and ``normals`` stays "file" (the mesh's own; the mesh
reader scales them to unit length again, which may move a last bit). A scene with no
lights gets one switched-off light, since the loader adds a headlight to a file without.

A scene made by :func:`compare.from_plotter.scene_from_plotter`, a preset, a shape or a
mesh file can so be saved, read, edited and compared again (``scanlab export SCENE -o
scene.toml``).

>>> import tempfile, pathlib
>>> from lab.loading import load_scene
>>> folder = pathlib.Path(tempfile.mkdtemp())
>>> path = write_scene(load_scene("cube"), folder / "cube.toml")
>>> load_scene(path).objects[0].mesh.n_triangles
12
"""
from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np

from lab.atomic import write_text


def _value(v) -> str:
    """A TOML value: bool, number (shortest round-trip text), string or list."""
    if isinstance(v, (bool, np.bool_)):
        return "true" if v else "false"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        if not math.isfinite(v):
            raise ValueError(f"cannot write {v!r} to a scene file")
        return repr(float(v))
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)  # a TOML basic string
    if isinstance(v, (list, tuple, np.ndarray)):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    raise TypeError(f"cannot write a {type(v).__name__} to a scene file")


def _table(header: str, items: dict) -> list[str]:
    lines = [header] if header else []
    lines += [f"{key} = {_value(v)}" for key, v in items.items() if v is not None]
    return lines + [""]


def _file_stem(index: int, name: str) -> str:
    safe = re.sub(r"[^A-Za-z0-9_.-]+", "-", name).strip("-.") or "object"
    return f"{index:02d}-{safe[:40]}"


def scene_to_toml(scene, mesh_files: list[str], texture_files: list[str | None]) -> str:
    """The text of a scene file for ``scene``; object i's mesh is ``mesh_files[i]`` and its
    texture ``texture_files[i]`` (paths relative to the scene file, already written)."""
    r, im, cam = scene.render, scene.image, scene.camera
    lines = [f"# {scene.source}, written by scanlab (lab/scene_writer.py)", ""]
    lines += _table("[render]", dict(
        interpolation=r.interpolation, hidden_surface=r.hidden_surface, transparency=r.transparency,
        separate_specular=r.separate_specular, cull_backfaces=r.cull_backfaces, global_ambient=r.global_ambient,
        local_viewer=r.local_viewer, ambient=r.ambient))
    lines += _table("[image]", dict(size=list(im.size), background=im.background))
    lines += _table("[camera]", dict(
        position=cam.position, focal_point=cam.focal_point, view_up=cam.view_up, view_angle=cam.view_angle,
        clipping_range=cam.clipping_range, parallel=cam.parallel, parallel_scale=cam.parallel_scale))
    if not scene.lights:  # the loader adds a headlight to a file without lights: say "none on" instead
        lines += ["# no lights in the scene: one switched off keeps the loader from adding a headlight",
                  *_table("[[light]]", dict(kind="headlight", on=False))]
    for li in scene.lights:
        lines += _table("[[light]]", dict(
            kind=li.kind, position=li.position, focal_point=li.focal_point, positional=li.positional,
            color=li.color, intensity=li.intensity, cone_angle=li.cone_angle, exponent=li.exponent,
            attenuation=li.attenuation, on=li.on, ambient_color=li.ambient_color, diffuse_color=li.diffuse_color,
            specular_color=li.specular_color))
    for obj, mesh, texture in zip(scene.objects, mesh_files, texture_files):
        m = obj.material
        items = dict(name=obj.name, mesh=mesh, shading=obj.shading, model=m.model, lighting=m.lighting,
                     color=m.color, ambient=m.ambient, diffuse=m.diffuse, specular=m.specular,
                     specular_power=m.specular_power, specular_color=m.specular_color, opacity=m.opacity,
                     ambient_color=m.ambient_color, diffuse_color=m.diffuse_color, shininess=m.shininess)
        if not np.array_equal(obj.model_to_world, np.eye(4)):
            items["matrix"] = [list(row) for row in obj.model_to_world]
        if texture is not None:
            items.update(texture=texture, texture_filter=obj.texture.filter, texture_wrap=obj.texture.wrap)
        lines += _table("[[object]]", items)
    return "\n".join(lines)


def scene_files(scene, path) -> tuple[list[Path], list[Path | None]]:
    """The mesh file and texture file (or None) :func:`write_scene` writes for each object."""
    path = Path(path)
    folder = path.parent / f"{path.stem}-files"
    stems = [_file_stem(i, obj.name) for i, obj in enumerate(scene.objects)]
    return ([folder / f"{stem}.vtp" for stem in stems],
            [None if obj.texture is None else folder / f"{stem}-texture.png" for stem, obj in zip(stems, scene.objects)])


def write_scene(scene, path) -> Path:
    """Write ``scene`` as a scene file ``path`` (.toml) with its meshes and textures in
    ``<stem>-files/`` beside it (:func:`scene_files`); return ``path``. Every file is
    written atomically."""
    from lab.meshfiles.write import write_vtp
    from lab.png import write_png

    path = Path(path)
    meshes, textures = scene_files(scene, path)
    meshes[0].parent.mkdir(parents=True, exist_ok=True)
    for obj, mesh, texture in zip(scene.objects, meshes, textures):
        write_vtp(obj.mesh, mesh)
        if texture is not None:
            write_png(texture, obj.texture.image_rows)
    relative = lambda p: None if p is None else f"{p.parent.name}/{p.name}"  # noqa: E731
    write_text(path, scene_to_toml(scene, [relative(m) for m in meshes], [relative(t) for t in textures]))
    return path
