"""What a short-lived command process can skip: collecting garbage while it imports, and
tearing its modules down when it ends.

A fresh ``scanlab render`` spends most of its time starting: it imports numpy and numba and
loads its kernels from the cache, and each of those makes tens of thousands of objects
(numba's typing templates, dispatchers, LLVM handles). Two parts of that time are not work
for the frame:

- **Collections while importing.** Python's cyclic collector runs each time enough objects are
  made, and each pass walks the objects made since the last one, although nothing an import
  makes is garbage: importing the renderer's modules ran 175 passes (about 60 ms).
  :func:`collections_paused` turns the collector off for a ``with`` block and, at its end,
  moves what the block made into the collector's permanent generation (``gc.freeze``), so
  later passes do not walk it again; then it turns the collector back on. Keep compiling out
  of such a block: numba's compiler does make garbage, and a cold start of a textured scene
  with the collector off peaked at 1.8 GB.
- **The teardown at exit.** After the PNG is written, the interpreter's shutdown frees those
  objects one at a time (about 0.3 s), although the operating system takes the whole process
  back at once. :func:`exit_now` does what the shutdown must do for a command, in the
  shutdown's order: it waits for the threads the command started that are not daemons, runs
  the ``atexit`` handlers, and flushes the standard streams. Then it ends the process with
  ``os._exit``: modules' objects are not freed one by one, and their ``__del__`` methods do
  not run.

Only the command line's entry points end the process (``scanlab`` and ``python -m lab``);
tests call :func:`lab.app.cli.main`, which returns its exit code.
"""
import atexit
import contextlib
import gc
import os
import sys
import threading


@contextlib.contextmanager
def collections_paused():
    """A ``with`` block in which the cyclic garbage collector does not run; what survives the
    block is frozen (``gc.freeze``) and the collector is on again after it, unless it was
    off before."""
    was_on = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if was_on:
            gc.enable()


def _wait_for_threads() -> None:
    """Join every thread that is neither the main thread nor a daemon, as the shutdown does."""
    for thread in threading.enumerate():
        if thread is not threading.main_thread() and not thread.daemon:
            thread.join()


def _flush(stream) -> None:
    """Flush a standard stream; a reader that has gone away (``scanlab … | head``) is not an error."""
    if stream is None:
        return
    try:
        stream.flush()
    except (BrokenPipeError, ValueError):  # the pipe's reader left, or the stream was closed
        pass


def exit_now(code) -> None:
    """End the process with exit status ``code`` (an int, or None for 0) after the threads,
    ``atexit`` handlers and standard streams are done, without the interpreter's teardown."""
    _wait_for_threads()
    atexit._run_exitfuncs()
    _flush(sys.stdout)
    _flush(sys.stderr)
    os._exit(0 if code is None else int(code))
