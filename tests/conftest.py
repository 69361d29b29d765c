"""Hypothesis profiles for the property-based tests (``tests/*/test_properties.py``).

``HYPOTHESIS_PROFILE=ci`` (the default): few examples, derandomized, so every run of
``make test`` draws the same scenes. ``HYPOTHESIS_PROFILE=thorough``: ten times as many,
freshly random each run, for hunting bugs.

Frames in the tests use the threads they are set to, however busy the machine is
(``SCANLAB_DYNAMIC_THREADS=0``, :mod:`renderer.free_cores`): a test that compares one thread
with two must really draw with two. ``tests/renderer/test_free_cores.py`` turns it back on.

The suite compiles most kernels, and runs with the collector's youngest generation collected
after :data:`lab.collector.YOUNG_THRESHOLD` new objects, as ``scanlab render`` and its
compile helper do (:func:`lab.collector.fewer_collections`).
"""
import os

import pytest
from hypothesis import HealthCheck, settings

from lab.collector import fewer_collections

_common = dict(deadline=None, print_blob=True,
               suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.filter_too_much])
settings.register_profile("ci", max_examples=40, derandomize=True, database=None, **_common)
settings.register_profile("thorough", max_examples=400, **_common)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
os.environ["SCANLAB_DYNAMIC_THREADS"] = "0"


@pytest.fixture(autouse=True, scope="session")
def _fewer_collections():
    with fewer_collections():
        yield
