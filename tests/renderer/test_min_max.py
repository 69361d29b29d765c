"""min, max and clamp for the kernels (renderer/min_max.py): the builtins' results, bit for bit
and type for type, with nothing compiled of their own; and no kernel uses the builtins."""
from __future__ import annotations

import importlib
import inspect
import math
import pkgutil
import re

import numpy as np
import pytest
from numba.core import event
from numba.core.registry import CPUDispatcher

import renderer
from renderer.jit import njit
from renderer.min_max import clamp, larger, smaller


@njit(cache=False)
def _ours(a, b):
    return smaller(a, b), larger(a, b)


@njit(cache=False)
def _builtin(a, b):
    return min(a, b), max(a, b)


@njit(cache=False)
def _clamp_both(x, lo, hi):
    return clamp(x, lo, hi), min(max(x, lo), hi)


PAIRS = [
    (1, 2), (2, 1), (-3, -3), (7, 2.5), (2.5, 7), (np.int32(5), 9), (np.float32(0.5), np.float32(-0.25)),
    (0.0, -0.0), (-0.0, 0.0), (math.nan, 1.0), (1.0, math.nan), (np.float32(1.5), 2.0), (True, 0),
]


def bits(v):
    """A value as its numpy type and bytes: 0.0 and −0.0 differ, NaN equals NaN."""
    v = np.asarray(v)
    return v.dtype.str, v.tobytes()


@pytest.mark.parametrize("a, b", PAIRS)
def test_smaller_and_larger_give_the_builtins_value_and_type(a, b):
    """The first argument is kept unless the second is strictly smaller or larger (NaN first is
    kept, ±0 the first's sign); mixed types meet as numba's builtins meet them."""
    assert [bits(v) for v in _ours(a, b)] == [bits(v) for v in _builtin(a, b)]


@pytest.mark.parametrize("x, lo, hi", [(0.5, 0.0, 1.0), (-2, 0, 9), (12, 0, 9), (math.nan, 0.0, 1.0),
                                       (np.float32(3.0), np.float32(-1.0), np.float32(1.0)), (-0.0, 0.0, 1.0)])
def test_clamp_is_min_of_max(x, lo, hi):
    ours, builtin = _clamp_both(x, lo, hi)
    assert bits(ours) == bits(builtin)


def compiles_when_first_called(kernel, *args):
    """The functions numba compiles when ``kernel`` is first called with ``args``."""
    names = []

    class Listener(event.Listener):
        def on_start(self, ev):
            names.append(ev.data["dispatcher"].py_func.__qualname__)

        def on_end(self, ev):
            pass

    with event.install_listener("numba:compile", Listener()):
        kernel(*args)
    return names


def test_they_compile_nothing_of_their_own():
    """Written into the kernel that uses them: its first call compiles that kernel alone, where
    numba's builtins compile a function of their own for each pair of argument types."""

    def ours(a, b):
        return smaller(a, b) + larger(a, b) + clamp(a, b, 9)

    def builtins(a, b):
        return min(a, b) + max(a, b) + min(max(a, b), 9)

    args = (np.int16(3), np.uint8(4))
    assert compiles_when_first_called(njit(cache=False)(ours), *args) == ["test_they_compile_nothing_of_their_own.<locals>.ours"]
    assert len(compiles_when_first_called(njit(cache=False)(builtins), *args)) > 1


def kernels():
    """Every kernel of the renderer package, by module."""
    for info in pkgutil.walk_packages(renderer.__path__, "renderer."):
        module = importlib.import_module(info.name)
        for name, value in vars(module).items():
            if isinstance(value, CPUDispatcher) and value.py_func.__module__ == info.name:
                yield f"{info.name}.{name}", value.py_func


def code_without_docstring(func):
    source = inspect.getsource(func)
    doc = func.__doc__
    return source.replace(doc, "") if doc else source


def test_no_kernel_calls_the_builtin_min_or_max():
    """The renderer's kernels use :mod:`renderer.min_max`, so a cold start compiles no builtin overloads."""
    found = [name for name, func in kernels() if re.search(r"(?<![\w.])(min|max)\(", code_without_docstring(func))]
    assert list(kernels()), "no kernels found"
    assert found == []
