"""The scene model's own arithmetic: world bounds of an object and of a scene."""
from dataclasses import replace

import numpy as np

from lab.matrices import model_matrix
from lab.mesh import Mesh
from lab.scene import Camera, Image, Scene, SceneObject


def square() -> Mesh:
    return Mesh(np.array([[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]), np.array([[0, 1, 2], [0, 2, 3]]))


def test_an_objects_world_bounds_are_its_model_box_carried_to_the_world():
    """A unit square turned 45° about z and moved: the turned box's corners, as VTK's GetBounds."""
    obj = SceneObject(mesh=square(), model_to_world=model_matrix(rotate=(0, 0, 45), translate=(2, 0, 0)))
    r = np.sqrt(0.5)
    np.testing.assert_allclose(obj.world_bounds(), [2 - r, 2 + r, 0, 2 * r, 0, 0], atol=1e-12)


def test_world_bounds_are_worked_out_once_and_handed_out_as_copies():
    obj = SceneObject(mesh=square(), model_to_world=model_matrix(translate=(0, 0, 5)))
    first = obj.world_bounds()
    first[:] = 99.0  # a caller scribbling on its copy
    np.testing.assert_array_equal(obj.world_bounds(), [0, 1, 0, 1, 5, 5])
    assert obj.world_bounds() is not obj.world_bounds()
    moved = replace(obj, model_to_world=model_matrix(translate=(0, 0, -5)))  # a new object, its own bounds
    np.testing.assert_array_equal(moved.world_bounds(), [0, 1, 0, 1, -5, -5])


def test_a_scenes_world_bounds_hold_every_object_and_an_empty_scene_a_unit_box():
    a = SceneObject(mesh=square())
    b = SceneObject(mesh=square(), model_to_world=model_matrix(translate=(3, -2, 1)))
    scene = Scene(image=Image(), camera=Camera(), lights=(), objects=(a, b))
    np.testing.assert_array_equal(scene.world_bounds(), [0, 4, -2, 1, 0, 1])
    np.testing.assert_array_equal(replace(scene, objects=()).world_bounds(), [-1, 1, -1, 1, -1, 1])
