"""Unusual but valid scenes (issue 6): each one a scene dict, with the mesh files it needs.

Every case is built the way a user would build it: a scene dictionary (what a TOML file
parses to) given to :func:`lab.loading.scene_from_dict`, with odd meshes written as small
OBJ files next to it. ``python -m tests.compare.unusual_scenes`` prints the figures of
every case against VTK.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from lab.loading import scene_from_dict
from lab.shapes import cylinder, icosphere


def obj_text(points, faces) -> str:
    """An OBJ file: ``v`` lines at full precision, ``f`` lines 1-based."""
    lines = [f"v {x!r} {y!r} {z!r}" for x, y, z in np.asarray(points, dtype=np.float64).tolist()]
    lines += ["f " + " ".join(str(i + 1) for i in face) for face in np.asarray(faces).tolist()]
    return "\n".join(lines) + "\n"


def _grid(n=6, size=2.0):
    """An n×n grid of quads in the z = 0 plane (2·n² counter-clockwise triangles, seen from +z)."""
    t = np.linspace(-size / 2, size / 2, n + 1)
    xx, yy = np.meshgrid(t, t)
    pts = np.column_stack([xx.ravel(), yy.ravel(), np.zeros(xx.size)])
    faces = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i
            faces += [(a, b, c), (a, c, d)]
    return pts, np.array(faces)


def _camera(position=(2.5, 2.0, 4.0), focal=(0.0, 0.0, 0.0), **more):
    return {"position": list(position), "focal_point": list(focal), "view_up": [0.0, 1.0, 0.0], **more}


def _scene(objects, camera=None, lights=None, size=(160, 120), **more):
    data = {"image": {"size": list(size), "background": [0.1, 0.2, 0.3]}, "camera": camera or _camera(),
            "object": objects, **more}
    if lights is not None:
        data["light"] = lights
    return data


MATERIAL = {"color": [0.8, 0.7, 0.3], "ambient": 0.1, "diffuse": 0.8, "specular": 0.3, "specular_power": 20.0}
TWO_LIGHTS = [{"kind": "scene", "position": [3.0, 4.0, 5.0]}, {"kind": "camera", "position": [-1.0, 0.5, 1.0],
                                                                 "intensity": 0.5}]


# --------------------------------------------------------------------------- the cases
def degenerate(tmp: Path):
    """A grid with zero-area triangles mixed in: a repeated index, three collinear points,
    one point three times, and a triangle seen exactly edge-on."""
    pts, faces = _grid()
    n = len(pts)
    extra = np.array([[0.3, 0.3, 0.5], [0.6, 0.6, 0.5], [0.9, 0.9, 0.5],  # collinear
                      [-0.5, 0.2, 0.4],                                    # one point, three times
                      [0.0, -0.5, 0.1], [0.0, -0.5, 0.9], [0.0, 0.5, 0.5]])  # in the plane x = 0
    pts = np.concatenate([pts, extra])
    bad = [(0, 0, 1), (5, 12, 5), (n, n + 1, n + 2), (n + 3, n + 3, n + 3), (n + 4, n + 5, n + 6)]
    faces = np.concatenate([faces[:20], bad, faces[20:]])
    (tmp / "degenerate.obj").write_text(obj_text(pts, faces))
    cam = _camera((4.0, 0.0, 0.3))  # looks along −x: the x = 0 triangle is edge-on
    cam_front = _camera((1.0, 0.8, 3.0))
    return {
        "flat": _scene([{"mesh": "degenerate.obj", **MATERIAL}], cam_front, TWO_LIGHTS),
        "gouraud-computed": _scene([{"mesh": "degenerate.obj", **MATERIAL, "normals": "computed",
                                     "shading": "gouraud"}], cam_front, TWO_LIGHTS),
        "edge-on": _scene([{"mesh": "degenerate.obj", **MATERIAL}], cam, TWO_LIGHTS),
    }


def sliver(tmp: Path):
    """A disc of 720 slivers (half a degree each) around one centre, and long needles
    narrower than a pixel."""
    k = 720
    a = np.linspace(0, 2 * np.pi, k, endpoint=False)
    pts = np.concatenate([[[0.0, 0.0, 0.0]], np.column_stack([np.cos(a), np.sin(a), np.zeros(k)])])
    faces = np.column_stack([np.zeros(k, int), 1 + np.arange(k), 1 + (np.arange(k) + 1) % k])
    (tmp / "fan.obj").write_text(obj_text(pts, faces))
    y = np.linspace(-0.9, 0.9, 12)
    needles = []
    for i, yi in enumerate(y):
        w = 10.0 ** (-1 - i % 4)  # 0.1 down to 1e-4 world units wide
        needles.append([[-1.2, yi, 0.0], [1.2, yi + 0.3 * w, 0.0], [1.2, yi + w, 0.0]])
    npts = np.concatenate(needles)
    (tmp / "needles.obj").write_text(obj_text(npts, np.arange(len(npts)).reshape(-1, 3)))
    cam = _camera((0.0, 0.0, 3.0), view_angle=50.0)
    return {
        "fan": _scene([{"mesh": "fan.obj", **MATERIAL}], _camera((0.5, 0.4, 2.5)), TWO_LIGHTS),
        "needles": _scene([{"mesh": "needles.obj", **MATERIAL}], cam, TWO_LIGHTS),
    }


def duplicates(tmp: Path):
    """Duplicate vertices: an icosphere whose every triangle has its own three points, some
    triangles listed twice, and some twice with the opposite winding."""
    sph = icosphere(level=2)
    tri = sph.triangles
    pts = sph.points[tri.reshape(-1)]
    own = np.arange(len(pts)).reshape(-1, 3)
    faces = np.concatenate([own, own[:40], own[40:80, ::-1]])  # listed twice; twice, turned over
    (tmp / "dups.obj").write_text(obj_text(pts, faces))
    same_winding = np.concatenate([own, own[:40], np.roll(own[40:80], 1, axis=1)])  # other first vertex
    (tmp / "dups-same-winding.obj").write_text(obj_text(pts, same_winding))
    # smooth normals on the split points: "radial" gives each copy the same normal
    return {
        "flat": _scene([{"mesh": "dups.obj", **MATERIAL}], None, TWO_LIGHTS),
        "phong-same-winding": _scene([{"mesh": "dups-same-winding.obj", **MATERIAL, "normals": "radial",
                                       "shading": "phong"}], None, TWO_LIGHTS),
        "phong-turned-over": _scene([{"mesh": "dups.obj", **MATERIAL, "normals": "radial", "shading": "phong"}],
                                    None, TWO_LIGHTS),
    }


def unreferenced(tmp: Path):
    """An icosphere with points no triangle uses, far from it, before and after its own."""
    sph = icosphere(level=2)
    far = np.array([[40.0, 30.0, -50.0], [-25.0, 60.0, 35.0]])
    pts = np.concatenate([far[:1], sph.points, far[1:]])
    (tmp / "unref.obj").write_text(obj_text(pts, sph.triangles + 1))
    return {
        "fitted-range": _scene([{"mesh": "unref.obj", **MATERIAL}], None, TWO_LIGHTS),
        "explicit-range": _scene([{"mesh": "unref.obj", **MATERIAL}], _camera(clipping_range=[2.0, 8.0]),
                                 TWO_LIGHTS),
    }


def scales(tmp: Path):
    """The same icosphere and camera at 1e-6 and 1e6, a unit sphere 1e6 from the origin, and
    one triangle 2e6 across that reaches behind the eye."""
    out = {}
    for name, s in (("1e-6", 1e-6), ("1e6", 1e6)):
        cam = _camera(tuple(np.array([2.5, 2.0, 4.0]) * s))
        lights = [{"kind": "scene", "position": [3.0 * s, 4.0 * s, 5.0 * s]},
                  {"kind": "scene", "position": [-3.0 * s, 1.0 * s, 2.0 * s], "positional": True,
                   "attenuation": [1.0, 0.0, 0.0]}]
        out[name] = _scene([{"shape": "icosphere", "params": {"level": 2, "radius": s}, **MATERIAL}], cam, lights)
        out[name + "-phong"] = _scene([{"shape": "icosphere", "params": {"level": 2, "radius": s}, **MATERIAL,
                                        "normals": "radial", "shading": "phong"}], cam, lights)
    huge = np.array([[-1e6, -1.0, -1e6], [1e6, -1.0, -1e6], [0.0, -1.0, 1e6]])  # one triangle, 2e6 across
    (tmp / "huge.obj").write_text(obj_text(huge, [[0, 1, 2]]))
    out["huge-triangle"] = _scene([{"mesh": "huge.obj", **MATERIAL}],
                                  _camera((0.0, 0.5, 3.0), clipping_range=[0.1, 1000.0]), TWO_LIGHTS)
    off = np.array([1e6, -2e5, 5e5])
    out["offset-1e6"] = _scene([{"shape": "icosphere", "params": {"level": 2}, **MATERIAL,
                                 "translate": off.tolist()}], _camera(tuple(off + [2.5, 2.0, 4.0]), tuple(off)),
                               TWO_LIGHTS)
    return out


def winding(tmp: Path):
    """An icosphere with every other triangle turned over (inconsistent winding)."""
    sph = icosphere(level=2)
    faces = sph.triangles.copy()
    faces[::2] = faces[::2, ::-1]
    (tmp / "mixed.obj").write_text(obj_text(sph.points, faces))
    return {
        "flat": _scene([{"mesh": "mixed.obj", **MATERIAL}], None, TWO_LIGHTS),
        "gouraud-radial": _scene([{"mesh": "mixed.obj", **MATERIAL, "normals": "radial", "shading": "gouraud"}],
                                 None, TWO_LIGHTS),
        "gouraud-computed": _scene([{"mesh": "mixed.obj", **MATERIAL, "normals": "computed",
                                     "shading": "gouraud"}], None, TWO_LIGHTS),
    }


def open_mesh(tmp: Path):
    """A cylinder without caps, seen so that its inside shows, and a hemisphere."""
    cyl = cylinder(segments=24, radius=0.6, height=1.5)
    side = cyl.triangles[: 2 * 24]
    (tmp / "tube.obj").write_text(obj_text(cyl.points, side))
    sph = icosphere(level=3)
    keep = sph.points[sph.triangles].mean(axis=1)[:, 2] > 0
    (tmp / "bowl.obj").write_text(obj_text(sph.points, sph.triangles[keep]))
    cam = _camera((1.2, 2.5, 3.0))
    return {
        "tube-flat": _scene([{"mesh": "tube.obj", **MATERIAL, "rotate": [-60.0, 0.0, 0.0]}], cam, TWO_LIGHTS),
        "tube-gouraud": _scene([{"mesh": "tube.obj", **MATERIAL, "rotate": [-60.0, 0.0, 0.0], "normals": "computed",
                                 "shading": "gouraud"}], cam, TWO_LIGHTS),
        "bowl-phong": _scene([{"mesh": "bowl.obj", **MATERIAL, "normals": "radial", "shading": "phong"}],
                             _camera((0.5, 1.0, 3.0)), TWO_LIGHTS),
    }


def inside(tmp: Path):
    """The camera inside a closed icosphere of radius 5, looking at its inside."""
    sphere = {"shape": "icosphere", "params": {"level": 3, "radius": 5.0}, **MATERIAL}
    cam = _camera((0.5, 0.3, 0.2), (3.0, 1.0, -1.0), view_angle=60.0)
    return {
        "flat": _scene([sphere], cam, TWO_LIGHTS),
        "phong-radial": _scene([{**sphere, "normals": "radial", "shading": "phong"}], cam, TWO_LIGHTS),
        "headlight": _scene([{**sphere, "normals": "radial", "shading": "gouraud"}], cam, None),
    }


def near_plane(tmp: Path):
    """A large floor and a sphere cut open by the near plane, and a triangle reaching behind
    the eye."""
    pts, faces = _grid(n=8, size=40.0)
    (tmp / "floor.obj").write_text(obj_text(pts, faces))
    behind = np.array([[-3.0, -1.0, 5.0], [3.0, -1.0, 5.0], [0.0, 2.0, -6.0]])  # eye at z = 3: two behind
    (tmp / "behind.obj").write_text(obj_text(behind, [[0, 1, 2]]))
    floor = {"mesh": "floor.obj", **MATERIAL, "rotate": [-90.0, 0.0, 0.0]}
    ball = {"shape": "icosphere", "params": {"level": 3}, **MATERIAL, "normals": "radial", "shading": "phong"}
    return {
        "floor-explicit": _scene([floor], _camera((0.0, 1.0, 3.0), (0.0, 0.5, 0.0), clipping_range=[3.0, 30.0]),
                                 TWO_LIGHTS),
        "sphere-cut-open": _scene([ball], _camera((0.0, 0.0, 3.2), clipping_range=[2.6, 10.0]), TWO_LIGHTS),
        "floor-fitted": _scene([floor], _camera((0.0, 1.0, 3.0), (0.0, 0.5, 0.0)), TWO_LIGHTS),
        "behind-eye": _scene([{"mesh": "behind.obj", **MATERIAL}],
                             _camera((0.0, 0.0, 3.0), (0.0, 0.0, 0.0), clipping_range=[0.5, 20.0]), TWO_LIGHTS),
    }


def outside(tmp: Path):
    """Objects that draw nothing: behind the camera, beside it, beyond the far plane."""
    cube = {"shape": "cube", **MATERIAL}
    return {
        "behind": _scene([{**cube, "translate": [0.0, 0.0, 10.0]}], _camera((0.0, 0.0, 4.0))),
        "beside": _scene([{**cube, "translate": [30.0, 0.0, 0.0]}], _camera((0.0, 0.0, 4.0))),
        "beyond-far": _scene([{**cube, "translate": [0.0, 0.0, -40.0]}],
                             _camera((0.0, 0.0, 4.0), clipping_range=[0.1, 20.0])),
        "before-near": _scene([{**cube, "scale": [0.2, 0.2, 0.2]}],
                              _camera((0.0, 0.0, 4.0), clipping_range=[4.5, 20.0])),
    }


def zero_lights(tmp: Path):
    """Lights of intensity zero: a lone headlight, one of two scene lights, a point light."""
    obj = {"shape": "icosphere", "params": {"level": 2}, **MATERIAL, "normals": "radial", "shading": "phong"}
    return {
        "headlight": _scene([obj], None, [{"kind": "headlight", "intensity": 0.0}]),
        "one-of-two": _scene([obj], None, [{"kind": "scene", "position": [3.0, 4.0, 5.0], "intensity": 0.0},
                                          {"kind": "scene", "position": [-3.0, 1.0, 2.0]}]),
        "all-zero-positional": _scene([obj], None, [{"kind": "scene", "position": [3.0, 4.0, 5.0], "intensity": 0.0,
                                                    "positional": True, "cone_angle": 40.0}]),
    }


def power_zero(tmp: Path):
    """specular_power = 0: (anything)^0 = 1, so the highlight covers the lit side evenly."""
    obj = {"shape": "icosphere", "params": {"level": 2}, **MATERIAL, "specular": 0.4, "specular_power": 0.0,
           "normals": "radial", "shading": "phong"}
    return {
        "headlight": _scene([obj], None, None),
        "directional": _scene([obj], None, TWO_LIGHTS),
        "positional": _scene([obj], None, [{"kind": "scene", "position": [3.0, 4.0, 5.0], "positional": True}]),
        "flat": _scene([{**obj, "shading": "flat"}], None, TWO_LIGHTS),
    }


def power_over_128(tmp: Path):
    """specular_power = 1000, which the loader accepts: VTK clamps it to 128."""
    obj = {"shape": "icosphere", "params": {"level": 2}, **MATERIAL, "specular": 1.0, "specular_power": 1000.0,
           "normals": "radial", "shading": "phong"}
    return {"headlight": _scene([obj], None, None), "directional": _scene([obj], None, TWO_LIGHTS)}


CASES = {"degenerate": degenerate, "sliver": sliver, "duplicates": duplicates, "unreferenced": unreferenced,
         "scales": scales, "winding": winding, "open": open_mesh, "inside": inside, "near-plane": near_plane,
         "outside": outside, "zero-lights": zero_lights, "power-zero": power_zero,
         "power-over-128": power_over_128}


def all_cases(tmp: Path) -> dict[str, dict]:
    """Every case as ``"group/variant" → scene dict``; mesh files are written into ``tmp``."""
    return {f"{group}/{variant}": data for group, make in CASES.items() for variant, data in make(tmp).items()}


def build(data: dict, tmp: Path):
    return scene_from_dict(data, source="<unusual>", base=tmp)


if __name__ == "__main__":  # the figures, one line per case
    import sys
    import tempfile

    from compare.metrics import failed_bars, measure
    from compare.reference import render_reference
    from renderer import render

    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d)
        for name, data in all_cases(tmp).items():
            if len(sys.argv) > 1 and not any(name.startswith(a) for a in sys.argv[1:]):
                continue
            scene = build(data, tmp)
            ours, ref = render(scene), render_reference(scene)
            m = measure(ours, ref)
            both = ours.coverage & ref.coverage
            dz = float(np.abs(ours.depth - ref.depth)[both].max()) if both.any() else 0.0
            print(f"{name:32s} mean {m['delta_e_2000']['mean']:.4f} over1 {100 * m['pixels_over_1']:.3f}% "
                  f"cov {100 * m['coverage_mismatch']:.3f}% maxch {m['max_channel_diff']:3d} "
                  f"dz {dz:.1e} ours {int(ours.coverage.sum()):6d} vtk {int(ref.coverage.sum()):6d} "
                  f"{'FAIL ' + '; '.join(failed_bars(m)) if failed_bars(m) else 'ok'}", flush=True)
