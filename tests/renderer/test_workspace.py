"""Memory kept from one frame to the next: named scratch arrays reused while they fit, and
freed frames served again from the heap instead of pages faulted in afresh."""
from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np

from renderer.workspace import KEEPS_FREED_MEMORY, Workspace, empty, kept, zeros


def test_an_array_is_reused_while_it_fits_and_replaced_when_it_does_not():
    ws = Workspace()
    a = ws.array("depth", (100, 10), np.int32)
    assert np.shares_memory(ws.array("depth", (50, 10), np.int32), a)
    assert not np.shares_memory(ws.array("depth", (200, 10), np.int32), a), "too small: a new one"
    b = ws.array("depth", (200, 10), np.int32)
    assert not np.shares_memory(ws.array("depth", (200, 10), np.float32), b), "another dtype: a new one"
    assert ws.array("other", 3).shape == (3,) and empty(None, "x", (2, 2)).shape == (2, 2)


def test_a_shape_may_be_an_int_a_tuple_a_list_or_numbers_from_numpy():
    ws = Workspace()
    assert ws.array("a", np.int64(4), np.uint8).shape == (4,) and ws.array("b", 0).shape == (0,)
    assert ws.array("c", [2, np.int32(3)]).shape == (2, 3) and ws.array("d", np.array([3, 2])).shape == (3, 2)
    assert ws.array("e", (np.int64(5), 1), np.int64).dtype == np.int64


def test_a_kept_table_is_built_again_only_when_its_key_changes():
    ws, built = Workspace(), []

    def build(n):
        built.append(n)
        return np.full(n, n)

    a = ws.kept("objects", (3,), lambda: build(3))
    assert ws.kept("objects", (3,), lambda: build(3)) is a and built == [3]
    assert ws.kept("objects", (4,), lambda: build(4)).tolist() == [4] * 4 and built == [3, 4]
    assert ws.kept("objects", (3,), lambda: build(3)) is not a and built == [3, 4, 3]
    assert kept(None, "objects", (2,), lambda: build(2)).tolist() == [2, 2]


def test_a_zeros_table_is_zero_when_made_and_grown_and_kept_as_its_callers_leave_it():
    ws = Workspace()
    a = ws.zeros("number", 5)
    assert a.tolist() == [0] * 5 and a.dtype == np.int64
    a[2] = 9
    assert np.shares_memory(ws.zeros("number", 4), a) and ws.zeros("number", 4)[2] == 9, "not filled again"
    a[2] = 0
    grown = ws.zeros("number", 50)
    assert not np.shares_memory(grown, a) and not grown.any()
    assert ws.zeros("n32", 3, np.int32).dtype == np.int32 and not zeros(None, "x", 6).any()


FRAMES = """
import json, resource, sys, numpy as np
if sys.argv[1] == "renderer":
    import renderer.workspace
faults = []
for i in range(8):
    before = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
    frames = [np.empty((1024, 1024)) for _ in range(4)]  # 32 MB, written, then freed together
    for frame in frames:
        frame[:] = 1.0
    del frames, frame
    faults.append(resource.getrusage(resource.RUSAGE_SELF).ru_minflt - before)
print(json.dumps(faults[2:]))
"""


def faults_per_frame(importing: str, environment=None) -> list[int]:
    """Minor page faults of each of the last frames of :data:`FRAMES` in a fresh process,
    ``importing`` "renderer" (its workspace module) or "numpy" alone."""
    done = subprocess.run([sys.executable, "-c", FRAMES, importing], capture_output=True, text=True, timeout=120,
                          env={**os.environ, **(environment or {})})
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_freed_frames_are_served_again_without_faulting_their_pages_in():
    """32 MB allocated, written and freed together, again and again: in a process that imported
    the renderer, no page is faulted in after the first frame; with glibc's own moving
    thresholds, the freed top of the heap is given back each time and faulted in again
    (about 2,000 faults a frame here). A trim threshold the user set is kept."""
    assert KEEPS_FREED_MEMORY
    assert max(faults_per_frame("renderer")) < 100
    assert min(faults_per_frame("numpy")) > 1000
    assert min(faults_per_frame("renderer", {"MALLOC_TRIM_THRESHOLD_": "131072"})) > 1000
