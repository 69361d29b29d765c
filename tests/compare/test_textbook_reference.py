"""Which reference draws each object, and the replaced shader's frame around its model's GLSL.

The VTK plumbing (unlit colours, vertex attributes, shader replacement) is checked against
real renders in ``test_parity_textbook.py`` and ``test_parity_separate_specular.py``.
"""
import numpy as np

from lab.mesh import Mesh
from lab.scene import Camera, Image, Material, RenderSettings, Scene, SceneObject
from lab.shapes import quad

from compare.lit_reference.eye_space import EyeLight
from compare.textbook_reference import (NATIVE, SHADER, UNLIT, object_reference, phong_shader, scene_reference,
                                       uses_separate_specular)

FLAT = quad(1.0)
SMOOTH = Mesh(FLAT.points, FLAT.triangles, point_normals=np.tile([0.0, 0.0, 1.0], (len(FLAT.points), 1)))


def obj(model, shading="phong", **material):
    return SceneObject(mesh=SMOOTH, shading=shading, material=Material(model=model, **material))


def scene(*objects, **render):
    return Scene(image=Image(), camera=Camera(), lights=(), objects=objects, render=RenderSettings(**render))


def test_each_object_gets_its_models_reference_unless_native_is_forced():
    assert object_reference(obj("vtk")) == NATIVE
    assert object_reference(obj("classic")) == SHADER
    assert object_reference(obj("opengl", "gouraud")) == UNLIT
    assert object_reference(obj("opengl", lighting=False)) == NATIVE
    assert object_reference(obj("classic"), forced=NATIVE) == NATIVE


def test_the_scene_is_named_by_its_least_native_reference():
    assert scene_reference(scene(obj("vtk"), obj("opengl", "flat"))) == UNLIT
    assert scene_reference(scene(obj("vtk"), obj("opengl", "flat"), obj("classic"))) == SHADER
    assert scene_reference(scene(obj("classic")), forced=NATIVE) == NATIVE


def test_only_the_opengl_model_keeps_a_separate_specular_and_only_when_asked():
    on = scene(separate_specular=True)
    assert uses_separate_specular(obj("opengl"), on)
    assert not uses_separate_specular(obj("opengl"), scene())
    assert not uses_separate_specular(obj("classic"), on) and not uses_separate_specular(obj("vtk"), on)


def test_the_phong_shader_undoes_vtks_two_sided_normal_and_writes_the_opacity():
    code = phong_shader(obj("classic", opacity=0.25), scene(), [EyeLight()])
    assert code.startswith("  vec3 n = normalize(normalVCVSOutput);\n  if (!gl_FrontFacing) { n = -n; }\n")
    assert code.endswith("  fragOutput0 = vec4(clamp(c, 0.0, 1.0), 0.25);\n")
