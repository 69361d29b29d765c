"""Starter files: the text ``scanlab exercise start NAME`` writes.

A starter is a module docstring (what the exercise is, how to check it, what the exit
statuses mean), ``import numpy as np``, and the function with its fixed signature, a
docstring that states every convention the checker relies on, and
``raise NotImplementedError``.
"""
from __future__ import annotations

import textwrap

MESH_CONVENTIONS = """\
Conventions
-----------
- Points are rows: ``points[i] = (x, y, z)``, float, in model units (row vectors, as
  in the course: a point p is transformed as p' = [x, y, z, 1] @ M).
- Triangles are rows of three point indices (0-based), counter-clockwise seen from
  outside the solid: (p1 - p0) x (p2 - p0) points out.
- The checker judges the surface, not your arrays: any point order and any
  triangulation of the right surface is right."""


def starter(name: str, lesson: str, title: str, signature: str, docstring: str, extra_imports: str = "") -> str:
    """The starter file's text for one exercise."""
    body = textwrap.indent(f'"""{docstring.strip()}\n"""', "    ")
    return (f'"""Exercise `{name}` (lesson {lesson}): {title}.\n\n'
            "Write the function below, then check it:\n\n"
            f"    scanlab exercise check {name} {name}.py\n\n"
            "Exit status 0: right. 1: wrong (the checker says why; --lang ja for Japanese).\n"
            "2: the file could not be judged (syntax error, exception, time or memory limit, ...).\n"
            '"""\n'
            f"import numpy as np\n{extra_imports}\n\n"
            f"def {signature}:\n{body}\n    raise NotImplementedError\n")
