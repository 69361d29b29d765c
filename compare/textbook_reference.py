"""References for the textbook models: VTK draws colours that numpy lit, or a replaced shader.

VTK cannot light the way fixed-function OpenGL or the course does (its "Gouraud" is
per-pixel Phong). So for an object with ``model = "opengl" | "classic"`` the colours are
computed by the model's lit reference (:mod:`compare.lit_reference`: numpy, written apart
from ``renderer/``) — per vertex for gouraud, per triangle for flat — and VTK draws them
unlit as point or cell RGB; for phong, VTK's fragment lighting is replaced by GLSL of the
model's formula. VTK then checks our rasterisation and (perspective-correct) colour
interpolation, and the numpy code checks our lighting. Which reference an object gets,
and everything model-specific, comes from
:data:`compare.lit_reference.lit_registry.LIT_REFERENCES`; this module holds the VTK
plumbing they share.

Everything is taken from VTK's own objects: the model and view matrices of the actor and
camera, and each light's transformed position after VTK has placed headlights and camera
lights. Cell colours reach VTK as 8-bit RGB, vertex colours as a float attribute (see
:func:`paint_unlit`).
"""
from __future__ import annotations

import numpy as np

from compare.lit_reference.eye_space import EyeLight, face_points_and_normals
from compare.lit_reference.lit_registry import lit_reference
from compare.lit_reference.reference_kinds import NATIVE, NONE, REFERENCES, SHADER, UNLIT  # noqa: F401
from compare.vtk_backend import numpy_to_vtk, vtk, vtk_to_numpy


def object_reference(obj, forced: str | None = None) -> str:
    """Which reference draws ``obj``: VTK's own shading, unlit colours, or a replaced shader
    (by its model's :class:`~compare.lit_reference.reference_kinds.LitReference`, unless
    ``forced`` is :data:`NATIVE`)."""
    return NATIVE if forced == NATIVE else lit_reference(obj).reference(obj)


def uses_separate_specular(obj, scene) -> bool:
    """Whether ``obj``'s specular colour is added after the texture (its model and the scene say so)."""
    return lit_reference(obj).separate_specular(scene)


def scene_reference(scene, forced: str | None = None) -> str:
    """One name for the whole scene: the least native reference any object needs."""
    kinds = {object_reference(o, forced) for o in scene.objects}
    for name in (SHADER, UNLIT):
        if name in kinds:
            return name
    return NATIVE


def _matrix(vtk_matrix) -> np.ndarray:
    return np.array([[vtk_matrix.GetElement(i, j) for j in range(4)] for i in range(4)])


def eye_lights(renderer) -> list[EyeLight]:
    """VTK's switched-on lights in view space, after it has placed headlights and camera lights."""
    renderer.UpdateLightsGeometryToFollowCamera()
    view = _matrix(renderer.GetActiveCamera().GetViewTransformMatrix())
    out = []
    lights = renderer.GetLights()
    lights.InitTraversal()
    for _ in range(lights.GetNumberOfItems()):
        li = lights.GetNextItem()
        if not li.GetSwitch():
            continue
        pos = view @ np.append(li.GetTransformedPosition(), 1.0)
        foc = view @ np.append(li.GetTransformedFocalPoint(), 1.0)
        direction = foc[:3] - pos[:3]
        intensity_rgb = np.asarray(li.GetDiffuseColor()) * li.GetIntensity()
        spot = li.GetPositional() and li.GetConeAngle() < 90.0
        out.append(EyeLight(position=pos[:3], direction=direction / np.linalg.norm(direction),
                            positional=bool(li.GetPositional()),
                            cos_cone=float(np.cos(np.radians(li.GetConeAngle()))) if spot else None,
                            exponent=li.GetExponent(), attenuation=np.asarray(li.GetAttenuationValues()),
                            intensity_rgb=intensity_rgb, ambient=np.zeros(3), diffuse=intensity_rgb,
                            specular=intensity_rgb))
    return out


def with_gl_colours(lights: list[EyeLight], scene) -> list[EyeLight]:
    """Give each VTK light the OpenGL colours of its scene light (VTK keeps only one colour)."""
    on = [li for li in scene.lights if li.on]
    for eye, light in zip(lights, on, strict=True):
        eye.ambient = np.asarray(light.ambient_color)
        eye.diffuse = np.asarray(light.gl_diffuse)
        eye.specular = np.asarray(light.gl_specular)
    return lights


def lit_colours(obj, actor, renderer, scene, lights) -> tuple[np.ndarray, str, np.ndarray | None]:
    """Lit 0..1 RGB for ``obj``: per point (gouraud with normals) or per cell; which; and
    the separate specular colour (None unless its model keeps one), by its model's ``lit``."""
    model_view = _matrix(renderer.GetActiveCamera().GetViewTransformMatrix()) @ _matrix(actor.GetMatrix())
    points = (np.c_[obj.mesh.points, np.ones(obj.mesh.n_points)] @ model_view.T)[:, :3]
    per_point = obj.shading == "gouraud" and obj.mesh.point_normals is not None
    if per_point:
        normals = obj.mesh.point_normals @ np.linalg.inv(model_view[:3, :3])
        normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
        where = "points"
    else:
        points, normals = face_points_and_normals(points, obj.mesh.triangles)
        where = "cells"
    rgb, secondary = lit_reference(obj).lit(points, normals, obj, scene, lights)
    return rgb, where, secondary


def unshare_points(poly):
    """A copy of triangle-only ``poly`` in which every triangle has its own three points
    (same coordinates, same order, texture coordinates kept), so a per-triangle value can
    be a point value."""
    vtk_ = vtk()
    points = vtk_to_numpy(poly.GetPoints().GetData())
    triangles = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    out = vtk_.vtkPolyData()
    pts = vtk_.vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points[triangles.reshape(-1)]), deep=True))
    out.SetPoints(pts)
    cells = vtk_.vtkCellArray()
    cells.SetData(3, numpy_to_vtk(np.arange(triangles.size, dtype=np.int64), deep=True,
                                  array_type=vtk_.VTK_ID_TYPE))
    out.SetPolys(cells)
    tcoords = poly.GetPointData().GetTCoords()
    if tcoords is not None:
        unshared = numpy_to_vtk(np.ascontiguousarray(vtk_to_numpy(tcoords)[triangles.reshape(-1)]), deep=True)
        unshared.SetName(tcoords.GetName() or "TCoords")
        out.GetPointData().SetTCoords(unshared)
    return out


def paint_unlit(actor, rgb: np.ndarray, where: str, secondary: np.ndarray | None = None) -> None:
    """Have VTK draw ``rgb`` (0..1) unlit: one colour per cell, or interpolated from points.

    Cell colours go in as VTK's ordinary 8-bit cell RGB (a flat colour is stored once,
    so 8 bits lose nothing the framebuffer keeps). Point colours go in as a float vertex
    attribute read by a two-line shader replacement: VTK's own 8-bit point colours would
    be rounded *before* interpolation, a half-step error the fixed-function pipeline
    does not have. Either way VTK rasterises and interpolates (perspective-correctly).
    A translucent or textured object's cell colours go in as float point colours of
    unshared vertices (:func:`unshare_points`): blending or the texture's modulation would
    show their 8-bit rounding. ``secondary`` (OpenGL's separate specular colour, per
    point or cell like ``rgb``) goes in the same way and is added after VTK's texture
    modulation (``//VTK::TCoord::Impl``), clamped as OpenGL's colour sum is.
    """
    mapper = actor.GetMapper()
    poly = mapper.GetInput()
    if where == "cells" and (actor.GetProperty().GetOpacity() < 1.0 or actor.GetTexture() is not None
                             or secondary is not None):
        poly = unshare_points(poly)
        mapper.SetInputData(poly)
        rgb, where = np.repeat(rgb, 3, axis=0), "points"
        secondary = None if secondary is None else np.repeat(secondary, 3, axis=0)
    if where == "cells":
        colours = numpy_to_vtk(np.rint(np.clip(rgb, 0.0, 1.0) * 255.0).astype(np.uint8), deep=True,
                               array_type=vtk().VTK_UNSIGNED_CHAR)
        colours.SetName("lit")
        poly.GetCellData().SetScalars(colours)
        mapper.ScalarVisibilityOn()
        mapper.SetColorModeToDirectScalars()
        mapper.SetScalarModeToUseCellData()
        prop = actor.GetProperty()
        prop.LightingOff()
        prop.SetAmbient(0.0)
        prop.SetDiffuse(1.0)
        prop.SetSpecular(0.0)
        return
    attributes = {"litColour": rgb} if secondary is None else {"litColour": rgb, "litSecondary": secondary}
    add_point_attributes(actor, attributes)
    opacity = actor.GetProperty().GetOpacity()
    actor.GetShaderProperty().AddFragmentShaderReplacement(
        "//VTK::Light::Impl", True, f"fragOutput0 = vec4(litColourVSOut, {opacity:.9g});\n", False)
    if secondary is not None:
        add_secondary_colour(actor, "litSecondaryVSOut")


def add_point_attributes(actor, attributes: dict[str, np.ndarray]) -> None:
    """Pass each float (N, 3) array per point to the fragment shader as ``<name>VSOut``
    (vertex attributes, interpolated perspective-correctly by VTK's rasteriser). One
    replacement per shader tag: VTK keeps one per tag, a second would replace the first."""
    vtk_ = vtk()
    mapper = actor.GetMapper()
    for name, values in attributes.items():
        array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float32), deep=True, array_type=vtk_.VTK_FLOAT)
        array.SetName(name)
        mapper.GetInput().GetPointData().AddArray(array)
        mapper.MapDataArrayToVertexAttribute(name, name, vtk_.vtkDataObject.FIELD_ASSOCIATION_POINTS, -1)
    vs_dec = "".join(f"in vec3 {name};\nout vec3 {name}VSOut;\n" for name in attributes)
    vs_impl = "".join(f"{name}VSOut = {name};\n" for name in attributes)
    fs_dec = "".join(f"in vec3 {name}VSOut;\n" for name in attributes)
    sp = actor.GetShaderProperty()
    sp.AddVertexShaderReplacement("//VTK::Color::Dec", True, "//VTK::Color::Dec\n" + vs_dec, False)
    sp.AddVertexShaderReplacement("//VTK::Color::Impl", True, "//VTK::Color::Impl\n" + vs_impl, False)
    sp.AddFragmentShaderReplacement("//VTK::Color::Dec", True, "//VTK::Color::Dec\n" + fs_dec, False)


def add_secondary_colour(actor, glsl_value: str) -> None:
    """Add ``glsl_value`` (a vec3 expression, clamped to 0..1) to the fragment's colour
    *after* VTK's texture modulation, and clamp the sum: OpenGL's colour sum with
    ``GL_SEPARATE_SPECULAR_COLOR``."""
    actor.GetShaderProperty().AddFragmentShaderReplacement(
        "//VTK::TCoord::Impl", True,
        f"//VTK::TCoord::Impl\n  fragOutput0.rgb = min(fragOutput0.rgb + clamp({glsl_value}, 0.0, 1.0), 1.0);\n",
        False)


# ------------------------------------------------------------- phong: a replaced shader
def phong_shader(obj, scene, lights: list[EyeLight]) -> str:
    """GLSL for VTK's ``//VTK::Light::Impl``: the object's model per fragment.

    Uses VTK's interpolated view-space normal and position (``normalVCVSOutput``,
    ``vertexVC``); VTK has already negated the normal on back faces for its two-sided
    lighting, which is undone here (the textbook models take normals as given). The
    model's ``glsl`` writes the lights and the material into the code as constants and
    sets ``c``; a specular term summed into ``secondary`` joins ``c`` there or, with
    separate specular, after the texture (:func:`add_secondary_colour`).
    """
    head = ("  vec3 n = normalize(normalVCVSOutput);\n"
            "  if (!gl_FrontFacing) { n = -n; }\n"
            "  vec3 P = vertexVC.xyz;\n"
            "  vec3 L; float att; float dist; float cs; float ndl;\n"
            "  vec3 secondary = vec3(0.0);\n")
    body = lit_reference(obj).glsl(obj, scene, lights)
    return head + body + f"  fragOutput0 = vec4(clamp(c, 0.0, 1.0), {obj.material.opacity:.9g});\n"


def replace_light_shader(actor, code: str, separate_specular: bool = False) -> None:
    """Swap VTK's fragment lighting for ``code`` (vtkShaderProperty replacement); with
    ``separate_specular``, its ``secondary`` colour is added after the texture."""
    actor.GetShaderProperty().AddFragmentShaderReplacement("//VTK::Light::Impl", True, code, False)
    actor.GetProperty().SetInterpolationToPhong()
    if separate_specular:
        add_secondary_colour(actor, "secondary")
