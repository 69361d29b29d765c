"""The compare side's registry of reflection models: every model the scene file knows, found by name."""
from lab.scene import MODELS, Material, SceneObject
from lab.shapes import quad

from compare.lit_reference.lit_registry import LIT_REFERENCES, lit_reference


def test_the_registry_covers_exactly_the_scene_models():
    assert set(LIT_REFERENCES) == set(MODELS)
    assert all(record.name == name for name, record in LIT_REFERENCES.items())


def test_an_object_finds_its_models_reference_and_an_unlit_one_finds_vtks():
    lit = SceneObject(mesh=quad(1.0), material=Material(model="opengl"))
    unlit = SceneObject(mesh=quad(1.0), material=Material(model="opengl", lighting=False))
    assert lit_reference(lit) is LIT_REFERENCES["opengl"]
    assert lit_reference(unlit) is LIT_REFERENCES["vtk"]


def test_only_a_native_model_needs_no_numpy_lighting_or_glsl():
    for record in LIT_REFERENCES.values():
        native = record.lit is None
        assert native == (record.glsl is None)
