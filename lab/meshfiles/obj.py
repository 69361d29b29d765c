"""Wavefront OBJ reader: ``v``, ``vt``, ``vn`` and ``f`` statements; everything else is ignored."""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh, fan_triangulate
from lab.meshfiles._common import make_mesh, reading


def _obj_index(text, count, what):
    """0-based index of a 1-based (or negative: relative to the ``count`` so far) OBJ index."""
    i = int(text)
    if i == 0 or count + i < 0:
        raise ValueError(f"{what} index {i} out of range (there are {count} so far)")
    return i - 1 if i > 0 else count + i


def _per_point(point_of, other_of, values, n_points, what):
    """Per-point rows of ``values`` (``vn`` or ``vt``) if every corner has one and each point
    is always paired with the same one, else None; points of no face get zeros."""
    if not values or not len(other_of) or (other_of < 0).any():
        return None
    if other_of.max() >= len(values):
        raise ValueError(f"a face refers to {what} {other_of.max() + 1}, but there are {len(values)}")
    pairing = np.full(n_points, -1)
    pairing[point_of] = other_of
    if not (pairing[point_of] == other_of).all():  # some point has two different ones
        return None
    values = np.array(values)
    rows = np.zeros((n_points, values.shape[1]))
    rows[pairing >= 0] = values[pairing[pairing >= 0]]
    return rows


def read_obj(path) -> Mesh:
    """Read a Wavefront OBJ file: ``v``, ``vt``, ``vn`` and ``f`` statements.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points are the ``v`` rows; faces are fan-triangulated; normals only if each point
        used by a face is always paired with one and the same ``vn``, and texture
        coordinates (the u, v of ``vt``; v is 0 when missing, w is ignored) likewise only
        if each such point is always paired with one and the same ``vt``. VTK's OBJ reader
        instead duplicates a point used with different ``vt`` or ``vn``; this reader never
        splits points, so such a file gives no texture coordinates (or no normals).

    Raises
    ------
    MeshFileError
    """
    with reading(path) as data:
        v, vt, vn, faces, corners = [], [], [], [], []  # corners: (point, tcoord or -1, normal or -1)
        for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            words = line.split()
            try:
                if words[:1] in (["v"], ["vn"]):
                    if len(words) < 4:
                        raise ValueError("fewer than 3 coordinates")
                    (v if words[0] == "v" else vn).append([float(x) for x in words[1:4]])
                elif words[:1] == ["vt"]:
                    if len(words) < 2:
                        raise ValueError("a texture coordinate without values")
                    vt.append([float(words[1]), float(words[2]) if len(words) > 2 else 0.0])
                elif words[:1] == ["f"]:
                    face = []
                    for corner in words[1:]:
                        parts = corner.split("/")
                        face.append(_obj_index(parts[0], len(v), "vertex"))
                        has_tcoord = len(parts) > 1 and parts[1]
                        has_normal = len(parts) > 2 and parts[2]
                        corners.append((face[-1],
                                        _obj_index(parts[1], len(vt), "texture coordinate") if has_tcoord else -1,
                                        _obj_index(parts[2], len(vn), "normal") if has_normal else -1))
                    faces.append(face)
            except ValueError as exc:
                raise ValueError(f"line {number}: {exc}") from None
        corners = np.array(corners, dtype=np.int64).reshape(-1, 3)
        point_of, tcoord_of, normal_of = corners.T
        if len(corners) and (point_of.min() < 0 or point_of.max() >= len(v)):
            bad = point_of[(point_of < 0) | (point_of >= len(v))][0]
            raise ValueError(f"a face refers to vertex {bad + 1}, but there are {len(v)}")
        normals = _per_point(point_of, normal_of, vn, len(v), "normal")
        tcoords = _per_point(point_of, tcoord_of, vt, len(v), "texture coordinate")
        return make_mesh(np.array(v).reshape(-1, 3), fan_triangulate(faces), normals, tcoords)
