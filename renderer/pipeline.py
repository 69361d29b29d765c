"""The whole pipeline, stage by stage: scene → :class:`lab.frame.Frame`.

1. model → world (:mod:`renderer.transform`), 2. world → view and 3. view → clip
(:mod:`renderer.camera`), 4. clipping (:mod:`renderer.clip`), 5. window mapping and
sub-pixel snapping (:mod:`renderer.window`), 6. scanline fill with the top-left rule and
the z-buffer (:mod:`renderer.raster`), 7. shading (:mod:`renderer.shading`,
:mod:`renderer.lighting`), 8. 8-bit output with the flip to image rows. Objects with
opacity < 1 skip the z-buffer: after the opaque frame is shaded they are composited over
it from per-pixel fragment lists (:mod:`renderer.translucency`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from lab.frame import Frame
from renderer.camera import clipping_range, view_to_clip, world_to_view
from renderer.clip import clip_triangles
from renderer.lighting import UNLIT, view_lights
from renderer.painter import painter_order
from renderer.raster import rasterize_triangles
from renderer.shading import (FACE_COLOUR, TEXTBOOK_PIXEL, VERTEX_COLOUR, VTK_FLAT, VTK_SMOOTH, Fragments,
                               ObjectTable, face_normals, shade, to_8bit)
from renderer.textbook_lighting import CLASSIC, OPENGL, light_faces, light_vertices
from renderer.texture import CLAMP, LINEAR, NEAREST, REPEAT
from renderer.translucency import draw_translucent
from renderer.transform import normal_matrix, transform_points
from renderer.window import clip_to_window, window_rows_to_image_rows
from renderer.workspace import empty, thread_workspace


@dataclass(frozen=True)
class RenderOptions:
    """Choices a lesson can change; the defaults are what VTK does.

    fill_rule : "top-left" (OpenGL/llvmpipe) or "bottom-right" (deliberately wrong).
    interpolation : None (the scene's ``[render] interpolation``), "perspective"
        (correct, GPUs) or "screen" (linear in screen space, as the course's scanline
        slides do), for colours, positions and normals.
    """

    fill_rule: str = "top-left"
    interpolation: str | None = None


class SceneGeometry(NamedTuple):
    """Every object's vertices after stages 1–3 and its triangles, concatenated in draw order.

    verts_view (N, 3) view-space positions; verts_clip (N, 4) clip-space positions;
    normals_view (N, 3) view-space vertex normals, unnormalised (zeros when the object has
    none); triangles (T, 3) indices into those rows; tri_object (T,) each triangle's
    object; vert_object (N,) each vertex's object; tcoords (N, 2) texture coordinates
    (zeros when the object has none); face_normals (T, 3) each triangle's unit view-space
    plane normal, (v1 − v0) × (v2 − v0) normalised (zero when it has no area).
    """

    verts_view: np.ndarray
    verts_clip: np.ndarray
    normals_view: np.ndarray
    triangles: np.ndarray
    tri_object: np.ndarray
    vert_object: np.ndarray
    tcoords: np.ndarray
    face_normals: np.ndarray


def transform_scene(scene, world_to_view_m: np.ndarray, view_to_clip_m: np.ndarray) -> SceneGeometry:
    """Stages 1–3 for every object: model → world → view → clip, vertex by vertex."""
    views, clips, normals, tris, owners, vert_owners, tcoords = [], [], [], [], [], [], []
    offset = 0
    for i, obj in enumerate(scene.objects):
        model_to_view = obj.model_to_world @ world_to_view_m
        verts_view = transform_points(obj.mesh.points, model_to_view)
        views.append(verts_view[:, :3])
        clips.append(verts_view @ view_to_clip_m)
        if obj.mesh.point_normals is not None:
            normals.append(obj.mesh.point_normals @ normal_matrix(model_to_view))
        else:
            normals.append(np.zeros((obj.mesh.n_points, 3)))
        tris.append(obj.mesh.triangles + offset)
        owners.append(np.full(obj.mesh.n_triangles, i, np.int64))
        vert_owners.append(np.full(obj.mesh.n_points, i, np.int64))
        tcoords.append(obj.mesh.tcoords if obj.mesh.tcoords is not None else np.zeros((obj.mesh.n_points, 2)))
        offset += obj.mesh.n_points
    verts_view, triangles = np.ascontiguousarray(np.concatenate(views)), np.concatenate(tris)
    normals_face = np.empty((len(triangles), 3))
    face_normals(verts_view, triangles, normals_face)
    return SceneGeometry(verts_view, np.concatenate(clips), np.concatenate(normals), triangles,
                         np.concatenate(owners), np.concatenate(vert_owners), np.concatenate(tcoords), normals_face)


MODEL_CODES = {"vtk": 0, "opengl": OPENGL, "classic": CLASSIC}

VTK_MAX_SPECULAR_POWER = 128.0
"""``vtkProperty::SetSpecularPower`` clamps to [0, 128]: a larger power in the vtk model
draws as 128 (measured: 1000 is read back as 128.0). The classic model keeps any power."""


def object_kind(obj) -> int:
    """How the shading kernel treats an object: by model, shading and whether it has normals."""
    smooth = obj.shading != "flat" and obj.mesh.point_normals is not None
    if obj.material.reflection_model == "vtk":
        return VTK_SMOOTH if smooth else VTK_FLAT
    if not smooth:
        return FACE_COLOUR
    return VERTEX_COLOUR if obj.shading == "gouraud" else TEXTBOOK_PIXEL


def object_table(scene, complexity: int) -> ObjectTable:
    """Per-object shading data for the kernels.

    amb, dif, spe, power by model — vtk: Ka·C, Kd·C, Ks·Cs, specular power (at most
    :data:`VTK_MAX_SPECULAR_POWER`, as VTK clamps it); opengl: the material's ambient,
    diffuse and specular colours and its shininess; classic: Ka·O, Kd·O, Ks·(1, 1, 1), n.
    """
    kind, model, comp, amb, dif, spe, power = [], [], [], [], [], [], []
    for obj in scene.objects:
        m = obj.material
        kind.append(object_kind(obj))
        model.append(MODEL_CODES[m.reflection_model])
        comp.append(complexity if m.lighting else UNLIT)
        colour = np.asarray(m.color)
        if m.reflection_model == "opengl":
            amb.append(m.gl_ambient), dif.append(m.gl_diffuse), spe.append(m.gl_specular)
            power.append(m.shininess)
        elif m.reflection_model == "classic":
            amb.append(m.ambient * colour), dif.append(m.diffuse * colour), spe.append(np.full(3, m.specular))
            power.append(m.specular_power)
        else:
            amb.append(m.ambient * colour), dif.append(m.diffuse * colour)
            spe.append(m.specular * np.asarray(m.effective_specular_color))
            power.append(min(m.specular_power, VTK_MAX_SPECULAR_POWER))
    r = scene.render
    tex = texture_table(scene)
    return ObjectTable(np.array(kind, np.int64), np.array(model, np.int64), np.array(comp, np.int64),
                       np.array(amb, np.float64), np.array(dif, np.float64), np.array(spe, np.float64),
                       np.array(power, np.float64), np.asarray(r.global_ambient, np.float64),
                       np.asarray(r.ambient, np.float64), bool(r.local_viewer), bool(r.separate_specular), *tex)


def texture_table(scene):
    """All objects' textures in one flat (Σ H·W, 3) uint8 array (their ``texels_8bit``), and
    per object: textured flag, offset, width, height, filter and wrap codes (see
    :mod:`renderer.texture`).

    Only textured objects take rows (the kernels sample nothing for the others). With one
    textured object the flat array is a view of its texels, not a copy: a 2048×1024 texture
    copied every frame cost more than shading the frame."""
    textured, offset, width, height, filt, wrap, chunks = [], [], [], [], [], [], []
    start = 0
    for obj in scene.objects:
        t = obj.texture
        textured.append(t is not None)
        h, w = (t.texels.shape[:2]) if t is not None else (1, 1)
        offset.append(start if t is not None else 0)
        width.append(w)
        height.append(h)
        filt.append(LINEAR if t is not None and t.filter == "linear" else NEAREST)
        wrap.append(CLAMP if t is not None and t.wrap == "clamp" else REPEAT)
        if t is not None:
            chunks.append(t.texels_8bit.reshape(-1, 3))
            start += h * w
    if not chunks:
        texels = np.full((1, 3), 255, np.uint8)
    else:
        texels = chunks[0] if len(chunks) == 1 else np.concatenate(chunks)
    as_int = lambda v: np.array(v, np.int64)  # noqa: E731
    return (np.array(textured, np.bool_), as_int(offset), as_int(width), as_int(height), as_int(filt), as_int(wrap),
            texels)


def textbook_colours(geo: SceneGeometry, objs: ObjectTable, lights, ws=None):
    """Lit colours per vertex (Gouraud) and per triangle (flat) for the textbook models:
    (N, 6) and (T, 6), primary RGB then secondary (separate specular) RGB."""
    vert_colour = empty(ws, "shade.vert_colour", (len(geo.verts_view), 6))
    face_colour = empty(ws, "shade.face_colour", (len(geo.triangles), 6))
    if (objs.kind == VERTEX_COLOUR).any():
        light_vertices(geo.verts_view, geo.normals_view, geo.vert_object, objs.model, objs.amb, objs.dif, objs.spe,
                       objs.power, objs.global_ambient, objs.local_viewer, objs.separate_specular,
                       objs.ambient_light, lights, vert_colour)
    if (objs.kind == FACE_COLOUR).any():
        light_faces(geo.verts_view, geo.triangles, geo.face_normals, geo.tri_object, objs.model, objs.amb, objs.dif,
                    objs.spe, objs.power, objs.global_ambient, objs.local_viewer, objs.separate_specular,
                    objs.ambient_light, lights, face_colour)
    return vert_colour, face_colour


class Stages(NamedTuple):
    """What the pipeline held on the way to a frame, for the stage views (:func:`render_stages`).

    Image rows (row 0 at the top) for the per-pixel buffers, window coordinates (y up,
    pixels) for the triangles, as :mod:`renderer.window` and :mod:`renderer.raster` hold them.

    geometry : the scene's vertices and source triangles after stages 1–3 (:class:`SceneGeometry`).
    tri_window : (K, 3, 3) the clipped triangles in window space (x, y up, z in 0..1), in
        draw order (back to front for the painter's algorithm).
    tri_fixed : (K, 3, 2) int64, their x, y snapped to 1/256 pixel.
    clip_source : (K,) the source triangle (row of ``geometry.triangles``) each came from.
    front : (K,) bool, counter-clockwise on screen (:func:`renderer.raster.signed_area_fixed` > 0).
    translucent : (K,) bool, drawn as translucent fragments instead of through the z-buffer.
    depth : (H, W) the z-buffer after the opaque pass: window depth on the 24-bit grid,
        1.0 where empty (the frame's ``depth``).
    triangle : (H, W) int64, the source triangle that won each pixel of the opaque pass,
        −1 where none did (the triangle-ID image).
    """

    geometry: SceneGeometry
    tri_window: np.ndarray
    tri_fixed: np.ndarray
    clip_source: np.ndarray
    front: np.ndarray
    translucent: np.ndarray
    depth: np.ndarray
    triangle: np.ndarray


def render(scene, options: RenderOptions = RenderOptions()) -> Frame:
    """Draw ``scene`` with scanlab's own pipeline.

    Returns a :class:`lab.frame.Frame`: ``rgb`` (H, W, 3) uint8 with row 0 at the top,
    ``depth`` window depth of the opaque surfaces (1.0 where empty; translucent ones write
    none, as in VTK), ``coverage`` (any surface, opaque or translucent).

    Examples
    --------
    >>> from lab import load_scene
    >>> render(load_scene("cube")).rgb.shape
    (384, 512, 3)
    """
    return _render(scene, options, keep_stages=False)[0]


def render_stages(scene, options: RenderOptions = RenderOptions()) -> tuple[Frame, Stages]:
    """:func:`render`, and the buffers the pipeline held before the colours (:class:`Stages`).

    >>> from lab import load_scene
    >>> frame, stages = render_stages(load_scene("cube"))
    >>> int(stages.triangle.max()) < 12 and stages.depth.shape == (384, 512)
    True
    """
    return _render(scene, options, keep_stages=True)


def _render(scene, options: RenderOptions, keep_stages: bool) -> tuple[Frame, Stages | None]:
    """The pipeline; with ``keep_stages`` its buffers are copied out of the workspace too."""
    width, height = scene.image.size
    cam = scene.camera
    w2v = world_to_view(cam)
    v2c = view_to_clip(cam, width / height, clipping_range(cam, scene.world_bounds()))
    geo = transform_scene(scene, w2v, v2c)

    ws = thread_workspace()
    tri_clip, clip_bary, clip_source = clip_triangles(geo.verts_clip, geo.triangles, ws)
    tri_window, tri_fixed = clip_to_window(tri_clip, width, height, ws)
    hidden = scene.render.hidden_surface
    if hidden == "painter":  # back to front; the fragments then simply overwrite
        order = painter_order(tri_window)
        tri_clip, clip_bary, clip_source = tri_clip[order], clip_bary[order], clip_source[order]
        tri_window, tri_fixed = tri_window[order], tri_fixed[order]
    # opaque objects through the z-buffer; translucent ones (opacity < 1) afterwards, as fragment lists
    opacity = np.array([obj.material.opacity for obj in scene.objects], np.float64)
    translucent = opacity[geo.tri_object[clip_source]] < 1.0
    opaque = ~translucent if translucent.any() else slice(None)
    depth, tri_index, bary, front = rasterize_triangles(tri_fixed[opaque], tri_window[opaque], width, height,
                                                        options.fill_rule, ws=ws, depth_test=hidden == "zbuffer",
                                                        cull_back=scene.render.cull_backfaces)

    lights = view_lights(scene.lights, cam, w2v)
    objs = object_table(scene, lights.complexity)
    vert_colour, face_colour = textbook_colours(geo, objs, lights, ws)
    interpolation = options.interpolation or scene.render.interpolation
    rgb = np.empty((height, width, 3), np.uint8)
    shade(Fragments(tri_index, bary, front, tri_clip[opaque], clip_bary[opaque], clip_source[opaque]), geo, objs,
          lights, vert_colour, face_colour, bool(cam.parallel), interpolation == "perspective",
          to_8bit(np.asarray(scene.image.background)), rgb)
    coverage = tri_index >= 0
    if translucent.any():
        coverage = coverage | draw_translucent(
            tri_fixed[translucent], tri_window[translucent], tri_clip[translucent], clip_bary[translucent],
            clip_source[translucent], depth, rgb, geo, objs, lights, vert_colour, face_colour, opacity,
            scene.render.transparency, bool(cam.parallel), interpolation == "perspective", options.fill_rule,
            depth_test=hidden == "zbuffer", cull_back=scene.render.cull_backfaces, ws=ws)
    frame = Frame(rgb=window_rows_to_image_rows(rgb), depth=window_rows_to_image_rows(depth.copy()),
                  coverage=window_rows_to_image_rows(coverage))
    if not keep_stages:
        return frame, None
    source = clip_source[opaque]
    triangle = np.where(tri_index >= 0, source[np.maximum(tri_index, 0)] if len(source) else -1, -1)
    area = ((tri_fixed[:, 1, 0] - tri_fixed[:, 0, 0]) * (tri_fixed[:, 2, 1] - tri_fixed[:, 0, 1])
            - (tri_fixed[:, 2, 0] - tri_fixed[:, 0, 0]) * (tri_fixed[:, 1, 1] - tri_fixed[:, 0, 1]))
    stages = Stages(geo, tri_window.copy(), tri_fixed.copy(), clip_source.copy(), area > 0, translucent.copy(),
                    frame.depth, window_rows_to_image_rows(triangle).copy())
    return frame, stages
