"""A sweep's SOURCES: scene files, mesh files, presets, built-in shapes and folders of files.

:func:`find_sources` checks the command line's SOURCES at the edge (each names a file, a
folder, a preset or a shape; a folder holds at least one scene or mesh file) and lists the
sources in order. It does not read mesh files: reading happens in the case's own process
(:func:`load_source`), so a file that trips a reader is recorded as that case's error and
the sweep goes on — how a corpus of public meshes finds reader bugs.

A source's ``key`` names it in the results table and in its cases' identity: the absolute
path of a file, or the preset name or shape spec as given.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from lab import shapes
from lab.framing import parse_shape_spec
from lab.loading import SceneError, load_scene
from lab.framing import mesh_file_scene
from lab.presets import preset_names
from lab.scene import Scene

MESH_SUFFIXES = (".ply", ".obj", ".stl", ".vtk", ".vtp")
"""Mesh files a folder source picks up (any case); a mesh file named on its own may have any
suffix :func:`lab.meshfiles.read_mesh` reads."""

KINDS = ("scene", "mesh", "preset", "shape")


@dataclass(frozen=True)
class Source:
    """One source: ``kind`` (one of :data:`KINDS`), ``key`` (its identity) and ``name``
    (short, for pages: a file's stem, a preset's or shape's spec)."""

    kind: str
    key: str
    name: str


def _file_source(path: Path) -> Source:
    kind = "scene" if path.suffix.lower() == ".toml" else "mesh"
    return Source(kind, str(path.resolve()), path.stem)


def _folder_sources(folder: Path) -> list[Source]:
    files = sorted(p for p in folder.rglob("*") if p.is_file()
                   and p.suffix.lower() in (".toml", *MESH_SUFFIXES) and not p.name.startswith("."))
    if not files:
        raise SceneError(f"{folder}: a folder with no scene (.toml) or mesh ({' '.join(MESH_SUFFIXES)}) files")
    return [_file_source(p) for p in files]


def _named_source(text: str) -> Source:
    if text in preset_names():
        return Source("preset", text, text)
    name, _ = parse_shape_spec(text)
    if name in shapes.SHAPES:
        load_scene(text)  # checks the parameters at the edge (a SceneError names the bad one)
        return Source("shape", text, text)
    raise SceneError(f"{text}: no such file, folder, preset or shape (shapes: {', '.join(shapes.SHAPES)}; "
                     f"presets: `scanlab scenes`)")


def find_sources(texts: list[str]) -> list[Source]:
    """The sources named on the command line, folders expanded (sorted, recursively), each
    source once, in the order given. Raises SceneError (one line) for a name that is none."""
    found: list[Source] = []
    for text in texts:
        path = Path(text)
        if path.is_dir():
            found += _folder_sources(path)
        elif path.is_file():
            found.append(_file_source(path))
        else:
            found.append(_named_source(text))
    unique = {s.key: s for s in found}
    return list(unique.values())


def load_source(kind: str, key: str) -> Scene:
    """The scene of a source (in the case's process): a scene file, preset or shape through
    :func:`lab.loading.load_scene`, a mesh file through :func:`lab.framing.mesh_file_scene`
    (framed and lit as a built-in shape is, as ``scanlab compare`` shows it)."""
    return mesh_file_scene(key) if kind == "mesh" else load_scene(key)
