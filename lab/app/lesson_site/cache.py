"""The figure cache: a figure is drawn once per version of everything that decides its pixels.

A figure's key (:func:`figure_key`) hashes the scene file and every file it reads
(meshes, textures), the figure's options, and the sources of the renderer
(:func:`renderer.jit.source_hash`), of ``compare/`` and of this package. An edit to any
of them gives a new key and a new drawing; an unchanged tree finds its figures again, so
a warm rebuild draws nothing. The entries are folders ``ROOT/<key>/`` holding the PNGs
and ``result.json``; an entry is made in a temporary folder and renamed into place, so a
half-made entry is never found (parallel readers that race for one key both succeed).
"""
from __future__ import annotations

import hashlib
import json
import os
import shutil
import tempfile
from functools import lru_cache
from pathlib import Path
from typing import Callable

from lab.atomic import write_text
from lab.app.lesson_site.places import ROOT

FORMAT = 1
"""Bumped when the layout of an entry changes."""

"""The repository root (renderer/, compare/ and lessons/ sit in it)."""

RESULT = "result.json"


@lru_cache(maxsize=1)
def sources_hash() -> str:
    """One hash of the renderer's, compare's and the lesson site's sources."""
    from renderer.jit import source_hash

    parts = [source_hash(), source_hash(ROOT / "compare"), source_hash(Path(__file__).resolve().parent)]
    return hashlib.sha256("/".join(parts).encode()).hexdigest()[:16]


def source_files() -> list[Path]:
    """The files whose contents :func:`sources_hash` covers (a page that draws figures depends on them)."""
    folders = (ROOT / "renderer", ROOT / "compare", Path(__file__).resolve().parent)
    return sorted(p for f in folders for p in f.rglob("*.py") if "__pycache__" not in p.parts)


def figure_key(inputs: list[str], options: dict) -> str:
    """Key of a figure drawn from the files ``inputs`` with ``options`` (JSON-able)."""
    digest = hashlib.sha256(json.dumps({"format": FORMAT, "sources": sources_hash(), "options": options},
                                       sort_keys=True).encode())
    for name in inputs:
        digest.update(b"\0" + Path(name).name.encode() + b"\0" + Path(name).read_bytes())
    return digest.hexdigest()[:20]


def cached(root: Path, key: str, make: Callable[[Path], dict]) -> tuple[Path, dict]:
    """The entry ``root/key`` and its result, made by ``make(folder) -> result`` if missing."""
    entry = root / key
    done = entry / RESULT
    if done.is_file():
        return entry, json.loads(done.read_text())
    root.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(dir=root, prefix=f".{key}."))
    try:
        result = make(work)
        path = work / RESULT
        write_text(path, json.dumps(result, indent=1, sort_keys=True) + "\n")
        try:
            os.rename(work, entry)
        except OSError:  # another process made it first: theirs is as good as ours
            if not done.is_file():
                raise
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return entry, json.loads(done.read_text())


def prune(root: Path, keep: set[str]) -> list[str]:
    """Remove the entries of ``root`` not in ``keep`` (figures no page shows any more); return them."""
    gone = []
    if root.is_dir():
        for entry in root.iterdir():
            if entry.is_dir() and entry.name not in keep:
                shutil.rmtree(entry, ignore_errors=True)
                gone.append(entry.name)
    return sorted(gone)
