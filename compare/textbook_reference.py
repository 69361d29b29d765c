"""References for the textbook models: VTK draws colours that numpy lit.

VTK cannot light the way fixed-function OpenGL or the course does (its "Gouraud" is
per-pixel Phong). So for an object with ``model = "opengl" | "classic"`` the colours are
computed here — per vertex for gouraud, per triangle for flat — by
:mod:`compare.textbook_lighting` (numpy, written apart from ``renderer/``), and VTK draws
them unlit as point or cell RGB. VTK then checks our rasterisation and (perspective-
correct) colour interpolation, and the numpy code checks our lighting.

Everything is taken from VTK's own objects: the model and view matrices of the actor and
camera, and each light's transformed position after VTK has placed headlights and camera
lights. Cell colours reach VTK as 8-bit RGB, vertex colours as a float attribute (see
:func:`paint_unlit`).
"""
from __future__ import annotations

import numpy as np

from compare.textbook_lighting import (EyeLight, classic_colours, face_points_and_normals, opengl_colour_parts,
                                      opengl_colours)

NATIVE, UNLIT, SHADER, NONE = "vtk-native", "vtk-unlit-colours", "vtk-shader-replacement", "none"
REFERENCES = (NATIVE, UNLIT, SHADER)


def object_reference(obj, forced: str | None = None) -> str:
    """Which reference draws ``obj``: VTK's own shading, unlit colours, or a replaced shader."""
    if forced == NATIVE or obj.material.reflection_model == "vtk":
        return NATIVE
    if obj.shading == "phong" and obj.mesh.point_normals is not None:
        return SHADER
    return UNLIT


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
        colour = np.asarray(li.GetDiffuseColor()) * li.GetIntensity()
        spot = li.GetPositional() and li.GetConeAngle() < 90.0
        out.append(EyeLight(position=pos[:3], direction=direction / np.linalg.norm(direction),
                            positional=bool(li.GetPositional()),
                            cos_cone=float(np.cos(np.radians(li.GetConeAngle()))) if spot else None,
                            exponent=li.GetExponent(), attenuation=np.asarray(li.GetAttenuationValues()),
                            colour=colour, ambient=np.zeros(3), diffuse=colour, specular=colour))
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
    the separate specular colour (None unless the opengl model with ``separate_specular``)."""
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
    m, r = obj.material, scene.render
    secondary = None
    if m.model == "opengl" and r.separate_specular:  # GL_SEPARATE_SPECULAR_COLOR: each part clamped on its own
        rgb, secondary = (np.clip(part, 0.0, 1.0) for part in opengl_colour_parts(
            points, normals, m.gl_ambient, m.gl_diffuse, m.gl_specular, m.shininess, lights,
            global_ambient=np.asarray(r.global_ambient), local_viewer=r.local_viewer))
    elif m.model == "opengl":
        rgb = opengl_colours(points, normals, m.gl_ambient, m.gl_diffuse, m.gl_specular, m.shininess, lights,
                             global_ambient=np.asarray(r.global_ambient), local_viewer=r.local_viewer)
    else:
        rgb = classic_colours(points, normals, np.asarray(m.color), m.ambient, m.diffuse, m.specular,
                              m.specular_power, lights, ambient_light=np.asarray(r.ambient))
    return rgb, where, secondary


def unshare_points(poly):
    """A copy of triangle-only ``poly`` in which every triangle has its own three points
    (same coordinates, same order, texture coordinates kept), so a per-triangle value can
    be a point value."""
    import vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy

    points = vtk_to_numpy(poly.GetPoints().GetData())
    triangles = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    out = vtk.vtkPolyData()
    pts = vtk.vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points[triangles.reshape(-1)]), deep=True))
    out.SetPoints(pts)
    cells = vtk.vtkCellArray()
    cells.SetData(3, numpy_to_vtk(np.arange(triangles.size, dtype=np.int64), deep=True,
                                  array_type=vtk.VTK_ID_TYPE))
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
    import vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk

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
                               array_type=vtk.VTK_UNSIGNED_CHAR)
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
    import vtk
    from vtkmodules.util.numpy_support import numpy_to_vtk

    mapper = actor.GetMapper()
    for name, values in attributes.items():
        array = numpy_to_vtk(np.ascontiguousarray(values, dtype=np.float32), deep=True, array_type=vtk.VTK_FLOAT)
        array.SetName(name)
        mapper.GetInput().GetPointData().AddArray(array)
        mapper.MapDataArrayToVertexAttribute(name, name, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, -1)
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
def _vec3(v) -> str:
    return "vec3(" + ", ".join(f"{float(x):.9g}" for x in v) + ")"


def _glsl_light_vector(i: int, li: EyeLight) -> str:
    """GLSL that sets ``L`` (toward the light) and ``att`` for light ``i``."""
    if not li.positional:
        return f"    L = -{_vec3(li.direction)}; att = 1.0;\n"
    a0, a1, a2 = (float(x) for x in li.attenuation)
    code = (f"    L = {_vec3(li.position)} - P; dist = length(L); L = L / dist;\n"
            f"    att = 1.0 / ({a0:.9g} + {a1:.9g} * dist + {a2:.9g} * dist * dist);\n")
    if li.cos_cone is not None:
        code += (f"    cs = dot(-L, {_vec3(li.direction)});\n"
                 f"    att = cs >= {li.cos_cone:.9g} ? att * pow(cs, {float(li.exponent):.9g}) : 0.0;\n")
    return code


def phong_shader(obj, scene, lights: list[EyeLight]) -> str:
    """GLSL for VTK's ``//VTK::Light::Impl``: the object's textbook model per fragment.

    Uses VTK's interpolated view-space normal and position (``normalVCVSOutput``,
    ``vertexVC``); VTK has already negated the normal on back faces for its two-sided
    lighting, which is undone here (the textbook models take normals as given). The
    lights and the material are written into the code as constants. The opengl model
    sums its specular term into ``secondary``, which joins ``c`` here (GL_SINGLE_COLOR)
    or, with separate specular, after the texture (:func:`add_secondary_colour`).
    """
    m, r = obj.material, scene.render
    head = ("  vec3 n = normalize(normalVCVSOutput);\n"
            "  if (!gl_FrontFacing) { n = -n; }\n"
            "  vec3 P = vertexVC.xyz;\n"
            "  vec3 L; float att; float dist; float cs; float ndl;\n"
            "  vec3 secondary = vec3(0.0);\n")
    if m.model == "opengl":
        ma, md, ms = _vec3(m.gl_ambient), _vec3(m.gl_diffuse), _vec3(m.gl_specular)
        viewer = "normalize(-P)" if r.local_viewer else "vec3(0.0, 0.0, 1.0)"
        body = f"  vec3 V = {viewer};\n  vec3 c = {_vec3(r.global_ambient)} * {ma};\n"
        for i, li in enumerate(lights):
            body += ("  {\n" + _glsl_light_vector(i, li) +
                     "    ndl = dot(n, L);\n    float sf = 0.0;\n"
                     f"    if (ndl > 0.0) {{ sf = pow(max(dot(n, normalize(L + V)), 0.0), {m.shininess:.9g}); }}\n"
                     f"    c += att * ({_vec3(li.ambient)} * {ma} + max(ndl, 0.0) * {_vec3(li.diffuse)} * {md});\n"
                     f"    secondary += att * sf * {_vec3(li.specular)} * {ms};\n  }}\n")
        if not r.separate_specular:
            body += "  c += secondary;\n"
    else:
        o = np.asarray(m.color)
        body = f"  vec3 V = normalize(-P);\n  vec3 c = {_vec3(m.ambient * o)} * {_vec3(r.ambient)};\n"
        for i, li in enumerate(lights):
            body += ("  {\n" + _glsl_light_vector(i, li) +
                     "    ndl = dot(n, L);\n"
                     "    if (att > 0.0 && ndl > 0.0) {\n"
                     "      vec3 R = 2.0 * ndl * n - L;\n"
                     f"      float sf = pow(max(dot(R, V), 0.0), {m.specular_power:.9g});\n"
                     f"      c += att * {_vec3(li.colour)} * ({_vec3(m.diffuse * o)} * ndl + {m.specular:.9g} * sf);\n"
                     "    }\n  }\n")
    return head + body + f"  fragOutput0 = vec4(clamp(c, 0.0, 1.0), {m.opacity:.9g});\n"


def replace_light_shader(actor, code: str, separate_specular: bool = False) -> None:
    """Swap VTK's fragment lighting for ``code`` (vtkShaderProperty replacement); with
    ``separate_specular``, its ``secondary`` colour is added after the texture."""
    actor.GetShaderProperty().AddFragmentShaderReplacement("//VTK::Light::Impl", True, code, False)
    actor.GetProperty().SetInterpolationToPhong()
    if separate_specular:
        add_secondary_colour(actor, "secondary")
