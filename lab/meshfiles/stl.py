"""STL reader: ascii and binary, exactly equal vertices merged."""
from __future__ import annotations

import struct

import numpy as np

from lab.mesh import Mesh
from lab.meshfiles._common import make_mesh, reading


def read_stl(path) -> Mesh:
    """Read an STL file, binary or ascii, merging exactly equal vertices.

    Parameters
    ----------
    path : str or os.PathLike

    Returns
    -------
    Mesh
        Points in order of first occurrence; one triangle per facet; no point normals.

    Raises
    ------
    MeshFileError
    """
    with reading(path) as data:
        n = struct.unpack_from("<I", data, 80)[0] if len(data) >= 84 else -1
        ascii_stl = data.lstrip()[:5].lower() == b"solid" and b"endloop" in data
        if len(data) == 84 + 50 * n or (n > 0 and len(data) > 84 + 50 * n and not ascii_stl):
            facet = np.dtype([("normal", "<f4", 3), ("corners", "<f4", (3, 3)), ("attribute", "<u2")])
            corners = np.frombuffer(data, facet, n, 84)["corners"].reshape(-1, 3)
        elif ascii_stl:
            words = np.array(data.split())
            at = np.flatnonzero((words == b"vertex") | (words == b"VERTEX"))
            corners = words[at[:, None] + np.arange(1, 4)].astype(np.float32)  # float32, as VTK reads them
            if len(corners) != 3 * np.count_nonzero((words == b"endloop") | (words == b"ENDLOOP")):
                raise ValueError("an ascii STL facet without exactly 3 vertices")
        else:
            raise ValueError("not an STL file (neither binary nor ascii 'solid')")
        # Merge equal corners: unique 12-byte rows (-0.0 made 0.0 first), kept in first-occurrence order.
        corners = np.ascontiguousarray(corners.reshape(-1, 3), dtype=np.float32) + np.float32(0)
        _, first, inverse = np.unique(corners.view("V12").ravel(), return_index=True, return_inverse=True)
        order = np.argsort(first)
        rank = np.empty_like(order)
        rank[order] = np.arange(len(order))
        return make_mesh(corners[first[order]], rank[inverse.reshape(-1)].reshape(-1, 3))
