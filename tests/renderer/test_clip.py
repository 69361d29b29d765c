"""Stage 4, clipping in homogeneous clip space: −w ≤ x, y, z ≤ w, nothing behind the eye, weights back to the source."""
import numpy as np
import pytest

from lab.scene import Camera
from renderer.camera import view_to_clip
from renderer.clip import clip_triangles

EPS = 1e-12
NEAR, FAR = 1.0, 10.0
PROJECTION = view_to_clip(Camera(view_angle=60.0), 1.0, (NEAR, FAR))


def clip_view(*tris_view):
    """Project view-space triangles with a 60° frustum (near 1, far 10) and clip them."""
    tris = np.array(tris_view, dtype=np.float64)
    clip = np.concatenate([tris, np.ones(tris.shape[:2] + (1,))], axis=2) @ PROJECTION
    verts = np.ascontiguousarray(clip.reshape(-1, 4))  # the clipper takes shared vertices and index triples
    return clip, clip_triangles(verts, np.arange(len(verts), dtype=np.int64).reshape(-1, 3))


def assert_weights_reproduce_sources(source_clip, out_clip, out_bary, out_source):
    """Each output vertex is its barycentric weights times its source triangle's clip vertices."""
    assert np.all(out_bary >= -EPS)
    np.testing.assert_allclose(out_bary.sum(axis=2), 1.0, atol=1e-12)
    for k in range(len(out_clip)):
        np.testing.assert_allclose(out_bary[k] @ source_clip[out_source[k]], out_clip[k], atol=1e-12)


def test_a_triangle_inside_the_frustum_is_kept_unchanged():
    """All three vertices inside: one output triangle, the same vertices, identity barycentrics."""
    clip, (out, bary, source) = clip_view([(0, 0, -2), (1, 0, -3), (0, 1, -4)])
    assert len(out) == 1
    np.testing.assert_array_equal(out[0], clip[0])
    np.testing.assert_array_equal(bary[0], np.eye(3))
    assert source.tolist() == [0]


def test_a_triangle_in_front_of_the_near_plane_disappears():
    """All three vertices between the eye and the near plane (z > −w): nothing remains."""
    _, (out, _, _) = clip_view([(0, 0, -0.5), (0.1, 0, -0.5), (0, 0.1, -0.9)])
    assert len(out) == 0


def test_one_vertex_past_the_near_plane_leaves_a_quad():
    """One vertex nearer than the near plane: the rest is a quad, two triangles, every vertex with z ≥ −w."""
    clip, (out, bary, source) = clip_view([(0, 0, -0.5), (1, 0, -3), (0, 1, -3)])
    assert len(out) == 2
    assert source.tolist() == [0, 0]
    assert np.all(out[..., 2] + out[..., 3] >= -EPS)
    # two new vertices lie exactly on the near plane: z_view = −near, i.e. w = near
    on_plane = np.isclose(out[..., 2] + out[..., 3], 0.0, atol=1e-12)
    assert len({tuple(np.round(v, 12)) for v in out[on_plane]}) == 2
    np.testing.assert_allclose(out[on_plane][:, 3], NEAR, atol=1e-12)
    assert_weights_reproduce_sources(clip, out, bary, source)


def test_two_vertices_past_the_near_plane_leave_one_triangle():
    """Two vertices nearer than the near plane: one smaller triangle, every vertex with z ≥ −w."""
    clip, (out, bary, source) = clip_view([(0, 0, -0.5), (0.3, 0, -0.5), (0, 0.3, -3)])
    assert len(out) == 1
    assert np.all(out[..., 2] + out[..., 3] >= -EPS)
    assert sorted(np.round(out[0, :, 3], 12).tolist()) == [NEAR, NEAR, 3.0]
    assert_weights_reproduce_sources(clip, out, bary, source)


def test_a_triangle_across_the_viewport_edge_is_cut_at_the_edge():
    """The x and y planes are the viewport's edges (no guard band): a triangle poking out to
    the right keeps the part with x ≤ w, and its new corners lie on x = w exactly."""
    clip, (out, bary, source) = clip_view([(0, 0, -2), (5, 0, -2), (0, 0.5, -2)])
    assert len(out) >= 1 and set(source.tolist()) == {0}
    assert np.all(out[..., 3] - out[..., 0] >= -EPS)
    on_edge = np.isclose(out[..., 0], out[..., 3], atol=1e-12)
    assert len({tuple(np.round(v, 12)) for v in out[on_edge]}) == 2
    assert_weights_reproduce_sources(clip, out, bary, source)


def test_clipped_weights_by_hand():
    """Edge from z_view = −0.5 to −3 crosses z_view = −1 one fifth of the way: weights (0.8, 0.2, 0)."""
    clip, (out, bary, source) = clip_view([(0, 0, -0.5), (1, 0, -3), (0, 1, -3)])
    rows = {tuple(np.round(b, 12)) for b in bary.reshape(-1, 3)}
    assert (0.8, 0.2, 0.0) in rows and (0.8, 0.0, 0.2) in rows
    assert (1.0, 0.0, 0.0) not in rows  # the cut-off vertex is gone


def test_nothing_behind_the_eye_survives():
    """A triangle reaching behind the eye (w ≤ 0) keeps only points with w ≥ near > 0; one wholly behind vanishes."""
    clip, (out, bary, source) = clip_view([(0, 0, 3), (2, 0, -5), (-2, 1, -6)],  # one vertex behind the eye
                                          [(0, 0, 2), (1, 0, 3), (0, 1, 4)],      # all behind the eye
                                          [(-1, 0, 4), (1, 0, 4), (0, 1, -5)])    # two behind the eye
    assert np.any(clip[..., 3] <= 0)
    assert set(source.tolist()) == {0, 2}
    assert np.all(out[..., 3] >= NEAR - 1e-12)
    assert_weights_reproduce_sources(clip, out, bary, source)


def test_the_eye_plane_itself_is_not_kept():
    """A vertex exactly at the eye (w = 0) is cut away: what is left has w ≥ near."""
    clip, (out, _, _) = clip_view([(0, 0, 0), (1, 0, -4), (0, 1, -4)])
    assert clip[0, 0, 3] == 0.0
    assert len(out) == 2
    assert np.all(out[..., 3] >= NEAR - 1e-12)


def test_a_triangle_beyond_the_far_plane_disappears():
    """All three vertices past the far plane (z > w): nothing remains."""
    _, (out, _, _) = clip_view([(0, 0, -11), (1, 0, -12), (0, 1, -20)])
    assert len(out) == 0


def test_a_triangle_crossing_the_far_plane_is_cut_at_it():
    """One vertex past the far plane: a quad remains, every vertex with z ≤ w, two on the plane at w = far."""
    clip, (out, bary, source) = clip_view([(0, 0, -20), (1, 0, -5), (0, 1, -5)])
    assert len(out) == 2
    assert np.all(out[..., 3] - out[..., 2] >= -EPS)
    on_plane = np.isclose(out[..., 3] - out[..., 2], 0.0, atol=1e-12)
    np.testing.assert_allclose(out[on_plane][:, 3], FAR, atol=1e-12)
    assert_weights_reproduce_sources(clip, out, bary, source)


def test_a_triangle_spanning_both_planes_is_cut_at_both():
    """Near and far cuts together: every vertex has −w ≤ z ≤ w and the weights still reproduce the source."""
    clip, (out, bary, source) = clip_view([(0, 0, -0.2), (1, 0, -30), (0, 1, -5)])
    assert len(out) >= 2
    assert np.all(out[..., 2] + out[..., 3] >= -EPS)
    assert np.all(out[..., 3] - out[..., 2] >= -EPS)
    assert_weights_reproduce_sources(clip, out, bary, source)


def test_shared_vertices_are_clipped_per_triangle():
    """A quad as 4 shared vertices and index triples (0,1,2), (0,2,3), vertex 0 past the near plane: each triangle is cut on its own."""
    verts_view = np.array([(0, 0, -0.5), (1, 0, -3), (1, 1, -3), (0, 1, -3)], dtype=np.float64)
    verts_clip = np.ascontiguousarray(np.concatenate([verts_view, np.ones((4, 1))], axis=1) @ PROJECTION)
    triangles = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.int64)
    out, bary, source = clip_triangles(verts_clip, triangles)
    assert source.tolist() == [0, 0, 1, 1]
    assert np.all(out[..., 2] + out[..., 3] >= -EPS)
    assert_weights_reproduce_sources(verts_clip[triangles], out, bary, source)


def test_output_keeps_source_order_and_winding():
    """Pieces come out in source order, each wound like its source (same sign of the x-y area after division)."""
    tris = [[(0, 0, -0.5), (1, 0, -3), (0, 1, -3)], [(0, 0, -2), (0, 1, -3), (1, 0, -4)], [(0, 0, -20), (1, 0, -5), (0, 1, -5)]]
    clip, (out, _, source) = clip_view(*tris)
    assert source.tolist() == sorted(source.tolist()) == [0, 0, 1, 2, 2]

    def area(t):
        p = t[:, :2] / t[:, 3:4]
        return (p[1, 0] - p[0, 0]) * (p[2, 1] - p[0, 1]) - (p[2, 0] - p[0, 0]) * (p[1, 1] - p[0, 1])

    for k, s in enumerate(source):
        assert np.sign(area(out[k])) == np.sign(area(clip[s]))


@pytest.mark.parametrize("seed", range(5))
def test_random_triangles_clip_into_the_visible_volume(seed):
    """Random triangles anywhere around the eye: every surviving vertex is inside −w ≤ x, y, z ≤ w, w > 0, with exact weights."""
    rng = np.random.default_rng(seed)
    anywhere = rng.uniform(-15, 15, (40, 3, 3))
    in_view = np.concatenate([rng.uniform(-2, 2, (10, 3, 2)), rng.uniform(-9.5, -1.5, (10, 3, 1))], axis=2)
    tris = rng.permutation(np.concatenate([anywhere, in_view]))
    clip, (out, bary, source) = clip_view(*tris)
    assert np.all(out[..., 2] + out[..., 3] >= -1e-9)
    assert np.all(out[..., 3] - out[..., 2] >= -1e-9)
    assert np.all(out[..., 3] > 0)
    assert np.all(out[..., 3] - np.abs(out[..., :2]).max(axis=-1) >= -1e-9)
    assert_weights_reproduce_sources(clip, out, bary, source)
    # a triangle entirely inside is passed through whole
    x, y, z, w = np.moveaxis(clip, 2, 0)
    inside = np.all((z >= -w) & (z <= w) & (np.abs(x) <= w) & (np.abs(y) <= w), axis=1)
    assert inside.any() and not inside.all()
    for t in np.flatnonzero(inside):
        assert (source == t).sum() == 1
        np.testing.assert_array_equal(out[source == t][0], clip[t])


@pytest.mark.parametrize("seed", range(3))
def test_trivial_accept_and_reject_give_what_cutting_every_triangle_gives(seed):
    """Outcodes only skip work: triangles wholly inside (vertices on a plane included), wholly
    outside one plane, outside different planes (not rejected: cut) and straddling ones come out
    exactly as when every triangle goes through all six planes."""
    rng = np.random.default_rng(seed)
    verts = rng.uniform(-2.0, 2.0, (300, 4))
    verts[:, 3] = rng.uniform(0.5, 1.5, 300)
    verts[:60, :3] = verts[:60, 3:4] * rng.uniform(-1, 1, (60, 3))  # inside
    verts[60:80, 0] = verts[60:80, 3]  # exactly on the right plane x = w: inside
    verts[80:100, 2] = -verts[80:100, 3] - 0.25  # all in front of the near plane
    tris = np.concatenate([rng.integers(0, 80, (120, 3)), rng.integers(80, 100, (30, 3)), rng.integers(0, 300, (150, 3))])
    fast = clip_triangles(verts, tris)
    plain = clip_triangles(verts, tris, trivial=False)
    assert len(fast[0]) > 0 and 0 < (fast[2] < 120).sum()
    for a, b in zip(fast, plain):
        np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("plane", range(6), ids=["near", "far", "right", "left", "top", "bottom"])
def test_a_triangle_is_cut_only_against_the_planes_its_corners_lie_outside_of(plane):
    """Triangles straddling one plane, their other corners inside or lying exactly on the other
    planes (x = w, y = −w, z = w): cut against that plane alone (:func:`renderer.clip.planes_to_cut`),
    they leave the pieces, corners and weights that cutting against all six gives."""
    from renderer.clip import ALL_PLANES, outcodes, planes_to_cut

    rng = np.random.default_rng(11 + plane)
    inside = rng.uniform(-0.9, 0.9, (200, 4))
    inside[:, 3] = 1.0
    on_edges = inside.copy()
    on_edges[0::3, 0], on_edges[1::3, 1], on_edges[2::3, 2] = 1.0, -1.0, 1.0  # on the right, bottom and far planes
    outside = inside.copy()
    axis, sign = [(2, -1), (2, 1), (0, 1), (0, -1), (1, 1), (1, -1)][plane]
    outside[:, axis] = sign * rng.uniform(1.2, 3.0, 200)
    verts = np.concatenate([inside, on_edges, outside])
    tris = np.stack([rng.integers(400, 600, 300), rng.integers(0, 400, 300), rng.integers(0, 400, 300)], axis=1)
    codes = np.empty(len(verts), np.uint8)
    outcodes(verts, codes)
    crossed = [planes_to_cut.py_func(tris, codes, t, True) for t in range(len(tris))]
    assert set(crossed) == {1 << plane} and planes_to_cut.py_func(tris, codes, 0, False) == ALL_PLANES
    fast = clip_triangles(verts, tris)
    plain = clip_triangles(verts, tris, trivial=False)
    assert len(fast[0]) > len(tris)  # cut into pieces
    for a, b in zip(fast, plain):
        np.testing.assert_array_equal(a, b)


def test_outcodes_given_are_used_as_the_clipper_would_work_them_out():
    """clip_mesh given the vertices' outcodes (the pipeline's, from the transform) gives what it
    gives working them out itself; codes that say "inside" for a vertex beyond the near plane
    keep its triangle whole: the codes given are the ones used."""
    from renderer.clip import clip_mesh, outcodes

    rng = np.random.default_rng(3)
    verts = rng.uniform(-2.0, 2.0, (200, 4))
    verts[:, 3] = rng.uniform(0.5, 1.5, 200)
    tris = rng.integers(0, 200, (300, 3))
    codes = np.empty(200, np.uint8)
    outcodes(verts, codes)
    for a, b in zip(clip_mesh(verts, tris, codes=codes), clip_mesh(verts, tris)):
        np.testing.assert_array_equal(a, b)
    lying = clip_mesh(verts, tris, codes=np.zeros(200, np.uint8))
    assert (lying.piece < 0).all() and lying.source.tolist() == list(range(300))


def test_many_straddling_triangles_are_cut_as_each_would_be_alone():
    """Hundreds of triangles straddling planes, cut :data:`~renderer.clip.CLIP_CHUNK` at a time in
    parallel: each one's pieces, in source order, are the very ones it gets clipped alone."""
    from renderer.clip import CLIP_CHUNK

    rng = np.random.default_rng(7)
    verts = rng.uniform(-2.0, 2.0, (900, 4))
    verts[:, 3] = rng.uniform(0.5, 1.5, 900)
    tris = rng.integers(0, 900, (5 * CLIP_CHUNK + 9, 3))
    together = clip_triangles(verts, tris)
    alone = [clip_triangles(verts, tris[t:t + 1]) for t in range(len(tris))]
    cut = sum(len(a[2]) != 1 or not np.array_equal(a[0][0], verts[tris[t]]) for t, a in enumerate(alone))
    assert cut > 2 * CLIP_CHUNK
    np.testing.assert_array_equal(together[0], np.concatenate([a[0] for a in alone]))
    np.testing.assert_array_equal(together[1], np.concatenate([a[1] for a in alone]))
    np.testing.assert_array_equal(together[2], np.concatenate([t + a[2] for t, a in enumerate(alone)]))


# (plane, a clip-space vertex outside it): near z < −w, far z > w, right x > w, left x < −w, top y > w, bottom y < −w
OUTSIDE = [(0, (0.0, 0.0, -2.0, 1.0)), (1, (0.0, 0.0, 2.0, 1.0)), (2, (2.0, 0.0, 0.0, 1.0)),
           (3, (-2.0, 0.0, 0.0, 1.0)), (4, (0.0, 2.0, 0.0, 1.0)), (5, (0.0, -2.0, 0.0, 1.0))]


@pytest.mark.parametrize("plane, out", OUTSIDE, ids=["near", "far", "right", "left", "top", "bottom"])
def test_triangles_kept_whole_are_named_not_copied(plane, out):
    """Against each plane: a triangle inside is kept whole (piece −1, no rows of its own), one
    wholly outside is dropped, one straddling the plane becomes pieces; written out, they are
    exactly what cutting every triangle gives."""
    from renderer.clip import clip_mesh, clipped_corners

    inside = [(0.1, 0.1, 0.1, 1.0), (0.3, -0.2, 0.0, 1.0), (-0.2, 0.4, -0.3, 1.0)]
    outside = [out, tuple(1.5 * np.asarray(out)[:3]) + (1.0,), tuple(np.asarray(out)[:3] + 0.1) + (1.0,)]
    verts = np.array(inside + outside, dtype=np.float64)
    tris = np.array([[0, 1, 2], [3, 4, 5], [0, 3, 1], [2, 0, 1]], dtype=np.int64)  # inside, outside, straddling, inside
    clipped = clip_mesh(verts, tris)
    assert clipped.source.tolist()[0] == 0 and clipped.source.tolist()[-1] == 3
    whole = clipped.piece < 0
    assert clipped.source[whole].tolist() == [0, 3] and 1 not in clipped.source.tolist()
    assert set(clipped.source[~whole].tolist()) == {2} and len(clipped.piece_clip) == (~whole).sum() >= 1
    assert sorted(clipped.piece[~whole].tolist()) == list(range(len(clipped.piece_clip)))
    for a, b in zip(clipped_corners(clipped, verts, tris), clip_triangles(verts, tris, trivial=False)):
        np.testing.assert_array_equal(a, b)


def test_a_mesh_inside_the_view_volume_never_reaches_the_cutting_passes(monkeypatch):
    """Every triangle trivially accepted or rejected: ``cut_polygons`` and ``write_pieces`` (and
    the clipping of a polygon they call) are not run, so a fresh process drawing such a scene
    never compiles them; one straddling triangle runs both, once."""
    import renderer.clip as clip

    calls = []
    for name in ("cut_polygons", "write_pieces"):
        original = getattr(clip, name)
        monkeypatch.setattr(clip, name, lambda *a, _k=original, _n=name: calls.append(_n) or _k(*a))
    verts = np.array([(0.1, 0.1, 0.1, 1.0), (0.3, -0.2, 0.0, 1.0), (-0.2, 0.4, -0.3, 1.0), (0.0, 0.0, -3.0, 1.0),
                      (0.2, 0.0, -3.0, 1.0), (0.0, 0.2, -3.0, 1.0)])
    inside_and_outside = np.array([[0, 1, 2], [3, 4, 5]], np.int64)
    clipped = clip.clip_mesh(verts, inside_and_outside)
    assert calls == [] and clipped.source.tolist() == [0] and len(clipped.piece_clip) == 0
    clip.clip_mesh(verts, np.array([[0, 1, 2], [0, 1, 3]], np.int64))
    assert calls == ["cut_polygons", "write_pieces"]


def test_a_corner_index_names_a_whole_triangles_vertices_and_a_pieces_own_rows():
    """Corner v of triangle k: its source triangle's vertex when kept whole (piece −1), else
    row N + 3p + v after the N source vertices; triangles given whole are pieces 0 … K − 1
    after no vertices (rows 3k + v); a batch is a view of its triangles."""
    from renderer.clip import CornerIndex, corner_rows
    triangles = np.array([[0, 1, 2], [2, 1, 3], [3, 4, 0]], np.int64)
    corners = CornerIndex(np.array([2, 0, 1, 1], np.int32), np.array([-1, 1, -1, 0], np.int32), triangles, 5)
    rows = np.empty((4, 3), np.int64)
    corner_rows(corners, rows)
    assert rows.tolist() == [[3, 4, 0], [8, 9, 10], [2, 1, 3], [5, 6, 7]]
    batch = corners.batch(1, 3)
    assert np.shares_memory(batch.source, corners.source) and batch.piece.tolist() == [1, -1]
    whole = np.empty((3, 3), np.int64)
    corner_rows(CornerIndex.of_whole(3), whole)
    assert whole.tolist() == [[0, 1, 2], [3, 4, 5], [6, 7, 8]]


def test_the_offsets_of_more_than_255_entries_sum_without_wrapping_as_plain_python():
    """write_whole sums the per-triangle counts (uint8: at most 9 entries a triangle) into
    offsets; as plain Python (the kernel's ``py_func``, as under NUMBA_DISABLE_JIT) the sum
    must not wrap at 256 as a uint8 would, and the jitted kernel gives the same."""
    from renderer.clip import write_whole

    n = 300
    counts, cut = np.ones(n, np.uint8), np.zeros(n, np.bool_)
    counts[::7] = 0  # rejected triangles: no entry
    for kernel in (write_whole.py_func, write_whole):
        offsets, source, piece = np.zeros(n + 1, np.int64), np.full(n, -7, np.int32), np.zeros(n, np.int32)
        total = kernel(counts, cut, offsets, source, piece)
        assert total == counts.sum() > 255
        np.testing.assert_array_equal(offsets, np.concatenate([[0], np.cumsum(counts)]))
        np.testing.assert_array_equal(source[:total], np.flatnonzero(counts))


def test_a_mesh_whose_every_vertex_is_inside_is_kept_whole_without_classifying(monkeypatch):
    """No vertex outside any plane: every triangle is kept whole, in source order, with no
    pass over the triangles (``trivial_pass``, ``write_whole`` not run) — the same triangles
    the classifying passes give, and written out, what cutting every triangle gives. The
    tables depend on the count alone: a workspace keeps them from frame to frame. One vertex
    outside, even one no triangle uses, and the triangles are classified as before."""
    import renderer.clip as clip
    from renderer.workspace import Workspace

    calls = []
    for name in ("trivial_pass", "write_whole"):
        original = getattr(clip, name)
        monkeypatch.setattr(clip, name, lambda *a, _k=original, _n=name: calls.append(_n) or _k(*a))
    rng = np.random.default_rng(3)
    verts = np.concatenate([rng.uniform(-0.9, 0.9, (40, 3)), np.ones((40, 1))], axis=1)
    tris = rng.integers(0, 40, (70, 3)).astype(np.int64)
    ws = Workspace()
    clipped = clip.clip_mesh(verts, tris, ws)
    assert calls == [] and len(clipped.piece_clip) == 0
    assert clipped.source.tolist() == list(range(70)) and clipped.piece.tolist() == [-1] * 70
    assert clip.clip_mesh(verts, tris, ws).source is clipped.source
    for a, b in zip(clip.clipped_corners(clipped, verts, tris), clip.clip_triangles(verts, tris, trivial=False)):
        np.testing.assert_array_equal(a, b)
    calls.clear()  # cutting every triangle (trivial=False) classified them
    unused_outside = np.concatenate([verts, [(0.0, 0.0, -3.0, 1.0)]])
    classified = clip.clip_mesh(unused_outside, tris)
    assert calls == ["trivial_pass", "write_whole"]
    np.testing.assert_array_equal(classified.source, clipped.source)
    np.testing.assert_array_equal(classified.piece, clipped.piece)


def test_triangles_picked_in_an_order_are_the_rows_of_that_order():
    """``picked`` takes the source and piece of the triangles an order names, in that order, as
    numpy's indexing does — repeats, the last row and an empty order included — and in a
    workspace the tables are its own (a second pick under another name leaves the first)."""
    from renderer.clip import picked
    from renderer.workspace import Workspace

    rng = np.random.default_rng(5)
    source = rng.integers(0, 1 << 30, 5000).astype(np.int32)
    piece = rng.integers(-1, 300, 5000).astype(np.int32)
    order = np.concatenate([rng.permutation(5000)[:1234], [4999, 0, 4999]]).astype(np.int64)
    ws = Workspace()
    got_source, got_piece = picked(source, piece, order, ws, "first")
    np.testing.assert_array_equal(got_source, source[order])
    np.testing.assert_array_equal(got_piece, piece[order])
    assert got_source.dtype == got_piece.dtype == np.int32
    picked(source, piece, order[::-1].copy(), ws, "second")
    np.testing.assert_array_equal(got_source, source[order])
    empty_source, empty_piece = picked(source, piece, np.empty(0, np.int64))
    assert len(empty_source) == len(empty_piece) == 0
