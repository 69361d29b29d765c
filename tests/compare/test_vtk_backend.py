"""The rendering door: VTK comes in here, after the offscreen check, and arrays cross it both ways."""
import numpy as np

from compare import vtk_backend


def test_the_door_hands_out_vtk_and_pyvista():
    vtk = vtk_backend.vtk()
    assert hasattr(vtk, "vtkRenderWindow") and hasattr(vtk_backend.pyvista(), "Plotter")


def test_arrays_cross_the_door_unchanged():
    values = np.arange(12, dtype=np.float32).reshape(4, 3)
    array = vtk_backend.numpy_to_vtk(values, array_type=vtk_backend.vtk().VTK_FLOAT)
    assert array.GetNumberOfTuples() == 4 and array.GetNumberOfComponents() == 3
    np.testing.assert_array_equal(vtk_backend.vtk_to_numpy(array), values)


def test_importing_the_door_loads_no_vtk():
    """VTK loads on the first call, not on import: the command line starts without it."""
    import subprocess
    import sys

    code = "import sys, compare.vtk_backend; print(any(m.split('.')[0] in ('vtk', 'vtkmodules', 'pyvista') for m in sys.modules))"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout.strip() == "False", done.stderr
