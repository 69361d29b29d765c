"""Arrays kept from one frame to the next, as a GL context keeps its framebuffer.

Allocating a few megabytes of fresh buffers per frame costs as much as drawing it: the
operating system hands out new pages, and each is faulted in on first touch. A
:class:`Workspace` lends the pipeline the same memory every frame when the sizes fit.
:func:`renderer.render` keeps one per thread; everything it returns is copied out, so a
:class:`~lab.frame.Frame` never shares memory with the workspace.

What a frame returns is new memory each time (a 1024² frame: rgb 3 MB, the integer depth
4 MB, divided into 8 MB of float64 only if read, coverage 1 MB). glibc's ``malloc`` serves blocks that large with a fresh ``mmap`` and gives
the top of its heap back to the system once more than a threshold of it is free; both
thresholds move as the process runs, so whether the next frame's outputs get pages faulted
in afresh depended on what the process did before (measured in ``scanlab bench``, VTK's
frames alternating with ours: 1,500 faults a frame, 6 MB, on the level-5 icosphere at
1024², 14.1 ms a frame against 7.2 ms without them). :func:`keep_freed_memory`, run when
this module is imported, fixes the thresholds so that freed frames are served again from
the heap: blocks up to 32 MiB come from it, and up to 256 MiB of free heap is kept.
Thresholds the user set (``MALLOC_MMAP_THRESHOLD_``, ``MALLOC_TRIM_THRESHOLD_``) are kept.
"""
from __future__ import annotations

import ctypes
import ctypes.util
import math
import os
import threading

import numpy as np

M_TRIM_THRESHOLD, M_MMAP_THRESHOLD = -1, -3
"""``mallopt`` parameters (glibc's ``malloc.h``)."""

KEPT_FREE = 256 << 20
"""Free memory at the top of the heap kept rather than given back (bytes)."""

FROM_HEAP = 32 << 20
"""Blocks up to this size come from the heap, not from a fresh ``mmap`` (glibc's largest
dynamic threshold on 64-bit systems)."""


def keep_freed_memory() -> bool:
    """Set glibc's trim and mmap thresholds (see the module docstring); False where the C
    library has no ``mallopt`` (not glibc) or it refuses."""
    name = ctypes.util.find_library("c")
    try:
        mallopt = ctypes.CDLL(name).mallopt
    except (OSError, AttributeError, TypeError):
        return False
    done = True
    if "MALLOC_TRIM_THRESHOLD_" not in os.environ:
        done &= mallopt(M_TRIM_THRESHOLD, KEPT_FREE) == 1
    if "MALLOC_MMAP_THRESHOLD_" not in os.environ:
        done &= mallopt(M_MMAP_THRESHOLD, FROM_HEAP) == 1
    return done


KEEPS_FREED_MEMORY = keep_freed_memory()


class Workspace:
    """Named scratch arrays, reused while they are large enough.

    >>> ws = Workspace()
    >>> a = ws.array("depth", (4, 3))
    >>> ws.array("depth", (2, 3)).base is a.base
    True
    """

    def __init__(self):
        self._arrays: dict[str, np.ndarray] = {}
        self._kept: dict[str, tuple] = {}
        self._zeros: dict[str, np.ndarray] = {}

    def array(self, name: str, shape, dtype=np.float64) -> np.ndarray:
        """An uninitialised C-contiguous array of ``shape`` (an int or a sequence of ints); its
        contents are undefined. Called some 40 times a frame, so it stays plain Python (with
        numpy's shape helpers it cost 2.5 µs a call)."""
        shape = tuple(map(int, shape)) if isinstance(shape, (tuple, list, np.ndarray)) else (int(shape),)
        size = math.prod(shape)
        store = self._arrays.get(name)
        if store is None or store.size < size or store.dtype != dtype:
            store = np.empty(max(size, 1), dtype)
            self._arrays[name] = store
        return store[:size].reshape(shape)


    def kept(self, name: str, key, build):
        """The array ``build()`` made for ``key`` (hashable), kept under ``name`` and made again
        only when the key changes: for tables that depend on the scene's layout alone (which
        object each triangle belongs to), not on the camera. Callers must not write to it.

        >>> ws = Workspace()
        >>> ws.kept("o", (2,), lambda: np.zeros(2)) is ws.kept("o", (2,), lambda: np.ones(2))
        True
        """
        held = self._kept.get(name)
        if held is None or held[0] != key:
            held = self._kept[name] = (key, build())
        return held[1]

    def zeros(self, name: str, size: int, dtype=np.int64) -> np.ndarray:
        """A 1-D array of ``size`` zeros that stays zero between uses: filled once when it is
        made (or grown), after which each caller puts back every zero it changed (cheaper than
        filling a table as long as a mesh's triangles when a frame touches few of its entries).

        >>> ws = Workspace()
        >>> a = ws.zeros("n", 4); a[1] = 7; a[1] = 0
        >>> ws.zeros("n", 3).tolist()
        [0, 0, 0]
        """
        store = self._zeros.get(name)
        if store is None or store.size < size or store.dtype != dtype:
            store = self._zeros[name] = np.zeros(max(int(size), 1), dtype)
        return store[:size]


def kept(ws: Workspace | None, name: str, key, build) -> np.ndarray:
    """``ws.kept(...)`` when a workspace is given, else ``build()``."""
    return build() if ws is None else ws.kept(name, key, build)


def zeros(ws: Workspace | None, name: str, size: int, dtype=np.int64) -> np.ndarray:
    """``ws.zeros(...)`` when a workspace is given, else a fresh ``np.zeros``."""
    return np.zeros(size, dtype) if ws is None else ws.zeros(name, size, dtype)


def empty(ws: Workspace | None, name: str, shape, dtype=np.float64) -> np.ndarray:
    """``ws.array(...)`` when a workspace is given, else a fresh ``np.empty``."""
    return np.empty(shape, dtype) if ws is None else ws.array(name, shape, dtype)


_local = threading.local()


def thread_workspace() -> Workspace:
    """This thread's workspace (renders in different threads never share buffers)."""
    ws = getattr(_local, "workspace", None)
    if ws is None:
        ws = _local.workspace = Workspace()
    return ws
