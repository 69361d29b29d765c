"""Ending a command's process without tearing its modules down.

After a fresh ``scanlab render`` has written its PNG, the interpreter's shutdown still took
about a third of a second: it freed numba's and llvmlite's tens of thousands of objects
(typing templates, dispatchers, LLVM handles) one at a time, although the operating system
takes the whole process back at once. :func:`exit_now` does what the shutdown must do for a
command, in the shutdown's order: it waits for the threads the command started that are not
daemons, runs the ``atexit`` handlers, and flushes the standard streams. Then it ends the
process with ``os._exit``: modules' objects are not freed one by one, and their ``__del__``
methods do not run.

Only the command line's entry points end the process (``scanlab`` and ``python -m lab``);
tests call :func:`lab.app.cli.main`, which returns its exit code.
"""
import atexit
import os
import sys
import threading


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
