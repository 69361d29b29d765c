"""VTK behind named doors: in non-test code, vtk, vtkmodules and pyvista are imported only by the door modules.

The rendering door is ``compare/vtk_backend.py``; the file-reading door on the ground floor
is ``lab/meshfiles/vtk_readers.py`` (allowed by name whether or not it exists yet). Every
other module asks a door for what it needs. Tests may import VTK directly. The check reads
each file's syntax tree: ``import vtk``, ``from vtkmodules.util import …``, ``import
pyvista as pv``, and ``importlib.import_module("vtk")`` / ``__import__("vtk")`` all count,
at module level or inside a function.
"""
from __future__ import annotations

import ast

from .source_files import parse, relative, source_files

DOORS = {"compare/vtk_backend.py", "lab/meshfiles/vtk_readers.py"}
GUARDED = ("vtk", "vtkmodules", "pyvista")


def guarded(name: str | None) -> bool:
    return bool(name) and any(name == g or name.startswith(g + ".") for g in GUARDED)


def vtk_imports(tree: ast.AST) -> list[str]:
    """The guarded modules ``tree`` imports, with their line numbers."""
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [f"{node.lineno}: import {a.name}" for a in node.names if guarded(a.name)]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and guarded(node.module):
            found.append(f"{node.lineno}: from {node.module} import …")
        elif isinstance(node, ast.Call) and node.args and isinstance(node.args[0], ast.Constant):
            func = node.func.attr if isinstance(node.func, ast.Attribute) else getattr(node.func, "id", "")
            if func in ("import_module", "__import__") and guarded(str(node.args[0].value)):
                found.append(f"{node.lineno}: {func}({node.args[0].value!r})")
    return found


def test_vtk_is_imported_only_behind_the_doors():
    offenders = {relative(p): vtk_imports(parse(p)) for p in source_files() if relative(p) not in DOORS}
    assert {f: lines for f, lines in offenders.items() if lines} == {}


def test_the_rendering_door_is_where_vtk_comes_in():
    """The check is not empty: the rendering door does import vtk and pyvista."""
    door = next(p for p in source_files() if relative(p) == "compare/vtk_backend.py")
    names = " ".join(vtk_imports(parse(door)))
    assert "import vtk" in names and "import pyvista" in names


def test_every_way_of_importing_is_caught():
    code = ("import vtk\nfrom vtkmodules.util.numpy_support import vtk_to_numpy\nimport pyvista as pv\n"
            "def f():\n    import importlib\n    return importlib.import_module('vtkmodules.all')\n"
            "import vtk_helpers_of_our_own\n")
    assert len(vtk_imports(ast.parse(code))) == 4
