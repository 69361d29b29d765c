"""The worker plugin: travels to the workers without its processes, one case process per thread."""
from __future__ import annotations

import pickle
import threading

from lab.app.sweep.case_runner import PLUGIN_NAME, CaseRunner


def test_the_plugin_pickles_to_a_fresh_one_with_the_same_memory_limit():
    runner = CaseRunner(memory_limit=1 << 30)
    first = runner.process()
    copy = pickle.loads(pickle.dumps(runner))
    assert copy.memory_limit == 1 << 30 and copy._processes == {}
    assert copy.name == PLUGIN_NAME and first.memory_limit == 1 << 30


def test_each_thread_gets_its_own_case_process_and_teardown_closes_them():
    runner = CaseRunner()
    here = runner.process()
    assert runner.process() is here
    other = []
    thread = threading.Thread(target=lambda: other.append(runner.process()))
    thread.start()
    thread.join()
    assert other[0] is not here
    runner.teardown(worker=None)
    assert runner._processes == {}
