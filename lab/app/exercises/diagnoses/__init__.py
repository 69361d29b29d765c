"""Diagnoses: every way a submission can be wrong or unjudgeable, by stable code.

The registry is :mod:`~lab.app.exercises.diagnoses.registry`; each family registers its
codes in its own module (``runtime``, ``mesh``, ``normals``, ``matrices``, ``raster``).
Importing this package loads nothing.
"""
