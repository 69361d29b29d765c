"""numba's ``njit`` and ``prange`` for the renderer's kernels, with a compiled-kernel cache
that can never serve code older than the sources.

numba's own on-disk cache (``cache=True``) checks only the file a kernel is written in.
A kernel that calls or inlines a function from another file (``shade_rows`` in
``shading.py`` inlines ``vtk_lighting`` from ``reflection/vtk_model.py``) keeps its old machine code
when only the callee's file changes. Here every cached kernel of the renderer is filed
under one folder named by a hash of *all* the renderer's sources (every ``*.py`` in this
package, by content, not by time stamp):

- any edit anywhere in ``renderer/`` gives a new hash, a new, empty folder, and every
  kernel is compiled again from the current sources;
- an unchanged tree keeps its hash and its warm cache (a checkout of an older commit
  finds its own folder again);
- only the :data:`KEEP` most recently used folders are kept; older ones are removed when
  a new folder is made.

Where the folders live (:func:`cache_root`): ``$SCANLAB_KERNEL_CACHE`` when set; else
``renderer/__pycache__/`` beside the sources when that is writable (a clone, an editable
install); else the user's cache folder, ``$XDG_CACHE_HOME/scanlab/kernels`` (by default
``~/.cache/scanlab/kernels``) — a read-only tree or a package installed where the user
cannot write.

Threads: importing this module chooses numba's threading layer before numba starts
(:mod:`renderer.threads`: TBB when it loads, else OpenMP with ``OMP_WAIT_POLICY=passive``).
Vectors: and the features numba compiles for, 512-bit vectors on AVX-512
(:mod:`renderer.vector_width`), before its first compile; and LLVM's straight-line (SLP)
vectoriser turned on, which numba leaves off: it packs like operations on neighbouring
values into one vector instruction (the four half-float sums of an ``oit`` fragment,
:func:`renderer.oit_buffers.add_run_to_oit`: one packed add and one packed rounding to
half instead of four each; a translucent-three frame at 1024² about 5 % quicker). It
reorders no floating-point arithmetic, so every kernel gives the same bits (every preset
and bench scene checked); elsewhere its effect was within the noise. Both are set in the
environment (``NUMBA_CPU_FEATURES``, ``NUMBA_SLP_VECTORIZE=1`` unless the user set it) as
well as on ``numba.config``: numba reads its configuration again from the environment
whenever a ``NUMBA_`` variable changes, which values set on ``numba.config`` alone did not
survive.

Every kernel module imports ``njit`` from here, not from numba, so no renderer kernel can
be cached without this locator being in place (``tests/renderer/test_jit.py`` checks).
The mechanism is numba's cache-locator hook (``numba.core.caching.CacheImpl``'s list of
locator classes, the one numba's own ``NUMBA_CACHE_LOCATOR_CLASSES`` fills).
"""
from __future__ import annotations

import fcntl
import functools
import hashlib
import os
import shutil
import sys
from pathlib import Path

from renderer.threads import choose_threading_layer
from renderer.vector_width import chosen_features

# Before numba starts: TBB's work-taking threads, else OpenMP's with passive waiting
# (renderer/threads.py); the package decides, not the user's shell.
LAYER = choose_threading_layer()
# The vectors' width and LLVM's straight-line vectoriser (numba's default: off) go through the
# environment too: numba reads its configuration again from it whenever a NUMBA_ variable
# changes, and values set on numba.config alone were then lost.
FEATURES = chosen_features()  # 512-bit vectors on AVX-512 (renderer/vector_width.py); None: the user's
if FEATURES is not None:
    os.environ["NUMBA_CPU_FEATURES"] = FEATURES
os.environ.setdefault("NUMBA_SLP_VECTORIZE", "1")

import numba  # noqa: E402  (after the threading layer is chosen)
from numba import prange  # noqa: E402
from numba.core.caching import CacheImpl, IndexDataCacheFile, _CacheLocator  # noqa: E402

numba.config.THREADING_LAYER = LAYER  # also when something imported numba before us
if FEATURES is not None:  # read at numba's first compile
    numba.config.CPU_FEATURES = FEATURES
numba.config.SLP_VECTORIZE = int(os.environ["NUMBA_SLP_VECTORIZE"])


def import_numpy_support_without_blas() -> None:
    """Import numba's numpy implementations (``numba.np.arraymath``) with ``scipy.linalg``
    hidden, unless it is already imported. On import, that module probes for BLAS (for
    ``np.dot`` in a kernel) by importing ``scipy.linalg``: 0.14 s of a warm start of 1.2 s,
    for code no renderer kernel uses (none calls BLAS). Hidden, the probe finds none, and
    numba's ``np.dot`` and ``np.linalg`` would not compile in a kernel; every other numpy
    function does. numba imports the module anyway before it loads or compiles the first kernel."""
    if "numba.np.arraymath" in sys.modules or "scipy.linalg" in sys.modules:
        return
    sys.modules["scipy.linalg"] = None  # an import of it or of any of its modules raises ImportError
    try:
        import numba.np.arraymath  # noqa: F401
    finally:
        del sys.modules["scipy.linalg"]


import_numpy_support_without_blas()

__all__ = ["njit", "prange", "SOURCE_DIR", "source_hash", "cache_root", "cache_folder", "KEEP"]

SOURCE_DIR = Path(__file__).resolve().parent
"""The renderer's source folder: the files whose contents key the cache."""

KEEP = 4
"""How many kernel folders (source versions) are kept; the least recently used go first."""

PREFIX = "kernels-"


def source_hash(folder: Path = SOURCE_DIR) -> str:
    """SHA-256 (first 16 hex digits) of every ``*.py`` under ``folder``: relative paths and
    contents, in sorted order. Time stamps play no part."""
    digest = hashlib.sha256()
    for path in sorted(folder.rglob("*.py")):
        if "__pycache__" in path.parts:
            continue
        digest.update(path.relative_to(folder).as_posix().encode() + b"\0")
        digest.update(path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def _writable(folder: Path) -> bool:
    """True when files can be made in ``folder`` (made first if missing)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        probe = folder / f".probe-{os.getpid()}"
        probe.touch()
        probe.unlink()
        return True
    except OSError:
        return False


def user_cache_home() -> Path:
    """scanlab's folder in the user's cache: ``$XDG_CACHE_HOME/scanlab``, by default
    ``~/.cache/scanlab`` (kernels here, :func:`user_cache_root`; exported revisions,
    :mod:`lab.app.bench_revisions`)."""
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "scanlab"


def user_cache_root() -> Path:
    """``$XDG_CACHE_HOME/scanlab/kernels``, by default ``~/.cache/scanlab/kernels``."""
    return user_cache_home() / "kernels"


def cache_root(source_dir: Path = SOURCE_DIR) -> Path:
    """The folder that holds the ``kernels-<hash>`` folders (see the module docstring)."""
    override = os.environ.get("SCANLAB_KERNEL_CACHE")
    if override:
        return Path(override)
    in_tree = source_dir / "__pycache__"
    return in_tree if _writable(in_tree) else user_cache_root()


def prune(root: Path, keep: int = KEEP) -> list[Path]:
    """Remove all but the ``keep`` most recently used ``kernels-*`` folders of ``root``;
    returns the removed ones."""
    folders = sorted((p for p in root.glob(PREFIX + "*") if p.is_dir()), key=lambda p: p.stat().st_mtime,
                     reverse=True)
    for old in folders[keep:]:
        shutil.rmtree(old, ignore_errors=True)
    return folders[keep:]


def cache_folder() -> Path:
    """This source tree's kernel folder, made (and old ones pruned) on first use; its time
    stamp is refreshed so that pruning keeps what is in use."""
    root = cache_root()
    folder = root / (PREFIX + source_hash())
    if not folder.is_dir():
        folder.mkdir(parents=True, exist_ok=True)
        prune(root)
    else:
        os.utime(folder)
    return folder


def njit(*args, refcounts: bool = True, from_python: bool = True, **options):
    """numba's ``njit`` with the renderer's defaults: ``error_model="numpy"``.

    With numba's default (``"python"``) every float division carries a test for a zero
    divisor that raises ZeroDivisionError; that branch alone keeps LLVM from vectorising a
    loop (measured: a float32 ``pow`` over 200k values took 18 ns each, 1.2 ns without it).
    Under numpy's model x/0 gives ±inf or nan as IEEE says; the kernels guard their own
    divisions where a zero can occur.

    ``refcounts=False`` (numba's ``_nrt=False``) compiles a kernel without reference counts:
    for the small kernels called once per span or run from inside a loop kernel, which
    allocate nothing and only read and write the arrays they are given. Each array argument
    otherwise costs an atomic increment and decrement per call (measured: 10 % of a
    textured-sphere frame in ``NRT_incref``/``NRT_decref``; without them in the lighting
    kernel, 1024², one thread, three alternating runs: 32.4–34.6 → 30.4–30.7 ms; the
    texture and translucency kernels called as often showed no gain and keep theirs). Such a
    kernel cannot make an array.

    Wrappers: numba compiles two for every kernel besides its machine code, a C one (for
    passing the kernel around as a function pointer, which no renderer code does: never
    compiled here) and a CPython one that unboxes each argument from a Python object.
    ``from_python=False`` leaves the second out too, for a kernel that only other kernels
    call (it then cannot be called from Python). Each wrapper is compiled to machine code of
    its own, which is most of a small kernel's compile time; measured, a cold start of the
    level-5 icosphere, four alternating runs each: no C wrappers 14.8 → 13.5 s of CPU
    (with :func:`renderer.raster.band_dividing` split off), then no CPython wrapper on the
    two kernels that only kernels call 13.6 → 13.1 s.
    """
    options.setdefault("error_model", "numpy")
    options["no_cfunc_wrapper"] = True
    if not refcounts:
        options["_nrt"] = False
    if from_python:
        return numba.njit(*args, **options)
    options["no_cpython_wrapper"] = True
    if args and callable(args[0]):
        return _kernels_only(numba.njit(**options)(args[0]))
    return lambda func: _kernels_only(numba.njit(*args, **options)(func))


class KernelsOnlyDispatcher(numba.core.registry.CPUDispatcher):
    """A kernel compiled without its CPython wrapper (``njit(from_python=False)``): other
    kernels call it as any other; a call from Python, which would jump into the missing
    wrapper, raises :class:`TypeError` instead."""

    def __call__(self, *args, **kwargs):
        raise TypeError(f"{self.py_func.__qualname__} is called from kernels only (njit(from_python=False)); "
                        "call it from a kernel, or call its py_func")


def _kernels_only(dispatcher):
    """``dispatcher`` made a :class:`KernelsOnlyDispatcher` (a plain function stays one: under
    ``NUMBA_DISABLE_JIT`` the kernels run as Python)."""
    if isinstance(dispatcher, numba.core.registry.CPUDispatcher):
        dispatcher.__class__ = KernelsOnlyDispatcher
    return dispatcher


_FOLDER: Path | None = None


def _folder() -> Path:
    global _FOLDER
    if _FOLDER is None:
        _FOLDER = cache_folder()
    return _FOLDER


class SourceTreeLocator(_CacheLocator):
    """numba cache locator for kernels defined in the renderer's own files.

    Cache path: :func:`cache_folder`; source stamp: the tree hash (so a stale index is
    never believed); disambiguator: the kernel's first line (numba adds the module and name).
    """

    def __init__(self, py_func, py_file):
        self._py_file = py_file  # numba's warning about a kernel it cannot cache names this file
        self._path = str(_folder())
        self._stamp = _folder().name
        self._disambiguator = str(py_func.__code__.co_firstlineno)

    def get_cache_path(self):
        return self._path

    def get_source_stamp(self):
        return self._stamp

    def get_disambiguator(self):
        return self._disambiguator

    def ensure_cache_path(self):
        """numba's check that the folder exists and takes a file, once per folder and process:
        numba's own makes and deletes a temporary file for each of the ~190 kernels a
        ``scanlab render`` imports (with resolving each kernel's file, about 40 ms of a warm
        start)."""
        if self._path not in _WRITABLE_FOLDERS:
            super().ensure_cache_path()
            _WRITABLE_FOLDERS.add(self._path)

    @classmethod
    def from_function(cls, py_func, py_file):
        try:
            inside = _in_source_tree(py_file)
        except OSError:
            return None
        if not inside:
            return None
        locator = cls(py_func, py_file)
        try:
            locator.ensure_cache_path()
        except OSError:
            return None
        return locator


_WRITABLE_FOLDERS: set[str] = set()
"""Cache folders :meth:`SourceTreeLocator.ensure_cache_path` found writable in this process."""


@functools.lru_cache(maxsize=None)
def _in_source_tree(py_file: str) -> bool:
    """Whether ``py_file`` lies in the renderer's sources (resolved once per file and process)."""
    return Path(py_file).resolve().is_relative_to(SOURCE_DIR)


if SourceTreeLocator not in CacheImpl._locator_classes:
    CacheImpl._locator_classes.insert(0, SourceTreeLocator)


def save_under_lock(save):
    """numba's ``IndexDataCacheFile.save`` holding an exclusive lock on the kernel's index
    (``<index>.lock``) while it reads the index, picks a data file name and writes both.
    numba's own save is not safe between processes: two that file different argument types
    of one kernel at once both take data file 1, and the index can end up naming the other
    process's machine code. The helper of :mod:`renderer.compile_ahead` and the frame it
    helps fill one cache at the same time."""
    def locked(self, key, data):
        with open(self._index_path + ".lock", "ab") as lock:
            fcntl.flock(lock, fcntl.LOCK_EX)  # released when the file closes
            save(self, key, data)
    locked.unlocked = save
    return locked


if not hasattr(IndexDataCacheFile.save, "unlocked"):
    IndexDataCacheFile.save = save_under_lock(IndexDataCacheFile.save)
