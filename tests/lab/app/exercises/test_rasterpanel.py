"""The raster picture: the meshes with the most wrong pixels, each pixel coloured by class."""
import numpy as np

from lab.app.exercises.rasterpanel import COLOURS, RasterPanel
from lab.app.exercises.rastercases import RasterMesh, classify


def panel(wrong_in):
    meshes, refs, studs, classes = [], [], [], []
    for i in range(6):
        tri = np.array([[[0.5, 0.5], [6.5, 0.5], [0.5, 6.5]]])
        ref = np.zeros((1, 8, 8), bool)
        ref[0, :3, :3] = True
        stu = ref.copy()
        if i == wrong_in:
            stu[0, 0, 0] = False
        meshes.append(RasterMesh(f"m{i}", f"m{i}", 8, 8, tri))
        refs.append(ref), studs.append(stu), classes.append(classify(ref, stu))
    return RasterPanel(meshes, refs, studs, classes)


def test_the_mesh_with_wrong_pixels_is_shown_and_coloured():
    p = panel(wrong_in=5)
    assert p.chosen() == [5]
    image = p.image(5)
    assert tuple(image[0, 0]) == COLOURS["missing"] and tuple(image[1, 1]) == COLOURS["correct"]
    assert tuple(image[7, 7]) == COLOURS["background"]


def test_without_mistakes_the_first_four_are_shown(tmp_path):
    p = panel(wrong_in=-1)
    assert p.chosen() == [0, 1, 2, 3]
    (path,) = p.write(tmp_path, "right")
    assert path.name == "right-panel.png" and path.stat().st_size > 5000
