"""scanlab's own renderer: the course's polygon pipeline in numpy and numba.

This package never imports vtk or pyvista: it is what the VTK reference checks. It
imports only the ground floor (``lab``'s scene model), numpy and numba.
Entry point: :func:`render`. Stages, in order: :mod:`~renderer.transform`,
:mod:`~renderer.camera`, :mod:`~renderer.clip`, :mod:`~renderer.window`,
:mod:`~renderer.raster`, :mod:`~renderer.lit_colours` and :mod:`~renderer.shading` (with the
reflection models of :mod:`~renderer.reflection` and the lights of :mod:`~renderer.lights`),
:mod:`~renderer.translucency`, assembled in :mod:`~renderer.pipeline`.

Importing the package loads nothing: ``render``, ``render_stages``, ``Stages`` and
``RenderOptions`` come from :mod:`renderer.pipeline` on first use, so
``import renderer.camera`` does not compile or load the kernels.
"""

__all__ = ["RenderOptions", "Stages", "render", "render_stages"]


def __getattr__(name):
    if name in __all__:
        from renderer import pipeline

        return getattr(pipeline, name)
    raise AttributeError(f"module 'renderer' has no attribute {name!r}")
