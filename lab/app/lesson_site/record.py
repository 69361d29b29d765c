"""What the figure directives leave in Sphinx's build environment, per page.

The directives run while pages are read, possibly in several processes (``-j 2``); what
they note here is merged back into the main process (:func:`merge`) and forgotten when a
page is read again (:func:`purge`). Three things per page: the cache keys of its
figures (copied to ``_figures/`` when the site is written), the scene files it shows
(copied to ``_scenes/``), and the figures whose verdict broke the lesson's promise.
"""
from __future__ import annotations

FIELDS = ("scanlab_figures", "scanlab_scenes", "scanlab_problems")


def _table(env, name: str) -> dict:
    if not hasattr(env, name):
        setattr(env, name, {})
    return getattr(env, name)


def figure(env, key: str) -> None:
    _table(env, "scanlab_figures").setdefault(env.docname, set()).add(key)


def scene(env, path: str) -> None:
    _table(env, "scanlab_scenes").setdefault(env.docname, set()).add(path)


def problem(env, text: str) -> None:
    _table(env, "scanlab_problems").setdefault(env.docname, []).append(text)


def all_of(env, name: str) -> dict:
    """``{docname: value}`` of one of :data:`FIELDS`."""
    return _table(env, name)


def purge(app, env, docname: str) -> None:
    for name in FIELDS:
        _table(env, name).pop(docname, None)


def merge(app, env, docnames, other) -> None:
    for name in FIELDS:
        mine, theirs = _table(env, name), _table(other, name)
        for docname in docnames:
            if docname in theirs:
                mine[docname] = theirs[docname]
