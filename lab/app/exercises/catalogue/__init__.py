"""The exercises, one module each; every module registers its exercise with
:func:`lab.app.exercises.exercise_registry.register` when it is imported. Adding an exercise is
adding a module here: :func:`lab.app.exercises.exercise_registry.exercises` finds it."""
