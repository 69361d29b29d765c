"""Reflection models, one module each, found through :mod:`renderer.reflection.registry`.

:mod:`~renderer.reflection.vtk_model` (VTK's own), :mod:`~renderer.reflection.opengl_model`
(fixed-function OpenGL) and :mod:`~renderer.reflection.classic_model` (the course's) each
hold a model's lighting kernel, its material row and its choice of shading path;
:mod:`~renderer.reflection.materials` holds what they share. Importing the package loads
nothing.
"""
