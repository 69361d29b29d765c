"""compare/from_plotter.py: a PyVista Plotter, built as PyVista's own examples build them, becomes a scene
that scanlab draws within the parity bars of a screenshot of the plotter itself."""
from __future__ import annotations

import numpy as np
import pytest

from compare.from_plotter import PlotterError, polygon_triangles, scene_from_plotter, strip_triangles
from compare.metrics import measure
from compare.reference import opaque_coverage, read_frame
from compare.verdict import failed_bars
from compare.vtk_backend import pyvista
from lab.frame import Frame
from renderer import render

pv = pyvista()
SIZE = (320, 240)


def screenshot(pl) -> Frame:
    """The plotter's own screenshot, with its z-buffer (and, with translucent actors, VTK's coverage)."""
    rgb = pl.screenshot(return_img=True)[..., :3]
    frame = read_frame(pl)
    assert np.array_equal(rgb, frame.rgb)  # what a user's screenshot holds
    if any(a.GetProperty().GetOpacity() < 1 for a in pl.renderer.actors.values() if hasattr(a, "GetProperty")):
        frame = Frame(frame.rgb, frame.depth, opaque_coverage(pl))
    return frame


def plotter(**kw):
    pl = pv.Plotter(off_screen=True, window_size=SIZE, **kw)
    pl.disable_anti_aliasing()  # MSAA blends every edge; a scene has no anti-aliasing (see the module docstring)
    return pl


def lit(*lights, **mesh_kw):
    """A smooth sphere over a floor under the given lights only (PyVista's lighting="none" + add_light)."""
    pl = plotter(lighting="none")
    pl.add_mesh(pv.Sphere(theta_resolution=40, phi_resolution=40), color="white", specular=0.5, specular_power=15,
                **{"smooth_shading": True, **mesh_kw})
    pl.add_mesh(pv.Plane(i_size=3, j_size=3, center=(0, 0, -0.6)), color="lightgrey")
    for light in lights:
        pl.add_light(light)
    return pl


def globe_plotter():
    from pyvista import examples

    pl = plotter()
    pl.add_mesh(examples.load_globe(), texture=examples.load_globe_texture())
    return pl


def switched_off():
    light = pv.Light(position=(-1, 0, 1), light_type="scene light")
    light.switch_off()
    return light


def transformed():
    pl = plotter()
    actor = pl.add_mesh(pv.Cone(), color="green")
    actor.position, actor.orientation, actor.scale = (0.5, 0, 0), (10, 30, 5), (1, 2, 1)
    return pl


def parallel():
    pl = plotter()
    pl.add_mesh(pv.Sphere(), color="white", specular=0.8, specular_power=20, interpolation="phong")
    pl.enable_parallel_projection()
    return pl


def translucent(peeling: bool):
    pl = plotter()
    pl.add_mesh(pv.Sphere(), color="white")
    pl.add_mesh(pv.Cube(center=(1.2, 0, 0)), color="red", opacity=0.5)
    if peeling:
        pl.enable_depth_peeling()
    return pl


def bent_polygons():
    """A bent quad, pentagon, hexagon and heptagon (no four corners in one plane): how each is cut into triangles
    shows (another cut of the pentagon alone gives a mean ΔE2000 of 30)."""
    pl = plotter(lighting="none")
    pl.add_light(pv.Light(position=(1, 2, 3), light_type="scene light"))
    for n, (dx, dy) in ((4, (-1.1, 1.1)), (5, (1.1, 1.1)), (6, (-1.1, -1.1)), (7, (1.1, -1.1))):
        a = np.linspace(0, 2 * np.pi, n, endpoint=False)
        bend = 0.6 * np.cos(3 * a + 0.7) + 0.3 * np.sin(a) + 0.4 * np.cos(2 * a)
        points = np.column_stack([np.cos(a) + dx, np.sin(a) + dy, bend])
        pl.add_mesh(pv.PolyData(points, faces=np.array([n, *range(n)])), color="white")
    pl.camera_position = [(0, -5, 8), (0, 0, 0), (0, 1, 0)]
    return pl


CASES = {
    "bent quad, pentagon, hexagon and heptagon": bent_polygons,
    "default light kit, smooth sphere": lambda: _with(plotter(), pv.Sphere(), color="tan", smooth_shading=True),
    "flat cube (quads)": lambda: _with(plotter(), pv.Cube(), color="orange"),
    "gouraud cylinder (quads, 100-gon caps)": lambda: _with(plotter(), pv.Cylinder(), color="white",
                                                            interpolation="gouraud"),
    "phong sphere, parallel camera": parallel,
    "textured globe": globe_plotter,
    "headlight": lambda: lit(pv.Light(light_type="headlight", intensity=0.8)),
    "camera light, coloured": lambda: lit(pv.Light(position=(1, 1, 1), light_type="camera light", color="yellow")),
    "scene light, directional": lambda: lit(pv.Light(position=(2, -1, 3), light_type="scene light", intensity=0.7)),
    "spot light with attenuation": lambda: lit(pv.Light(position=(0, 0, 2), positional=True, cone_angle=25,
                                                        exponent=4, attenuation_values=(1, 0.2, 0.05),
                                                        light_type="scene light")),
    "point light and a switched-off light": lambda: lit(pv.Light(position=(1, 2, 2), positional=True,
                                                                 cone_angle=120, light_type="scene light"),
                                                        switched_off()),
    "flat sphere under a scene light": lambda: lit(pv.Light(position=(2, -1, 3), light_type="scene light"),
                                                   smooth_shading=False),
    "translucent, OIT": lambda: translucent(False),
    "translucent, depth peeling": lambda: translucent(True),
    "moved, turned and stretched actor": transformed,
    "unstructured grid": lambda: _with(plotter(), __import__("pyvista").examples.load_hexbeam(), color="white"),
}


def _with(pl, mesh, **kw):
    pl.add_mesh(mesh, **kw)
    return pl


@pytest.mark.parametrize("case", list(CASES))
def test_the_converted_scene_meets_the_bars_against_the_plotters_own_screenshot(case):
    pl = CASES[case]()
    try:
        scene = scene_from_plotter(pl, case)  # before the first render: the plotter is left untouched
        m = measure(render(scene), screenshot(pl))
        assert not failed_bars(m), (case, m)
        again = scene_from_plotter(pl)  # after it: the same camera
        assert again.camera == scene.camera
    finally:
        pl.close()


def test_every_light_kind_and_shading_is_among_the_cases():
    kinds, shadings = set(), set()
    for build in CASES.values():
        pl = build()
        scene = scene_from_plotter(pl)
        kinds |= {li.kind for li in scene.lights}
        shadings |= {o.shading for o in scene.objects}
        pl.close()
    assert kinds == {"headlight", "camera", "scene"} and shadings == {"flat", "gouraud", "phong"}


def test_a_converted_scene_saved_as_toml_loads_and_still_meets_the_bars(tmp_path):
    """The round trip: plotter → scene → scene file (lab.scene_writer) → scene → both renderers."""
    from lab.loading import load_scene
    from lab.scene_writer import write_scene

    pl = globe_plotter()
    try:
        path = write_scene(scene_from_plotter(pl), tmp_path / "globe.toml")
        m = measure(render(load_scene(path)), screenshot(pl))
        assert not failed_bars(m), m
    finally:
        pl.close()


@pytest.mark.parametrize("build, words", [
    (lambda pl: pl.add_mesh(_with_scalars(pv.Sphere())), ["colours mapped from the scalars 'height'"]),
    (lambda pl: pl.add_mesh(pv.Sphere(), style="wireframe", name="ball"), ["actor 'ball'", "wireframe"]),
    (lambda pl: pl.add_mesh(pv.Sphere(), style="points"), ["points representation"]),
    (lambda pl: pl.add_mesh(pv.Sphere(), show_edges=True), ["edges shown"]),
    (lambda pl: pl.add_mesh(pv.Sphere(), pbr=True), ["physically based rendering"]),
    (lambda pl: (pl.add_mesh(pv.Sphere()), pl.add_text("hello")), ["CornerAnnotation", "surfaces only"]),
    (lambda pl: (pl.add_mesh(pv.Sphere()), pl.set_background("white", top="blue")), ["gradient background"]),
    (lambda pl: (pl.add_mesh(pv.Sphere()), pl.add_axes()), ["another renderer"]),
    (lambda pl: pl.add_mesh(pv.Line(), color="red"), ["lines or vertices"]),
    (lambda pl: None, ["shows no surface"]),
])
def test_what_a_scene_cannot_express_is_a_clear_error(build, words):
    pl = plotter()
    build(pl)
    try:
        with pytest.raises(PlotterError) as err:
            scene_from_plotter(pl)
        assert all(w in str(err.value) for w in words), str(err.value)
    finally:
        pl.close()


def test_several_renderers_are_refused():
    pl = pv.Plotter(off_screen=True, shape=(1, 2))
    pl.add_mesh(pv.Sphere())
    with pytest.raises(PlotterError, match="2 renderers"):
        scene_from_plotter(pl)
    pl.close()


def _with_scalars(mesh):
    mesh["height"] = mesh.points[:, 2]
    return mesh


def test_polygons_and_strips_are_cut_as_vtk_draws_them():
    assert polygon_triangles(3) == [(0, 1, 2)]
    assert polygon_triangles(6) == [(0, 1, 2), (0, 2, 3), (0, 3, 4), (0, 4, 5)]
    assert strip_triangles(5) == [(0, 1, 2), (2, 1, 3), (2, 3, 4)]


def test_compare_takes_a_plotter():
    import compare

    pl = plotter()
    pl.add_mesh(pv.Sphere(), color="tan")
    result = compare.compare(pl, timings=False)
    assert result.passed and result.ours.shape == (240, 320, 3)
    pl.close()
