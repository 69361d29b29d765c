"""No source file over 600 lines: a long file is several rooms that want their own modules.

Counts every ``.py`` file under the four top-level packages (tests are not counted).
"""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("lab", "renderer", "compare", "lessons")
MAX_LINES = 600


def source_files() -> list[Path]:
    return sorted(p for package in PACKAGES for p in (ROOT / package).rglob("*.py"))


def line_count(path: Path) -> int:
    with path.open("rb") as f:
        return sum(1 for _ in f)


def test_the_packages_hold_source_files():
    names = {p.relative_to(ROOT).as_posix() for p in source_files()}
    assert {"lab/loading.py", "renderer/pipeline.py", "compare/metrics.py"} <= names


def test_no_source_file_is_over_600_lines():
    long = {p.relative_to(ROOT).as_posix(): n for p in source_files() if (n := line_count(p)) > MAX_LINES}
    assert long == {}, f"over {MAX_LINES} lines (split them into modules named for what they hold): {long}"
