"""The vtk model's reference: VTK itself, with the scene's material as it is."""
from lab.scene import Material, SceneObject
from lab.shapes import quad

from compare.lit_reference.reference_kinds import NATIVE
from compare.lit_reference.vtk_lit import REFERENCE, native, vtk_property


def test_vtk_draws_the_vtk_model_natively():
    obj = SceneObject(mesh=quad(1.0), shading="phong")
    assert native(obj) == REFERENCE.reference(obj) == NATIVE
    assert REFERENCE.separate_specular(None) is False


def test_the_property_is_the_scenes_material():
    """Colour for ambient and diffuse, the specular colour (the colour when unset), Ka, Kd, Ks, power as given
    (VTK clamps it at 128 itself)."""
    m = Material(color=(1.0, 0.5, 0.0), ambient=0.1, diffuse=0.7, specular=0.3, specular_power=500.0)
    v = vtk_property(SceneObject(mesh=quad(1.0), material=m), None)
    assert v == dict(ambient_color=(1.0, 0.5, 0.0), ambient=0.1, diffuse_color=(1.0, 0.5, 0.0), diffuse=0.7,
                     specular_color=(1.0, 0.5, 0.0), specular=0.3, power=500.0)


def test_a_specular_colour_of_its_own_is_kept():
    m = Material(color=(1.0, 0.5, 0.0), specular_color=(0.0, 0.0, 1.0))
    assert vtk_property(SceneObject(mesh=quad(1.0), material=m), None)["specular_color"] == (0.0, 0.0, 1.0)
