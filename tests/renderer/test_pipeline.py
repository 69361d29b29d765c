"""The whole pipeline: the Frame it returns, image-row orientation, 8-bit output, determinism, plain-Python kernels,
the lean path's bytes and memory."""
import json
import os
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from lab import load_scene
from lab.mesh import Mesh
from lab.scene import Camera, Image, Light, Material, RenderSettings, Scene, SceneObject, headlight
from lab.shapes import icosphere, quad
from renderer import render
from renderer.shading import to_8bit
from lab.matrices import model_matrix

REPO = Path(__file__).resolve().parents[2]


def upper_quad_scene():
    """64×48, parallel camera of half-height 2 on a unit quad moved up by 1: it spans y ∈ [0.5, 1.5], x ∈ [−0.5, 0.5]."""
    obj = SceneObject(mesh=quad(1.0), model_to_world=model_matrix(translate=(0.0, 1.0, 0.0)))
    return Scene(image=Image(size=(64, 48), background=(0.0, 0.0, 0.0)),
                 camera=Camera(position=(0.0, 0.0, 5.0), parallel=True, parallel_scale=2.0),
                 lights=(headlight(),), objects=(obj,))


def tiny_scene():
    """32×24: a smooth-shaded icosphere with normals and a flat tilted quad, under a headlight and a spot light."""
    ball = icosphere(level=1, radius=0.8)
    ball = Mesh(ball.points, ball.triangles, point_normals=ball.points / 0.8)
    shiny = Material(color=(0.6, 0.7, 0.9), ambient=0.1, diffuse=0.7, specular=0.4, specular_power=15.0)
    objects = (
        SceneObject(mesh=ball, material=shiny, shading="phong", model_to_world=model_matrix(translate=(-0.4, 0, 0))),
        SceneObject(mesh=quad(1.5), material=Material(color=(0.9, 0.5, 0.2), ambient=0.2),
                    model_to_world=model_matrix(rotate=(-30, 20, 0), translate=(0.7, 0, -0.5))),
    )
    lights = (headlight(), Light(kind="scene", position=(2, 2, 3), positional=True, cone_angle=40, exponent=2,
                                 attenuation=(1, 0.1, 0.01)))
    return Scene(image=Image(size=(32, 24), background=(0.2, 0.3, 0.4)),
                 camera=Camera(position=(0.5, 1.0, 4.0), view_angle=40.0), lights=lights, objects=objects)


@pytest.mark.parametrize("name", ["cube", "icosphere:level=2"])
def test_frame_layout(name):
    """render() gives rgb uint8 (H, W, 3), depth exactly 1.0 where nothing is drawn and < 1 where something is."""
    scene = load_scene(name)
    frame = render(scene)
    width, height = scene.image.size
    assert frame.rgb.dtype == np.uint8 and frame.rgb.shape == (height, width, 3)
    assert frame.depth.shape == frame.coverage.shape == (height, width)
    assert frame.coverage.dtype == np.bool_
    assert frame.coverage.any() and not frame.coverage.all()
    assert np.all(frame.depth[~frame.coverage] == 1.0)
    assert np.all((frame.depth[frame.coverage] >= 0.0) & (frame.depth[frame.coverage] < 1.0))


def test_empty_pixels_show_the_background():
    """Where coverage is False the pixel is the background colour in 8 bits (white → 255)."""
    frame = render(load_scene("cube"))
    assert np.all(frame.rgb[~frame.coverage] == 255)
    assert not np.all(frame.rgb[frame.coverage] == 255)


def test_row_zero_is_the_top_of_the_image():
    """A quad in the upper half of the view lands in the top image rows: exactly rows 6–17, columns 26–37 of 64×48."""
    frame = render(upper_quad_scene())
    expected = np.zeros((48, 64), bool)
    expected[6:18, 26:38] = True  # window rows 30..41 (y up) are image rows 47−41..47−30
    np.testing.assert_array_equal(frame.coverage, expected)
    assert np.all(frame.depth[expected] < 1.0) and np.all(frame.rgb[expected].max(axis=1) > 0)


def test_to_8bit_rounds_exact_halves_to_even_in_float32():
    """float32((k + ½)/255)·255 is exactly k + ½ in float32, and rounds to the even neighbour: 0.5/255 → 0, 1.5/255 → 2."""
    k = np.arange(255)
    ties = ((k + 0.5) / 255).astype(np.float32)
    assert np.all(ties * np.float32(255) == (k + 0.5).astype(np.float32))  # really exact ties
    out = to_8bit(ties.astype(np.float64))
    np.testing.assert_array_equal(out, np.where(k % 2 == 0, k, k + 1))
    assert to_8bit(np.array([0.5 / 255, 1.5 / 255])).tolist() == [0, 2]


def test_to_8bit_computes_in_float32_not_float64():
    """0.06470588735294118·255 is 16.500000001 in float64 (→ 17) but exactly 16.5 in float32 (→ 16, even)."""
    c = 0.06470588735294118
    assert np.rint(c * 255) == 17
    assert to_8bit(np.array([c])).tolist() == [16]


def test_to_8bit_clamps_to_0_1():
    """Values outside 0..1 are clamped first: −0.25 → 0, 1.5 → 255; 0 → 0, 1 → 255."""
    assert to_8bit(np.array([[-0.25, 0.0, 1.0, 1.5]])).tolist() == [[0, 0, 255, 255]]


def test_rendering_twice_gives_identical_bytes():
    """Same scene, same bytes: rgb, depth and coverage are deterministic (serial raster, row-parallel shading)."""
    scene = tiny_scene()
    a, b = render(scene), render(scene)
    assert a.rgb.tobytes() == b.rgb.tobytes()
    assert a.depth.tobytes() == b.depth.tobytes()
    assert a.coverage.tobytes() == b.coverage.tobytes()
    c, d = render(load_scene("cube")), render(load_scene("cube"))
    assert c.rgb.tobytes() == d.rgb.tobytes() and c.depth.tobytes() == d.depth.tobytes()


def test_a_frames_depth_read_after_later_frames_is_still_its_own():
    """The frame keeps its integer depth and divides it when first read: read after two other
    scenes of the same size were drawn, it is the depth of its own scene (no memory shared
    with the next frame's buffers), and it is made once."""
    cube, sphere = load_scene("cube"), load_scene("icosphere:level=2")
    sphere = replace(sphere, image=replace(sphere.image, size=cube.image.size))
    read_at_once = render(cube).depth.copy()
    first = render(cube)
    render(sphere), render(sphere)
    assert first.depth.tobytes() == read_at_once.tobytes() and first.depth is first.depth
    assert (first.depth < 1.0).sum() != (render(sphere).depth < 1.0).sum()  # really another picture


_PLAIN_PYTHON_RENDER = """
import runpy, sys
import numpy as np
import numba
assert numba.config.DISABLE_JIT
from renderer import render
frame = render(runpy.run_path(sys.argv[1])["tiny_scene"]())
np.savez(sys.argv[2], rgb=frame.rgb, depth=frame.depth, coverage=frame.coverage)
"""


def test_kernels_run_as_plain_python_with_the_same_bytes(tmp_path):
    """With NUMBA_DISABLE_JIT=1 (kernels as plain Python) a tiny scene renders to the very bytes of the jitted run."""
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PYTHONPATH=os.pathsep.join([str(REPO), os.environ.get("PYTHONPATH", "")]))
    out = tmp_path / "plain.npz"
    result = subprocess.run([sys.executable, "-c", _PLAIN_PYTHON_RENDER, __file__, str(out)], cwd=REPO, env=env,
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-3000:]
    plain = np.load(out)
    jitted = render(tiny_scene())
    assert jitted.coverage.sum() > 100  # the scene really draws something
    np.testing.assert_array_equal(plain["coverage"], jitted.coverage)
    np.testing.assert_array_equal(plain["depth"], jitted.depth)
    np.testing.assert_array_equal(plain["rgb"], jitted.rgb)


def test_threads_and_bands_do_not_change_a_byte():
    """One thread or two, one band of rows or many: the same depth, coverage and colours (z-buffer ties included)."""
    import numba

    from renderer.raster import rasterize_triangles
    from renderer.window import clip_to_window
    from renderer.clip import clip_triangles

    # Two coincident copies of a sphere: every pixel is a depth tie the later copy must win.
    ball = icosphere(level=3)
    twin = SceneObject(mesh=ball, material=Material(color=(0.2, 0.8, 0.3)))
    scene = Scene(image=Image(size=(160, 120)), camera=Camera(position=(1.0, 1.5, 4.0)), lights=(headlight(),),
                  objects=(SceneObject(mesh=ball), twin))
    reference = render(scene)
    saved = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        serial = render(scene)
    finally:
        numba.set_num_threads(saved)
    assert np.array_equal(serial.rgb, reference.rgb) and np.array_equal(serial.depth, reference.depth)
    assert (reference.rgb[reference.coverage] == serial.rgb[serial.coverage]).all()

    clip = np.concatenate([(np.c_[ball.points, np.ones(len(ball.points))] * 0.9) + [0, 0, 0, 2.0]])
    tri_clip, _, _ = clip_triangles(clip, ball.triangles)
    window, fixed = clip_to_window(tri_clip, 97, 61)
    one = rasterize_triangles(fixed, window, 97, 61, n_bands=1)
    for bands in (2, 7, 61):
        many = rasterize_triangles(fixed, window, 97, 61, n_bands=bands)
        for a, b in zip(one, many):
            assert np.array_equal(a[one[1] >= 0] if a.ndim == 3 else a, b[one[1] >= 0] if b.ndim == 3 else b)


def test_vtk_model_clamps_the_specular_power_to_128_as_vtk_does():
    """vtkProperty clamps SpecularPower to [0, 128]: 1000 draws as 128 in the vtk model; the classic model keeps it."""
    from dataclasses import replace

    from renderer.reflection.registry import material_table

    scene = tiny_scene()
    shiny = scene.objects[0]
    classic = replace(shiny, material=replace(shiny.material, specular_power=1000.0, model="classic"))
    objs = (replace(shiny, material=replace(shiny.material, specular_power=1000.0)), classic)
    table = material_table(replace(scene, objects=objs))
    assert table.power.tolist() == [128.0, 1000.0]
    at_1000 = render(replace(scene, objects=objs[:1]))
    at_128 = render(replace(scene, objects=(replace(shiny, material=replace(shiny.material, specular_power=128.0)),)))
    assert np.array_equal(at_1000.rgb, at_128.rgb)


# --------------------------------------------------------------------------- the stage buffers
def test_render_stages_returns_the_frame_render_returns_and_its_buffers():
    """render_stages gives render's frame, bit for bit, and the z-buffer it came from."""
    from renderer import render_stages

    scene = tiny_scene()
    frame, stages = render_stages(scene)
    plain = render(scene)
    assert np.array_equal(frame.rgb, plain.rgb) and np.array_equal(frame.depth, plain.depth)
    assert np.array_equal(stages.depth, frame.depth)
    assert np.array_equal(stages.triangle >= 0, frame.coverage)  # all opaque: coverage = a triangle won


def test_the_triangle_id_image_names_the_source_triangle_that_won():
    """A unit quad (triangles 0 and 1, split along the diagonal from corner 0 to corner 2) seen head on: the
    lower-right half of the image belongs to triangle 0, the upper-left half to triangle 1."""
    from renderer import render_stages

    _, stages = render_stages(upper_quad_scene())
    ids = stages.triangle
    assert set(np.unique(ids)) == {-1, 0, 1}
    rows, cols = np.nonzero(ids >= 0)
    u = (cols - cols.min()) / (cols.max() - cols.min())  # 0 at the left, 1 at the right
    v = (rows.max() - rows) / (rows.max() - rows.min())  # 0 at the bottom, 1 at the top (y up)
    first = ids[rows, cols] == 0
    assert np.all(v[first] <= u[first] + 0.05) and np.all(v[~first] >= u[~first] - 0.05)
    assert 0.45 < first.mean() < 0.55


def test_back_faces_are_flagged_as_the_rasteriser_sees_them():
    """The cube seen from outside: every clipped triangle is front or back, half and half; culled back faces
    leave the triangle-ID image but stay flagged."""
    import dataclasses

    from renderer import render_stages

    scene = load_scene("cube")
    _, stages = render_stages(scene)
    assert stages.front.sum() == 6 and len(stages.front) == 12
    assert set(np.unique(stages.triangle[stages.triangle >= 0])) <= set(stages.clip_source[stages.front])
    culled = dataclasses.replace(scene, render=dataclasses.replace(scene.render, cull_backfaces=True))
    frame, kept = render_stages(culled)
    assert kept.front.sum() == 6 and np.array_equal(frame.coverage, kept.triangle >= 0)


def test_a_triangle_cut_by_the_near_plane_becomes_several_clipped_triangles():
    from renderer import render_stages

    _, stages = render_stages(load_scene("near-plane"))
    assert len(stages.tri_window) > len(stages.geometry.triangles) - np.count_nonzero(
        np.bincount(stages.clip_source, minlength=len(stages.geometry.triangles)) == 0)
    assert np.bincount(stages.clip_source).max() >= 2


# The lean path (RenderOptions.lean): triangles clipping keeps whole are indexed, not copied;
# the raster sets up and draws them in batches; shading gets the tables of the winners only.

NEAR, FAR = 1.0, 10.0


def view_volume_scene(settings=None, camera=None):
    """The camera at the origin looking down −z (world = view space), near 1, far 10, 80×60,
    and triangles placed against the view volume: a sheet of shared vertices, with holes, that
    crosses all six planes (its corner cells two or three at once), a ball wholly inside, balls
    wholly behind the eye and beyond the far plane, a soup of small loose triangles
    anywhere (some across the eye plane), and a translucent ball across the left edge."""
    rng = np.random.default_rng(3)
    u, v = np.meshgrid(np.linspace(-1.0, 1.0, 25), np.linspace(-1.0, 1.0, 25))
    points = np.c_[14.0 * u.ravel(), 12.0 * v.ravel(), -8.1 + 7.9 * v.ravel() + rng.uniform(-0.4, 0.4, u.size)]
    i = (np.arange(24)[:, None] * 25 + np.arange(24)[None, :]).ravel()
    cells = np.concatenate([np.c_[i, i + 1, i + 26], np.c_[i, i + 26, i + 25]])
    sheet = Mesh(points, cells[rng.uniform(size=len(cells)) < 0.7],  # with holes: the background shows through
                 point_normals=np.tile([0.0, 0.3, 1.0], (len(points), 1)))
    soup_points = (rng.uniform(-12.0, 12.0, (60, 1, 3)) + rng.uniform(-1.5, 1.5, (60, 3, 3))).reshape(-1, 3)
    soup = Mesh(soup_points, np.arange(180).reshape(-1, 3))
    ball = icosphere(level=2, radius=0.8)
    ball = Mesh(ball.points, ball.triangles, point_normals=ball.points / 0.8)
    colour = lambda c, **kw: Material(color=c, ambient=0.2, diffuse=0.7, specular=0.3, **kw)  # noqa: E731
    at = lambda x, y, z: model_matrix(translate=(x, y, z))  # noqa: E731
    objects = (SceneObject(mesh=sheet, material=colour((0.8, 0.7, 0.5)), shading="phong"),
               SceneObject(mesh=ball, material=colour((0.3, 0.6, 0.9)), shading="gouraud", model_to_world=at(0.5, 0, -5)),
               SceneObject(mesh=ball, material=colour((0.9, 0.2, 0.2)), model_to_world=at(0, 0, 3)),
               SceneObject(mesh=ball, material=colour((0.9, 0.2, 0.2)), model_to_world=at(0, 0, -30)),
               SceneObject(mesh=soup, material=colour((0.4, 0.9, 0.4)), shading="flat"),
               SceneObject(mesh=ball, material=colour((0.9, 0.9, 0.2), opacity=0.5), shading="phong",
                           model_to_world=model_matrix(scale=(2.0, 2.0, 2.0), translate=(-3.6, 0.3, -5))))
    camera = camera or Camera(position=(0.0, 0.0, 0.0), focal_point=(0.0, 0.0, -1.0), view_angle=60.0,
                              clipping_range=(NEAR, FAR))
    return Scene(image=Image(size=(80, 60), background=(0.1, 0.1, 0.15)), camera=camera,
                 lights=(headlight(), Light(kind="scene", position=(2.0, 3.0, 1.0))), objects=objects,
                 render=settings or RenderSettings())


def clipping_cases(scene):
    """How the scene's triangles meet the view volume: (straddling (6,) per plane, kept whole,
    rejected, cut into pieces), counted with the clipper's own outcodes and output."""
    from renderer.camera import view_to_clip, world_to_view
    from renderer.clip import clip_mesh, outcodes
    from renderer.pipeline import transform_scene

    w, h = scene.image.size
    geo = transform_scene(scene, world_to_view(scene.camera), view_to_clip(scene.camera, w / h, (NEAR, FAR)))
    codes = np.empty(len(geo.verts_clip), np.uint8)
    outcodes(geo.verts_clip, codes)
    c = codes[geo.triangles]
    straddling = [int(np.sum(((c >> p) & 1).any(axis=1) & ~((c >> p) & 1).all(axis=1))) for p in range(6)]
    clipped = clip_mesh(geo.verts_clip, geo.triangles)
    return straddling, int(np.sum(clipped.piece < 0)), int(np.sum((c[:, 0] & c[:, 1] & c[:, 2]) > 0)), \
        len(clipped.piece_clip)


SETTINGS = {"zbuffer": RenderSettings(), "painter": RenderSettings(hidden_surface="painter"),
            "culled": RenderSettings(cull_backfaces=True), "screen-linear": RenderSettings(interpolation="screen"),
            "no-depth-test": RenderSettings(hidden_surface="none")}


@pytest.mark.parametrize("renumbered", [True, False], ids=["winners-renumbered", "raster-numbers"])
@pytest.mark.parametrize("settings", SETTINGS, ids=list(SETTINGS))
def test_the_lean_path_gives_the_bytes_of_the_plain_path(settings, renumbered, monkeypatch):
    """Every triangle written out, cut against all six planes and set up at once, or the lean
    path in batches of 7 triangles (every batch boundary inside some object), its winners
    renumbered or not (:func:`renderer.visible.renumbering_pays`): the same rgb, depth,
    coverage and stage buffers, on a scene that straddles each plane."""
    import renderer.pipeline
    import renderer.visible
    from renderer import RenderOptions, render_stages

    scene = view_volume_scene(SETTINGS[settings])
    straddling, whole, rejected, pieces = clipping_cases(scene)
    assert min(straddling) > 0 and whole > 50 and rejected > 50 and pieces > 50
    plain, plain_stages = render_stages(scene, RenderOptions(lean=False))
    monkeypatch.setattr(renderer.pipeline, "BATCH", 7)
    monkeypatch.setattr(renderer.pipeline, "ONE_BATCH", 0)  # no frame drawn as one batch
    monkeypatch.setattr(renderer.visible, "PIXELS_PER_TRIANGLE", 10 ** 9 if renumbered else 0)
    monkeypatch.setattr(renderer.visible, "HELD_PIXELS_PER_TRIANGLE", 10 ** 9 if renumbered else 0)
    assert renderer.visible.renumbering_pays(1, *scene.image.size) == renumbered
    lean, lean_stages = render_stages(scene, RenderOptions())
    assert 0.3 < plain.coverage.mean() < 1.0
    for name in ("rgb", "depth", "coverage"):
        np.testing.assert_array_equal(getattr(lean, name), getattr(plain, name), err_msg=name)
    for name in ("tri_window", "tri_fixed", "clip_source", "front", "translucent", "triangle"):
        np.testing.assert_array_equal(getattr(lean_stages, name), getattr(plain_stages, name), err_msg=name)


def test_the_lean_path_keeps_the_bytes_under_a_parallel_camera():
    from renderer import RenderOptions

    scene = view_volume_scene(camera=Camera(position=(0.0, 0.0, 0.0), focal_point=(0.0, 0.0, -1.0), parallel=True,
                                            parallel_scale=4.0, clipping_range=(NEAR, FAR)))
    assert min(clipping_cases(scene)[0][:2]) > 0  # near and far planes still cut
    lean, plain = render(scene), render(scene, RenderOptions(lean=False))
    for name in ("rgb", "depth", "coverage"):
        np.testing.assert_array_equal(getattr(lean, name), getattr(plain, name), err_msg=name)


_MEMORY_CHILD = """
import gc, json, os, sys
from lab.loading import load_scene
from renderer import RenderOptions, render

def kib(field):
    return next(int(l.split()[1]) for l in open("/proc/self/status") if l.startswith(field + ":"))

render(load_scene("icosphere:level=1").with_overrides(size=(32, 32)))  # kernels loaded
scene = load_scene(sys.argv[1], allow_large=True).with_overrides(size=(128, 128))
options = RenderOptions(lean=sys.argv[2] == "lean")
gc.collect()
baseline = kib("VmRSS")
with open("/proc/self/clear_refs", "w") as f:
    f.write("5")  # the high-water mark starts again from here
render(scene, options)
render(scene, options)
print(json.dumps({"peak_kib": kib("VmHWM") - baseline, "triangles": scene.objects[0].mesh.n_triangles}))
"""


def test_a_large_mesh_renders_in_memory_proportionate_to_its_triangles():
    """A 328k-triangle sphere at 128×128 in a fresh process: the memory rendering it takes (the
    high-water mark over the baseline after loading, as ``scanlab bench`` measures it) stays
    under 200 bytes per triangle on the lean path — its vertex tables, one index pair per
    triangle and a few per-triangle bytes while clipping. Writing every triangle out takes
    over 400 (clip, window and set-up tables; the plain path, measured alongside so that the
    bar is seen to tell them apart)."""
    per_triangle = {}
    for path in ("lean", "plain"):
        done = subprocess.run([sys.executable, "-c", _MEMORY_CHILD, "icosphere:level=7", path], cwd=REPO,
                              capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr[-3000:]
        m = json.loads(done.stdout.strip().splitlines()[-1])
        per_triangle[path] = m["peak_kib"] * 1024 / m["triangles"]
    assert per_triangle["lean"] < 200 < 400 < per_triangle["plain"], per_triangle


def test_the_scene_tables_live_in_the_workspace_and_what_render_stages_returns_is_a_copy():
    """Stages 1–3 write into the workspace (the same memory frame after frame: no page faults);
    the geometry ``render_stages`` hands back is its own, untouched by the next frame; with
    several objects the tables hold every object's rows, its triangles shifted to them."""
    from renderer.camera import view_to_clip, world_to_view
    from renderer.pipeline import render_stages, transform_scene
    from renderer.workspace import Workspace

    scene = load_scene("translucent-three")  # three objects
    assert len(scene.objects) == 3
    w, h = scene.image.size
    ws = Workspace()
    args = (scene, world_to_view(scene.camera), view_to_clip(scene.camera, w / h, (NEAR, FAR)))
    first, again, fresh = transform_scene(*args, ws), transform_scene(*args, ws), transform_scene(*args)
    for a, b, c in zip(first[:-1], again[:-1], fresh[:-1]):
        assert np.shares_memory(a, b) or a is b
        np.testing.assert_array_equal(b, c)
    starts = np.cumsum([0] + [o.mesh.n_points for o in scene.objects])
    np.testing.assert_array_equal(fresh.triangles, np.concatenate([o.mesh.triangles + a for o, a in
                                                                   zip(scene.objects, starts)]))
    np.testing.assert_array_equal(fresh.tri_object, np.repeat([0, 1, 2], [o.mesh.n_triangles for o in scene.objects]))

    _, stages = render_stages(scene)
    kept = [np.array(v, copy=True) for v in stages.geometry[:-1]]
    render(scene.with_overrides(size=(64, 48)))
    render(load_scene("cube"))
    for held, now in zip(kept, stages.geometry[:-1]):
        np.testing.assert_array_equal(held, now)


def test_the_tables_of_the_scene_layout_are_kept_across_frames_and_made_again_when_it_changes():
    """Each triangle's and vertex's object, and the zero texture coordinates of a scene without
    any, depend on the scene's layout alone: kept in the workspace from one frame to the next
    (the same memory, not written again), and made again for a scene laid out otherwise —
    frames of different scenes through one workspace give each scene's own tables."""
    from renderer.camera import view_to_clip, world_to_view
    from renderer.pipeline import object_numbers, transform_scene
    from renderer.workspace import Workspace

    ws = Workspace()
    globe = load_scene("textured-sphere")
    bare = replace(globe, objects=(replace(globe.objects[0], mesh=replace(globe.objects[0].mesh, tcoords=None),
                                           texture=None),))  # the same layout, no texture coordinates
    scenes = [load_scene("translucent-three"), bare, globe, bare, load_scene("cube"), load_scene("translucent-three")]
    textured = []
    for scene in scenes:
        w, h = scene.image.size
        args = (scene, world_to_view(scene.camera), view_to_clip(scene.camera, w / h, (NEAR, FAR)))
        kept, fresh = transform_scene(*args, ws), transform_scene(*args)
        for name in ("tri_object", "vert_object", "tcoords"):
            np.testing.assert_array_equal(getattr(kept, name), getattr(fresh, name), err_msg=name)
        textured.append(bool(kept.tcoords.any()))
        np.testing.assert_array_equal(kept.vert_object, np.repeat(np.arange(len(scene.objects)),
                                                                  [o.mesh.n_points for o in scene.objects]))
    assert textured == [False, False, True, False, False, False]
    again = transform_scene(scenes[0], world_to_view(scenes[0].camera), np.eye(4), ws)
    assert again.tri_object is transform_scene(scenes[0], np.eye(4), np.eye(4), ws).tri_object
    assert object_numbers([2, 0, 3]).tolist() == [0, 0, 2, 2, 2]


@pytest.mark.parametrize("shading, model, renumbered, computed", [
    ("phong", "vtk", True, "none"), ("gouraud", "vtk", True, "none"), ("flat", "vtk", True, "shown"),
    ("flat", "vtk", False, "all"), ("flat", "opengl", True, "all")])
def test_plane_normals_are_worked_out_only_for_a_frame_that_reads_them(shading, model, renumbered, computed,
                                                                       monkeypatch):
    """Flat shading reads the plane normals of the triangles it shows (lit per pixel under the
    vtk model, when the winners are renumbered; with the raster's numbers kept,
    :func:`renderer.visible.renumbering_pays`, of every triangle), or of every triangle (lit
    once each under opengl); phong and gouraud (vertex normals) read none, and their frames
    skip working them out. Either way the frame has the bytes of one that worked them all
    out, with the workspace's table poisoned first (stale normals from an earlier frame
    cannot hide a frame that reads them unworked); ``render_stages`` always has them all."""
    import renderer.pipeline as pipeline
    import renderer.shading
    import renderer.visible
    from renderer.pipeline import render_stages
    from renderer.workspace import thread_workspace

    monkeypatch.setattr(renderer.visible, "PIXELS_PER_TRIANGLE", 10 ** 9 if renumbered else 0)

    monkeypatch.setattr(renderer.visible, "HELD_PIXELS_PER_TRIANGLE", 10 ** 9 if renumbered else 0)
    scene = load_scene("textbook-sphere").with_overrides(shading=shading, model=model)
    triangles = sum(o.mesh.n_triangles for o in scene.objects)
    monkeypatch.setattr(pipeline, "any_face_colour", lambda materials: True)
    expected = render(scene).rgb
    monkeypatch.undo()
    monkeypatch.setattr(renderer.visible, "PIXELS_PER_TRIANGLE", 10 ** 9 if renumbered else 0)
    monkeypatch.setattr(renderer.visible, "HELD_PIXELS_PER_TRIANGLE", 10 ** 9 if renumbered else 0)
    worked_out, span_planes = [], []
    for module in (pipeline, renderer.shading):  # the span table is built in either, by what shading reads
        monkeypatch.setattr(module, "with_span_table", lambda frags, geo, *a, _table=module.with_span_table, **k:
                            span_planes.append(len(geo.face_normals)) or _table(frags, geo, *a, **k))
    original = pipeline.face_normals_of
    monkeypatch.setattr(pipeline, "face_normals_of", lambda *a: worked_out.append(len(np.unique(a[2]))) or original(*a))
    monkeypatch.setattr(pipeline, "face_normals", lambda verts, tris, out: pipeline.face_normals_of(
        verts, tris, np.arange(len(tris), dtype=np.int64), out))
    thread_workspace().array("geometry.face_normals", (triangles, 3)).fill(np.nan)
    np.testing.assert_array_equal(render(scene).rgb, expected)
    assert {"none": worked_out == [], "all": worked_out == [triangles],
            "shown": len(worked_out) == 1 and 0 < worked_out[0] < triangles / 2}[computed], worked_out
    # none read: none handed on to the span table (a frame painted from held colours builds none)
    assert set(span_planes) == {0} if computed == "none" else set(span_planes) <= {triangles}, span_planes
    _, stages = render_stages(scene)
    assert np.allclose(np.linalg.norm(stages.geometry.face_normals, axis=1), 1.0)


def test_a_flat_frame_works_out_the_normals_of_what_it_shows_with_the_bytes_of_all(monkeypatch):
    """On the view-volume scene made flat (triangles cut into pieces, a soup across the eye
    plane, a translucent ball across an edge) a frame works out only the plane normals of
    the triangles that won a pixel and of the translucent ones, the rest poisoned: the same
    bytes as :func:`render_stages`, which works them all out, lean and plain, z-buffer and painter."""
    from dataclasses import replace

    from renderer import RenderOptions, render_stages
    from renderer.workspace import thread_workspace

    for settings in (RenderSettings(), RenderSettings(hidden_surface="painter")):
        base = view_volume_scene(settings)
        scene = replace(base, objects=tuple(replace(o, shading="flat") for o in base.objects))
        expected = render_stages(scene)[0]
        assert 0.3 < expected.coverage.mean() < 1.0
        for options in (RenderOptions(), RenderOptions(lean=False)):
            thread_workspace().array("geometry.face_normals", (sum(o.mesh.n_triangles for o in scene.objects), 3)
                                     ).fill(np.nan)
            frame = render(scene, options)
            for name in ("rgb", "depth", "coverage"):
                np.testing.assert_array_equal(getattr(frame, name), getattr(expected, name), err_msg=name)


def test_a_frame_painted_from_held_colours_builds_no_planes_and_keeps_the_bytes(monkeypatch):
    """Flat triangles under a lone headlight are painted from one colour each
    (``painted_from_held``): the pipeline then hands shading their source triangles only —
    no weight planes, corners or span table — and the frame is the plain path's, byte for
    byte. A phong object needs them all."""
    from renderer import RenderOptions, pipeline

    seen = []
    real = pipeline.shading_fragments

    def spy(*args, **kwargs):
        frags = real(*args, **kwargs)
        seen.append((len(frags.clip_source), len(frags.plane), len(frags.tri_clip)))
        return frags

    monkeypatch.setattr(pipeline, "shading_fragments", spy)
    flat = load_scene("icosphere:level=2").with_overrides(shading="flat", size=(64, 48))
    fast = render(flat)
    count, planes, corners = seen[-1]
    assert count > 0 and planes == corners == 0
    np.testing.assert_array_equal(fast.rgb, render(flat, RenderOptions(spans=False)).rgb)
    render(tiny_scene())
    count, planes, corners = seen[-1]
    assert count > 0 and planes == corners == count


def test_a_frame_painted_from_held_colours_alone_works_out_no_plane_normals(monkeypatch):
    """A flat icosphere under a lone headlight is painted from held colours, whose normals come
    from the corners: the frame works out no table of plane normals (the table poisoned: the
    bytes of a frame that worked them all out). A translucent object's fragments read the
    table, so with one in the frame the normals of what it shows are worked out."""
    import renderer.pipeline as pipeline
    from renderer.reflection.registry import material_table
    from renderer.shading import EVERYTHING, HELD
    from renderer.workspace import thread_workspace

    scene = load_scene("icosphere:level=3").with_overrides(shading="flat", size=(96, 72))
    assert [light.kind for light in scene.lights] == ["headlight"]
    monkeypatch.setattr(pipeline, "any_face_colour", lambda materials: True)
    expected = render(scene).rgb
    monkeypatch.undo()
    worked_out = []
    original = pipeline.face_normals_of
    monkeypatch.setattr(pipeline, "face_normals_of", lambda *a: worked_out.append(len(a[2])) or original(*a))
    thread_workspace().array("geometry.face_normals", (scene.objects[0].mesh.n_triangles, 3)).fill(np.nan)
    np.testing.assert_array_equal(render(scene).rgb, expected)
    assert worked_out == []
    materials = material_table(scene)
    assert not pipeline.normals_of_shown(materials, False, HELD, any_translucent=False)
    assert pipeline.normals_of_shown(materials, False, HELD, any_translucent=True)
    assert pipeline.normals_of_shown(materials, False, EVERYTHING, any_translucent=False)


def test_a_frame_without_translucent_objects_keeps_its_all_opaque_mask_across_frames():
    """Which clipped triangles are translucent (``translucent_triangles``): in a frame without a
    translucent object, all False, and the array is the workspace's from frame to frame (not
    made and tested afresh); with one, each triangle's object's opacity decides."""
    from renderer.pipeline import clip_and_map, transform_scene, translucent_triangles
    from renderer.workspace import Workspace

    scene = tiny_scene()
    ws = Workspace()
    clipped = clip_and_map(transform_scene(scene, np.eye(4), np.eye(4), ws), 64, 48, ws)
    opaque = np.ones(len(scene.objects))
    mask = translucent_triangles(clipped, opaque, ws)
    assert mask.dtype == np.bool_ and len(mask) == clipped.count > 0 and not mask.any()
    assert translucent_triangles(clipped, opaque, ws) is mask
    some = np.where(np.arange(len(scene.objects)) == 0, 0.5, 1.0)
    np.testing.assert_array_equal(translucent_triangles(clipped, some, ws),
                                  clipped.geometry.tri_object[clipped.clip_source] == 0)


def test_vertices_mapped_with_the_transform_give_the_clipped_mesh_of_the_mapping_after_clipping():
    """``transform_and_map`` maps the vertices in the transform's loop; ``clip_and_map`` given them
    gives the tables it gives mapping them itself, bit for bit: on a scene inside the view (the
    vertices' own tables, nothing copied), on one that clipping cuts into pieces (their corners
    in the rows after the vertices, in the same storage), and when the pieces outgrow the
    workspace's tables (a bigger table, the vertices' rows copied over)."""
    from renderer.camera import view_to_clip, world_to_view
    from renderer.pipeline import clip_and_map, transform_and_map, transform_scene
    from renderer.workspace import Workspace

    def both(scene, ws):
        w, h = scene.image.size
        args = (scene, world_to_view(scene.camera), view_to_clip(scene.camera, w / h, (NEAR, FAR)))
        geo, vertices = transform_and_map(*args, (w, h), ws)
        mapped = clip_and_map(geo, w, h, ws, vertices=vertices)
        plain = clip_and_map(transform_scene(*args), w, h)
        for name in ("clip_source", "piece", "window", "fixed", "cells"):
            np.testing.assert_array_equal(getattr(mapped, name), getattr(plain, name), err_msg=name)
        return vertices, mapped

    inside = replace(tiny_scene(), camera=Camera(position=(0.0, 0.0, 6.0), view_angle=40.0))
    vertices, mapped = both(inside, Workspace())
    assert len(mapped.clipped.piece_clip) == 0 and mapped.window is vertices.window
    ws, cut = Workspace(), view_volume_scene()
    vertices, mapped = both(cut, ws)  # the tables first sized for the vertices: outgrown, their rows copied
    assert len(mapped.clipped.piece_clip) > 0 and not np.shares_memory(mapped.window, vertices.window)
    vertices, mapped = both(cut, ws)  # large enough now: the pieces' rows after the vertices', in place
    assert np.shares_memory(mapped.window, vertices.window)


# --------------------------------------------------------------------------- nothing opaque
@pytest.mark.parametrize("hidden", ["zbuffer", "painter"])
@pytest.mark.parametrize("transparency", ["oit", "depth_peeling", "sorted"])
def test_a_frame_with_nothing_opaque_gives_the_bytes_of_the_cleared_buffers(transparency, hidden, monkeypatch):
    """Translucent objects only: with ``oit`` the frame clears no opaque buffer and its
    fragments skip the depth test they would all pass (``untested_visibility``; the raster
    is not called), the other modes clear and read the buffers; either way the rgb, depth and
    coverage of ``render_stages``, which always rasterises the (empty) opaque pass."""
    import renderer.pipeline
    from renderer import render_stages

    scene = load_scene("translucent-three")
    scene = replace(scene, image=replace(scene.image, size=(160, 120)),
                    render=replace(scene.render, transparency=transparency, hidden_surface=hidden))
    assert all(obj.material.opacity < 1.0 for obj in scene.objects)
    cleared, _ = render_stages(scene)
    if transparency == "oit":
        monkeypatch.setattr(renderer.pipeline, "rasterize_visibility", None)  # a call would fail
        unwritten = renderer.pipeline.untested_visibility

        def poisoned(tri_index):  # buffers nothing may read: depth 0 would hide every fragment
            vis = unwritten(tri_index)
            vis.depth.fill(0)
            vis.tri_index.fill(0)
            return vis

        monkeypatch.setattr(renderer.pipeline, "untested_visibility", poisoned)
    frame = render(scene)
    assert 0.2 < frame.coverage.mean() < 0.9
    for name in ("rgb", "depth", "coverage"):
        np.testing.assert_array_equal(getattr(frame, name), getattr(cleared, name), err_msg=name)


def test_a_frame_of_up_to_one_batch_of_triangles_is_set_up_and_drawn_at_once(monkeypatch):
    """The lean path hands the raster all of a frame's triangles as one batch up to
    ONE_BATCH, else batches of BATCH (renderer.pipeline.raster_batch); the plain path, none."""
    import renderer.pipeline
    from renderer import RenderOptions
    from renderer.pipeline import raster_batch

    assert raster_batch(10) == 10 and raster_batch(renderer.pipeline.ONE_BATCH) == renderer.pipeline.ONE_BATCH
    assert raster_batch(renderer.pipeline.ONE_BATCH + 1) == renderer.pipeline.BATCH
    asked = []
    real = renderer.pipeline.rasterize_visibility

    def spy(triangles, *args, **kwargs):
        asked.append((triangles.count, kwargs["batch"]))
        return real(triangles, *args, **kwargs)

    monkeypatch.setattr(renderer.pipeline, "rasterize_visibility", spy)
    scene = load_scene("icosphere:level=2").with_overrides(size=(48, 48))  # 320 triangles, all in view
    monkeypatch.setattr(renderer.pipeline, "BATCH", 100)
    render(scene)
    monkeypatch.setattr(renderer.pipeline, "ONE_BATCH", 319)
    render(scene)
    render(scene, RenderOptions(lean=False))
    assert asked == [(320, 320), (320, 100), (320, None)]
