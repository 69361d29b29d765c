"""Diagnoses: every way a submission can be wrong or unjudgeable, by stable code.

The registry is :mod:`~lab.app.exercises.diagnoses.codes`; each family registers its
codes in its own module (``runtime_faults``, ``mesh_faults``, ``normal_faults``,
``matrix_faults``, ``raster_faults``).
Importing this package loads nothing.
"""
