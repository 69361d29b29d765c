"""The scenes the live lab can open: the only files it reads.

The picker offers a fixed list, made on the server at start-up: the presets
(``lab/scenes``), the lessons' scene files (``lessons/NN-*/*.toml``), the built-in shapes
(with their parameters), the files the user named on the command line, and the scenes
the lab itself saved. The browser sends only a *key* of this list (``preset:cube``,
``lesson:08-lights/red-point.toml``, ``shape:icosphere``, ``file:0``, ``saved:0``) and,
for a shape, its parameters; a key that is not in the list is refused. So nothing the
browser sends is ever used as a path.

A shape's parameters arrive as typed (numbers or text) and are checked by the scene
loader itself (:func:`lab.loading.load_scene` on ``NAME:key=value,...``).
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from lab.app.lesson_site.places import LESSONS as LESSONS_DIR
from lab.framing import parse_shape_spec
from lab.loading import load_scene
from lab.presets import preset_description, preset_names, preset_path
from lab.shapes import SHAPES, shape_parameters
from lab.validation import SceneError

GROUPS = ("preset", "lesson", "shape", "file", "saved")
"""The kinds of entry, in the picker's order."""


@dataclass(frozen=True)
class Entry:
    """One scene of the picker.

    key : what the browser sends (``group:name``).
    group : one of :data:`GROUPS`.
    label : what the picker shows.
    path : the file to load (None for a shape).
    shape : the shape's name (None for a file).
    """

    key: str
    group: str
    label: str
    path: str | None = None
    shape: str | None = None


def lesson_files() -> list[Path]:
    """The lessons' scene files, in lesson order."""
    return sorted(LESSONS_DIR.glob("[0-9][0-9]-*/*.toml"))


class Catalogue:
    """The picker's entries (see the module docstring); ``files`` are those named on the
    command line (scene files or mesh files), checked by loading them once."""

    def __init__(self, files: tuple[str, ...] = ()):
        self.entries: dict[str, Entry] = {}
        for name in preset_names():
            self._add(Entry(f"preset:{name}", "preset", f"{name} — {preset_description(name)}",
                            path=str(preset_path(name))))
        for path in lesson_files():
            rel = path.relative_to(LESSONS_DIR).as_posix()
            self._add(Entry(f"lesson:{rel}", "lesson", rel, path=str(path)))
        for name in SHAPES:
            self._add(Entry(f"shape:{name}", "shape", name, shape=name))
        for i, name in enumerate(files):
            load_scene(name)  # a file that cannot be read stops the start-up with its one-line error
            self._add(Entry(f"file:{i}", "file", Path(name).name, path=str(Path(name).resolve())))

    def _add(self, entry: Entry) -> None:
        self.entries[entry.key] = entry

    def add_saved(self, path: Path) -> str:
        """Offer a scene file the lab has written; its key (the same key again for the same file)."""
        path = Path(path).resolve()
        for entry in self.entries.values():
            if entry.group == "saved" and entry.path == str(path):
                return entry.key
        key = f"saved:{sum(e.group == 'saved' for e in self.entries.values())}"
        self._add(Entry(key, "saved", path.name, path=str(path)))
        return key

    def key_for(self, spec: str) -> str:
        """The key of a SCENE given on the command line: a preset or shape name (shape
        parameters go to :func:`initial_parameters`), or one of ``files``."""
        name = spec.partition(":")[0]
        if f"preset:{spec}" in self.entries:
            return f"preset:{spec}"
        if name in SHAPES:
            return f"shape:{name}"
        for entry in self.entries.values():
            if entry.group == "file" and entry.path == str(Path(spec).resolve()):
                return entry.key
        load_scene(spec)  # says what is wrong with it, with a suggestion
        raise SceneError(f"{spec}: not a preset, shape or file of this lab")

    def spec(self, key, params: dict | None = None) -> str:
        """What :func:`lab.loading.load_scene` reads for entry ``key``: its file, or
        ``NAME:key=value,...`` for a shape. SceneError for a key not in the list or a
        parameter that is not a plain number."""
        entry = self.entries.get(key) if isinstance(key, str) else None
        if entry is None:
            raise SceneError(f"{str(key)[:80]!r} is not a scene of this lab")
        if entry.shape is None:
            return entry.path
        if params is not None and not isinstance(params, dict):
            raise SceneError(f"{entry.shape}: expected its parameters by name, got {str(params)[:40]!r}")
        words = []
        for name, value in (params or {}).items():
            text = str(value).strip()
            if not _plain_number(text) or not isinstance(name, str) or not name.isidentifier():
                raise SceneError(f"{entry.shape}: {str(name)[:40]}: expected a number, got {text[:40]!r}")
            words.append(f"{name}={text}")
        return f"{entry.shape}:{','.join(words)}" if words else entry.shape

    def load(self, key, params: dict | None = None):
        """The scene of entry ``key`` (with a shape's ``params``), as loaded (cached)."""
        return load_spec(self.spec(key, params))

    def picker_items(self, group_titles: dict[str, str]) -> list[dict]:
        """The picker's items for a Vuetify select: a header per group, then its entries."""
        items = []
        for group in GROUPS:
            entries = [e for e in self.entries.values() if e.group == group]
            if entries:
                items.append({"type": "subheader", "title": group_titles[group]})
                items += [{"title": e.label, "value": e.key} for e in entries]
        return items


def _plain_number(text: str) -> bool:
    """Whether ``text`` is an integer or decimal number (no names, no separators)."""
    try:
        float(text)
    except ValueError:
        return False
    return all(c in "0123456789.-+eE" for c in text)


def shape_defaults(name: str) -> dict:
    """A shape's parameters with their defaults (``{"level": 2, "radius": 1.0}``)."""
    return {p: default for p, default, _ in shape_parameters(name)}


def initial_parameters(spec: str) -> dict:
    """The parameters of a shape spec given on the command line, over the defaults."""
    name, params = parse_shape_spec(spec)
    return {**shape_defaults(name), **params}


def load_spec(spec: str):
    """:func:`lab.loading.load_scene`, remembered: switching back to a scene costs nothing.
    A file is read again when it has changed (a scene saved again under the same name)."""
    try:
        stamp = os.stat(spec).st_mtime_ns
    except (OSError, ValueError):
        stamp = None
    return _load(spec, stamp)


@lru_cache(maxsize=16)
def _load(spec: str, stamp):
    return load_scene(spec)
