"""Mesh files drawn by scanlab against VTK's render of the same file *as VTK reads it*.

Each case is a scene whose object is a mesh file. scanlab loads it (``lab.meshfiles``:
VTK's reader, then our triangulation and checks) and draws it; the reference is the plotter
``compare.reference`` sets up for the same scene (camera, lights, material, shading), with
the object's polygon data replaced by ``pyvista.read`` of the file: VTK's reader and
VTK's mapper, with the file's own normals and texture coordinates, untouched by scanlab.
Both must meet the parity bars.

The files: Keenan Crane's *spot* cut to its head (``tests/data``: quads, texture
coordinates split along UV seams, its texture), and files made here with the structure of
the issue's real models: points carrying two normals (the beetle), quads with normals
(suzanne), triangle strips (legacy VTK).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from compare.metrics import failed_bars, measure
from compare.reference import build_plotter, read_frame
from lab.loading import load_scene
from lab.meshfiles import read_mesh
from renderer import render

pv = pytest.importorskip("pyvista")
DATA = Path(__file__).resolve().parents[1] / "data"


def scene_file(tmp_path: Path, mesh: Path, shading: str, camera: str, extra: str = "") -> Path:
    """A scene drawing ``mesh`` (absolute path) with two lights and the given shading."""
    text = f"""
[image]
size = [320, 240]
background = [0.95, 0.95, 0.92]

[camera]
{camera}

[[light]]
kind = "camera"
position = [0.4, 0.8, 1.0]

[[light]]
kind = "scene"
position = [-3.0, 2.0, 2.0]
intensity = 0.6

[[object]]
mesh = "{mesh}"
color = [0.85, 0.7, 0.45]
ambient = 0.15
diffuse = 0.75
specular = 0.4
specular_power = 25.0
shading = "{shading}"
{extra}
"""
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return path


def vtk_frame_of_file(scene, mesh: Path):
    """VTK's render of ``scene`` with its one object's polygon data read from ``mesh`` by VTK."""
    pl = build_plotter(scene)
    try:
        actors = pl.renderer.GetActors()
        assert actors.GetNumberOfItems() == 1
        actors.GetItemAsObject(0).GetMapper().SetInputData(pv.read(mesh))
        pl.ren_win.Render()
        return read_frame(pl)
    finally:
        pl.close()


def parity(tmp_path, mesh: Path, shading: str, camera: str, extra: str = ""):
    scene = load_scene(scene_file(tmp_path, mesh, shading, camera, extra))
    ours = render(scene)
    assert ours.coverage.mean() > 0.1, "the object should fill a good part of the image"
    return measure(ours, vtk_frame_of_file(scene, mesh))


# --------------------------------------------------------------------------- spot (real)
SPOT = DATA / "spot-head.obj"
SPOT_CAMERA = 'position = [1.3, 0.2, 2.6]\nfocal_point = [0.0, -0.25, 0.75]\nview_up = [0.0, 1.0, 0.0]\nview_angle = 30.0'


@pytest.mark.parametrize("filt", ["nearest", "linear"])
def test_spot_textured_quads_with_uv_seams_match_vtk(tmp_path, filt):
    """spot's head: quads fanned as VTK's mapper fans them, texture coordinates split along
    the UV seams as vtkOBJReader splits them, its texture on top: within the bars."""
    mesh = read_mesh(SPOT)
    assert mesh.tcoords is not None
    seams = len(np.unique(mesh.points, axis=0)) < mesh.n_points  # points repeated with other (s, t)
    assert seams
    m = parity(tmp_path, SPOT, "gouraud", SPOT_CAMERA,
               f'texture = "{DATA / "spot-texture.png"}"\ntexture_filter = "{filt}"')
    assert not failed_bars(m), m


# --------------------------------------------------------------------------- made here
def dome_with_a_base(segments=24, rings=8) -> str:
    """An OBJ like the beetle's: a smooth dome on a flat base, sharing its rim points. Each
    rim point carries two normals (``vn``): the dome's, radial, and the base's, straight down."""
    lines = []
    phi = np.linspace(0, np.pi / 2, rings + 1)[:-1]  # from the rim up, the pole apart
    theta = np.linspace(0, 2 * np.pi, segments, endpoint=False)
    for p in phi:
        for t in theta:
            lines.append(f"v {np.cos(p) * np.cos(t):.9f} {np.sin(p):.9f} {np.cos(p) * np.sin(t):.9f}")
    lines.append("v 0 1 0")
    lines += [line.replace("v ", "vn ", 1) for line in lines]  # unit sphere: the normal is the position
    lines.append("vn 0 -1 0")
    pole, down = rings * segments + 1, rings * segments + 2
    for r in range(rings - 1):
        for s in range(segments):
            a, b = r * segments + s + 1, r * segments + (s + 1) % segments + 1
            c, d = b + segments, a + segments
            lines.append(f"f {a}//{a} {d}//{d} {c}//{c} {b}//{b}")
    top = (rings - 1) * segments
    for s in range(segments):
        a, b = top + s + 1, top + (s + 1) % segments + 1
        lines.append(f"f {a}//{a} {pole}//{pole} {b}//{b}")
    lines.append("f " + " ".join(f"{s + 1}//{down}" for s in range(segments)))  # the base: one polygon
    return "\n".join(lines) + "\n"


DOME_CAMERA = 'position = [1.8, -1.1, 2.2]\nfocal_point = [0.0, 0.25, 0.0]\nview_up = [0.0, 1.0, 0.0]\nview_angle = 35.0'


@pytest.mark.parametrize("shading", ["gouraud", "phong"])
def test_points_with_two_normals_draw_smooth_as_vtk(tmp_path, shading):
    """The beetle's case: rim points with two ``vn``. VTK's reader gives each face corner its
    own point and normal; so do we, and the dome is drawn smooth (not faceted), within the bars."""
    path = tmp_path / "dome.obj"
    path.write_text(dome_with_a_base())
    mesh = read_mesh(path)
    assert mesh.point_normals is not None
    assert (np.abs(mesh.point_normals[:, 1] + 1) < 1e-12).sum() == 24  # the base's corners keep "down"
    m = parity(tmp_path, path, shading, DOME_CAMERA)
    assert not failed_bars(m), m


def quad_torus_obj(big=24, small=12) -> str:
    """An OBJ like suzanne's: quads, one ``vn`` per point with the same index (``f a//a``)."""
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, big, endpoint=False), np.linspace(0, 2 * np.pi, small, endpoint=False),
                       indexing="ij")
    centre = np.stack([np.cos(u), np.zeros_like(u), np.sin(u)], -1)
    normal = np.stack([np.cos(v) * np.cos(u), np.sin(v), np.cos(v) * np.sin(u)], -1)
    points = centre + 0.35 * normal
    lines = [f"v {x:.9f} {y:.9f} {z:.9f}" for x, y, z in points.reshape(-1, 3)]
    lines += [f"vn {x:.9f} {y:.9f} {z:.9f}" for x, y, z in normal.reshape(-1, 3)]
    for i in range(big):
        for j in range(small):
            a, b = i * small + j + 1, i * small + (j + 1) % small + 1
            c, d = ((i + 1) % big) * small + (j + 1) % small + 1, ((i + 1) % big) * small + j + 1
            lines.append(f"f {a}//{a} {b}//{b} {c}//{c} {d}//{d}")
    return "\n".join(lines) + "\n"


TORUS_CAMERA = 'position = [0.0, 2.2, 2.6]\nfocal_point = [0.0, 0.0, 0.0]\nview_up = [0.0, 1.0, 0.0]\nview_angle = 40.0'


def test_quads_with_normals_match_vtk(tmp_path):
    """Suzanne's structure: quads (fanned from their first vertex, as VTK's mapper does) with
    a normal per point and no splitting, phong: within the bars."""
    path = tmp_path / "torus.obj"
    path.write_text(quad_torus_obj())
    mesh = read_mesh(path)
    assert mesh.n_points == 24 * 12 and mesh.n_triangles == 2 * 24 * 12  # nothing split
    m = parity(tmp_path, path, "phong", TORUS_CAMERA)
    assert not failed_bars(m), m


def test_triangle_strips_match_vtk(tmp_path):
    """Triangle strips (a legacy VTK file, as ``strip()`` makes them) cut as VTK's mapper cuts
    them, with point normals, gouraud: within the bars."""
    sphere = pv.Sphere(theta_resolution=24, phi_resolution=16).strip()
    assert sphere.n_strips > 0 and sphere.n_cells == sphere.n_strips
    path = tmp_path / "strips.vtk"
    sphere.save(path, binary=False)
    m = parity(tmp_path, path, "gouraud",
               'position = [0.6, 0.9, 1.4]\nfocal_point = [0.0, 0.0, 0.0]\nview_up = [0.0, 1.0, 0.0]\nview_angle = 40.0')
    assert not failed_bars(m), m


def concave_panel_obj() -> str:
    """Concave polygons whose fans are sound, with normals that differ at every point, so a
    different cut would interpolate differently: a notched pentagon, and a notched hexagon
    whose fan starts at the notch."""
    points = [(0, 0), (2, 0), (1, 0.5), (2, 2), (0, 2),                       # pentagon, notch at point 3
              (3, 0), (5, 0), (6, 1), (6, 2), (4.5, 1.2), (3, 2)]             # hexagon, notch at point 10
    lines = [f"v {x - 3:.3f} {y - 1:.3f} 0" for x, y in points]
    lines += [f"vn {np.cos(i) * 0.6:.6f} {np.sin(i) * 0.6:.6f} 1" for i in range(len(points))]
    lines += ["f 1//1 2//2 3//3 4//4 5//5", "f 10//10 11//11 6//6 7//7 8//8 9//9"]
    return "\n".join(lines) + "\n"


def test_concave_polygons_with_sound_fans_match_vtk(tmp_path):
    """VTK 9.7's mapper fans a concave polygon when its fan is sound; so do we: within the bars."""
    path = tmp_path / "panel.obj"
    path.write_text(concave_panel_obj())
    assert read_mesh(path).n_triangles == 3 + 4
    m = parity(tmp_path, path, "gouraud",
               'position = [0.0, 0.0, 4.5]\nfocal_point = [0.0, 0.0, 0.0]\nview_up = [0.0, 1.0, 0.0]\nview_angle = 45.0')
    assert not failed_bars(m), m


def test_vtk_does_not_fan_a_polygon_whose_fan_fails(tmp_path):
    """Why such files are refused: VTK's render of the polygon differs from its render of
    the fan (here the fan would even cover ground outside the polygon)."""
    text = concave_panel_obj().replace("f 1//1 2//2 3//3 4//4 5//5", "f 2//2 3//3 4//4 5//5 1//1")
    (tmp_path / "polygon.obj").write_text(text.replace("f 10//10", "# f 10//10"))
    fan = "f 2//2 3//3 4//4\nf 2//2 4//4 5//5\nf 2//2 5//5 1//1\n"
    (tmp_path / "fan.obj").write_text(text.replace("f 2//2 3//3 4//4 5//5 1//1", fan).replace("f 10//10", "# f 10//10"))
    scene = load_scene(scene_file(tmp_path, tmp_path / "fan.obj", "gouraud", 'position = [0.0, 0.0, 4.5]\n'
                                  'focal_point = [0.0, 0.0, 0.0]\nview_up = [0.0, 1.0, 0.0]\nview_angle = 45.0'))
    as_polygon, as_fan = vtk_frame_of_file(scene, tmp_path / "polygon.obj"), vtk_frame_of_file(scene, tmp_path / "fan.obj")
    assert (as_polygon.coverage != as_fan.coverage).sum() > 100
