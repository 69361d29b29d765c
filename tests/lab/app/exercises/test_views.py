"""Pictures of a submission: what can be drawn, and the comparison through the parity bars (real VTK)."""
import numpy as np

from lab import shapes
from lab.app.exercises.views import View, compare_meshes, renderable
from lab.mesh import Mesh

REF = shapes.icosphere(1)
VIEW = View(position=(1.6, 2.4, 3.4), size=(96, 96))


def test_only_sane_meshes_are_drawn():
    assert renderable(REF, REF)
    assert not renderable(Mesh(REF.points * np.nan, REF.triangles), REF)
    assert not renderable(Mesh(REF.points, REF.triangles + 100), REF)
    assert not renderable(Mesh(REF.points * 1e6, REF.triangles), REF)
    assert not renderable(Mesh(REF.points, REF.triangles[:0]), REF)


def test_the_same_surface_meets_the_bars_and_another_does_not(tmp_path):
    same = compare_meshes("icosphere(1)", Mesh(REF.points[::-1], (len(REF.points) - 1 - REF.triangles)[:, [1, 2, 0]]),
                          REF, VIEW, "test-views")
    assert same.failed == []
    other = compare_meshes("icosphere(1)", shapes.icosphere(0), REF, VIEW, "test-views")
    assert other.failed and other.metrics["coverage_mismatch"] > 0
    panel, vtk = other.write(tmp_path, "x")
    assert panel.stat().st_size > 5000 and vtk.stat().st_size > 500
