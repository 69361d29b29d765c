"""Ctrl-C during a sweep: the first SIGINT only asks to stop (no exception, wherever the main
thread is); a second one interrupts at once; leaving the context puts the old handler back."""
from __future__ import annotations

import io
import signal
import threading

import pytest

from lab.app.sweep.interrupts import STOPPING, StopRequest


def ctrl_c():
    """SIGINT to this (the main) thread, its handler run before this returns. A SIGINT sent to
    the process may be taken by another of its threads (numba's workers, started by earlier
    tests in the same process); the main thread then runs the handler some bytecodes later,
    and a test that expects the exception at once saw none (CI, one run in many)."""
    signal.raise_signal(signal.SIGINT)


def test_the_first_ctrl_c_sets_requested_and_says_how_to_stop_at_once():
    said = io.StringIO()
    with StopRequest(stream=said) as stop:
        assert not stop() and not stop.requested
        ctrl_c()
        assert stop.requested and stop()
    assert said.getvalue().strip() == STOPPING and "Ctrl-C again" in STOPPING


@pytest.fixture
def python_handler():
    """Python's own SIGINT handler in place for the test, and whatever was there put back after:
    the suite runs many tests in one process, and once (CI, a clean clone) an earlier one left
    another handler, which a second Ctrl-C then went to instead of raising."""
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, before)


def test_a_second_ctrl_c_raises_keyboard_interrupt(python_handler):
    """The first Ctrl-C puts back the handler that was there before (Python's own here), so the
    second goes to it and raises KeyboardInterrupt at once."""
    with StopRequest(stream=io.StringIO()) as stop:
        ctrl_c()
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
        with pytest.raises(KeyboardInterrupt):
            ctrl_c()
    assert stop.requested


def test_leaving_the_context_puts_the_previous_handler_back():
    before = signal.getsignal(signal.SIGINT)
    with StopRequest():
        assert signal.getsignal(signal.SIGINT) is not before
    assert signal.getsignal(signal.SIGINT) is before


def test_outside_the_main_thread_it_does_nothing():
    seen = {}

    def enter():
        with StopRequest() as stop:
            seen["requested"] = stop.requested
            seen["handler"] = signal.getsignal(signal.SIGINT)

    before = signal.getsignal(signal.SIGINT)
    worker = threading.Thread(target=enter)
    worker.start()
    worker.join()
    assert seen == {"requested": False, "handler": before}
