"""Ending a command's process without tearing its modules down.

After a fresh ``scanlab render`` has written its PNG, the interpreter's shutdown still took
about a third of a second: it freed numba's and llvmlite's tens of thousands of objects
(typing templates, dispatchers, LLVM handles) one at a time, although the operating system
takes the whole process back at once. :func:`exit_now` does what the shutdown must do for a
command: it runs the ``atexit`` handlers and flushes the standard streams, then ends the
process with ``os._exit``: modules' objects are not freed one by one, and their ``__del__``
methods do not run. While a thread other than the main one that is not a daemon is alive (a
thread pool's workers, which leave when the shutdown tells them to), it leaves the ending to
the interpreter's shutdown, which stops and joins them in its own order. So it does while a
profiler or tracer watches (``python -m cProfile -m lab …`` writes its figures after the
program returns; coverage and debuggers trace).

Only the command line's entry points end the process (``scanlab`` and ``python -m lab``);
tests call :func:`lab.app.cli.main`, which returns its exit code.
"""
import atexit
import os
import sys
import threading


def _threads_to_join() -> bool:
    """Whether a thread other than the main one, not a daemon, is alive (the shutdown would join it)."""
    return any(t is not threading.main_thread() and not t.daemon and t.is_alive() for t in threading.enumerate())


def _watched() -> bool:
    """Whether a profiler or a tracer is set (``sys.getprofile``, ``sys.gettrace``)."""
    return sys.getprofile() is not None or sys.gettrace() is not None


def _flush(stream) -> None:
    """Flush a standard stream; a reader that has gone away (``scanlab … | head``) is not an error."""
    if stream is None:
        return
    try:
        stream.flush()
    except (BrokenPipeError, ValueError):  # the pipe's reader left, or the stream was closed
        pass


def exit_now(code) -> None:
    """End the process with exit status ``code`` (an int, or None for 0) after the ``atexit``
    handlers and standard streams are done, without the interpreter's teardown; with threads
    to join (:func:`_threads_to_join`) or a profiler watching (:func:`_watched`), through the
    interpreter's shutdown (``sys.exit``)."""
    if _threads_to_join() or _watched():
        sys.exit(code)
    atexit._run_exitfuncs()
    _flush(sys.stdout)
    _flush(sys.stderr)
    os._exit(0 if code is None else int(code))
