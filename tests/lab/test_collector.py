"""The collector's settings for a process that starts, compiles kernels and ends."""
import gc

import pytest

from lab.collector import YOUNG_THRESHOLD, collections_paused, fewer_collections


@pytest.fixture(autouse=True)
def unfrozen():
    yield
    gc.unfreeze()


def test_collections_are_paused_in_the_block_and_on_again_after():
    assert gc.isenabled()
    with collections_paused():
        assert not gc.isenabled()
    assert gc.isenabled()


def test_collections_are_on_again_after_an_error_in_the_block():
    with pytest.raises(RuntimeError):
        with collections_paused():
            raise RuntimeError("in the block")
    assert gc.isenabled()


def test_collections_stay_off_if_they_were_off_before():
    gc.disable()
    try:
        with collections_paused():
            pass
        assert not gc.isenabled()
    finally:
        gc.enable()


def test_what_survives_the_pause_is_frozen():
    gc.unfreeze()
    with collections_paused():
        kept = [[] for _ in range(100)]
    assert gc.get_freeze_count() >= len(kept)


def test_fewer_collections_raise_the_youngest_threshold_and_set_it_back():
    before = gc.get_threshold()
    with fewer_collections():
        assert gc.get_threshold() == (YOUNG_THRESHOLD, *before[1:])
    assert gc.get_threshold() == before


def test_fewer_collections_set_the_threshold_back_after_an_error():
    before = gc.get_threshold()
    with pytest.raises(RuntimeError):
        with fewer_collections(5000):
            assert gc.get_threshold()[0] == 5000
            raise RuntimeError("in the block")
    assert gc.get_threshold() == before


def test_fewer_collections_run_fewer_passes():
    """Counted with the collector's own callback: 50,000 new objects that live on (the
    default threshold set explicitly: the suite runs with fewer collections, tests/conftest.py)."""
    def passes(block):
        count = [0]

        def seen(phase, info):
            count[0] += phase == "start"

        gc.callbacks.append(seen)
        try:
            with block():
                kept = [[] for _ in range(50_000)]
        finally:
            gc.callbacks.remove(seen)
        del kept
        return count[0]

    assert passes(fewer_collections) * 10 < passes(lambda: fewer_collections(700))
