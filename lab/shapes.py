"""Built-in shapes, in model space, each a function returning a :class:`lab.mesh.Mesh`.

All faces are counter-clockwise seen from outside (the course's orientation rule).
Shapes carry no normals unless stated: the renderers then shade each triangle with its
plane normal.
"""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh

PHI = (1.0 + 5.0 ** 0.5) / 2.0  # the golden ratio


def cube(size: float = 1.0) -> Mesh:
    """An axis-aligned cube of edge ``size`` centred at the origin: 8 points, 12 triangles.

    The face table follows the course's cube (six quads, counter-clockwise from outside),
    each quad split into two triangles.

    >>> cube().n_triangles
    12
    """
    h = size / 2.0
    pts = np.array([[x, y, z] for z in (-h, h) for y in (-h, h) for x in (-h, h)])
    # point index = x + 2y + 4z with x, y, z in {0, 1}
    quads = [
        (0, 2, 3, 1),  # z = -h, seen from -z
        (4, 5, 7, 6),  # z = +h
        (0, 1, 5, 4),  # y = -h
        (2, 6, 7, 3),  # y = +h
        (0, 4, 6, 2),  # x = -h
        (1, 3, 7, 5),  # x = +h
    ]
    tris = [(q[0], q[i], q[i + 1]) for q in quads for i in (1, 2)]
    return Mesh(pts, np.array(tris))


def quad(size: float = 1.0) -> Mesh:
    """A square of edge ``size`` in the z = 0 plane, centred at the origin, facing +z.

    >>> quad().n_triangles
    2
    """
    h = size / 2.0
    pts = np.array([[-h, -h, 0.0], [h, -h, 0.0], [h, h, 0.0], [-h, h, 0.0]])
    return Mesh(pts, np.array([[0, 1, 2], [0, 2, 3]]))


def _icosahedron_points_faces() -> tuple[np.ndarray, np.ndarray]:
    """The 12 golden-ratio vertices (0, ±1, ±φ) and cyclic shifts, and the 20 faces."""
    p = PHI
    pts = np.array([
        [-1, p, 0], [1, p, 0], [-1, -p, 0], [1, -p, 0],
        [0, -1, p], [0, 1, p], [0, -1, -p], [0, 1, -p],
        [p, 0, -1], [p, 0, 1], [-p, 0, -1], [-p, 0, 1],
    ], dtype=np.float64)
    faces = np.array([
        [0, 11, 5], [0, 5, 1], [0, 1, 7], [0, 7, 10], [0, 10, 11],
        [1, 5, 9], [5, 11, 4], [11, 10, 2], [10, 7, 6], [7, 1, 8],
        [3, 9, 4], [3, 4, 2], [3, 2, 6], [3, 6, 8], [3, 8, 9],
        [4, 9, 5], [2, 4, 11], [6, 2, 10], [8, 6, 7], [9, 8, 1],
    ])
    return pts, faces


def icosahedron(radius: float = 1.0) -> Mesh:
    """The regular icosahedron of the textbook, scaled to circumradius ``radius``.

    Vertices are the cyclic permutations of (0, ±1, ±φ); 20 outward faces.

    >>> icosahedron().n_triangles
    20
    """
    pts, faces = _icosahedron_points_faces()
    pts = pts / np.linalg.norm(pts[0]) * radius
    return Mesh(pts, faces)


def split_in_four(points: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """One subdivision step: each triangle (a, b, c) split into (a, ab, ca), (b, bc, ab),
    (c, ca, bc), (ab, bc, ca) at its edge midpoints, a midpoint shared by the two triangles
    of its edge. Returns the midpoints (E, 3), to be appended after ``points`` (their indices
    follow them), and the 4·T new triangles, every one wound as its parent.

    Triangle i's four children are rows 4i … 4i + 3 (in the order above), so the new list
    keeps its parent's order: triangles near one another in the list lie near one another
    on the surface, level after level. With the children in four blocks instead (all the
    (a, ab, ca) first, then all the (b, bc, ab), …), neighbours in a level-7 icosphere's
    list lay on different faces of the icosahedron, and a renderer drawing in list order
    reads its vertices and its frame buffer all over memory: measured in one process,
    ico7-phong at 1024², frames of the blocked order against this one took 1.97× as long
    in VTK and 1.36–1.39× in scanlab (``docs/performance.md``).

    >>> mid, tris = split_in_four(np.eye(3), np.array([[0, 1, 2]]))
    >>> len(mid), tris.tolist()[-1]
    (3, [3, 5, 4])
    """
    edges = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    unique, inverse = np.unique(np.sort(edges, axis=1), axis=0, return_inverse=True)
    mid = (points[unique[:, 0]] + points[unique[:, 1]]) / 2.0
    ab, bc, ca = inverse.reshape(3, -1) + len(points)  # rows: ab, bc, ca per triangle
    a, b, c = triangles.T
    children = np.stack([np.stack(t, axis=1) for t in ((a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca))], axis=1)
    return mid, children.reshape(-1, 3)


def icosphere(level: int = 2, radius: float = 1.0, uv: int = 0) -> Mesh:
    """The textbook's subdivided icosahedron: 20·4^level faces on a sphere of ``radius``.

    Each triangle (a, b, c) is split into four, (a, ab, ca), (b, bc, ab), (c, ca, bc),
    (ab, bc, ca), and each new edge midpoint is pushed out onto the circumscribed sphere.
    Midpoints are shared between neighbouring triangles, so the surface stays closed.

    Texture coordinates (``uv=1``)
    ------------------------------
    Longitude and latitude with +y as the north pole, for an equirectangular image
    (longitude −180°…180° left to right, north at the top):

        s = 0.5 + atan2(x, z) / (2π),   t = 0.5 + asin(y / |p|) / π.

    Longitude 0 (the image's middle column) faces +z and longitude grows toward +x, so
    the image is seen unmirrored from outside with +y up; the seam (s = 0 ≡ 1) is the
    half circle x = 0, z < 0. Each point gets s in [0, 1) first; then

    - seam: in a triangle whose vertices' s spread over more than 0.5 (it straddles the
      seam), the vertices with s < 0.5 take s + 1, so s lies in [0, 1.5) and no triangle
      interpolates across the whole image (sample with a repeating texture);
    - poles (0, ±radius, 0), where the longitude is undefined (at level ≥ 1 they are
      vertices): in each triangle the pole takes the mean s of the triangle's two other
      vertices (after the seam fix), t = 1 (north) or 0 (south).

    A point whose triangles need different (s, t) is duplicated, once per distinct pair:
    the point keeps its index for the pair of its first use, the copies follow all the
    original points in order of first use. Positions and triangles (count, order,
    winding, surface) are the same as with ``uv=0``; only points are split, so the
    surface is closed geometrically but no longer topologically along the seam and at
    the poles. Level 0 has no pole vertex: each pole lies on an edge, and the two
    triangles of that edge span half the image (s spread 0.5).

    Parameters
    ----------
    level : subdivision depth (0 is the icosahedron).
    radius : radius of the sphere.
    uv : 0 (default) no texture coordinates, 1 the longitude/latitude ones above.

    >>> icosphere(level=1).n_triangles
    80
    """
    mesh = icosahedron(radius)
    pts, tris = mesh.points, mesh.triangles
    for _ in range(int(level)):
        mid, tris = split_in_four(pts, tris)
        mid *= radius / np.linalg.norm(mid, axis=1, keepdims=True)  # onto the sphere
        pts = np.concatenate([pts, mid])
    if not uv:
        return Mesh(pts, tris)
    return _split_corners(pts, tris, _sphere_corner_tcoords(pts, tris))


def _sphere_corner_tcoords(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """(T, 3, 2) longitude/latitude (s, t) of every triangle corner, seam and poles fixed
    (see :func:`icosphere`)."""
    x, y, z = points.T
    r = np.linalg.norm(points, axis=1)
    s = (0.5 + np.arctan2(x, z) / (2.0 * np.pi)) % 1.0              # [0, 1)
    t = 0.5 + np.arcsin(np.clip(y / np.where(r > 0, r, 1.0), -1.0, 1.0)) / np.pi
    pole = np.hypot(x, z) <= 1e-12 * np.maximum(r, 1e-300)
    cs, cpole = s[triangles], pole[triangles]                        # (T, 3)
    lo = np.where(cpole, np.inf, cs).min(axis=1, keepdims=True)
    hi = np.where(cpole, -np.inf, cs).max(axis=1, keepdims=True)
    cs = np.where((hi - lo > 0.5) & (cs < 0.5) & ~cpole, cs + 1.0, cs)  # unwrap across the seam
    others = np.where(cpole, 0.0, cs).sum(axis=1, keepdims=True) / np.maximum((~cpole).sum(axis=1, keepdims=True), 1)
    cs = np.where(cpole, others, cs)                                 # pole: mean of the others
    return np.stack([cs, t[triangles]], axis=2)


def _split_corners(points, triangles, corner_tcoords) -> Mesh:
    """A mesh with one (s, t) per point from per-corner (s, t): a point whose corners have
    different (s, t) is duplicated, once per distinct pair.

    The point keeps its index for the pair of its first use (corner order: triangle by
    triangle); copies are appended after the original points, in order of first use.
    Triangles keep their order and winding.
    Points used by no triangle keep (s, t) = (0, 0).
    """
    n = len(points)
    vertex = triangles.ravel()
    st = corner_tcoords.reshape(-1, 2) + 0.0                         # -0.0 -> 0.0
    key = np.column_stack([vertex.astype(np.float64), st])
    uniq, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    group_vertex = vertex[first]
    by_use = np.argsort(first)                                      # groups in order of first use
    _, primary_at = np.unique(group_vertex[by_use], return_index=True)
    primary = np.zeros(len(first), dtype=bool)
    primary[by_use[primary_at]] = True                              # each vertex's first pair
    extra = by_use[~primary[by_use]]
    new_id = np.empty(len(first), dtype=np.int64)
    new_id[primary] = group_vertex[primary]
    new_id[extra] = n + np.arange(len(extra))
    tcoords = np.zeros((n + len(extra), 2))
    tcoords[new_id] = uniq[:, 1:]
    source = np.concatenate([np.arange(n), group_vertex[extra]])
    return Mesh(np.asarray(points)[source], new_id[inverse].reshape(-1, 3), None, tcoords)


# The unit cube's corners as (x, y, z) offsets in {0, 1}, point index = x + 2y + 4z (as in
# cube()), and its six quads counter-clockwise from outside (the same face table as cube()).
_CUBE_CORNERS = np.array([[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=np.int64)
_CUBE_QUADS = np.array([
    (0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5),
], dtype=np.int64)

# The 20 cells of a 3×3×3 grid that a Menger step keeps: (i, j, k) in {0, 1, 2}³ with at
# most one coordinate equal to the middle one, 1 (the 6 face centres and the body centre go).
_MENGER_CELLS = np.array([c for c in np.ndindex(3, 3, 3) if sum(x == 1 for x in c) <= 1], dtype=np.int64)


def _quads_to_triangles(quads: np.ndarray) -> np.ndarray:
    """(F, 4) quads → (2F, 3) triangles (q0, q1, q2), (q0, q2, q3), the two of a quad adjacent."""
    q = np.asarray(quads, dtype=np.int64).reshape(-1, 4)
    return np.stack([q[:, [0, 1, 2]], q[:, [0, 2, 3]]], axis=1).reshape(-1, 3)


def menger(level: int = 2, keep_internal: int = 0) -> Mesh:
    """The Menger sponge of ``level``: a cube of side 1 centred at the origin, holes and all.

    Construction
    ------------
    Work on the integer grid of step 3^-N (N = ``level``), where the sponge fills
    [0, 3^N]³. Level 0 is one cell at (0, 0, 0). Each level replaces every cell ``c`` by
    the 20 cells ``3·c + o`` for the offsets ``o`` in {0, 1, 2}³ having at most one
    coordinate equal to 1 (the 27 sub-cells less the 6 face centres and the body centre);
    this is one vectorised step per level, so level N has 20^N cells of side 3^-N.

    Each cell gives the 6 quads of :func:`cube` (counter-clockwise from outside), two
    triangles each. With ``keep_internal=0`` every face shared by two touching cells
    (a face inside the solid) is removed: face centres, doubled to integers on the grid,
    are hashed, and the faces whose centre occurs twice go (the two cells' copies of the
    face, which have opposite orientations). Points with equal integer coordinates are
    merged (``np.unique``), so no point is repeated and the remaining surface is closed
    and consistently oriented. No two cells of the sponge meet along an edge or at a
    corner only, so the surface is a closed 2-manifold: every edge is used by exactly two
    triangles, once in each direction (checked for N ≤ 3 in tests/lab/test_shapes.py).

    The remaining surface has area 2·(20/9)^N + 4·(8/9)^N and encloses volume (20/27)^N.
    With ``keep_internal=1`` all 6·20^N faces stay (area 6·20^N·9^-N; as the doubled faces
    have opposite orientations the divergence-theorem volume is unchanged). No point
    normals: the faces are flat.

    Parameters
    ----------
    level : recursion depth N ≥ 0; 20^N cells, so memory and time grow twentyfold per
        level (level 4, 160 000 cells, takes about a second; level 5 would be 3.2 million
        cells).
    keep_internal : 0 (default) removes the faces between touching cells, 1 keeps them.

    >>> menger(level=0).n_triangles, menger(level=1).n_triangles
    (12, 144)
    """
    n = int(level)
    if n < 0:
        raise ValueError(f"menger: level must be >= 0, got {level!r}")
    cells = np.zeros((1, 3), dtype=np.int64)                       # lower corners, grid units
    for _ in range(n):
        cells = (3 * cells[:, None, :] + _MENGER_CELLS[None, :, :]).reshape(-1, 3)

    quad_offsets = _CUBE_CORNERS[_CUBE_QUADS]                      # (6 faces, 4 corners, 3)
    face_cell = np.repeat(np.arange(len(cells)), 6)
    face_kind = np.tile(np.arange(6), len(cells))
    if not keep_internal:
        # Twice the face centre is 2·corner + (sum of the quad's offsets) / 2: an integer
        # point in [0, 2·3^N]³, hashed to one int64.
        m = 2 * 3 ** n + 1
        centre2 = 2 * cells[:, None, :] + (quad_offsets.sum(axis=1) // 2)[None, :, :]
        key = ((centre2[..., 2] * m + centre2[..., 1]) * m + centre2[..., 0]).ravel()
        _, inverse, counts = np.unique(key, return_inverse=True, return_counts=True)
        single = counts[inverse.ravel()] == 1
        face_cell, face_kind = face_cell[single], face_kind[single]

    corners = cells[face_cell][:, None, :] + quad_offsets[face_kind]   # (F, 4, 3) grid points
    p = 3 ** n + 1
    key = (corners[..., 2] * p + corners[..., 1]) * p + corners[..., 0]  # z-major, as cube()
    uniq, inverse = np.unique(key.ravel(), return_inverse=True)
    grid = np.stack([uniq % p, (uniq // p) % p, uniq // (p * p)], axis=1)
    points = grid / float(3 ** n) - 0.5
    return Mesh(points, _quads_to_triangles(inverse.reshape(-1, 4)))


def icosahedron_fractal(level: int = 2) -> Mesh:
    """The textbook's icosahedron flake: 12^level icosahedra, 20·12^level triangles.

    Construction
    ------------
    Start with :func:`icosahedron` of circumradius 1 centred at the origin. At each level
    every icosahedron (centre c, circumradius R) is replaced by 12 copies of itself scaled
    by s = 1/(1 + φ) (φ the golden ratio), centred at c + (1 − s)·R·v_i for its 12 unit
    vertex directions v_i. Each copy keeps the parent's orientation, so its vertex in
    direction v_i is c + (1 − s)·R·v_i + s·R·v_i = c + R·v_i: the copy touches the
    parent's circumsphere exactly at the parent's vertex, and every copy lies inside the
    parent's circumscribed ball (so the whole flake lies in the unit ball).

    Neighbouring copies touch. Two copies at adjacent vertices v_i, v_j are translates
    of each other by d = (1 − s)·R·(v_j − v_i), of length (1 − s)·R·e with e = 2/√(1 + φ²)
    the edge of the unit-circumradius icosahedron. The direction of an edge is the
    direction of the midpoint of two other, opposite, edges, at the midradius
    ρ = φ/√(1 + φ²) of the copy, ρ·s·R. The copies touch when |d| is the sum of their
    reaches in that direction, |d| = 2·s·R·ρ, i.e. (1 − s)·e = 2·s·ρ, i.e. 1 − s = s·φ,
    i.e. s = 1/(1 + φ) — the chosen scale. They then share a whole edge (of length s·R·e,
    perpendicular to d) and nothing more: their interiors lie on either side of the
    plane through that edge perpendicular to d. (Copies at non-adjacent vertices are
    farther apart and do not touch.) tests/lab/test_shapes.py checks this numerically.

    The icosahedra are kept as separate closed surfaces: points are not merged, so a
    shared edge appears once in each of its two icosahedra. The centres array grows
    twelvefold per level (one vectorised step per level). No point normals (flat faces).

    Parameters
    ----------
    level : recursion depth N ≥ 0 (12^N icosahedra).

    >>> icosahedron_fractal(level=1).n_triangles
    240
    """
    n = int(level)
    if n < 0:
        raise ValueError(f"icosahedron_fractal: level must be >= 0, got {level!r}")
    base = icosahedron(1.0)
    dirs, faces = base.points, base.triangles                      # unit vertex directions
    s = 1.0 / (1.0 + PHI)
    centres = np.zeros((1, 3))
    radius = 1.0
    for _ in range(n):
        centres = (centres[:, None, :] + (1.0 - s) * radius * dirs[None, :, :]).reshape(-1, 3)
        radius *= s
    points = (centres[:, None, :] + radius * dirs[None, :, :]).reshape(-1, 3)
    tris = (faces[None, :, :] + 12 * np.arange(len(centres))[:, None, None]).reshape(-1, 3)
    return Mesh(points, tris)


def _ring_angles(segments: int, name: str) -> np.ndarray:
    n = int(segments)
    if n < 3:
        raise ValueError(f"{name}: segments must be >= 3, got {segments!r}")
    return 2.0 * np.pi * np.arange(n) / n


def _cap_tcoords(points: np.ndarray, r: float) -> np.ndarray:
    """Planar (s, t) of cap points: s = 0.5 + x/(2r), t = 0.5 + y/(2r) (the image seen from +z)."""
    return np.column_stack([0.5 + points[:, 0] / (2.0 * r), 0.5 + points[:, 1] / (2.0 * r)])


def cylinder(segments: int = 32, radius: float = 0.5, height: float = 1.0, uv: int = 0) -> Mesh:
    """A closed cylinder around the z axis, from z = −height/2 to z = +height/2.

    Construction
    ------------
    The circle of ``radius`` is approximated by the regular ``segments``-gon with corners
    at θ_k = 2πk/segments (k = 0 … segments − 1), the first at +x.

    - Side: 2·segments points (a ring at each end) with the radial unit normals
      (cos θ_k, sin θ_k, 0), shared between neighbouring quads (smooth around, as VTK's
      cylinder source); quad k joins bottom k, bottom k + 1, top k + 1, top k (two
      triangles), counter-clockwise from outside.
    - Caps: each its own centre point and ring of ``segments`` points, normals (0, 0, 1)
      on top and (0, 0, −1) at the bottom, triangulated as a fan from the centre.

    Points are duplicated along the two rims (side and cap points at the same place with
    different normals), so the surface is closed geometrically (its triangles cover it
    without gaps, all outward) but not topologically (rim edges are not shared by
    indices). Volume: that of the polygonal prism, segments/2·r²·sin(2π/segments)·h.

    Texture coordinates (``uv=1``): on the side s = θ/(2π), t = (z + height/2)/height, the
    image wrapped once around, unmirrored seen from outside with +z up; each ring gets a
    seam point at θ = 2π (s = 1, at the place of θ = 0), so the side has 2·(segments + 1)
    points and no triangle spans the whole image. Caps: planar, s = 0.5 + x/(2r),
    t = 0.5 + y/(2r) (the image as seen from +z: mirrored on the bottom cap seen from
    below). All in [0, 1]. Triangles (count, order, winding) are those of ``uv=0``.

    Parameters
    ----------
    segments : number of sides, any whole number ≥ 3. (The scene loader currently accepts
        whole-number shape parameters in 0..8 only; that range is to be widened by the
        integrator. The default, 32, applies when the parameter is not given.)
    radius, height : positive sizes.
    uv : 0 (default) no texture coordinates, 1 the ones above.

    >>> cylinder(segments=8).n_triangles
    32
    """
    t = _ring_angles(segments, "cylinder")
    n, r, h2 = len(t), float(radius), float(height) / 2.0
    cols = n + 1 if uv else n                                      # side columns (uv: seam copy)
    kk = np.arange(cols) % n                                       # column -> corner angle index
    c, s = np.cos(t)[kk], np.sin(t)[kk]
    zeros, ones = np.zeros(cols), np.ones(cols)
    k = np.arange(n)
    k1 = k + 1 if uv else (k + 1) % n

    ring_lo = np.column_stack([r * c, r * s, -h2 * ones])
    ring_hi = np.column_stack([r * c, r * s, h2 * ones])
    radial = np.column_stack([c, s, zeros])
    side_pts = np.concatenate([ring_lo, ring_hi])                  # bottom 0..cols-1, then top
    side_nrm = np.concatenate([radial, radial])
    side_tris = _quads_to_triangles(np.column_stack([k, k1, cols + k1, cols + k]))

    up, down = np.array([[0.0, 0.0, 1.0]]), np.array([[0.0, 0.0, -1.0]])
    top0 = 2 * cols                                                # top centre, then top ring
    top_pts = np.concatenate([[[0.0, 0.0, h2]], ring_hi[:n]])
    top_tris = np.column_stack([np.full(n, top0), top0 + 1 + k, top0 + 1 + (k + 1) % n])
    bot0 = top0 + n + 1                                            # bottom centre, then ring
    bot_pts = np.concatenate([[[0.0, 0.0, -h2]], ring_lo[:n]])
    bot_tris = np.column_stack([np.full(n, bot0), bot0 + 1 + (k + 1) % n, bot0 + 1 + k])

    points = np.concatenate([side_pts, top_pts, bot_pts])
    normals = np.concatenate([side_nrm, np.repeat(up, n + 1, axis=0), np.repeat(down, n + 1, axis=0)])
    tcoords = None
    if uv:
        side_st = np.column_stack([np.arange(cols) / n, zeros])
        tcoords = np.concatenate([side_st, side_st + [0.0, 1.0], _cap_tcoords(top_pts, r), _cap_tcoords(bot_pts, r)])
    return Mesh(points, np.concatenate([side_tris, top_tris, bot_tris]), normals, tcoords)


def cone(segments: int = 32, radius: float = 0.5, height: float = 1.0, uv: int = 0) -> Mesh:
    """A closed cone around the z axis: base circle at z = −height/2, apex at z = +height/2.

    Construction
    ------------
    The base circle of ``radius`` is the regular ``segments``-gon with corners at
    θ_k = 2πk/segments, the first at +x.

    - Side: ``segments`` triangles (base k, base k + 1, apex k), counter-clockwise from
      outside. The cone's exact outward normal at angle θ is

          n(θ) = (h·cos θ, h·sin θ, r) / √(h² + r²),

      the gradient of ρ − r·(h/2 − z)/h (ρ the distance to the axis), which points
      outward and *up* (toward the apex): it is the radial direction tilted up out of the
      horizontal by the cone's half-angle α = atan(r/h), i.e. its angle to the +z axis is
      acos(r/√(h² + r²)) = 90° − α. The base ring points (shared by neighbouring side
      triangles) carry n(θ_k). The apex has no single normal, so it is one point per side
      triangle (``segments`` apex points at the same place), apex k carrying n at the
      middle of its segment, θ = θ_k + π/segments.
    - Base cap: its own centre point and ring, normal (0, 0, −1), a fan from the centre.

    Points are duplicated at the apex and along the rim, so the surface is closed
    geometrically (all triangles outward, no gaps) but not topologically. Volume: that of
    the polygonal pyramid, segments/2·r²·sin(2π/segments)·h/3.

    Texture coordinates (``uv=1``): on the side s = θ/(2π), t = (z + height/2)/height, so
    base ring points have t = 0 and apex k, at the middle of its segment, has
    s = (k + ½)/segments and t = 1; the base ring gets a seam point at θ = 2π (s = 1, at the
    place of θ = 0), so the side has 2·segments + 1 points. Base cap: planar,
    s = 0.5 + x/(2r), t = 0.5 + y/(2r) (the image as seen from +z, so mirrored seen from
    below). All in [0, 1]. Triangles (count, order, winding) are those of ``uv=0``.

    Parameters
    ----------
    segments : number of sides, any whole number ≥ 3 (the scene loader's 0..8 range for
        whole-number parameters is to be widened by the integrator; the default, 32,
        applies when the parameter is not given).
    radius, height : positive sizes.
    uv : 0 (default) no texture coordinates, 1 the ones above.

    >>> cone(segments=8).n_triangles
    16
    """
    t = _ring_angles(segments, "cone")
    n, r, h = len(t), float(radius), float(height)
    h2 = h / 2.0
    cols = n + 1 if uv else n                                      # side ring points (uv: seam copy)
    kk = np.arange(cols) % n                                       # ring point -> corner angle index
    k = np.arange(n)
    k1 = k + 1 if uv else (k + 1) % n

    def tilted(theta):
        return np.column_stack([h * np.cos(theta), h * np.sin(theta), r * np.ones_like(theta)]) / np.hypot(h, r)

    ring = np.column_stack([r * np.cos(t), r * np.sin(t), -h2 * np.ones(n)])
    apex = np.tile([0.0, 0.0, h2], (n, 1))
    side_pts = np.concatenate([ring[kk], apex])                    # ring 0..cols-1, then apexes
    side_nrm = np.concatenate([tilted(t)[kk], tilted(t + np.pi / n)])
    side_tris = np.column_stack([k, k1, cols + k])

    base0 = cols + n
    base_pts = np.concatenate([[[0.0, 0.0, -h2]], ring])
    base_nrm = np.tile([0.0, 0.0, -1.0], (n + 1, 1))
    base_tris = np.column_stack([np.full(n, base0), base0 + 1 + (k + 1) % n, base0 + 1 + k])

    tcoords = None
    if uv:
        tcoords = np.concatenate([np.column_stack([np.arange(cols) / n, np.zeros(cols)]),
                                  np.column_stack([(k + 0.5) / n, np.ones(n)]), _cap_tcoords(base_pts, r)])
    return Mesh(np.concatenate([side_pts, base_pts]), np.concatenate([side_tris, base_tris]),
                np.concatenate([side_nrm, base_nrm]), tcoords)


PARAM_RANGES = {
    # (shape, whole-number parameter): allowed range; the rest allow 0..8
    ("icosphere", "level"): (0, 7),
    ("menger", "level"): (0, 4),
    ("menger", "keep_internal"): (0, 1),
    ("icosahedron_fractal", "level"): (0, 4),
    ("cylinder", "segments"): (3, 4096),
    ("cone", "segments"): (3, 4096),
    ("icosphere", "uv"): (0, 1),
    ("cylinder", "uv"): (0, 1),
    ("cone", "uv"): (0, 1),
}
"""Ranges of whole-number parameters, checked on loading (memory grows as 20^level, 12^level …)."""

SHAPES = {"cube": cube, "quad": quad, "icosahedron": icosahedron, "icosphere": icosphere, "menger": menger,
          "icosahedron_fractal": icosahedron_fractal, "cylinder": cylinder, "cone": cone}
"""The built-in shapes by name: ``NAME:key=value,...`` on the command line, ``shape = NAME`` in a scene file."""


def shape_parameters(name: str) -> list[tuple[str, object, tuple[int, int] | None]]:
    """Each parameter of shape ``name``: (parameter, default, whole-number range or None).

    >>> shape_parameters("menger")
    [('level', 2, (0, 4)), ('keep_internal', 0, (0, 1))]
    """
    import inspect

    params = inspect.signature(SHAPES[name]).parameters.values()
    return [(p.name, p.default, PARAM_RANGES.get((name, p.name), (0, 8)) if isinstance(p.default, int) else None)
            for p in params]


def shape_summary(name: str) -> str:
    """One line: ``NAME:param=default (lo..hi),...`` and the first line of its docstring.

    >>> shape_summary("quad").split("  ")[0]
    'quad:size=1.0'
    """
    params = ",".join(f"{p}={d}" + (f" ({r[0]}..{r[1]})" if r else "") for p, d, r in shape_parameters(name))
    doc = (SHAPES[name].__doc__ or "").strip().splitlines()[0].replace("``", "")
    return f"{name}:{params}  {doc}"
