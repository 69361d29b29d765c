"""The rendering door to VTK: offscreen set-up, the check that an OpenGL context exists, and
the VTK modules the reference uses.

No other module of ``compare/`` imports vtk, vtkmodules or pyvista: they ask here
(:func:`pyvista`, :func:`vtk`, :func:`numpy_to_vtk`, :func:`vtk_to_numpy`), and VTK loads on
the first call, after the offscreen check, never on import (``tests/test_doors.py``
checks). The ground floor has a door of its own for reading mesh files
(``lab/meshfiles/vtk_readers.py``). ``VTK_DEFAULT_OPENGL_WINDOW`` must be set before VTK
loads; EGL (Mesa's llvmpipe on a machine with no display) is the default.
"""
from __future__ import annotations

import functools
import os
import re
import subprocess
import sys

os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")

PACKAGES_HINT = ("install Mesa's offscreen OpenGL: on Debian/Ubuntu `apt-get install libegl1 libegl-mesa0 "
                 "libgl1-mesa-dri` (EGL), or `libosmesa6` with VTK_DEFAULT_OPENGL_WINDOW=vtkOSOpenGLRenderWindow")

_PROBE = """
import os
os.environ.setdefault("VTK_DEFAULT_OPENGL_WINDOW", "vtkEGLRenderWindow")
import vtk
rw = vtk.vtkRenderWindow(); rw.SetOffScreenRendering(1); rw.SetSize(8, 8)
rw.AddRenderer(vtk.vtkRenderer()); rw.Render()
raise SystemExit(0 if rw.SupportsOpenGL() else 3)
"""


class ReferenceUnavailable(RuntimeError):
    """VTK cannot draw here (no offscreen OpenGL context, or vtk missing)."""


@functools.lru_cache(maxsize=1)
def check_offscreen_gl() -> None:
    """Make sure VTK can open an offscreen OpenGL context; raise :class:`ReferenceUnavailable` if not.

    The probe runs in a child process, because a failed context can abort the process
    that tried it. Runs once per process.
    """
    try:
        result = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, timeout=120, text=True)
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise ReferenceUnavailable(f"VTK offscreen OpenGL probe failed ({exc}); {PACKAGES_HINT}") from None
    if result.returncode != 0:
        lines = re.sub(r"\x1b\[[0-9;]*m", "", result.stderr).strip().splitlines() or ["no message"]
        last = lines[-1].rsplit("| ", 1)[-1].strip()[:160]
        if "No module named" in last:
            raise ReferenceUnavailable(f"VTK is not installed ({last}); run `make demo` or `pip install -e .`")
        raise ReferenceUnavailable(f"VTK could not create an offscreen OpenGL context ({last}); {PACKAGES_HINT}")


def pyvista():
    """Import and return pyvista after the offscreen check."""
    check_offscreen_gl()
    import pyvista as pv

    return pv


def vtk():
    """Import and return the ``vtk`` module (every VTK class the reference uses) after the
    offscreen check."""
    check_offscreen_gl()
    import vtk as vtk_module

    return vtk_module


def numpy_to_vtk(values, deep: bool = True, array_type=None):
    """VTK's ``numpy_support.numpy_to_vtk``: a VTK data array holding ``values``."""
    from vtkmodules.util.numpy_support import numpy_to_vtk as convert

    return convert(values, deep=deep, array_type=array_type)


def vtk_to_numpy(array):
    """VTK's ``numpy_support.vtk_to_numpy``: a numpy view of a VTK data array."""
    from vtkmodules.util.numpy_support import vtk_to_numpy as convert

    return convert(array)
