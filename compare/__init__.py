"""The reference and the comparison: VTK draws what scanlab draws, and the difference is measured.

The Python API, for a notebook or a script::

    import compare
    result = compare.compare("spot-attenuation")        # a preset, shape, scene or mesh file,
    result.passed, result.metrics["delta_e_2000"]       # a lab.scene.Scene or a pyvista.Plotter
    result                                              # a notebook cell shows the panel

    scene = compare.scene_from_plotter(plotter)         # a PyVista Plotter as a scanlab scene

Importing the package loads nothing heavy: :func:`compare`, :func:`scene_from_plotter`,
:class:`Comparison` and :class:`PlotterError` come from their modules
(:mod:`compare.comparison`, :mod:`compare.from_plotter`) on first use, and VTK only when
a reference is drawn.
"""

_LAZY = {"compare": "compare.comparison", "Comparison": "compare.comparison", "run_comparison": "compare.comparison",
         "scene_from_plotter": "compare.from_plotter", "PlotterError": "compare.from_plotter"}

__all__ = sorted(_LAZY)


def __getattr__(name):
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'compare' has no attribute {name!r}")
