""""Save scene": the scene on screen as a scene file that ``scanlab compare`` reproduces.

The file goes into the folder chosen when the lab was started (``--save-dir``, default
the current folder), never anywhere else: the page sends only a *name*, which must be
letters, digits, ``-`` and ``_`` (``.toml`` is added). :func:`lab.scene_writer.write_scene`
writes it, with the meshes and textures in ``NAME-files/`` beside it.

A name is refused when its file (or its ``NAME-files/`` folder) would overwrite a file
the scene was read from, or a file that exists and was not written by this lab in this
session. The scene saved is the intact one (what VTK draws); a "break it" entry is not
part of a scene file, so the commands given back include ``scanlab lessons measure
--break`` to break it again.
"""
from __future__ import annotations

import os
import re
import shlex
from pathlib import Path
from typing import NamedTuple

from lab.app.live.controls import Problem, Problems

NAME = re.compile(r"[A-Za-z0-9_-]{1,60}")


class Saved(NamedTuple):
    """A scene written: its ``path`` and the ``commands`` that reproduce the comparison."""

    path: Path
    commands: list[str]


class Saver:
    """Writes scene files into ``folder`` (created when the first one is saved)."""

    def __init__(self, folder):
        self.folder = Path(folder).resolve()
        self.written: set[Path] = set()

    def target(self, name) -> Path:
        """The file for ``name``; :class:`Problems` (under ``save_name``) for a name that is not plain."""
        if not isinstance(name, str) or not NAME.fullmatch(name.strip().removesuffix(".toml")):
            raise Problems({"save_name": Problem("name")})
        return self.folder / f"{name.strip().removesuffix('.toml')}.toml"

    def write(self, scene, name, breakage: str = "") -> Saved:
        """Write ``scene`` as ``name``; the path and the commands that reproduce what the page shows."""
        from lab.scene_writer import scene_files, write_scene

        path = self.target(name)
        meshes, textures = scene_files(scene, path)
        inputs = [Path(p).resolve() for p in scene.inputs]
        for out in [path, *meshes, *(t for t in textures if t is not None)]:
            if any(_same_file(out, source) for source in inputs):
                raise Problems({"save_name": Problem("input", (str(out),))})
            if out.exists() and out.resolve() not in self.written:
                raise Problems({"save_name": Problem("exists", (str(out),))})
        try:
            self.folder.mkdir(parents=True, exist_ok=True)
            write_scene(scene, path)
        except OSError as exc:
            raise Problems({"save_name": Problem("not_saved", (f"{path}: {exc.strerror or exc}",))}) from None
        self.written |= {p.resolve() for p in [path, *meshes, *textures] if p is not None}
        return Saved(path, commands(path, breakage))


def commands(path: Path, breakage: str = "") -> list[str]:
    """The commands that measure a saved scene again (and, with a breakage, break it again)."""
    quoted = shlex.quote(str(path))
    out = [f"scanlab compare {quoted} --out out/{path.stem}"]
    if breakage:
        out.append(f"scanlab lessons measure {quoted} --break {breakage} --out out/{path.stem}-broken")
    return out


def _same_file(a: Path, b: Path) -> bool:
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False
