"""Starter files: the signature, a docstring stating every convention, and raise NotImplementedError."""
import ast

import pytest

from lab.app.exercises.exercise_registry import exercises

ALL = exercises()


@pytest.mark.parametrize("name", ALL)
def test_the_starter_is_valid_python_with_the_fixed_signature(name):
    ex = ALL[name]
    tree = ast.parse(ex.starter)
    (function,) = [n for n in tree.body if isinstance(n, ast.FunctionDef)]
    assert function.name == name
    assert [a.arg for a in function.args.args] == list(ex.parameters)
    assert isinstance(function.body[-1], ast.Raise) and ast.unparse(function.body[-1].exc) == "NotImplementedError"
    assert f"scanlab exercise check {name} {name}.py" in ast.get_docstring(tree)


@pytest.mark.parametrize("name, words", [
    ("menger", ["row", "counter-clockwise", "[-0.5, 0.5]", "share"]),
    ("icosahedron_fractal", ["row", "counter-clockwise", "1 / (1 + phi)"]),
    ("icosphere", ["row", "counter-clockwise", "m / |m|", "10 * 4**N + 2"]),
    ("cylinder", ["row", "counter-clockwise", "unit normal", "(0, 0, +1)", "own centre"]),
    ("cone", ["row", "counter-clockwise", "unit normal", "apex point", "sqrt(h**2 + r**2)"]),
    ("look_at", ["row vectors", "[x, y, z, 1] @ M", "looking down -z", "right-handed"]),
    ("perspective", ["row", "degrees", "-1 <= x, y, z <= 1", "w_c = -z"]),
    ("covered_pixels", ["y up", "(x + 0.5, y + 0.5)", "1/256", "BOTTOM row", "top-left", "zero area"]),
])
def test_the_docstring_states_the_conventions_the_checker_relies_on(name, words):
    doc = ast.get_docstring([n for n in ast.parse(ALL[name].starter).body if isinstance(n, ast.FunctionDef)][0])
    for word in words:
        assert word in doc, word
