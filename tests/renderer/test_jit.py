"""The compiled-kernel cache never serves code older than the sources (renderer/jit.py).

The end-to-end case reproduces the stale-kernel bug: ``shade_band_lit_spans`` (shading.py) inlines
``vtk_span`` (reflection/vtk_spans.py); editing only vtk_spans.py must change the next render, in a
fresh process, while an unchanged tree starts from its warm cache.
"""
from __future__ import annotations

import ast
import hashlib
import json
import os
import resource
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from renderer import jit

ROOT = Path(__file__).resolve().parents[2]
PACKAGES = ("lab", "renderer", "compare", "lessons")

RENDER_AND_COUNT = """
import hashlib, json, sys, time
start = time.perf_counter()
import numba
from lab import load_scene
from renderer import render
frame = render(load_scene("headlight-icosphere"))
seconds = time.perf_counter() - start
hits = misses = 0
for name, module in list(sys.modules.items()):
    if name.startswith("renderer."):
        for obj in vars(module).values():
            if isinstance(obj, numba.core.registry.CPUDispatcher):
                hits += sum(obj.stats.cache_hits.values())
                misses += sum(obj.stats.cache_misses.values())
print(json.dumps({"image": hashlib.sha256(frame.rgb.tobytes()).hexdigest()[:12],
                  "hits": hits, "misses": misses, "seconds": seconds}))
"""


def copy_tree(dest: Path) -> Path:
    """The project's packages copied into ``dest``, without any compiled-kernel cache."""
    for package in PACKAGES:
        shutil.copytree(ROOT / package, dest / package, ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    return dest


def render_in_fresh_process(tree: Path, **env) -> dict:
    environment = {k: v for k, v in os.environ.items() if k not in ("SCANLAB_KERNEL_CACHE", "NUMBA_CACHE_DIR")}
    environment.update(PYTHONPATH=str(tree), **env)
    done = subprocess.run([sys.executable, "-c", RENDER_AND_COUNT], cwd=tree, env=environment, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.strip().splitlines()[-1])


def test_an_edit_to_a_callee_in_another_file_shows_in_the_next_render(tmp_path):
    tree = copy_tree(tmp_path / "copy")
    cold = render_in_fresh_process(tree)
    warm = render_in_fresh_process(tree)
    assert cold["misses"] > 0, "a fresh copy has no cache: its kernels must be compiled"
    assert warm["misses"] == 0 and warm["hits"] > 0, "an unchanged tree must start from its cache"
    assert warm["image"] == cold["image"]
    assert warm["seconds"] < cold["seconds"]
    print(f"start-up with the kernel cache cold {cold['seconds']:.1f} s, warm {warm['seconds']:.1f} s")

    lighting = tree / "renderer" / "reflection" / "vtk_spans.py"
    source = lighting.read_text()
    assert source.count("df = larger(HEADLIGHT_FLOOR, points[5, np.uint64(first + i)])") == 1
    lighting.write_text(source.replace("df = larger(HEADLIGHT_FLOOR, points[5, np.uint64(first + i)])", "df = np.float32(0.5) * larger(HEADLIGHT_FLOOR, points[5, first + i])"))
    edited = render_in_fresh_process(tree)
    assert edited["misses"] > 0
    assert edited["image"] != cold["image"], "the headlight's halved diffuse term must show"

    lighting.write_text(source)  # back to the first sources: their folder is still there, warm
    restored = render_in_fresh_process(tree)
    assert restored["image"] == cold["image"] and restored["misses"] == 0


COLD_START_CPU_SECONDS = 35.0
"""The bar of :func:`test_a_cold_start_compiles_within_the_bar`: CPU seconds (user + system)
of a fresh ``scanlab render icosphere:level=5`` with an empty kernel cache, compiled in that
one process (``SCANLAB_COMPILE_AHEAD=0``). A guard of how much there is to compile, not issue
15's start-up bar itself: that bar is wall time with the compile helper
(:mod:`renderer.compile_ahead`), which ``scanlab bench`` measures. CPU time, unlike wall time,
grows little when a loaded CI box shares its cores, but it follows the machine's speed.

History: the kernels once took 44 s; no wrappers no one calls, no builtin ``min``/``max`` in a kernel
(:mod:`renderer.min_max`) and the raster's band work compiled once outside its parallel loop
brought it to 11.7 s (median of four), 14.2–20.0 s on slower days, and the bar was 25 s. On
2026-11-30 the machine (and the CI box) ran about twice as slow as on the 11.7 s day: a
10⁷-step pure-Python loop took 1.07 s; the tree of ``04c7349``, one commit before the last
round and with the same first-frame kernels, took 25.9–26.8 s, alternating with this one at
23.6–26.0 s, and a CI run failed at 26.1 s. The bar is 35 s, a third above the slow day: a
return of the old compile (44 s on a fast day) still fails it on any of these days."""


def test_a_cold_start_compiles_within_the_bar(tmp_path):
    """A fresh process with an empty kernel cache compiles every kernel the level-5 icosphere's
    first frame needs and writes its PNG, within :data:`COLD_START_CPU_SECONDS` of CPU."""
    environment = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    environment["SCANLAB_KERNEL_CACHE"] = str(tmp_path / "kernels")
    environment["SCANLAB_COMPILE_AHEAD"] = "0"  # one process: its CPU time is all there is to compile
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    started = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "lab", "render", "icosphere:level=5", "-o", str(tmp_path / "ico5.png")],
                          cwd=ROOT, env=environment, capture_output=True, text=True, timeout=900)
    wall = time.perf_counter() - started
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "ico5.png").stat().st_size > 0
    assert any((tmp_path / "kernels").rglob("*.nbi")), "the cold start must have filled the empty cache"
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    print(f"cold start: {cpu:.1f} s CPU, {wall:.1f} s wall")
    assert cpu < COLD_START_CPU_SECONDS, f"a cold start took {cpu:.1f} s of CPU (bar {COLD_START_CPU_SECONDS} s)"


def probe(code: str) -> str:
    """What a fresh Python process running ``code`` prints (the repository on its path)."""
    done = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout.strip()


def test_a_render_process_does_not_import_scipy_linalg_for_numbas_blas_probe():
    """Importing the renderer (which imports numba's numpy support with ``scipy.linalg`` hidden,
    ``jit.import_numpy_support_without_blas``) and drawing a frame leaves ``scipy.linalg``
    unimported (0.14 s of a warm start); the hiding is undone, so an import of it afterwards
    works; and a process that imported it first keeps numba's BLAS."""
    drawn = probe("import sys; from renderer import render; from lab import load_scene; render(load_scene('cube')); "
                  "print('scipy.linalg' in sys.modules); import scipy.linalg; print(scipy.linalg.norm([3.0, 4.0]))")
    assert drawn.split() == ["False", "5.0"]
    first = probe("import scipy.linalg; import renderer.jit; import numba.np.arraymath as m; print(m._HAVE_BLAS)")
    assert first == "True"


def test_the_hash_follows_contents_not_time_stamps(tmp_path):
    (tmp_path / "a.py").write_text("x = 1\n")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "b.py").write_text("y = 2\n")
    first = jit.source_hash(tmp_path)
    os.utime(tmp_path / "a.py", (1, 1))
    assert jit.source_hash(tmp_path) == first
    (tmp_path / "sub" / "b.py").write_text("y = 3\n")
    assert jit.source_hash(tmp_path) != first
    (tmp_path / "sub" / "b.py").write_text("y = 2\n")
    assert jit.source_hash(tmp_path) == first


def test_the_cache_sits_beside_the_sources_when_they_are_writable(tmp_path, monkeypatch):
    monkeypatch.delenv("SCANLAB_KERNEL_CACHE", raising=False)
    assert jit.cache_root(tmp_path) == tmp_path / "__pycache__"


def test_a_read_only_tree_caches_in_the_user_cache_folder(tmp_path, monkeypatch):
    monkeypatch.delenv("SCANLAB_KERNEL_CACHE", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path / "xdg"))
    monkeypatch.setattr(jit, "_writable", lambda folder: False)  # root ignores file modes: pretend
    assert jit.cache_root(tmp_path / "tree") == tmp_path / "xdg" / "scanlab" / "kernels"


def test_a_named_cache_folder_wins(tmp_path, monkeypatch):
    monkeypatch.setenv("SCANLAB_KERNEL_CACHE", str(tmp_path / "mine"))
    assert jit.cache_root() == tmp_path / "mine"


def test_old_kernel_folders_do_not_pile_up(tmp_path):
    for age in range(7):
        folder = tmp_path / f"kernels-{age:016x}"
        folder.mkdir()
        os.utime(folder, (1000 - age, 1000 - age))  # kernels-0 is the newest
    (tmp_path / "unrelated").mkdir()
    removed = jit.prune(tmp_path, keep=jit.KEEP)
    left = sorted(p.name for p in tmp_path.iterdir())
    assert left == [f"kernels-{age:016x}" for age in range(jit.KEEP)] + ["unrelated"]
    assert len(removed) == 7 - jit.KEEP


def test_every_kernel_module_takes_njit_from_the_cached_door():
    offenders = []
    for path in sorted((ROOT / "renderer").rglob("*.py")):
        if path.name == "jit.py":
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom) and node.module == "numba":
                names = {alias.name for alias in node.names}
                if names & {"njit", "jit", "prange", "vectorize", "guvectorize"}:
                    offenders.append(f"{path.name}: from numba import {', '.join(sorted(names))}")
    assert not offenders


def test_kernels_are_filed_under_this_trees_hash():
    from renderer import shading  # noqa: F401  (registers nothing new: jit did on import)
    folder = jit.cache_folder()
    assert folder.name == "kernels-" + jit.source_hash()
    assert jit.SourceTreeLocator in __import__("numba").core.caching.CacheImpl._locator_classes


def test_the_cache_folder_is_checked_once_per_process(monkeypatch):
    """numba's check (a temporary file made and deleted) runs for the first kernel filed in a
    folder, not for each of the ~190 a render imports; a kernel outside the sources gets no locator."""
    from numba.core.caching import _CacheLocator
    from renderer import shading, spans

    checks = []
    monkeypatch.setattr(_CacheLocator, "ensure_cache_path", lambda self: checks.append(self.get_cache_path()))
    monkeypatch.setattr(jit, "_WRITABLE_FOLDERS", set())
    for kernel in (shading.shade_rows_lit_spans, spans.span_table_of_corners, shading.shade_rows):
        f = kernel.py_func
        assert jit.SourceTreeLocator.from_function(f, f.__code__.co_filename) is not None
    assert checks == [str(jit.cache_folder())]
    assert jit.SourceTreeLocator.from_function(ast.walk, ast.__file__) is None


def test_a_cache_folder_that_takes_no_file_gives_no_locator(monkeypatch):
    from numba.core.caching import _CacheLocator
    from renderer import shading

    def refuse(self):
        raise PermissionError("read-only")

    monkeypatch.setattr(_CacheLocator, "ensure_cache_path", refuse)
    monkeypatch.setattr(jit, "_WRITABLE_FOLDERS", set())
    f = shading.shade_rows.py_func
    assert jit.SourceTreeLocator.from_function(f, f.__code__.co_filename) is None


def kernels(tree):
    """The functions of a module decorated with ``njit`` (bare or called)."""
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef):
            for d in node.decorator_list:
                name = d.func if isinstance(d, ast.Call) else d
                if isinstance(name, ast.Name) and name.id == "njit":
                    yield node


def writes_through_fields(function) -> list[str]:
    """Assignments in ``function`` whose target is an element of an attribute: ``bundle.field[i] = …``."""
    found = []
    for node in ast.walk(function):
        targets = node.targets if isinstance(node, ast.Assign) else [node.target] if isinstance(
            node, (ast.AugAssign, ast.AnnAssign)) else []
        for target in targets:
            for t in (target.elts if isinstance(target, ast.Tuple) else [target]):
                value = t
                while isinstance(value, ast.Subscript):
                    value = value.value
                if t is not value and isinstance(value, ast.Attribute):
                    found.append(f"{function.name}:{node.lineno}")
    return found


def test_no_kernel_writes_through_a_named_tuple_field():
    """Kernels read their bundles (NamedTuples of arrays) but write only into plain arrays: inside a
    ``prange`` loop, numba drops writes made through a NamedTuple's fields (numba issues #5872,
    #7135, #10338: the frame silently keeps stale memory). Inlined helpers count, so every kernel
    is held to it."""
    offenders = []
    for path in sorted((ROOT / "renderer").rglob("*.py")):
        for kernel in kernels(ast.parse(path.read_text())):
            offenders += [f"{path.name}:{w}" for w in writes_through_fields(kernel)]
    assert offenders == []


def test_the_field_write_check_sees_one():
    code = ("@njit(cache=True)\ndef k(buf, out):\n    buf.depth[0, 1] = 1.0\n    out[0] = buf.depth[0, 0]\n"
            "    a.b[0], c[1] = 1, 2\n")
    assert writes_through_fields(next(kernels(ast.parse(code)))) == ["k:3", "k:5"]


def test_a_kernel_numba_cannot_cache_gets_numbas_warning_not_a_crash():
    """numba names the kernel's file in its warning (``locator._py_file``); a kernel calling
    ``numba.get_num_threads()`` is one it refuses to cache."""
    import warnings

    import numba

    source = "def threads():\n    return numba.get_num_threads()\n"
    namespace = {"numba": numba}
    exec(compile(source, str(jit.SOURCE_DIR / "shading.py"), "exec"), namespace)  # as if written in the tree
    kernel = jit.njit(cache=True)(namespace["threads"])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert kernel() >= 1
    assert any("Cannot cache" in str(w.message) for w in caught)


def test_a_kernel_compiled_without_refcounts_counts_no_references():
    """``njit(refcounts=False)``: the compiled code calls no ``NRT_incref``/``NRT_decref``, where
    the same function with them does; the lighting kernel, called once per span, and the
    raster's band kernels, which take views of the set-up rows per triangle, and the set-up's
    chunk kernel, which writes each triangle's row of planes through a view, are built so."""
    import numpy as np

    from renderer.raster import band_dividing, band_walking, set_up_range
    from renderer.reflection.vtk_spans import vtk_light_kernel

    def total(a, b):
        view = a[1:]
        return view.sum() + b[0]

    counted, uncounted = jit.njit(total), jit.njit(total, refcounts=False)
    args = (np.arange(5.0), np.ones(2))
    assert counted(*args) == uncounted(*args) == 11.0
    assert "NRT_incref" in counted.inspect_llvm(counted.signatures[0])
    assert "NRT_incref" not in uncounted.inspect_llvm(uncounted.signatures[0])
    assert "NRT_decref" not in uncounted.inspect_llvm(uncounted.signatures[0])
    for kernel in (vtk_light_kernel, band_dividing, band_walking, set_up_range):
        assert kernel.targetoptions.get("_nrt") is False, kernel


def test_kernels_are_compiled_without_the_wrappers_they_do_not_need():
    """``njit`` builds no C wrapper for any kernel (nothing passes a kernel around as a
    function pointer), and none of the CPython kind for ``from_python=False``: that kernel is
    called from kernels only; Python gets a clear error instead of a jump into the missing
    wrapper (a crash)."""
    import numpy as np

    def twice(a):
        return 2.0 * a[0]

    inner = jit.njit(twice, from_python=False)

    @jit.njit
    def outer(a):
        return inner(a) + 1.0

    assert outer(np.ones(1)) == 3.0
    ir = outer.inspect_llvm(outer.signatures[0])
    assert "@cfunc." not in ir, "no kernel has a C wrapper"
    assert "@_ZN7cpython" in ir, "a kernel Python calls has its CPython wrapper"
    with pytest.raises(TypeError, match="called from kernels only"):
        inner(np.ones(1))
    from renderer.raster import band_dividing, band_walking
    from renderer.reflection.vtk_spans import vtk_light_kernel
    for kernel in (band_dividing, band_walking, vtk_light_kernel):
        assert kernel.targetoptions.get("no_cpython_wrapper") is True


def test_a_kernel_is_filed_under_a_lock_another_process_can_hold(tmp_path):
    """numba's save of a kernel (index, then data file) waits while another process holds the
    kernel's index lock (:func:`renderer.jit.save_under_lock`): the helper of
    :mod:`renderer.compile_ahead` and the frame it helps never pick the same data file."""
    import fcntl
    import threading

    from numba.core.caching import IndexDataCacheFile

    cache = IndexDataCacheFile(str(tmp_path), "kernel-1", "stamp")
    with open(cache._index_path + ".lock", "ab") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        saving = threading.Thread(target=cache.save, args=(("sig", "cpu"), b"machine code"))
        saving.start()
        saving.join(0.5)
        assert saving.is_alive() and cache.load(("sig", "cpu")) is None  # waiting for the lock
    saving.join(10)
    assert not saving.is_alive() and cache.load(("sig", "cpu")) == b"machine code"


def test_like_operations_side_by_side_become_one_vector_instruction(monkeypatch):
    """LLVM's straight-line vectoriser is on for every kernel (numba leaves it off): four
    sums of neighbouring values compile to a packed add, not four scalar ones — also after a
    ``NUMBA_`` variable changed, when numba reads its configuration again (as a test that
    sets one makes it do)."""
    import platform

    import numpy as np

    if platform.machine() not in ("x86_64", "AMD64"):
        pytest.skip("the packed-add instruction checked is x86's")

    monkeypatch.setenv("NUMBA_DEBUG_CACHE", "0")  # numba's configuration read again at the next compile

    @jit.njit
    def four_sums(a, b):
        a0, a1, a2, a3 = a[0] + b[0], a[1] + b[1], a[2] + b[2], a[3] + b[3]
        a[0], a[1], a[2], a[3] = a0, a1, a2, a3

    four_sums(np.zeros(4, np.float32), np.ones(4, np.float32))
    assembly = four_sums.inspect_asm(four_sums.signatures[0])
    assert "addps" in assembly and "addss" not in assembly
