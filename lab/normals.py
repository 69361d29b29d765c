"""Vertex normals for the lab's meshes: what both renderers shade with.

Four ways of giving a mesh its normals (``NORMAL_MODES``):

``"file"``
    The mesh as read: its own point normals, or none.
``"computed"``
    Angle-weighted vertex normals (Thürmer & Wüthrich 1998), smooth everywhere, or split
    at creases when a crease angle is given (:func:`split_at_creases`).
``"face"``
    No point normals at all: the renderers shade each triangle with its plane normal
    (flat, faceted shading).
``"radial"``
    The normalised vertex position (model space, seen from the origin): the textbook's
    exact normals of a sphere centred at the origin.

Everything here is vectorised numpy: no Python loop per vertex or per triangle.
"""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh

NORMAL_MODES = ("file", "computed", "face", "radial")

# Two corner normals closer than this (per component) are the same normal: their corners
# share one output point in split_at_creases.
_NORMAL_TOL = 1e-9
# Slack on the crease test so that coplanar faces (dot product 1 up to rounding) are never
# cut apart, even with a crease angle of 0.
_DOT_SLACK = 1e-12


def _unit_rows(v: np.ndarray) -> np.ndarray:
    """Rows of ``v`` scaled to unit length; rows of zero length stay zero."""
    norm = np.linalg.norm(v, axis=1, keepdims=True)
    return np.divide(v, norm, out=np.zeros_like(v), where=norm > 0.0)


def face_normals(points, triangles) -> np.ndarray:
    """Unit plane normals of triangles, (v1 − v0) × (v2 − v0) normalised.

    Parameters
    ----------
    points : (N, 3) array of positions.
    triangles : (T, 3) array of point indices, counter-clockwise from outside.

    Returns
    -------
    (T, 3) float64 array; outward for counter-clockwise triangles, zero for degenerate
    triangles (zero area: repeated or collinear points).

    Examples
    --------
    >>> face_normals([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]]).tolist()
    [[0.0, 0.0, 1.0]]
    """
    p = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    v0, v1, v2 = p[t[:, 0]], p[t[:, 1]], p[t[:, 2]]
    return _unit_rows(np.cross(v1 - v0, v2 - v0))


def _corner_angles(points: np.ndarray, triangles: np.ndarray) -> np.ndarray:
    """(T, 3) interior angle (radians) of each triangle at each of its three corners.

    Computed as atan2(|e1 × e2|, e1 · e2), accurate for small and for near-flat angles;
    a corner with a zero-length edge gets angle 0.
    """
    tp = points[triangles]                     # (T, 3 corners, 3 coords)
    e1 = np.roll(tp, -1, axis=1) - tp          # to the next corner
    e2 = np.roll(tp, -2, axis=1) - tp          # to the previous corner
    sin = np.linalg.norm(np.cross(e1, e2), axis=2)
    cos = np.einsum("tck,tck->tc", e1, e2)
    return np.arctan2(sin, cos)


def _accumulate(index: np.ndarray, vectors: np.ndarray, length: int) -> np.ndarray:
    """Sum rows of ``vectors`` into ``length`` bins by ``index`` (np.add.at, but faster)."""
    sums = [np.bincount(index, weights=vectors[:, k], minlength=length) for k in range(3)]
    return np.stack(sums, axis=1).astype(np.float64, copy=False)  # (bincount of nothing is int)


def angle_weighted_normals(mesh: Mesh) -> np.ndarray:
    """Vertex normals weighted by the incident corner angles.

    Vertex normal = normalised sum over incident triangles of (corner angle at that
    vertex) × (unit face normal), as in Thürmer & Wüthrich 1998, "Computing vertex normals
    from polygonal facets". Unlike count or area weights, the result depends only on the
    surface's shape, not on how its faces were cut into triangles.

    Returns
    -------
    (N, 3) float64 array of unit normals; zero where undefined (points used by no
    triangle, or whose weighted normals cancel out).
    """
    fn = face_normals(mesh.points, mesh.triangles)
    angles = _corner_angles(mesh.points, mesh.triangles)
    weighted = (angles[:, :, None] * fn[:, None, :]).reshape(-1, 3)
    summed = _accumulate(mesh.triangles.ravel(), weighted, mesh.n_points)
    return _unit_rows(summed)


def _corner_normals(mesh: Mesh, crease_angle: float) -> np.ndarray:
    """(3T, 3) angle-weighted normal of every corner (corner c = triangle c // 3, slot c % 3),
    gathering only the incident triangles within ``crease_angle`` of the corner's own face."""
    tris = mesh.triangles
    n_corners = 3 * len(tris)
    fn = face_normals(mesh.points, tris)
    vertex = tris.ravel()                                       # corner -> vertex id
    tri = np.repeat(np.arange(len(tris)), 3)                    # corner -> triangle id
    angle = _corner_angles(mesh.points, tris).ravel()           # corner -> angle

    # Group the corners by vertex: sorted[g_start[v] : g_start[v] + valence[v]].
    order = np.argsort(vertex, kind="stable")
    valence = np.bincount(vertex, minlength=mesh.n_points)
    g_start = np.concatenate([[0], np.cumsum(valence)[:-1]])

    # Every ordered pair (i, j) of corners sharing a vertex, i itself included:
    # corner i (at sorted position p) is repeated valence times, and paired with the
    # sorted positions g_start .. g_start + valence - 1 of its group.
    k = valence[vertex[order]]                                  # group size per sorted corner
    i = np.repeat(order, k)
    first = np.repeat(np.cumsum(k) - k, k)                      # where each run of i starts
    rank = np.arange(len(i)) - first                            # 0 .. k-1 within the run
    j = order[np.repeat(g_start[vertex[order]], k) + rank]

    # Keep the pairs whose faces lie within the crease angle of each other. A corner of a
    # degenerate triangle (zero face normal) has no direction to compare with: it gathers
    # all its vertex's triangles, i.e. gets the smooth normal.
    dot = np.einsum("pk,pk->p", fn[tri[i]], fn[tri[j]])
    own_zero = ~fn[tri[i]].any(axis=1)
    keep = (dot >= np.cos(np.radians(crease_angle)) - _DOT_SLACK) | own_zero
    i, j = i[keep], j[keep]

    summed = _accumulate(i, angle[j, None] * fn[tri[j]], n_corners)
    return _unit_rows(summed)


def split_at_creases(mesh: Mesh, crease_angle: float) -> Mesh:
    """Angle-weighted normals that stay sharp across creases, splitting points as needed.

    Each corner (a vertex as used by one triangle) gets its own angle-weighted normal,
    gathering only the incident triangles whose face normal lies within ``crease_angle``
    degrees of the corner's own triangle's face normal. The corners of one vertex with
    equal normals (to 1e-9) then share one output point; a vertex whose corners disagree
    is duplicated, once per distinct normal.

    This is the "within the angle of this face" rule of many modelling (DCC) tools, not
    the edge walking of ``vtkPolyDataNormals`` (which splits along sharp *edges* and
    follows connectivity around each vertex). The two differ only at vertices where faces
    meet at graded angles (a face may be within the crease of two neighbours that are not
    within it of each other). That is fine here: the lab computes normals once and both
    renderers receive the very same mesh, so the comparison is never affected; only a
    comparison with VTK's own normal filter would be.

    Parameters
    ----------
    mesh : the mesh (its own point normals are ignored).
    crease_angle : degrees; 0 splits every non-coplanar edge, 180 (or more) smooths all.

    Returns
    -------
    A new :class:`Mesh`: points ordered by original point, then by first use (so a mesh
    with no creases keeps its points, order and all, and points used by no triangle stay,
    with a zero normal); the triangles reindexed in the same order and with the same
    winding; ``point_normals`` the unit corner normals (zero where undefined);
    ``tcoords`` those of each point's source point (None if the mesh has none).
    """
    n_points = mesh.n_points
    n_corners = 3 * mesh.n_triangles
    vertex = mesh.triangles.ravel()
    normals = _corner_normals(mesh, crease_angle)

    # Corners with the same vertex and the same (quantised) normal form one output point.
    quant = np.round(normals / _NORMAL_TOL).astype(np.int64)    # also folds -0.0 into 0
    key = np.column_stack([vertex, quant])
    _, group, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    first_use = np.full(len(group), n_corners, dtype=np.int64)
    np.minimum.at(first_use, inverse, np.arange(n_corners))

    # Points used by no triangle are kept, after every used one, so that unsplit meshes
    # keep their point list unchanged.
    unused = np.flatnonzero(np.bincount(vertex, minlength=n_points) == 0)
    out_vertex = np.concatenate([vertex[group], unused])
    out_first = np.concatenate([first_use, np.full(len(unused), n_corners)])
    out_normal = np.concatenate([normals[group], np.zeros((len(unused), 3))])

    order = np.lexsort((out_first, out_vertex))                # by vertex, then first use
    new_index = np.empty(len(order), dtype=np.int64)
    new_index[order] = np.arange(len(order))
    triangles = new_index[inverse].reshape(-1, 3)
    source = out_vertex[order]                                 # output point -> input point
    tcoords = None if mesh.tcoords is None else mesh.tcoords[source]
    return Mesh(mesh.points[source], triangles, out_normal[order], tcoords)


def radial_normals(points) -> np.ndarray:
    """Normalised positions, points / |points|: a sphere's normals (zero at the origin)."""
    return _unit_rows(np.asarray(points, dtype=np.float64).reshape(-1, 3))


def with_normals(mesh: Mesh, mode: str, crease_angle: float | None = None, source: str = "") -> Mesh:
    """The mesh with the normals of ``mode`` (one of ``NORMAL_MODES``).

    - ``"file"``: the mesh as is (the same object, its own normals or none);
    - ``"computed"``: angle-weighted normals, split at creases when ``crease_angle``
      (degrees) is given, else smooth everywhere (points unchanged);
    - ``"face"``: no point normals (faceted: the renderers use the plane normals);
    - ``"radial"``: normal = normalised vertex position (model space, from the origin),
      the textbook's smooth sphere.

    ``crease_angle`` is used by ``"computed"`` only. ``source`` names where the mode
    came from (a scene file, a command-line option) in the error message. Every mode
    keeps the mesh's texture coordinates (split points copy their source point's).

    Raises
    ------
    ValueError
        For an unknown mode, naming ``source``.
    """
    if mode == "file":
        return mesh
    if mode == "computed":
        if crease_angle is None:
            return Mesh(mesh.points, mesh.triangles, angle_weighted_normals(mesh), mesh.tcoords)
        return split_at_creases(mesh, crease_angle)
    if mode == "face":
        return Mesh(mesh.points, mesh.triangles, None, mesh.tcoords)
    if mode == "radial":
        return Mesh(mesh.points, mesh.triangles, radial_normals(mesh.points), mesh.tcoords)
    where = f"{source}: " if source else ""
    raise ValueError(f"{where}unknown normals mode {mode!r}; expected one of {', '.join(NORMAL_MODES)}")


def scene_with_normals(scene, crease_angle: float | None = None):
    """A copy of ``scene`` in which every object without point normals gets computed ones."""
    from dataclasses import replace

    objs = tuple(o if o.mesh.point_normals is not None else
                 replace(o, mesh=with_normals(o.mesh, "computed", crease_angle)) for o in scene.objects)
    return replace(scene, objects=objs)
