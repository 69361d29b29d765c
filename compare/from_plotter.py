"""A PyVista ``Plotter`` turned into a scanlab scene: :func:`scene_from_plotter`.

What is read, all from VTK's own objects (no vtk import here: the objects' methods are
called, and PyVista itself comes through :func:`compare.vtk_backend.pyvista`):

- every visible surface actor: its mesh (the mapper's input; a non-polygonal dataset
  through VTK's surface filter, as ``vtkDataSetMapper`` draws it), its transform
  (``GetMatrix``: position, orientation, scale, origin and user matrix), colour,
  ambient/diffuse/specular, specular power and colour, opacity, interpolation
  (flat/gouraud/phong), lighting on/off, back-face culling, texture (image, nearest or
  linear, repeat or clamp) and texture coordinates, point normals;
- every light: headlight, camera light or scene light, position and focal point,
  positional, cone angle, exponent, attenuation, intensity, colour, on/off; none means
  VTK's automatic headlight;
- the camera (position, focal point, view up, view angle, parallel projection and
  scale, clipping range), the window size and the background; depth peeling or
  order-independent transparency.

Polygons become triangles as VTK's OpenGL mapper cuts them, a fan from the first corner
((0, 1, 2), (0, 2, 3), ...: measured on bent quads, pentagons, hexagons and heptagons,
where any other cut shows); strips with alternating winding.

What a scene cannot express raises :class:`PlotterError`, naming the actor and the
feature: colours mapped from scalars, wireframe or points representation, edges or
vertices shown, lines or vertices in the mesh, physically based rendering, different
ambient and diffuse colours, cell normals that are not the faces' own, several
renderers or overlays, a gradient or textured background, one-sided lighting, render
passes (shadows, eye-dome lighting, SSAO), an off-centre or sheared camera.

Anti-aliasing is not part of a scene: a screenshot of a plotter with MSAA or FXAA on
differs from both renderers along every edge (``plotter.disable_anti_aliasing()``).

If the plotter has not rendered yet, the camera is read as its first render will place
it (PyVista frames the scene then); the plotter itself is left untouched.
"""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh
from lab.scene import Camera, Image, Light, Material, RenderSettings, Scene, SceneObject
from lab.texture import Texture

INTERPOLATIONS = {0: "flat", 1: "gouraud", 2: "phong"}  # VTK_FLAT, VTK_GOURAUD, VTK_PHONG; 3 = VTK_PBR
LIGHT_KINDS = {1: "headlight", 2: "camera", 3: "scene"}  # VTK_LIGHT_TYPE_*
SURFACE = 2  # VTK_SURFACE representation


class PlotterError(ValueError):
    """The plotter holds something a scanlab scene cannot express; the message says what and where."""


def _matrix(vtk_matrix) -> np.ndarray:
    """A vtkMatrix4x4 (column vectors) as our row-vector matrix: its transpose."""
    return np.array([[vtk_matrix.GetElement(i, j) for j in range(4)] for i in range(4)]).T


def _items(collection) -> list:
    collection.InitTraversal()
    return [collection.GetNextItemAsObject() for _ in range(collection.GetNumberOfItems())]


# --------------------------------------------------------------------------- meshes
def polygon_triangles(n: int) -> list[tuple[int, int, int]]:
    """The triangles (corner indices) VTK's OpenGL mapper cuts an n-gon into: a fan from corner 0.

    >>> polygon_triangles(4), polygon_triangles(5)
    ([(0, 1, 2), (0, 2, 3)], [(0, 1, 2), (0, 2, 3), (0, 3, 4)])
    """
    return [(0, i, i + 1) for i in range(1, n - 1)]


def strip_triangles(n: int) -> list[tuple[int, int, int]]:
    """A strip of n points as triangles with alternating winding: (0, 1, 2), (2, 1, 3), (2, 3, 4) …"""
    return [(i, i + 1, i + 2) if i % 2 == 0 else (i + 1, i, i + 2) for i in range(n - 2)]


def _cells(cell_array) -> list[np.ndarray]:
    """A vtkCellArray's cells as lists of point ids (through PyVista's numpy view)."""
    pv = _pyvista()
    offsets = pv.convert_array(cell_array.GetOffsetsArray())
    conn = pv.convert_array(cell_array.GetConnectivityArray())
    return [conn[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)]


def _triangulate(poly, where: str) -> tuple[np.ndarray, np.ndarray]:
    """(T, 3) triangles of a vtkPolyData's polygons then strips (VTK's draw order), and
    (T,) the cell each came from."""
    if poly.GetNumberOfLines() or poly.GetNumberOfVerts():
        raise PlotterError(f"{where}: the mesh holds lines or vertices, which a scene cannot draw")
    tris, owner = [], []
    for kind, cells, cut in (("poly", poly.GetPolys(), polygon_triangles), ("strip", poly.GetStrips(),
                                                                               strip_triangles)):
        for c, ids in enumerate(_cells(cells)):
            if len(ids) < 3:
                continue
            for t in cut(len(ids)):
                tris.append(ids[list(t)])
                owner.append(c if kind == "poly" else poly.GetNumberOfPolys() + c)
    if not tris:
        raise PlotterError(f"{where}: the mesh has no polygons")
    return np.array(tris, np.int64), np.array(owner, np.int64)


def _mesh(actor, where: str) -> Mesh:
    pv = _pyvista()
    mapper = actor.GetMapper()
    mapper.Update()
    data = mapper.GetInputDataObject(0, 0)
    if data is None:
        raise PlotterError(f"{where}: the actor's mapper has no input")
    data = pv.wrap(data)
    if not isinstance(data, pv.PolyData):
        if not hasattr(data, "extract_surface"):
            raise PlotterError(f"{where}: a {type(data).__name__} is not a surface a scene can hold")
        data = data.extract_surface(algorithm="dataset_surface")  # vtkDataSetSurfaceFilter, as vtkDataSetMapper
    _no_scalar_colours(mapper, data, where)
    triangles, owner = _triangulate(data, where)
    points = np.asarray(data.points, np.float64)
    normals = data.GetPointData().GetNormals()
    normals = None if normals is None else np.asarray(pv.convert_array(normals), np.float64)
    tcoords = data.GetPointData().GetTCoords()
    if tcoords is not None:
        tcoords = np.asarray(pv.convert_array(tcoords), np.float64)
        tcoords = tcoords[:, :2] if tcoords.ndim == 2 and tcoords.shape[1] >= 2 else None
    _cell_normals_are_the_faces(data, points, triangles, owner, where)
    return Mesh(points, triangles, normals, tcoords)


def _no_scalar_colours(mapper, data, where: str) -> None:
    if not mapper.GetScalarVisibility():
        return
    named = mapper.GetArrayName()
    if named and (data.GetPointData().GetArray(named) is not None or data.GetCellData().GetArray(named) is not None):
        raise PlotterError(f"{where}: colours mapped from the scalars {named!r}; a scene object has one colour "
                           "(add_mesh(..., color=...) or scalars=None)")
    if data.GetPointData().GetScalars() is not None or data.GetCellData().GetScalars() is not None:
        raise PlotterError(f"{where}: colours mapped from the active scalars; a scene object has one colour")


def _cell_normals_are_the_faces(data, points, triangles, owner, where: str) -> None:
    """VTK lights a face with its cell normal when it has one; the scene uses the face's own
    plane normal (counter-clockwise). Where they agree both draw the same."""
    cell = data.GetCellData().GetNormals()
    if cell is None:
        return
    cn = np.asarray(_pyvista().convert_array(cell), np.float64)[owner]
    p = points[triangles]
    face = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    length = np.linalg.norm(face, axis=1) * np.linalg.norm(cn, axis=1)
    ok = length > 0
    if np.any(np.einsum("ij,ij->i", face[ok], cn[ok]) < 0.999 * length[ok]):
        raise PlotterError(f"{where}: cell normals that are not the faces' own (counter-clockwise) normals")


# --------------------------------------------------------------------------- materials
def _texture(actor, where: str) -> Texture | None:
    tex = actor.GetTexture()
    if tex is None:
        return None
    if actor.GetProperty().GetNumberOfTextures():
        raise PlotterError(f"{where}: several textures on one property")
    for test, what in ((tex.GetMipmap(), "mipmaps"), (tex.GetCubeMap(), "a cube map"),
                       (tex.GetUseSRGBColorSpace(), "an sRGB texture"),
                       (tex.GetTransform() is not None, "a texture transform")):
        if test:
            raise PlotterError(f"{where}: a texture with {what}")
    tex.Update()
    image = tex.GetInput()
    pv = _pyvista()
    wrapped = pv.wrap(image)
    w, h, depth = wrapped.dimensions
    scalars = wrapped.active_scalars
    if depth != 1 or scalars is None or scalars.dtype != np.uint8:
        raise PlotterError(f"{where}: a texture that is not an 8-bit 2D image")
    texels = np.asarray(scalars).reshape(h, w, -1)
    if texels.shape[2] in (2, 4) and np.any(texels[..., -1] != 255):
        raise PlotterError(f"{where}: a texture with transparent texels")
    rgb = texels[..., :3] if texels.shape[2] >= 3 else np.repeat(texels[..., :1], 3, axis=2)
    return Texture(texels=np.ascontiguousarray(rgb, np.float64) / 255.0,
                   filter="linear" if tex.GetInterpolate() else "nearest",
                   wrap="repeat" if tex.GetRepeat() else "clamp", source=f"{where} texture")


def _material(prop, where: str) -> Material:
    if prop.GetInterpolation() not in INTERPOLATIONS:
        raise PlotterError(f"{where}: physically based rendering (pbr=True); a scene uses VTK's Phong lighting")
    if prop.GetRepresentation() != SURFACE:
        kind = {0: "points", 1: "wireframe"}.get(prop.GetRepresentation(), "a non-surface")
        raise PlotterError(f"{where}: {kind} representation; a scene draws surfaces")
    for test, what in ((prop.GetEdgeVisibility(), "edges shown (show_edges)"),
                       (prop.GetVertexVisibility(), "vertices shown"),
                       (prop.GetFrontfaceCulling(), "front-face culling")):
        if test:
            raise PlotterError(f"{where}: {what}")
    diffuse, ambient_colour = prop.GetDiffuseColor(), prop.GetAmbientColor()
    if prop.GetAmbient() > 0 and not np.allclose(diffuse, ambient_colour, atol=1e-12):
        raise PlotterError(f"{where}: an ambient colour {ambient_colour} unlike the diffuse colour {diffuse}")
    specular = tuple(prop.GetSpecularColor())
    return Material(color=tuple(diffuse), ambient=prop.GetAmbient(), diffuse=prop.GetDiffuse(),
                    specular=prop.GetSpecular(), specular_power=prop.GetSpecularPower(),
                    specular_color=None if np.allclose(specular, diffuse, atol=1e-12) else specular,
                    opacity=prop.GetOpacity(), lighting=bool(prop.GetLighting()))  # VTK lights it: the default model


def _object(actor, label: str) -> SceneObject:
    where = f"actor {label!r}"
    m = _matrix(actor.GetMatrix())
    if not np.allclose(m[:, 3], [0.0, 0.0, 0.0, 1.0]):
        raise PlotterError(f"{where}: a projective transform")
    mesh = _mesh(actor, where)
    texture = _texture(actor, where)
    if texture is not None and mesh.tcoords is None:
        texture = None  # VTK draws no texture without texture coordinates
    prop = actor.GetProperty()
    return SceneObject(mesh=mesh, material=_material(prop, where), shading=INTERPOLATIONS[prop.GetInterpolation()],
                       model_to_world=m, name=label, texture=texture)


# --------------------------------------------------------------------------- lights, camera
def _light(light, i: int) -> Light:
    kind = LIGHT_KINDS.get(light.GetLightType())
    if kind is None:
        raise PlotterError(f"light {i}: unknown light type {light.GetLightType()}")
    if kind == "scene" and light.GetTransformMatrix() is not None:
        raise PlotterError(f"light {i}: a scene light with a transform matrix")
    return Light(kind=kind, position=tuple(light.GetPosition()), focal_point=tuple(light.GetFocalPoint()),
                 color=tuple(light.GetDiffuseColor()), intensity=light.GetIntensity(),
                 positional=bool(light.GetPositional()), cone_angle=light.GetConeAngle(),
                 exponent=light.GetExponent(), attenuation=tuple(light.GetAttenuationValues()),
                 on=bool(light.GetSwitch()))


def _camera(renderer) -> Camera:
    cam = renderer.GetActiveCamera()
    for test, what in ((cam.GetUseHorizontalViewAngle(), "a horizontal view angle"),
                       (tuple(cam.GetWindowCenter()) != (0.0, 0.0), "an off-centre window"),
                       (tuple(cam.GetViewShear()) != (0.0, 0.0, 1.0), "a sheared view"),
                       (cam.GetUseOffAxisProjection(), "an off-axis projection"),
                       (cam.GetUserTransform() is not None or cam.GetUserViewTransform() is not None,
                        "a user transform")):
        if test:
            raise PlotterError(f"camera: {what}")
    return Camera(position=tuple(cam.GetPosition()), focal_point=tuple(cam.GetFocalPoint()),
                  view_up=tuple(cam.GetViewUp()), view_angle=cam.GetViewAngle(),
                  clipping_range=tuple(cam.GetClippingRange()), parallel=bool(cam.GetParallelProjection()),
                  parallel_scale=cam.GetParallelScale())


CAMERA_STATE = ("Position", "FocalPoint", "ViewUp", "ViewAngle", "ParallelScale", "ClippingRange")


def _first_camera(plotter, ren) -> Camera:
    """The camera the plotter renders with. Before its first render PyVista has not placed
    it yet: it is placed here as that render will place it (``get_default_cam_pos`` and
    ``ResetCamera``), read, and put back, so the plotter is left as it was."""
    cam = ren.GetActiveCamera()
    if not getattr(plotter, "_first_time", False) or getattr(ren.camera, "is_set", True):
        return _camera(ren)
    saved = {k: getattr(cam, f"Get{k}")() for k in CAMERA_STATE}
    try:
        ren.camera_position = ren.get_default_cam_pos()
        ren.ResetCamera()
        return _camera(ren)
    finally:
        for k, v in saved.items():
            getattr(cam, f"Set{k}")(*v) if isinstance(v, tuple) else getattr(cam, f"Set{k}")(v)
        ren.camera.is_set = False


def _renderer(plotter):
    """The plotter's one renderer, after checking nothing else draws into the window."""
    renderers = list(plotter.renderers)
    if len(renderers) != 1:
        raise PlotterError(f"the plotter has {len(renderers)} renderers (subplots); a scene is one view")
    ren = renderers[0]
    for other in _items(plotter.ren_win.GetRenderers()):
        if other is not ren and any(p.GetVisibility() for p in _items(other.GetViewProps())):
            raise PlotterError("another renderer draws into the window (an axes widget, a background image, ...)")
    for test, what in ((tuple(ren.GetViewport()) != (0.0, 0.0, 1.0, 1.0), "a viewport smaller than the window"),
                       (ren.GetGradientBackground(), "a gradient background"),
                       (ren.GetTexturedBackground(), "a textured background"),
                       (not ren.GetTwoSidedLighting(), "one-sided lighting"),
                       (ren.GetPass() is not None, "a render pass (shadows, eye-dome lighting, SSAO, ...)"),
                       (ren.GetUseHiddenLineRemoval(), "hidden-line removal")):
        if test:
            raise PlotterError(f"renderer: {what}")
    return ren


def _actor_names(plotter) -> dict[str, str]:
    return {a.GetAddressAsString("vtkObject"): name for name, a in plotter.renderer.actors.items()
            if hasattr(a, "GetAddressAsString")}


def scene_from_plotter(plotter, name: str | None = None) -> Scene:
    """The scene a PyVista ``Plotter`` shows, for scanlab's renderer and the comparison.

    Parameters
    ----------
    plotter : ``pyvista.Plotter`` (one renderer), rendered or not.
    name : the scene's ``source`` (default "PyVista plotter").

    Raises
    ------
    PlotterError
        The plotter holds something a scene cannot express (see the module docstring).

    Examples
    --------
    >>> import pyvista as pv                                    # doctest: +SKIP
    >>> pl = pv.Plotter(off_screen=True, window_size=(320, 240))  # doctest: +SKIP
    >>> _ = pl.add_mesh(pv.Sphere(), color="tan", smooth_shading=True)  # doctest: +SKIP
    >>> scene = scene_from_plotter(pl)                          # doctest: +SKIP
    >>> scene.objects[0].shading, len(scene.lights)             # doctest: +SKIP
    ('phong', 5)
    """
    ren = _renderer(plotter)
    names = _actor_names(plotter)
    objects = []
    for prop in _items(ren.GetViewProps()):
        if not prop.GetVisibility():
            continue
        label = names.get(prop.GetAddressAsString("vtkObject"), prop.GetClassName())
        where = f"actor {label!r}"
        if not prop.IsA("vtkActor") or prop.GetMapper() is None or not prop.GetMapper().IsA("vtkMapper"):
            raise PlotterError(f"{where}: a {prop.GetClassName()} (text, scalar bar, volume, axes ...); a scene "
                               "holds surfaces only")
        objects.append(_object(prop, label))
    if not objects:
        raise PlotterError("the plotter shows no surface")
    cull = {o_actor.GetProperty().GetBackfaceCulling() for o_actor in _items(ren.GetActors())
            if o_actor.GetVisibility()}
    if len(cull) > 1:
        raise PlotterError("back-face culling on some actors only; a scene culls all or none")
    lights = tuple(_light(li, i) for i, li in enumerate(_items(ren.GetLights())))
    if not lights and ren.GetAutomaticLightCreation():
        lights = (Light(kind="headlight"),)  # what VTK adds at the first render
    translucent = any(o.material.opacity < 1.0 for o in objects)
    if translucent and not (ren.GetUseDepthPeeling() or ren.GetUseOIT()):
        raise PlotterError("translucent actors blended in draw order (neither depth peeling nor OIT)")
    width, height = plotter.window_size
    render = RenderSettings(cull_backfaces=bool(cull.pop()),
                            transparency="depth_peeling" if ren.GetUseDepthPeeling() else "oit")
    return Scene(image=Image(size=(int(width), int(height)), background=tuple(ren.GetBackground())),
                 camera=_first_camera(plotter, ren), lights=lights, objects=tuple(objects), source=name or "PyVista plotter",
                 render=render)


def _pyvista():
    from compare.vtk_backend import pyvista

    return pyvista()
