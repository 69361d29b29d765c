"""The cyclic garbage collector's settings for a process that starts, compiles kernels and
ends: a fresh ``scanlab render`` and its compile helper.

Python's collector runs each time 700 more objects have been made than freed, and every
tenth run also walks the older objects, every hundredth all of them. Importing numba and
compiling kernels make hundreds of thousands of objects that live on, so most of those runs
find nothing:

- **Importing.** Importing the renderer's modules ran 175 passes (about 60 ms of a warm
  start of about 1 s). :func:`collections_paused` turns the collector off for a ``with``
  block and, at its end, moves what the block made into the collector's permanent
  generation (``gc.freeze``), so later passes do not walk it again; then it turns the
  collector back on. Keep compiling out of such a block: numba's compiler does make
  garbage, and a cold start of a textured scene with the collector off peaked at 1.8 GB.
- **Compiling.** A cold first frame of ``icosphere:level=5`` in one process ran 2,234
  passes, 2.0 s of its 19.6 s (1.4 s after a frozen import). :func:`fewer_collections`
  collects the youngest objects after :data:`YOUNG_THRESHOLD` new ones instead: 238 passes,
  0.65 s, and a peak of 272 MB instead of 253.
"""
import contextlib
import gc

YOUNG_THRESHOLD = 20_000
"""New objects between two collections of the youngest generation in :func:`fewer_collections` (Python's default: 700)."""


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


@contextlib.contextmanager
def fewer_collections(young: int = YOUNG_THRESHOLD):
    """A ``with`` block in which the youngest generation is collected after ``young`` new
    objects; the thresholds before it are set again after it."""
    before = gc.get_threshold()
    gc.set_threshold(young, *before[1:])
    try:
        yield
    finally:
        gc.set_threshold(*before)
