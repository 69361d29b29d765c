"""lab/framing.py: a mesh file given where a scene is expected is framed like a built-in shape."""
import numpy as np
import pytest

from lab.loading import SceneError, load_scene
from lab.meshfiles import write_mesh
from lab.presets import SCENES_DIR
from lab.shapes import icosphere


def test_a_mesh_file_is_a_scene_framed_with_one_headlight_like_a_shape(tmp_path):
    """The same icosphere as a built-in shape and as a PLY file: the same camera, material and light."""
    path = tmp_path / "ball.ply"
    write_mesh(icosphere(level=2), path)
    from_file, from_shape = load_scene(str(path)), load_scene("icosphere:level=2")
    assert from_file.camera == from_shape.camera and from_file.lights == from_shape.lights
    assert from_file.objects[0].material == from_shape.objects[0].material
    assert np.allclose(from_file.objects[0].mesh.points, from_shape.objects[0].mesh.points)
    assert from_file.objects[0].name == "ball" and from_file.inputs == (str(path),)


def test_the_torus_of_the_presets_loads_as_a_scene():
    scene = load_scene(SCENES_DIR / "models" / "torus.ply")
    assert scene.objects[0].mesh.n_triangles == 1024 and scene.objects[0].mesh.point_normals is not None


def test_a_folder_or_a_broken_mesh_is_one_line(tmp_path):
    with pytest.raises(SceneError, match="is a folder, not a scene file or mesh file"):
        load_scene(str(tmp_path))
    (tmp_path / "bad.stl").write_text("hello")
    with pytest.raises(SceneError, match="bad.stl"):
        load_scene(str(tmp_path / "bad.stl"))
