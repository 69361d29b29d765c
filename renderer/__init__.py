"""scanlab's own renderer: the course's polygon pipeline in numpy and numba.

This package never imports vtk or pyvista: it is what the VTK reference checks.
Entry point: :func:`render`. Stages, in order: :mod:`~renderer.transform`,
:mod:`~renderer.camera`, :mod:`~renderer.clip`, :mod:`~renderer.window`,
:mod:`~renderer.raster`, :mod:`~renderer.shading` (with :mod:`~renderer.lighting`),
assembled in :mod:`~renderer.pipeline`.
"""
from renderer.pipeline import RenderOptions, render

__all__ = ["RenderOptions", "render"]
