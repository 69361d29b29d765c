"""Exercises that check themselves (``scanlab exercise list|start|check|grade``).

- :mod:`~lab.app.exercises.exercise_registry`: the exercises by name; each lives in one module of
  :mod:`lab.app.exercises.catalogue` and registers itself.
- :mod:`~lab.app.exercises.diagnoses`: what can be wrong, by stable code, in English and
  Japanese; one module per family.
- :mod:`~lab.app.exercises.sandbox` (parent) and :mod:`~lab.app.exercises.runner`
  (child): the student's code runs in a separate, limited process.
- :mod:`~lab.app.exercises.checker`: one file judged; :mod:`~lab.app.exercises.grader`: a
  class judged in parallel into ``grades.csv`` and ``index.html``;
  :mod:`~lab.app.exercises.command`: the command line.

Importing this package loads nothing.
"""
