"""The whole pipeline: the Frame it returns, image-row orientation, 8-bit output, determinism, plain-Python kernels."""
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from lab import load_scene
from lab.mesh import Mesh
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject, headlight
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
