"""The ``{src}`` role: a lesson names the code and the tests it teaches, and the build checks them.

In a lesson: ``{src}`renderer/raster.py::scanline_span``` (a function or class in a file
of the repository) or ``{src}`tests/renderer/test_raster.py``` (a file). The role shows
the name as code; when the file or the definition does not exist, the build warns, and
since warnings fail the build (``scanlab lessons build``), a lesson cannot point at code
that has moved or gone: lesson → code → test stays one hop each way.
"""
from __future__ import annotations

import re
from pathlib import Path

from docutils import nodes

from lab.app.lesson_site.places import ROOT


def problem(target: str, root: Path = ROOT) -> str | None:
    """Why ``FILE`` or ``FILE::NAME`` does not name existing code (None when it does)."""
    file, _, name = target.partition("::")
    path = root / file
    if not path.is_file():
        return f"{file}: no such file in the repository"
    if name:
        pattern = rf"^\s*(?:async\s+)?(?:def|class)\s+{re.escape(name.split('.')[-1])}\b|^{re.escape(name)}\s*[:=]"
        if not re.search(pattern, path.read_text(encoding="utf-8"), re.M):
            return f"{file}: defines no {name}"
    return None


def src_role(name, rawtext, text, lineno, inliner, options=None, content=None):
    """``{src}`FILE[::NAME]```: the name as code, checked against the repository."""
    target = text.strip()
    node = nodes.literal(rawtext, target, classes=["scanlab-src"])
    why = problem(target)
    if why:
        return [node], [inliner.reporter.warning(f"{{src}}`{target}`: {why}", line=lineno)]
    return [node], []
