"""The one place a mesh read from a file is checked: :func:`make_mesh`, and its error."""
from __future__ import annotations

import numpy as np

from lab.mesh import Mesh
from lab.values import MAX_MAGNITUDE


class MeshFileError(ValueError):
    """A mesh file that cannot be read; the one-line message is ``"<path>: <what is wrong>"``."""


def _finite_within(values: np.ndarray, what: str) -> None:
    """Refuse NaN, infinity and (for coordinates) magnitudes beyond ±MAX_MAGNITUDE."""
    if len(values) == 0:
        return
    lo, hi = float(values.min()), float(values.max())  # NaN propagates into both
    if not (np.isfinite(lo) and np.isfinite(hi)):
        raise ValueError(f"{what} contain NaN or infinity")
    if what == "point coordinates" and max(-lo, hi) > MAX_MAGNITUDE:
        raise ValueError(f"point coordinates beyond ±{MAX_MAGNITUDE:g}")


def make_mesh(points, triangles, normals=None, tcoords=None) -> Mesh:
    """Check points, triangles, normals and texture coordinates, make normals unit length,
    build the Mesh: the one place every mesh read from a file is validated.

    Parameters
    ----------
    points : (N, 3) array, model space (float32 or float64 as the reader gave them).
    triangles : (M, 3) integer array of point indices.
    normals : (N, 3) array or None; scaled here to unit length (zero normals stay zero).
    tcoords : (N, 2) array or None; texture coordinates (s, t).

    Raises
    ------
    ValueError
        NaN, infinite or beyond ±MAX_MAGNITUDE coordinates; no triangles; point indices
        out of range; normals or texture coordinates not one per point, or not finite.
        The reader prefixes the message with the file's path (:class:`MeshFileError`).
    """
    points = np.asarray(points).reshape(-1, 3)
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    _finite_within(points, "point coordinates")
    points = points.astype(np.float64, copy=False)
    if len(triangles) == 0:
        raise ValueError("no triangles")
    lo, hi = int(triangles.min()), int(triangles.max())
    if lo < 0 or hi >= len(points):
        bad = lo if lo < 0 else hi
        raise ValueError(f"point index {bad} out of range (there are {len(points)} points)")
    if normals is not None:
        normals = np.asarray(normals).reshape(-1, 3)
        if len(normals) != len(points):
            raise ValueError(f"{len(normals)} normals for {len(points)} points")
        _finite_within(normals, "normals")
        normals = normals.astype(np.float64)  # a copy: the reader's array is left alone
        length = np.sqrt(np.einsum("ij,ij->i", normals, normals))[:, None]
        if length.min() > 0:
            normals /= length
        else:
            np.divide(normals, length, out=normals, where=length > 0)
    if tcoords is not None:
        tcoords = np.asarray(tcoords).reshape(-1, 2)
        if len(tcoords) != len(points):
            raise ValueError(f"{len(tcoords)} texture coordinates for {len(points)} points")
        _finite_within(tcoords, "texture coordinates")
        tcoords = tcoords.astype(np.float64)
    return Mesh(points, triangles, normals, tcoords)
