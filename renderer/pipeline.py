"""The whole pipeline, stage by stage: scene → :class:`lab.frame.Frame`.

1. model → world (:mod:`renderer.transform`), 2. world → view and 3. view → clip
(:mod:`renderer.camera`), 4. clipping (:mod:`renderer.clip`), 5. window mapping and
sub-pixel snapping (:mod:`renderer.window`), 6. scanline fill with the top-left rule and
the z-buffer (:mod:`renderer.raster`), 7. shading (:mod:`renderer.lit_colours`, :mod:`renderer.shading`, the
reflection models of :mod:`renderer.reflection`), 8. 8-bit output with the flip to image rows. Objects with
opacity < 1 skip the z-buffer: after the opaque frame is shaded they are composited over
it from per-pixel fragment lists (:mod:`renderer.translucency`).

Memory: per-triangle tables stay short. Clipping names the triangles it keeps whole
instead of copying them and the window mapping maps each vertex once
(:class:`ClippedMesh`); the raster sets up and draws :data:`renderer.raster.BATCH`
triangles at a time (a frame of up to :data:`ONE_BATCH`, all at once); shading gets tables
for the triangles that won a pixel only
(:mod:`renderer.visible`). ``RenderOptions(lean=False)`` is the plain path the tests
compare this with.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial
from itertools import accumulate
from typing import NamedTuple

import numpy as np

from lab.frame import Frame
from renderer.camera import clipping_range, view_to_clip, world_to_view
from renderer.clip import Clipped, CornerIndex, clip_mesh, clipped_corners, corner_rows, picked
from renderer.free_cores import threads_of_this_frame
from renderer.lights import view_lights
from renderer.lit_colours import lit_colours
from renderer.painter import painter_order
from renderer.indexed_triangles import IndexedTriangles
from renderer.raster import BATCH, rasterize_visibility, weight_planes
from renderer.reflection.materials import any_face_colour, any_flat
from renderer.reflection.registry import material_table
from renderer.plane_normals import face_normals, face_normals_of
from renderer.shading import (EVERYTHING, HELD, Fragments, ShadingInputs, fragment_reads, fragments, shade, to_8bit,
                              with_span_table)
from renderer.spans import CornerTables
from renderer.texture_sampling import texture_table
from renderer.translucency import draw_translucent, reads_opaque_depth
from renderer.transform import normal_matrix, normals_to_view, transform_vertices
from renderer.visibility_buffer import cleared_depth, depth_to_window, untested_visibility
from renderer.visible import renumbering_pays, visible_triangles
from renderer.window import WindowVertices, window_into, window_rows_to_image_rows
from renderer.workspace import empty, kept, thread_workspace


@dataclass(frozen=True)
class RenderOptions:
    """Choices a lesson can change; the defaults are what VTK does.

    fill_rule : "top-left" (OpenGL/llvmpipe) or "bottom-right" (deliberately wrong).
    interpolation : None (the scene's ``[render] interpolation``), "perspective"
        (correct, GPUs) or "screen" (linear in screen space, as the course's scanline
        slides do), for colours, positions and normals.
    spans : shade each row in spans of one triangle (the fast path, :mod:`renderer.spans`)
        or, False, pixel by pixel (the plain path; the same bytes, tests compare them).
    lean : keep per-triangle tables short (the lean path): a triangle clipping keeps whole
        is not copied, triangles are set up and drawn in batches, and shading gets the
        tables of the triangles that won a pixel only; False (the plain path, the same
        bytes, tests compare them) cuts every triangle against all six planes, writes each
        out, and sets them all up at once for the raster and for shading.
    backs_last : with the z-buffer on, draw the back faces after the front faces and skip
        those a tile z-buffer shows hidden (:mod:`renderer.hidden_back_faces`); False draws
        every triangle in order (the plain path; the same bytes, tests compare them).
    """

    fill_rule: str = "top-left"
    interpolation: str | None = None
    spans: bool = True
    lean: bool = True
    backs_last: bool = True


class SceneGeometry(NamedTuple):
    """Every object's vertices after stages 1–3 and its triangles, concatenated in draw order.

    verts_view (N, 3) view-space positions; verts_clip (N, 4) clip-space positions;
    outcodes (N,) uint8 each clip-space position's outcode (:func:`renderer.clip.outcode`);
    normals_view (N, 3) view-space vertex normals, unnormalised (zeros when the object has
    none); triangles (T, 3) indices into those rows; tri_object (T,) each triangle's
    object; vert_object (N,) each vertex's object; tcoords (N, 2) texture coordinates
    (zeros when the object has none); face_normals (T, 3) each triangle's unit view-space
    plane normal, (v1 − v0) × (v2 − v0) normalised (zero when it has no area); parallel:
    the camera projects in parallel (the viewer is at infinity along +z, which decides
    which side of a triangle faces it).
    """

    verts_view: np.ndarray
    verts_clip: np.ndarray
    outcodes: np.ndarray
    normals_view: np.ndarray
    triangles: np.ndarray
    tri_object: np.ndarray
    vert_object: np.ndarray
    tcoords: np.ndarray
    face_normals: np.ndarray
    parallel: bool


class ClippedTriangles(NamedTuple):
    """Clipped triangles written out one by one (:meth:`ClippedMesh.written_out`), in draw order.

    tri_clip (K, 3, 4) clip-space vertices; clip_bary (K, 3, 3) their weights in the source
    triangle; clip_source (K,) int64 the source triangle; tri_window (K, 3, 3) window space
    (x, y up, z in 0..1); tri_fixed (K, 3, 2) int64 x and y on the 1/256-pixel grid.
    """

    tri_clip: np.ndarray
    clip_bary: np.ndarray
    clip_source: np.ndarray
    tri_window: np.ndarray
    tri_fixed: np.ndarray


@dataclass(frozen=True)
class ClippedMesh:
    """The triangles after clipping (stage 4) and window mapping (stage 5), in draw order,
    held as indices: nothing is copied per triangle.

    Each of the K triangles names its source triangle and, when clipping cut it, its piece
    (:class:`renderer.clip.Clipped`). Its corners are rows of vertex tables: rows 0 … N − 1
    are the scene's vertices (the corners of a triangle kept whole), rows N + 3p + v corner
    v of piece p (:class:`renderer.clip.CornerIndex`). A vertex shared by many triangles is
    mapped to the window once, which gives each of them the bits it would get alone.

    clip_source (K,) int32, piece (K,) int32 (−1: kept whole); clipped: the
    :class:`renderer.clip.Clipped` these index (all of the frame's pieces); geometry: the
    :class:`SceneGeometry` (its ``triangles`` and ``verts_clip``); window (N + 3P, 3) and
    fixed (N + 3P, 2) int64: the rows in window space (:func:`renderer.window.clip_to_window`);
    cells (N + 3P,) int64: their centre cells (:func:`renderer.window.centre_cell`).
    """

    clip_source: np.ndarray
    piece: np.ndarray
    clipped: Clipped
    geometry: SceneGeometry
    window: np.ndarray
    fixed: np.ndarray
    cells: np.ndarray

    @property
    def count(self) -> int:
        return len(self.clip_source)

    def take(self, index) -> "ClippedMesh":
        """The triangles picked by ``index`` (a mask or an order), in that order."""
        return replace(self, clip_source=self.clip_source[index], piece=self.piece[index])

    def take_in_order(self, order: np.ndarray, ws=None, name: str = "picked") -> "ClippedMesh":
        """:meth:`take` of the triangles ``order`` (int64), in that order, with the tables in workspace
        ``ws`` under ``name`` (:func:`renderer.clip.picked`)."""
        source, piece = picked(self.clip_source, self.piece, order, ws, name)
        return replace(self, clip_source=source, piece=piece)

    def corner_index(self) -> CornerIndex:
        """Where the triangles' corners are in ``window`` and ``fixed`` (:class:`renderer.clip.CornerIndex`)."""
        return CornerIndex(self.clip_source, self.piece, self.geometry.triangles, len(self.geometry.verts_clip))

    def corner_tables(self) -> CornerTables:
        """The triangles' corners as clipping and the window mapping left them
        (:class:`renderer.spans.CornerTables`)."""
        c = self.clipped
        return CornerTables(*self.corner_index(), c.piece_clip, c.piece_bary, self.geometry.verts_clip, self.window,
                            self.fixed)

    def corner_rows(self) -> np.ndarray:
        """(K, 3) int64: the rows of the triangles' corners in ``window`` and ``fixed``, written out."""
        rows = np.empty((self.count, 3), np.int64)
        corner_rows(self.corner_index(), rows)
        return rows

    def indexed(self) -> IndexedTriangles:
        """The triangles as the raster takes them (:class:`renderer.raster.IndexedTriangles`)."""
        return IndexedTriangles(self.corner_index(), self.fixed, self.window, self.cells)

    def corners_written_out(self, ws=None, name="clipped"):
        """``(tri_clip, clip_bary, clip_source)`` as :class:`ClippedTriangles` holds them."""
        picked = self.clipped._replace(source=self.clip_source, piece=self.piece)
        return clipped_corners(picked, self.geometry.verts_clip, self.geometry.triangles, ws, name)

    def written_out(self) -> ClippedTriangles:
        """Every table of :class:`ClippedTriangles`, one row per triangle (a copy)."""
        rows = self.corner_rows()
        return ClippedTriangles(*self.corners_written_out(), np.take(self.window, rows, axis=0),
                                np.take(self.fixed, rows, axis=0))  # np.take: 11 µs, indexing 42 µs (1,484 triangles)


def clip_and_map(geo: SceneGeometry, width: int, height: int, ws=None, trivial: bool = True,
                 vertices: WindowVertices | None = None) -> ClippedMesh:
    """Stages 4 and 5: clip the scene's triangles (:func:`renderer.clip.clip_mesh`; ``trivial``
    False cuts every one) and map the scene's vertices and the pieces' corners to the
    window, once each. ``vertices``: the scene's vertices already mapped
    (:func:`transform_and_map`), in workspace ``ws``'s tables when given one; the pieces'
    corners are then mapped into the rows after them (in the same storage while it is large
    enough, else the vertices' rows are copied over: a frame with more pieces than any before)."""
    clipped = clip_mesh(geo.verts_clip, geo.triangles, ws, trivial, geo.outcodes)
    n, p = len(geo.verts_clip), len(clipped.piece_clip)
    if vertices is not None and not p:
        return ClippedMesh(clipped.source, clipped.piece, clipped, geo, vertices.window, vertices.fixed, vertices.cells)
    window, fixed, cells = window_tables(ws, n + 3 * p)
    if vertices is None:
        window_into(geo.verts_clip, width, height, window[:n], fixed[:n], cells[:n])
    else:
        for table, mapped in zip((window, fixed, cells), (vertices.window, vertices.fixed, vertices.cells)):
            if not np.shares_memory(table[:n], mapped):
                table[:n] = mapped
    if p:  # no pieces, no parallel loop to start
        window_into(clipped.piece_clip.reshape(-1, 4), width, height, window[n:], fixed[n:], cells[n:])
    return ClippedMesh(clipped.source, clipped.piece, clipped, geo, window, fixed, cells)


def window_tables(ws, rows: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``window`` (rows, 3), ``fixed`` (rows, 2) int64 and ``cells`` (rows,) int64 for points
    mapped to the window (:func:`renderer.window.window_into`), in workspace ``ws``: the
    scene's vertices in the first rows, the pieces' corners after them (:class:`ClippedMesh`)."""
    return (empty(ws, "window.window", (rows, 3)), empty(ws, "window.fixed", (rows, 2), np.int64),
            empty(ws, "window.cells", rows, np.int64))


class RasterRules(NamedTuple):
    """How fragments are made: ``fill_rule`` ("top-left" or "bottom-right"), ``depth_test``
    (the z-buffer, else the last fragment drawn wins) and ``cull_back`` (drop clockwise
    triangles)."""

    fill_rule: str = "top-left"
    depth_test: bool = True
    cull_back: bool = False


def transform_scene(scene, world_to_view_m: np.ndarray, view_to_clip_m: np.ndarray, ws=None,
                    with_face_normals: bool = True) -> SceneGeometry:
    """Stages 1–3 for every object: model → world → view → clip, vertex by vertex
    (:func:`renderer.transform.transform_vertices`, each object into its rows). With a
    workspace ``ws`` the tables live in it (a 327,680-triangle sphere's are 28 MB, faulted
    in page by page when allocated afresh each frame); the tables that depend on the
    scene's layout alone — each triangle's and vertex's object (:func:`object_numbers`), and
    zero texture coordinates when no mesh has any — are kept there from frame to frame, not
    written again (:meth:`renderer.workspace.Workspace.kept`). ``with_face_normals`` False leaves
    ``face_normals`` undefined, for a frame no object of which reads them
    (:func:`renderer.reflection.materials.any_flat`)."""
    return transform_and_map(scene, world_to_view_m, view_to_clip_m, None, ws, with_face_normals).geometry


class MappedScene(NamedTuple):
    """:func:`transform_and_map`'s result: the scene's ``geometry`` after stages 1–3
    (:class:`SceneGeometry`) and its ``vertices`` in window space (stage 5,
    :class:`renderer.window.WindowVertices`; tables without rows when not mapped)."""

    geometry: SceneGeometry
    vertices: WindowVertices


def transform_and_map(scene, world_to_view_m: np.ndarray, view_to_clip_m: np.ndarray, size, ws=None,
                      with_face_normals: bool = True) -> MappedScene:
    """:func:`transform_scene`, and each vertex mapped to a window ``size`` (width, height)
    pixels in the same kernel (None: not mapped), into the first rows of the window tables
    (:func:`window_tables`) that :func:`clip_and_map` then completes with the pieces' corners."""
    objects = scene.objects
    n_points = [obj.mesh.n_points for obj in objects]
    n_triangles = [obj.mesh.n_triangles for obj in objects]
    starts, firsts = np.array([0, *accumulate(n_points)], np.int64), np.array([0, *accumulate(n_triangles)], np.int64)
    n, t = int(starts[-1]), int(firsts[-1])
    verts_view, verts_clip = empty(ws, "geometry.verts_view", (n, 3)), empty(ws, "geometry.verts_clip", (n, 4))
    codes = empty(ws, "geometry.outcodes", n, np.uint8)
    normals = empty(ws, "geometry.normals_view", (n, 3))
    window, fixed, cells = window_tables(ws, n) if size is not None else UNMAPPED
    pixels = (0, 0) if size is None else (int(size[0]), int(size[1]))
    tri_object = kept(ws, "geometry.tri_object", tuple(n_triangles), partial(object_numbers, n_triangles))
    vert_object = kept(ws, "geometry.vert_object", tuple(n_points), partial(object_numbers, n_points))
    textured = any(obj.mesh.tcoords is not None for obj in objects)
    tcoords = (empty(ws, "geometry.tcoords", (n, 2)) if textured
               else kept(ws, "geometry.no_tcoords", n, partial(np.zeros, (n, 2))))
    no_normals = np.empty((0, 3))
    for obj, a, b in zip(objects, starts[:-1], starts[1:]):
        model_to_view = obj.model_to_world @ world_to_view_m
        mesh = obj.mesh
        transform_vertices(np.ascontiguousarray(mesh.points, dtype=np.float64), model_to_view, view_to_clip_m, pixels,
                           verts_view[a:b], verts_clip[a:b], codes[a:b], window[a:b], fixed[a:b], cells[a:b])
        has_normals = mesh.point_normals is not None
        normals_to_view(np.ascontiguousarray(mesh.point_normals, dtype=np.float64) if has_normals else no_normals,
                        normal_matrix(model_to_view) if has_normals else np.eye(3), normals[a:b])
        if textured:
            tcoords[a:b] = mesh.tcoords if mesh.tcoords is not None else 0.0
    if len(objects) == 1:
        triangles = np.ascontiguousarray(objects[0].mesh.triangles, dtype=np.int64)
    else:
        triangles = empty(ws, "geometry.triangles", (t, 3), np.int64)
        for obj, a, first, last in zip(objects, starts[:-1], firsts[:-1], firsts[1:]):
            np.add(obj.mesh.triangles, a, out=triangles[first:last])
    normals_face = empty(ws, "geometry.face_normals", (t, 3))
    if with_face_normals:
        face_normals(verts_view, triangles, normals_face)
    geometry = SceneGeometry(verts_view, verts_clip, codes, normals, triangles, tri_object, vert_object, tcoords,
                             normals_face, bool(scene.camera.parallel))
    return MappedScene(geometry, WindowVertices(fixed, window, cells))


UNMAPPED = (np.empty((0, 3)), np.empty((0, 2), np.int64), np.empty(0, np.int64))
"""The window tables of vertices not mapped (:func:`transform_and_map` without a size): no rows."""


ONE_BATCH = 1 << 18
"""The most triangles of a frame the raster sets up and draws as one batch (:func:`raster_batch`;
about 45 MB of set-up tables, against 5 MB a batch of :data:`renderer.raster.BATCH`): then
every front face of the frame is drawn before its back faces, and the tile z-buffer hides
most of those (:mod:`renderer.hidden_back_faces`). Measured, whole frames, one batch against
batches alternating in one process (20 pairs): the level-7 icospheres, 190k triangles kept,
0.87–0.91 of the time (flat and phong, 512² and 1024²). Larger frames stay in batches: as one
batch the 270k-triangle scan took 0.91–0.96, but the 672k-triangle sponge 1.045 and the 1M
scan 1.03, and a whole 328k-triangle sphere 192 bytes a triangle at 128² instead of 50
(docs/performance.md)."""


def raster_batch(count: int) -> int:
    """Triangles the raster sets up and draws at a time, of a frame's ``count``: all of them up
    to :data:`ONE_BATCH`, else :data:`renderer.raster.BATCH`."""
    return count if count <= ONE_BATCH else BATCH


def object_numbers(counts) -> np.ndarray:
    """(Σ counts,) int64: object i's number repeated ``counts[i]`` times — the object of each
    triangle (or vertex) of the concatenated tables. It depends on the counts alone, so
    :func:`transform_scene` keeps it in the workspace from frame to frame (written afresh,
    a 672,768-triangle sponge's took 0.8 ms a frame)."""
    return np.repeat(np.arange(len(counts), dtype=np.int64), counts)


NO_FACE_NORMALS = np.empty((0, 3))
"""The ``face_normals`` of a :class:`SceneGeometry` whose frame reads none (no object shaded flat):
the span table then neither reads nor asks ahead for a plane normal a triangle
(:func:`renderer.spans.table_row`), one cache line a triangle read at random, and worked out
for nothing."""


def translucent_triangles(clipped: ClippedMesh, opacity: np.ndarray, ws=None) -> np.ndarray:
    """(K,) bool: which of the ``clipped`` triangles belong to a translucent object (``opacity``
    < 1, each object's). In a frame without one, an array of False kept in the workspace
    from frame to frame (callers do not write to it): made afresh, with the two tests of it,
    0.25 ms a frame of the 1M-triangle scan."""
    if (opacity < 1.0).any():
        return opacity[clipped.geometry.tri_object[clipped.clip_source]] < 1.0
    return kept(ws, "pipeline.none_translucent", clipped.count, partial(np.zeros, clipped.count, np.bool_))


def normals_of_shown(materials, every_normal: bool, reads: str, any_translucent: bool) -> bool:
    """True when a frame works out the plane normals of the triangles it shows
    (:func:`shown_sources`): some object is flat, the transform did not make them all
    (``every_normal``), and something reads them. A frame painted from held colours alone
    (``reads`` is :data:`~renderer.shading.HELD`) with nothing translucent reads none: the
    held colours work their normals out from the corners (:func:`renderer.held_colours.held_colours`).
    Measured, whole frames alternating in one process against a table worked out first and
    read by the held colours (30 pairs): ico7-flat 0.96 (512²) and 0.97 (1024²), the level-4
    sponge 0.98 and 0.995; the small flat frames 0.98–1.01 (60 pairs), two copies of the old
    0.98–1.02 (docs/performance.md)."""
    return any_flat(materials) and not every_normal and not (reads == HELD and not any_translucent)


def shown_sources(won: ClippedMesh, translucent_sources: np.ndarray) -> np.ndarray:
    """The source triangles whose plane normals a flat frame reads (int64, repeats allowed):
    those that won a pixel of the opaque pass and every translucent one. Only these are
    worked out (:func:`renderer.plane_normals.face_normals_of`): a 327,680-triangle sphere at
    512² shows one in six of its triangles (51,191), a level-4 Menger sponge (672,768
    triangles) one in seventeen."""
    return np.concatenate([np.asarray(won.clip_source, np.int64), np.asarray(translucent_sources, np.int64)])


def copied(geo: SceneGeometry) -> SceneGeometry:
    """``geo`` with every table copied (out of the workspace, for a caller to keep)."""
    return SceneGeometry(*(v.copy() if isinstance(v, np.ndarray) else v for v in geo))


class Stages(NamedTuple):
    """What the pipeline held on the way to a frame, for the stage views (:func:`render_stages`).

    Image rows (row 0 at the top) for the per-pixel buffers, window coordinates (y up,
    pixels) for the triangles, as :mod:`renderer.window` and :mod:`renderer.raster` hold them.

    geometry : the scene's vertices and source triangles after stages 1–3 (:class:`SceneGeometry`).
    tri_window : (K, 3, 3) the clipped triangles in window space (x, y up, z in 0..1), in
        draw order (back to front for the painter's algorithm).
    tri_fixed : (K, 3, 2) int64, their x, y snapped to 1/256 pixel.
    clip_source : (K,) the source triangle (row of ``geometry.triangles``) each came from.
    front : (K,) bool, counter-clockwise on screen (:func:`renderer.window.signed_area_fixed` > 0).
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


def shading_fragments(won: ClippedMesh, tri_index: np.ndarray, perspective: bool, ws=None,
                      reads: str = EVERYTHING) -> Fragments:
    """The :class:`renderer.shading.Fragments` of the triangles that won a pixel (``won``,
    numbered as ``tri_index`` numbers them, :func:`renderer.visible.visible_triangles`), with
    what shading reads of them (``reads``, :func:`renderer.shading.fragment_reads`):
    :data:`~renderer.shading.EVERYTHING`, their corners and weights written out, their facing
    and the planes of their weights (:func:`renderer.raster.weight_planes`: shading reads no
    depth plane, rows or spans); :data:`~renderer.shading.SPAN_TABLE`, their source triangles
    and span table, read straight from the clipped corners (:class:`renderer.spans.CornerTables`),
    the rest empty; :data:`~renderer.shading.HELD`, their source triangles only, for a frame
    painted from held colours."""
    if reads != EVERYTHING:
        source = empty(ws, "visible.source", won.count, np.int64)
        source[:] = won.clip_source
        frags = fragments(tri_index, np.empty((0, 6)), np.empty(0, np.bool_), np.empty((0, 3, 4)), np.empty((0, 3, 3)),
                          source, perspective)
        return frags if reads == HELD else with_span_table(frags, won.geometry, ws, clipped=won.corner_tables())
    tri_clip, clip_bary, clip_source = won.corners_written_out(ws, "visible")
    front, plane = empty(ws, "visible.front", won.count, np.bool_), empty(ws, "visible.plane", (won.count, 6))
    weight_planes(won.corner_index(), won.fixed, won.window, front, plane)
    return fragments(tri_index, plane, front, tri_clip, clip_bary, clip_source, perspective)


def image_depth(depth: np.ndarray) -> np.ndarray:
    """The frame's depth: the visibility buffer's 24-bit integers (window rows, y up) as window
    depth 0..1 in image rows (row 0 at the top), a new float64 array. A :class:`lab.frame.Frame`
    runs it when its ``depth`` is first read, not every frame (8 bytes a pixel, 4–5 % of a
    1024² frame of the level-5 icosphere)."""
    return depth_to_window(window_rows_to_image_rows(depth))


def image_depth_of_nothing(shape) -> np.ndarray:
    """:func:`image_depth` of a frame with nothing opaque (:func:`renderer.visibility_buffer.cleared_depth`)."""
    return image_depth(cleared_depth(shape))


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
    with threads_of_this_frame():
        return _render(scene, options, keep_stages=False)[0]


def render_stages(scene, options: RenderOptions = RenderOptions()) -> tuple[Frame, Stages]:
    """:func:`render`, and the buffers the pipeline held before the colours (:class:`Stages`).

    >>> from lab import load_scene
    >>> frame, stages = render_stages(load_scene("cube"))
    >>> int(stages.triangle.max()) < 12 and stages.depth.shape == (384, 512)
    True
    """
    with threads_of_this_frame():
        return _render(scene, options, keep_stages=True)


def _render(scene, options: RenderOptions, keep_stages: bool) -> tuple[Frame, Stages | None]:
    """The pipeline; with ``keep_stages`` its buffers are copied out of the workspace too."""
    width, height = scene.image.size
    cam = scene.camera
    w2v = world_to_view(cam)
    near_far = cam.clipping_range if cam.clipping_range is not None else clipping_range(cam, scene.world_bounds())
    v2c = view_to_clip(cam, width / height, near_far)
    ws = thread_workspace()
    materials = material_table(scene)
    every_normal = keep_stages or any_face_colour(materials)
    geo, vertices = transform_and_map(scene, w2v, v2c, (width, height), ws, with_face_normals=every_normal)
    if not (every_normal or any_flat(materials)):
        geo = geo._replace(face_normals=NO_FACE_NORMALS)  # nothing reads them: the span table neither

    lean = options.lean
    clipped = clip_and_map(geo, width, height, ws, trivial=lean, vertices=vertices)
    hidden = scene.render.hidden_surface
    if hidden == "painter":  # back to front; the fragments then simply overwrite
        clipped = clipped.take(painter_order(clipped.written_out().tri_window))
    rules = RasterRules(options.fill_rule, depth_test=hidden == "zbuffer", cull_back=scene.render.cull_backfaces)
    # opaque objects through the z-buffer; translucent ones (opacity < 1) afterwards, as fragment lists
    translucent = translucent_triangles(clipped, materials.opacity, ws)
    any_translucent = bool((materials.opacity < 1.0).any()) and bool(translucent.any())
    opaque = clipped.take(~translucent) if any_translucent else clipped
    backs_last = options.backs_last and rules.depth_test and not rules.cull_back
    untested = (any_translucent and opaque.count == 0 and not keep_stages
                and not reads_opaque_depth(scene.render.transparency, options.spans))
    if untested:  # nothing opaque: every translucent fragment passes the depth test, so none is made
        vis = untested_visibility(empty(ws, "raster.tri_index", (height, width), np.int32))
        rules = rules._replace(depth_test=False)
    else:
        vis = rasterize_visibility(opaque.indexed(), width, height, rules.fill_rule, ws=ws,
                                   depth_test=rules.depth_test, cull_back=rules.cull_back,
                                   batch=raster_batch(opaque.count) if lean else None, backs_last=backs_last)
    lights = view_lights(scene.lights, cam, w2v, scene.render)
    inputs = ShadingInputs(materials, texture_table(scene), lights, lit_colours(geo, materials, lights, ws))
    reads = fragment_reads(inputs, options.spans)
    if lean and renumbering_pays(opaque.count, height, width, held=reads == HELD):  # the winners only, in sight order
        won = opaque.take_in_order(visible_triangles(vis.tri_index, opaque.count, ws), ws, "won")
    else:
        won = opaque  # vis.tri_index counts every opaque triangle
    if normals_of_shown(materials, every_normal, reads, any_translucent):
        seen_through = clipped.clip_source[translucent] if any_translucent else clipped.clip_source[:0]
        face_normals_of(geo.verts_view, geo.triangles, shown_sources(won, seen_through), geo.face_normals)

    perspective = (options.interpolation or scene.render.interpolation) == "perspective"
    rgb = np.empty((height, width, 3), np.uint8)
    frags = shading_fragments(won, vis.tri_index, perspective, ws, reads)
    shade(frags, geo, inputs, to_8bit(np.asarray(scene.image.background)), rgb, spans=options.spans, reads=reads)
    coverage = vis.covered
    if any_translucent:
        cover = draw_translucent(clipped.take(translucent).written_out(), vis.depth, rgb, geo, inputs,
                                 scene.render.transparency, perspective, rules, ws, options.spans)  # a fresh array
        coverage = np.logical_or(coverage, cover, out=cover) if opaque.count else cover
    depth = partial(image_depth_of_nothing, (height, width)) if untested else partial(image_depth, vis.depth)
    frame = Frame(rgb=window_rows_to_image_rows(rgb), depth=depth,
                  coverage=window_rows_to_image_rows(coverage))
    if not keep_stages:
        return frame, None
    source = won.clip_source.astype(np.int64)
    tri_index = vis.tri_index
    triangle = np.where(tri_index >= 0, source[np.maximum(tri_index, 0)] if len(source) else -1, -1)
    tables = clipped.written_out()
    fixed = tables.tri_fixed
    area = ((fixed[:, 1, 0] - fixed[:, 0, 0]) * (fixed[:, 2, 1] - fixed[:, 0, 1])
            - (fixed[:, 2, 0] - fixed[:, 0, 0]) * (fixed[:, 1, 1] - fixed[:, 0, 1]))
    stages = Stages(copied(geo), tables.tri_window, fixed, tables.clip_source, area > 0,
                    translucent.copy(), frame.depth, window_rows_to_image_rows(triangle).copy())
    return frame, stages
