"""Arrays kept from one frame to the next, as a GL context keeps its framebuffer.

Allocating a few megabytes of fresh buffers per frame costs as much as drawing it: the
operating system hands out new pages, and each is faulted in on first touch. A
:class:`Workspace` lends the pipeline the same memory every frame when the sizes fit.
:func:`renderer.render` keeps one per thread; everything it returns is copied out, so a
:class:`~lab.frame.Frame` never shares memory with the workspace.
"""
from __future__ import annotations

import math
import threading

import numpy as np


class Workspace:
    """Named scratch arrays, reused while they are large enough.

    >>> ws = Workspace()
    >>> a = ws.array("depth", (4, 3))
    >>> ws.array("depth", (2, 3)).base is a.base
    True
    """

    def __init__(self):
        self._arrays: dict[str, np.ndarray] = {}

    def array(self, name: str, shape, dtype=np.float64) -> np.ndarray:
        """An uninitialised C-contiguous array of ``shape``; its contents are undefined."""
        shape = tuple(int(s) for s in np.atleast_1d(shape))
        size = math.prod(shape)
        store = self._arrays.get(name)
        if store is None or store.size < size or store.dtype != np.dtype(dtype):
            store = np.empty(max(size, 1), dtype)
            self._arrays[name] = store
        return store[:size].reshape(shape)


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
