"""The benchmark set: every scene builds at any size, the public mesh's strips become the
right triangles, subdivision keeps the surface (compare/bench_scenes.py)."""
from __future__ import annotations

import numpy as np
import pytest

from compare import bench_scenes
from compare.bench_scenes import BENCH_SCENES, MeshUnavailable, bench_scene, strips_to_triangles, subdivide
from lab.mesh import Mesh


def test_a_strip_alternates_its_winding_and_restarts_after_minus_one():
    # strip 0 1 2 3 then a new strip 4 5 6: (0,1,2), (1,3,2) keeps the winding (VTK's order), (4,5,6)
    tri = strips_to_triangles([0, 1, 2, 3, -1, 4, 5, 6])
    assert tri.tolist() == [[0, 1, 2], [1, 3, 2], [4, 5, 6]]


def test_triangles_with_a_repeated_vertex_are_dropped():
    # a join by a repeated index: 0 1 2 2 3 4 gives (0,1,2) and, after the join, (2,3,4)
    tri = strips_to_triangles([0, 1, 2, 2, 3, 4])
    assert [sorted(t) for t in tri.tolist()] == [[0, 1, 2], [2, 3, 4]]


def area(mesh):
    p, t = mesh.points, mesh.triangles
    return 0.5 * np.linalg.norm(np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]]), axis=1).sum()


def test_subdivision_makes_four_triangles_of_each_and_keeps_the_area():
    quad = Mesh(np.array([[0.0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]]), np.array([[0, 1, 2], [0, 2, 3]]))
    fine = subdivide(quad)
    assert fine.n_triangles == 8
    assert fine.n_points == 4 + 5  # one midpoint per edge, the shared diagonal once
    assert area(fine) == pytest.approx(area(quad))


@pytest.mark.parametrize("name", [n for n in BENCH_SCENES if not n.startswith("igea")])
def test_every_scene_of_the_set_builds_at_the_size_asked(name):
    scene = bench_scene(name, (96, 64))
    assert scene.image.size == (96, 64)
    assert sum(o.mesh.n_triangles for o in scene.objects) > 0


def test_a_missing_public_mesh_is_reported_as_unavailable(tmp_path, monkeypatch):
    monkeypatch.setenv("SCANLAB_BENCH_MESHES", str(tmp_path))
    monkeypatch.setattr(bench_scenes, "IGEA_URL", (tmp_path / "nowhere.ply").as_uri())
    with pytest.raises(MeshUnavailable, match="copy igea.ply into"):
        bench_scene("igea-270k", (64, 64))


def test_the_public_mesh_is_read_from_the_cache_and_converted_once(tmp_path, monkeypatch):
    # a two-triangle strip in the Igea file's layout: float x y z vertices, one int list
    header = b"ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n" \
             b"property float z\nelement tristrips 1\nproperty list int int vertex_indices\nend_header\n"
    points = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], "<f4")
    body = points.tobytes() + np.array([4], "<i4").tobytes() + np.array([0, 1, 2, 3], "<i4").tobytes()
    (tmp_path / "igea.ply").write_bytes(header + body)
    monkeypatch.setenv("SCANLAB_BENCH_MESHES", str(tmp_path))
    mesh = bench_scenes.public_mesh()
    assert mesh.triangles.tolist() == [[0, 1, 2], [1, 3, 2]]
    assert (tmp_path / "igea-triangles.npz").exists()
    (tmp_path / "igea.ply").unlink()
    assert bench_scenes.public_mesh().triangles.tolist() == [[0, 1, 2], [1, 3, 2]]
