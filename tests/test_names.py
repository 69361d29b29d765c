"""Honest names: no two source files share a basename, and a reflection model is named only in its rooms.

- Two modules called ``texture.py`` (or ``textbook_lighting.py``) in two packages read as one
  idea in two places; every non-test source file has a basename of its own, but the package
  files ``__init__.py`` and ``__main__.py``.
- One room per reflection model: in the renderer and the comparison, the strings "vtk",
  "opengl" and "classic" appear as values (not in docstrings) only in the models' own
  modules and their registries. Code elsewhere looks a model up; it never asks which one
  it is. (The ground floor keeps the list of names and validates them; a lesson or the
  command line may name a model as data, as a scene file does.)
"""
from __future__ import annotations

import ast
import sys
from collections import defaultdict
from pathlib import Path

from lab.scene import MODELS

from .source_files import parse, relative, source_files

PACKAGE_FILES = {"__init__.py", "__main__.py"}


def model_rooms() -> set[str]:
    """The registries and the modules of the models they register (found through them, so that a
    new model's modules count without editing this test)."""
    from compare.lit_reference import lit_registry
    from renderer.reflection import registry

    modules = {registry, lit_registry}
    modules |= {sys.modules[r.material_row.__module__] for r in registry.REFLECTION_MODELS.values()}
    modules |= {sys.modules[r.vtk_property.__module__] for r in lit_registry.LIT_REFERENCES.values()}
    return {relative(Path(m.__file__)) for m in modules}


def test_no_two_source_files_share_a_basename():
    by_name = defaultdict(list)
    for path in source_files():
        if path.name not in PACKAGE_FILES:
            by_name[path.name].append(relative(path))
    assert {name: paths for name, paths in by_name.items() if len(paths) > 1} == {}


def docstrings(tree: ast.AST) -> set[int]:
    """ids of the string constants that are docstrings (or bare string statements)."""
    return {id(node.value) for node in ast.walk(tree) if isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)}


def model_names_in(tree: ast.AST) -> list[str]:
    skip = docstrings(tree)
    return [f"{node.lineno}: {node.value!r}" for node in ast.walk(tree)
            if isinstance(node, ast.Constant) and node.value in MODELS and id(node) not in skip]


def test_reflection_models_are_named_only_in_their_rooms():
    rooms = model_rooms()
    assert "renderer/reflection/opengl_model.py" in rooms and "compare/lit_reference/classic_lit.py" in rooms
    outside = [p for p in source_files(("renderer", "compare")) if relative(p) not in rooms]
    found = {relative(p): model_names_in(parse(p)) for p in outside}
    assert {f: lines for f, lines in found.items() if lines} == {}


def test_the_rooms_check_sees_a_branch_on_a_model_name():
    code = 'def kind(m):\n    """opengl or not"""\n    return 1 if m.model == "opengl" else 0\n'
    assert model_names_in(ast.parse(code)) == ["3: 'opengl'"]
