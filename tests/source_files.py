"""The project's own source files, for the tests that read code rather than run it (not a test file).

Non-test sources are every ``*.py`` under the top-level packages; tests, virtual
environments and build output are not sources.
"""
from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("lab", "renderer", "compare", "lessons")


def source_files(packages=PACKAGES) -> list[Path]:
    """Every non-test ``*.py`` of ``packages``, sorted, caches left out."""
    return sorted(p for package in packages for p in (ROOT / package).rglob("*.py") if "__pycache__" not in p.parts)


def relative(path: Path) -> str:
    """``path`` relative to the repository, with forward slashes (``compare/vtk_backend.py``)."""
    return path.relative_to(ROOT).as_posix()


def parse(path: Path) -> ast.Module:
    return ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
