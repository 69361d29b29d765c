"""A command's process ends without the interpreter's teardown, after its threads, atexit handlers and streams."""
import os
import subprocess
import sys
import textwrap

from lab.app import process_exit

ENDING = textwrap.dedent("""
    import atexit, sys, threading, time
    from lab.app.process_exit import exit_now

    class Noisy:
        def __del__(self):
            sys.stderr.write("torn down\\n")

    kept = Noisy()  # a module global: freed by the interpreter's teardown
    atexit.register(lambda: open(sys.argv[1] + "/atexit", "w").close())

    def late():
        time.sleep(0.3)
        open(sys.argv[1] + "/thread", "w").close()

    if "thread" in sys.argv[2:]:
        threading.Thread(target=late).start()
    sys.stdout.write("no newline, still buffered")
    {end}
""")


def _run(tmp_path, end: str, *options: str):
    buffered = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}  # stdout to a pipe keeps its buffer
    return subprocess.run([sys.executable, "-c", ENDING.format(end=end), str(tmp_path), *options],
                          capture_output=True, text=True, timeout=60, env=buffered)


def test_exit_now_runs_atexit_flushes_and_skips_the_teardown(tmp_path):
    done = _run(tmp_path, "exit_now(3)")
    assert done.returncode == 3
    assert done.stdout == "no newline, still buffered"
    assert (tmp_path / "atexit").exists()
    assert "torn down" not in done.stderr


def test_with_a_thread_to_join_exit_now_leaves_the_ending_to_the_shutdown(tmp_path):
    """A live thread that is not a daemon: joined (its file is written), then the teardown runs."""
    done = _run(tmp_path, "exit_now(3)", "thread")
    assert done.returncode == 3
    assert done.stdout == "no newline, still buffered"
    assert (tmp_path / "thread").exists() and (tmp_path / "atexit").exists()
    assert "torn down" in done.stderr


def test_a_thread_pool_left_open_does_not_hang_the_exit():
    """concurrent.futures' idle workers leave only when the shutdown tells them to."""
    script = ("from concurrent.futures import ThreadPoolExecutor\n"
              "from lab.app.process_exit import exit_now\n"
              "pool = ThreadPoolExecutor(2); pool.submit(print, 'ran').result()\n"
              "exit_now(0)\n")
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=20)
    assert done.returncode == 0 and done.stdout == "ran\n"


def test_the_plain_exit_tears_down_what_exit_now_skips(tmp_path):
    """The control: the same script ended by sys.exit runs the __del__ that exit_now skips."""
    done = _run(tmp_path, "sys.exit(3)")
    assert done.returncode == 3 and "torn down" in done.stderr


def test_a_profiler_still_writes_its_figures(tmp_path):
    """python -m cProfile writes after the program returns: exit_now leaves the ending to the shutdown."""
    script = tmp_path / "ends.py"
    script.write_text("from lab.app.process_exit import exit_now\nexit_now(0)\n")
    figures = tmp_path / "figures.prof"
    done = subprocess.run([sys.executable, "-m", "cProfile", "-o", str(figures), str(script)],
                          capture_output=True, text=True, timeout=60)
    assert done.returncode == 0 and figures.exists()


def test_exit_now_of_none_is_success(tmp_path):
    assert _run(tmp_path, "exit_now(None)").returncode == 0


def test_a_reader_that_left_is_not_an_error():
    class Gone:
        def flush(self):
            raise BrokenPipeError

    process_exit._flush(Gone())
    process_exit._flush(None)
