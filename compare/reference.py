"""The reference: VTK (through PyVista, offscreen) draws the same triangles.

Set-up, following ``shared/docs/vtk-parity.md``: exactly the scene's lights (no light
kit), no anti-aliasing of any kind, the scene's camera with the clipping range set last
(or fitted by VTK's own ``ResetCameraClippingRange`` when the scene gives none), float
colours set directly on ``vtkProperty``/``vtkLight``, the same triangles and point
normals as scanlab's renderer, the model transform given to VTK as its column-vector
matrix (the transpose of ours). Coverage comes from VTK's depth buffer (with translucent
props, from a second render with every prop opaque: see :func:`opaque_coverage`). VTK always
removes hidden surfaces with its z-buffer, whatever ``[render] hidden_surface`` says:
against it the painter's algorithm shows where it fails.
"""
from __future__ import annotations

import time

import numpy as np

from compare.lit_reference.lit_registry import lit_reference
from compare.textbook_reference import (NATIVE, SHADER, eye_lights, lit_colours, object_reference, paint_unlit,
                                       phong_shader, replace_light_shader, uses_separate_specular, with_gl_colours)
from compare.vtk_backend import pyvista, vtk, vtk_to_numpy
from lab.frame import Frame

INTERPOLATION = {"flat": 0, "gouraud": 1, "phong": 2}  # VTK_FLAT, VTK_GOURAUD, VTK_PHONG


def _polydata(pv, mesh):
    poly = pv.PolyData.from_regular_faces(mesh.points, mesh.triangles)
    if mesh.point_normals is not None:
        poly.point_data["Normals"] = mesh.point_normals
        poly.point_data.active_normals_name = "Normals"
    if mesh.tcoords is not None:
        poly.active_texture_coordinates = mesh.tcoords
    return poly


def _texture(pv, texture):
    """A vtkTexture with the scene's filter and wrap, no mipmaps. ``pv.Texture`` reads an
    array with row 0 at the top (it flips it to t = 1), which is what ``image_rows`` gives."""
    tex = pv.Texture(texture.image_rows)
    tex.SetInterpolate(texture.filter == "linear")
    tex.SetMipmap(False)
    tex.SetRepeat(texture.wrap == "repeat")
    tex.SetEdgeClamp(texture.wrap == "clamp")
    return tex


def vtk_material(obj, scene) -> dict:
    """The vtkProperty values that draw ``obj``'s material with VTK's own lighting: for the vtk
    model the scene's values; for a textbook model (``--reference vtk-native``) VTK's nearest
    equivalent (its model's ``vtk_property``, :mod:`compare.lit_reference`)."""
    return lit_reference(obj).vtk_property(obj, scene)


def _actor(pv, obj, scene):
    vtk_ = vtk()
    mapper = vtk_.vtkPolyDataMapper()
    mapper.SetInputData(_polydata(pv, obj.mesh))
    mapper.ScalarVisibilityOff()
    actor = vtk_.vtkActor()
    actor.SetMapper(mapper)
    user = vtk_.vtkMatrix4x4()
    column = obj.model_to_world.T  # VTK multiplies column vectors: its matrix is our transpose
    for i in range(4):
        for j in range(4):
            user.SetElement(i, j, float(column[i, j]))
    actor.SetUserMatrix(user)
    if obj.texture is not None:
        actor.SetTexture(_texture(pv, obj.texture))
    m, prop, v = obj.material, actor.GetProperty(), vtk_material(obj, scene)
    prop.SetAmbientColor(*v["ambient_color"])
    prop.SetDiffuseColor(*v["diffuse_color"])
    prop.SetSpecularColor(*v["specular_color"])
    prop.SetAmbient(v["ambient"])
    prop.SetDiffuse(v["diffuse"])
    prop.SetSpecular(v["specular"])
    prop.SetSpecularPower(v["power"])
    prop.SetOpacity(m.opacity)
    prop.SetInterpolation(INTERPOLATION[obj.shading])
    prop.SetLighting(m.lighting)
    prop.SetBackfaceCulling(scene.render.cull_backfaces)
    return actor


def _light(light, camera):
    """A vtkLight for a scene light. An "eye" light (view coordinates) becomes a camera
    light: VTK's camera frame puts the eye at (0, 0, 1) in units of the camera distance d,
    so view point (x, y, z) is camera-light point (x/d, y/d, z/d + 1)."""
    v = vtk().vtkLight()
    position, focal = light.position, light.focal_point
    if light.kind == "eye":
        d = float(np.linalg.norm(np.subtract(camera.position, camera.focal_point)))
        position, focal = (np.asarray(position) / d + (0, 0, 1), np.asarray(focal) / d + (0, 0, 1))
    {"scene": v.SetLightTypeToSceneLight, "camera": v.SetLightTypeToCameraLight, "eye": v.SetLightTypeToCameraLight,
     "headlight": v.SetLightTypeToHeadlight}[light.kind]()
    v.SetPosition(*position)
    v.SetFocalPoint(*focal)
    v.SetColor(*light.color)
    v.SetIntensity(light.intensity)
    v.SetPositional(light.positional)
    v.SetConeAngle(light.cone_angle)
    v.SetExponent(light.exponent)
    v.SetAttenuationValues(*light.attenuation)
    v.SetSwitch(light.on)
    return v


def _set_camera(renderer, cam):
    c = renderer.GetActiveCamera()
    c.SetPosition(*cam.position)
    c.SetFocalPoint(*cam.focal_point)
    c.SetViewUp(*cam.view_up)
    c.SetViewAngle(cam.view_angle)
    c.SetParallelProjection(cam.parallel)
    c.SetParallelScale(cam.parallel_scale)
    if cam.clipping_range is not None:  # last: nothing may re-fit it afterwards
        c.SetClippingRange(*cam.clipping_range)
    else:
        renderer.ResetCameraClippingRange()


MAX_PEELS = 1000
"""Peels for exact depth peeling: more than any pixel here has layers (with occlusion ratio 0
VTK stops as soon as a peel adds nothing)."""


def _set_transparency(pl, mode: str):
    """VTK's compositing of translucent props, configured as ``[render] transparency`` asks.

    "oit": VTK's default weighted-average order-independent transparency (PyVista leaves
    depth peeling off; OIT is set on explicitly). "depth_peeling" and "sorted": exact depth
    peeling — occlusion ratio 0 and :data:`MAX_PEELS` peels. Not 0 peels, although
    PyVista documents 0 as "no limit": VTK 9.7's dual depth peeling then stops at once
    and blends what is left in draw order (red before green gives green over red).
    """
    if mode == "oit":
        pl.disable_depth_peeling()
        pl.renderer.SetUseOIT(True)
    else:
        if not pl.enable_depth_peeling(number_of_peels=MAX_PEELS, occlusion_ratio=0.0):
            raise RuntimeError("VTK cannot do depth peeling on this OpenGL context")


def build_plotter(scene, reference: str | None = None):
    """A PyVista offscreen plotter holding the scene, ready to render (not yet rendered).

    Objects with a textbook model are drawn as unlit colours lit by their model's lit
    reference, or with a replaced shader (:mod:`compare.textbook_reference`), unless
    ``reference="vtk-native"`` asks for VTK's own shading of every object.
    """
    pv = pyvista()
    width, height = scene.image.size
    pl = pv.Plotter(off_screen=True, window_size=(width, height), lighting="none")
    pl.ren_win.SetMultiSamples(0)
    pl.disable_anti_aliasing()
    pl.renderer.SetBackground(*scene.image.background)
    pl.renderer.SetTwoSidedLighting(True)
    _set_transparency(pl, scene.render.transparency)
    actors = [_actor(pv, obj, scene) for obj in scene.objects]
    for actor in actors:
        pl.renderer.AddActor(actor)
    for light in scene.lights:
        pl.renderer.AddLight(_light(light, scene.camera))
    pl.camera_set = True  # PyVista must not reset the camera on the first render
    _set_camera(pl.renderer, scene.camera)
    textbook = [(o, a) for o, a in zip(scene.objects, actors) if object_reference(o, reference) != NATIVE]
    if textbook:
        lights = with_gl_colours(eye_lights(pl.renderer), scene)
        for obj, actor in textbook:
            if object_reference(obj, reference) == SHADER:
                replace_light_shader(actor, phong_shader(obj, scene, lights), uses_separate_specular(obj, scene))
            else:
                paint_unlit(actor, *lit_colours(obj, actor, pl.renderer, scene, lights))
    return pl


def read_frame(pl) -> Frame:
    """The rendered colour and depth buffers as a :class:`Frame` (row 0 at the top)."""
    vtk_ = vtk()
    rw = pl.ren_win
    width, height = rw.GetSize()
    rgba = vtk_.vtkUnsignedCharArray()
    rw.GetRGBACharPixelData(0, 0, width - 1, height - 1, 0, rgba, 0)  # back buffer, left
    rgb = vtk_to_numpy(rgba).reshape(height, width, 4)[::-1, :, :3]
    z = vtk_.vtkFloatArray()
    rw.GetZbufferData(0, 0, width - 1, height - 1, z)
    depth = vtk_to_numpy(z).reshape(height, width)[::-1].astype(np.float64)
    return Frame(rgb=np.ascontiguousarray(rgb), depth=np.ascontiguousarray(depth), coverage=depth < 1.0)


def opaque_coverage(pl) -> np.ndarray:
    """Which pixels VTK's rasteriser covers, translucent props included (row 0 at the top).

    VTK writes no depth for translucent fragments (neither with OIT nor with depth
    peeling), so its depth buffer misses the pixels only translucent props cover. This
    renders the same plotter once more with every prop opaque (same triangles, same
    rasteriser) and reads that depth buffer; the opacities are then put back.
    """
    collection = pl.renderer.GetActors()
    actors = [collection.GetItemAsObject(i) for i in range(collection.GetNumberOfItems())]
    saved = [a.GetProperty().GetOpacity() for a in actors]
    for a in actors:
        a.GetProperty().SetOpacity(1.0)
    pl.ren_win.Render()
    coverage = read_frame(pl).coverage
    for a, opacity in zip(actors, saved):
        a.GetProperty().SetOpacity(opacity)
    return coverage


def render_reference(scene, timings: dict | None = None, reference: str | None = None) -> Frame:
    """Draw ``scene`` with VTK offscreen and return its :class:`Frame`.

    ``timings``, if given, receives ``"reference_ms"``: the time of a *warm* frame, VTK's
    render call plus the read-back of colour and depth, after a first frame that compiles
    the shaders (the plotter's construction is not counted either).
    """
    pl = build_plotter(scene, reference)
    try:
        if timings is not None:
            pl.ren_win.Render()
        t0 = time.perf_counter()
        pl.ren_win.Render()
        frame = read_frame(pl)
        if timings is not None:
            timings["reference_ms"] = (time.perf_counter() - t0) * 1e3
        if any(obj.material.opacity < 1.0 for obj in scene.objects):
            frame = Frame(rgb=frame.rgb, depth=frame.depth, coverage=opaque_coverage(pl))
        return frame
    finally:
        pl.close()
