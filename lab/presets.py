"""The preset scenes: TOML files shipped in ``lab/scenes/``, found by name.

A preset's first line is a ``# comment`` that describes it; ``scanlab scenes`` lists them.
"""
from __future__ import annotations

from pathlib import Path

SCENES_DIR = Path(__file__).parent / "scenes"
"""The folder of preset scene files (``<name>.toml``)."""


def preset_names() -> list[str]:
    """Every preset's name, sorted."""
    return sorted(p.stem for p in SCENES_DIR.glob("*.toml"))


def preset_path(name: str) -> Path:
    """The file of preset ``name`` (it may not exist: check with :func:`preset_names`)."""
    return SCENES_DIR / f"{name}.toml"


def preset_description(name: str) -> str:
    """The first line of a preset's file, without its ``#``."""
    first = preset_path(name).read_text(encoding="utf-8").splitlines()[0]
    return first.lstrip("# ").strip()
