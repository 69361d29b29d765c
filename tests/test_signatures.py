"""Kernel inputs travel bundled: no function of the renderer or the comparison takes more than ten parameters.

Past about ten, the arguments have a shape that deserves a name (a NamedTuple of arrays
numba accepts: geometry, fragments, materials, textures, lights): see the README's
"Layout". Every function and lambda, nested ones and methods included; ``self``, ``*args``
and ``**kwargs`` count as one each.
"""
from __future__ import annotations

import ast

from .source_files import parse, relative, source_files

MAX_PARAMETERS = 10


def parameter_counts(tree: ast.AST) -> dict[str, int]:
    counts = {}
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            a = node.args
            n = len(a.posonlyargs) + len(a.args) + len(a.kwonlyargs) + (a.vararg is not None) + (a.kwarg is not None)
            counts[f"{node.lineno}: {getattr(node, 'name', 'lambda')}"] = n
    return counts


def test_no_function_takes_more_than_ten_parameters():
    too_many = {}
    for path in source_files(("renderer", "compare")):
        for name, n in parameter_counts(parse(path)).items():
            if n > MAX_PARAMETERS:
                too_many[f"{relative(path)}:{name}"] = n
    assert too_many == {}


def test_the_count_sees_every_kind_of_parameter():
    code = "def f(a, /, b, *c, d, e=1, **g):\n    h = lambda x, y: x\n"
    assert sorted(parameter_counts(ast.parse(code)).values()) == [2, 6]
