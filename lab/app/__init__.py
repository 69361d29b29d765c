"""The application, the top floor: the ``scanlab`` command line, the demo, the loader fuzzer.

It imports every floor below it (the ground floor ``lab``, ``renderer``, ``compare``);
nothing below imports it. See docs/development.md, "Layout".
"""
