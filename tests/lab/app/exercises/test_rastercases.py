"""The raster exercise's test meshes and classifier; the slow numpy rule equals the renderer's."""
import numpy as np
import pytest

from lab.app.exercises.rastercases import classify, edge_function_masks, raster_meshes as meshes
from renderer.coverage import triangle_coverage

MESHES = meshes()


@pytest.mark.parametrize("mesh", MESHES, ids=[m.name for m in MESHES])
def test_the_numpy_top_left_rule_is_the_renderer_s_and_no_pixel_is_drawn_twice(mesh):
    kernel = np.array([triangle_coverage(*t, mesh.width, mesh.height) for t in mesh.triangles])
    slow = np.array([edge_function_masks(t, mesh.width, mesh.height) for t in mesh.triangles])
    assert (kernel == slow).all()
    assert kernel.sum(axis=0).max() <= 1, "the triangles of a test mesh must not overlap"


def test_the_meshes_hold_what_the_exercise_promises():
    total = sum(len(m.triangles) for m in MESHES)
    assert 300 <= total <= 600
    area = lambda t: (t[1, 0] - t[0, 0]) * (t[2, 1] - t[0, 1]) - (t[2, 0] - t[0, 0]) * (t[1, 1] - t[0, 1])  # noqa
    every = np.concatenate([m.triangles for m in MESHES])
    areas = np.array([area(t) for t in every])
    assert (areas < 0).sum() >= 50, "clockwise triangles"
    assert (areas == 0).sum() >= 3, "zero-area triangles"
    assert (np.abs(areas) < 1).sum() >= 20, "tiny triangles"
    assert np.abs(every).max() > 1000, "huge triangles"
    assert any(not m.on_grid for m in MESHES)


def test_the_tie_rules_differ_exactly_on_edges_through_pixel_centres():
    """A centre on the shared diagonal of two pixel-aligned triangles: inclusive draws it twice, exclusive never."""
    a = np.array([[0.5, 0.5], [4.5, 0.5], [4.5, 4.5]])
    b = np.array([[0.5, 0.5], [4.5, 4.5], [0.5, 4.5]])
    count = lambda rule: sum(edge_function_masks(t, 6, 6, rule).astype(int) for t in (a, b))  # noqa: E731
    diagonal = np.eye(4, dtype=bool)  # the top-right corner (4, 4) belongs to neither: a top and a right edge
    assert (count("top-left")[:4, :4][diagonal] == 1).all() and count("top-left")[4, 4] == 0
    assert (count("inclusive")[1:4, 1:4][np.eye(3, dtype=bool)] == 2).all()
    assert (count("exclusive")[1:4, 1:4][np.eye(3, dtype=bool)] == 0).all()


def test_pixels_are_classified():
    ref = np.array([[[1, 1, 0]], [[0, 0, 1]]], bool)
    stu = np.array([[[1, 0, 0]], [[1, 0, 0]]], bool)
    c = classify(ref, stu)
    assert [c[k].ravel().tolist() for k in ("correct", "missing", "duplicated", "unexpected")] == \
        [[False, False, False], [False, True, True], [True, False, False], [False, False, False]]
