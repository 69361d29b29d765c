"""One numba thread for the length of a ``with`` block, for the tests that compare a frame drawn
on one thread with the same frame on the default number (two on the reference machine).

Not a test file: ``from .single_thread import one_thread``.
"""
from __future__ import annotations

import contextlib

import numba


@contextlib.contextmanager
def one_thread():
    """Run the block's renders on one numba thread; the number before is restored after."""
    saved = numba.get_num_threads()
    numba.set_num_threads(1)
    try:
        yield
    finally:
        numba.set_num_threads(saved)
