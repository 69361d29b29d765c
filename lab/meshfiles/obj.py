"""Wavefront OBJ reader: ``v``, ``vn`` and ``f`` statements; everything else is ignored."""
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


def read_obj(path) -> Mesh:
    """Read a Wavefront OBJ file: ``v``, ``vn`` and ``f`` statements.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points are the ``v`` rows; faces are fan-triangulated; normals only if each point
        used by a face is always paired with one and the same ``vn``.

    Raises
    ------
    MeshFileError
    """
    with reading(path) as data:
        v, vn, faces, corners = [], [], [], []  # corners: (point, normal or -1)
        for number, line in enumerate(data.decode("utf-8", "replace").splitlines(), 1):
            words = line.split()
            try:
                if words[:1] in (["v"], ["vn"]):
                    if len(words) < 4:
                        raise ValueError("fewer than 3 coordinates")
                    (v if words[0] == "v" else vn).append([float(x) for x in words[1:4]])
                elif words[:1] == ["f"]:
                    face = []
                    for corner in words[1:]:
                        parts = corner.split("/")
                        face.append(_obj_index(parts[0], len(v), "vertex"))
                        has_normal = len(parts) > 2 and parts[2]
                        corners.append((face[-1], _obj_index(parts[2], len(vn), "normal") if has_normal else -1))
                    faces.append(face)
            except ValueError as exc:
                raise ValueError(f"line {number}: {exc}") from None
        corners = np.array(corners, dtype=np.int64).reshape(-1, 2)
        point_of, normal_of = corners[:, 0], corners[:, 1]
        if len(corners) and (point_of.min() < 0 or point_of.max() >= len(v)):
            bad = point_of[(point_of < 0) | (point_of >= len(v))][0]
            raise ValueError(f"a face refers to vertex {bad + 1}, but there are {len(v)}")
        normals = None
        if vn and len(corners) and (normal_of >= 0).all():
            if normal_of.max() >= len(vn):
                raise ValueError(f"a face refers to normal {normal_of.max() + 1}, but there are {len(vn)}")
            pairing = np.full(len(v), -1)
            pairing[point_of] = normal_of
            if (pairing[point_of] == normal_of).all():  # each point has one normal
                normals = np.zeros((len(v), 3))
                normals[pairing >= 0] = np.array(vn)[pairing[pairing >= 0]]
        return make_mesh(np.array(v).reshape(-1, 3), fan_triangulate(faces), normals)
