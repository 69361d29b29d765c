"""A short-lived command process: no collections while it starts, no teardown when it ends."""
import gc
import os
import subprocess
import sys
import textwrap

import pytest

from lab.app import short_lived
from lab.app.short_lived import collections_paused, exit_now

ENDING = textwrap.dedent("""
    import atexit, sys, threading, time
    from lab.app.short_lived import exit_now

    class Noisy:
        def __del__(self):
            sys.stderr.write("torn down\\n")

    kept = Noisy()  # a module global: freed by the interpreter's teardown
    atexit.register(lambda: open(sys.argv[1] + "/atexit", "w").close())

    def late():
        time.sleep(0.3)
        open(sys.argv[1] + "/thread", "w").close()

    threading.Thread(target=late).start()
    sys.stdout.write("no newline, still buffered")
    {end}
""")


def _run(tmp_path, end: str):
    buffered = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}  # stdout to a pipe keeps its buffer
    return subprocess.run([sys.executable, "-c", ENDING.format(end=end), str(tmp_path)],
                          capture_output=True, text=True, timeout=60, env=buffered)


def test_exit_now_waits_for_threads_runs_atexit_flushes_and_skips_the_teardown(tmp_path):
    done = _run(tmp_path, "exit_now(3)")
    assert done.returncode == 3
    assert done.stdout == "no newline, still buffered"
    assert (tmp_path / "thread").exists() and (tmp_path / "atexit").exists()
    assert "torn down" not in done.stderr


def test_the_plain_exit_tears_down_what_exit_now_skips(tmp_path):
    """The control: the same script ended by sys.exit runs the __del__ that exit_now skips."""
    done = _run(tmp_path, "sys.exit(3)")
    assert done.returncode == 3 and "torn down" in done.stderr


def test_exit_now_of_none_is_success(tmp_path):
    assert _run(tmp_path, "exit_now(None)").returncode == 0


def test_a_reader_that_left_is_not_an_error():
    class Gone:
        def flush(self):
            raise BrokenPipeError

    short_lived._flush(Gone())
    short_lived._flush(None)


def test_collections_are_paused_in_the_block_and_on_again_after():
    assert gc.isenabled()
    with collections_paused():
        assert not gc.isenabled()
    assert gc.isenabled()
    gc.unfreeze()


def test_collections_are_on_again_after_an_error_in_the_block():
    with pytest.raises(RuntimeError):
        with collections_paused():
            raise RuntimeError("in the block")
    assert gc.isenabled()
    gc.unfreeze()


def test_collections_stay_off_if_they_were_off_before():
    gc.disable()
    try:
        with collections_paused():
            pass
        assert not gc.isenabled()
    finally:
        gc.enable()
        gc.unfreeze()


def test_what_survives_the_block_is_frozen():
    gc.unfreeze()
    with collections_paused():
        kept = [[] for _ in range(100)]
    try:
        assert gc.get_freeze_count() >= len(kept)
    finally:
        gc.unfreeze()
