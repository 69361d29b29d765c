"""The renderer's registry of reflection models: every model the scene file knows, found by name.

The ground floor keeps the list of names (``lab.scene.MODELS``, which loading validates);
the registry must cover exactly those, and the dispatch kernel must hand each code to its
own model.
"""
import gc
from dataclasses import replace

import numpy as np
import pytest

from lab.mesh import Mesh
from lab.scene import MODELS, Material, Scene, SceneObject, Camera, Image
from lab.shapes import quad
from renderer.reflection import registry
from renderer.reflection.materials import FACE_COLOUR, PIXEL_AS_GIVEN, PIXEL_TWO_SIDED, VERTEX_COLOUR
from renderer.reflection.registry import CODES, REFLECTION_MODELS, material_table, reflect

from ..kernel_inputs import materials, view_lights


def test_the_registry_covers_exactly_the_scene_models():
    assert set(REFLECTION_MODELS) == set(MODELS)
    assert all(record.name == name for name, record in REFLECTION_MODELS.items())


def test_codes_number_the_models_from_zero():
    assert sorted(CODES.values()) == list(range(len(MODELS)))


@pytest.mark.parametrize("name", MODELS)
def test_reflect_hands_each_code_to_its_own_model(name):
    """At random points, normals and lights: reflect() gives exactly what the model's own kernel gives."""
    rng = np.random.default_rng(CODES[name])
    lights = view_lights([{"direction": rng.normal(size=3), "intensity_rgb": rng.random(3)},
                          {"positional": True, "position": rng.normal(size=3), "attenuation": (1, 0.1, 0.01)}],
                         complexity=3)
    table = materials(rng.random(3), rng.random(3), rng.random(3), 12.0, model=name)
    for _ in range(20):
        n = rng.normal(size=3)
        n /= np.linalg.norm(n)
        p = rng.normal(size=3) - (0, 0, 4)
        assert reflect(n, p, 0, table, lights) == REFLECTION_MODELS[name].lighting(n, p, 0, table, lights)


def smooth_quad():
    flat = quad(1.0)
    return Mesh(flat.points, flat.triangles, point_normals=np.tile([0.0, 0.0, 1.0], (len(flat.points), 1)))


def test_the_material_table_is_filled_by_each_objects_model():
    """One row per object, by its model: code, path, colours; an unlit object is the vtk model's."""
    red = Material(color=(1.0, 0.0, 0.0), ambient=0.5, diffuse=0.25, specular=0.5, specular_power=300.0,
                   shininess=20.0, opacity=0.5)
    objects = tuple(SceneObject(mesh=smooth_quad(), shading=shading, material=Material(**{**red.__dict__,
                                                                                          "model": model}))
                    for model, shading in (("vtk", "phong"), ("opengl", "gouraud"), ("classic", "phong")))
    objects += (SceneObject(mesh=smooth_quad(), material=Material(**{**red.__dict__, "model": "classic",
                                                                     "lighting": False})),)
    table = material_table(Scene(image=Image(), camera=Camera(), lights=(), objects=objects))
    assert table.model.tolist() == [CODES["vtk"], CODES["opengl"], CODES["classic"], CODES["vtk"]]
    assert table.shading_path.tolist()[:3] == [PIXEL_TWO_SIDED, VERTEX_COLOUR, PIXEL_AS_GIVEN]
    assert table.lit.tolist() == [True, True, True, False]
    assert table.power.tolist() == [128.0, 20.0, 300.0, 128.0]
    np.testing.assert_allclose(table.ambient[:3], [[0.5, 0, 0], [1, 0, 0], [0.5, 0, 0]])
    np.testing.assert_allclose(table.opacity, [0.5] * 4)


def test_a_flat_textbook_object_is_lit_once_per_face():
    obj = SceneObject(mesh=smooth_quad(), shading="flat", material=Material(model="opengl"))
    assert material_table(Scene(image=Image(), camera=Camera(), lights=(), objects=(obj,))).shading_path.tolist() \
        == [FACE_COLOUR]


def test_a_scene_keeps_its_material_table_and_a_changed_scene_gets_its_own():
    """The table is made once per scene (frames of one scene share it); a scene made from it
    with another material, even with the same objects' meshes, gets a table of its own; and
    the kept table goes with its scene."""
    obj = SceneObject(mesh=smooth_quad(), material=Material(opacity=0.5))
    scene = Scene(image=Image(), camera=Camera(), lights=(), objects=(obj,))
    first = material_table(scene)
    assert material_table(scene) is first
    assert material_table(replace(scene, camera=Camera(position=(0.0, 0.0, 9.0)))).opacity.tolist() == [0.5]
    other = replace(scene, objects=(replace(obj, material=Material(opacity=0.25)),))
    assert material_table(other).opacity.tolist() == [0.25]
    assert material_table(scene).opacity.tolist() == [0.5]
    kept = len(registry._TABLES)
    del scene, other
    gc.collect()
    assert len(registry._TABLES) == kept - 2


def test_a_span_is_stored_as_round_half_even_of_its_clamped_colours_three_bytes_a_pixel():
    """store_span (one vectorised loop over the bytes of the row, r, g, b side by side) writes
    round_half_even(clamp(c, 0, 1)·255) of each channel, as numpy works it out in float32, for
    colours below 0, above 1, on rounding ties and in between, into a row of a frame
    (H, W, 3), for spans shorter and longer than a vector register; nothing past the span is
    touched."""
    from renderer.jit import njit
    from renderer.reflection.registry import store_span

    @njit
    def into_row(colour, count, rgb, row, first):
        store_span(colour, count, rgb[row, first:first + count])

    rng = np.random.default_rng(3)
    ties = (np.arange(256) + 0.5).astype(np.float32) / np.float32(255)
    for count in (1, 7, 8, 9, 63, 300):
        colour = rng.uniform(-0.2, 1.2, (3, 300)).astype(np.float32)
        colour[:, ::3] = ties[rng.integers(0, 256, (3, 100))]
        rgb = np.full((3, 320, 3), 7, np.uint8)
        into_row(colour, count, rgb, 1, 5)
        expected = np.rint(np.clip(colour[:, :count], np.float32(0), np.float32(1)) * np.float32(255)).astype(np.uint8)
        np.testing.assert_array_equal(rgb[1, 5:5 + count], expected.T)
        rgb[1, 5:5 + count] = 7
        assert (rgb == 7).all() and len(np.unique(expected)) > min(count, 40)
