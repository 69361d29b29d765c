"""Ctrl-C during a sweep: a request to stop, answered where the sweep can stop cleanly.

Python's own SIGINT handler raises ``KeyboardInterrupt`` wherever the main thread happens
to be. Where that is a finaliser (a Parquet writer or a Dask future being collected), the
exception is printed as "ignored" and dropped, and the sweep ran on to the end and exited
0 as if nobody had asked it to stop. :class:`StopRequest` takes SIGINT instead: the first
one only sets :attr:`StopRequest.requested`, which the sweep reads between batches of
results (and :func:`lab.app.sweep.cluster.run_cases` while it waits), so the sweep stops
submitting, still writes its table and page, and exits 130. The first one also puts the
previous handler back, so a second Ctrl-C interrupts at once.
"""
from __future__ import annotations

import signal
import sys
import threading

STOPPING = ("scanlab sweep: stopping (the cases running now are dropped; the rows so far are kept); "
            "press Ctrl-C again to stop at once")


class StopRequest:
    """A context that turns SIGINT into ``requested = True`` while it is entered.

    Outside the main thread (where Python cannot set signal handlers) it does nothing and
    ``requested`` stays False.
    """

    def __init__(self, stream=None) -> None:
        self.requested = False
        self._stream = stream
        self._previous = None
        self._installed = False

    def __enter__(self) -> "StopRequest":
        if threading.current_thread() is threading.main_thread():
            self._previous = signal.signal(signal.SIGINT, self._on_sigint)
            self._installed = True
        return self

    def __exit__(self, *exc) -> None:
        self._restore()

    def __call__(self) -> bool:
        """Whether a stop was asked for (for code that takes a ``stop`` callable)."""
        return self.requested

    def _on_sigint(self, signum, frame) -> None:
        self.requested = True
        self._restore()
        print(STOPPING, file=self._stream or sys.stderr, flush=True)

    def _restore(self) -> None:
        if self._installed:
            signal.signal(signal.SIGINT, self._previous)
            self._installed = False
