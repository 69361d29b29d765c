"""Shared parts of the mesh file readers: the error, its wrapper, checks, cell triangulation."""
from __future__ import annotations

import contextlib
import struct
import xml.etree.ElementTree as ET
import zlib
from pathlib import Path

import numpy as np

from lab.mesh import Mesh, fan_triangulate
from lab.values import MAX_MAGNITUDE, file_problem


class MeshFileError(ValueError):
    """A mesh file that cannot be read; the message is ``"<path>: <what is wrong>"``."""


@contextlib.contextmanager
def reading(path):
    """Yield the bytes of ``path``; turn any error inside the block into MeshFileError.

    Only regular files are read (a folder, a device such as /dev/zero or a pipe is refused).
    """
    problem = file_problem(path)
    if problem:
        raise MeshFileError(f"{path}: cannot read file: {problem}")
    try:
        yield Path(path).read_bytes()
    except MeshFileError:
        raise
    except OSError as exc:
        raise MeshFileError(f"{path}: cannot read file: {exc.strerror or exc}") from None
    except ET.ParseError as exc:
        raise MeshFileError(f"{path}: not valid XML: {exc}") from None
    except (ValueError, IndexError, KeyError, TypeError, struct.error, zlib.error, OverflowError) as exc:
        message = " ".join(str(exc).split()) or type(exc).__name__
        if isinstance(exc, (IndexError, struct.error)) or "buffer is smaller" in message:
            message = f"file is truncated or malformed ({message})"
        raise MeshFileError(f"{path}: {message}") from None


def make_mesh(points, triangles, normals=None, tcoords=None) -> Mesh:
    """Check points, triangles, normals and texture coordinates, make normals unit length,
    build the Mesh: the one place every reader's mesh is validated.

    Refused (ValueError, which :func:`reading` prefixes with the path): NaN, infinite or
    beyond ±MAX_MAGNITUDE coordinates; no triangles; point indices out of range; normals
    or texture coordinates not one per point, or not finite.
    """
    points = np.asarray(points, dtype=np.float64).reshape(-1, 3)
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    if not np.isfinite(points).all():
        raise ValueError("point coordinates contain NaN or infinity")
    if len(points) and np.abs(points).max() > MAX_MAGNITUDE:
        raise ValueError(f"point coordinates beyond ±{MAX_MAGNITUDE:g}")
    if len(triangles) == 0:
        raise ValueError("no triangles")
    if triangles.min() < 0 or triangles.max() >= len(points):
        bad = triangles[(triangles < 0) | (triangles >= len(points))][0]
        raise ValueError(f"point index {bad} out of range (there are {len(points)} points)")
    if normals is not None:
        normals = np.asarray(normals, dtype=np.float64).reshape(-1, 3)
        if len(normals) != len(points):
            raise ValueError(f"{len(normals)} normals for {len(points)} points")
        if not np.isfinite(normals).all():
            raise ValueError("normals contain NaN or infinity")
        length = np.linalg.norm(normals, axis=1, keepdims=True)
        normals = np.divide(normals, length, out=np.zeros_like(normals), where=length > 0)
    if tcoords is not None:
        tcoords = np.asarray(tcoords, dtype=np.float64).reshape(-1, 2)
        if len(tcoords) != len(points):
            raise ValueError(f"{len(tcoords)} texture coordinates for {len(points)} points")
        if not np.isfinite(tcoords).all():
            raise ValueError("texture coordinates contain NaN or infinity")
    return Mesh(points, triangles, normals, tcoords)


def split_counted(flat, n_cells):
    """Cells stored as ``[k, i1..ik, k, ...]`` -> (offsets, connectivity)."""
    flat = np.asarray(flat).astype(np.int64)
    starts = np.empty(n_cells, dtype=np.int64)
    pos = 0
    for cell in range(n_cells):
        if pos >= len(flat):
            raise ValueError(f"cell list ends after {cell} of {n_cells} cells")
        if flat[pos] < 0:
            raise ValueError(f"negative cell size {flat[pos]}")
        starts[cell] = pos
        pos += 1 + int(flat[pos])
    if pos != len(flat):
        raise ValueError(f"cell sizes add up to {pos} values, not {len(flat)}")
    keep = np.ones(len(flat), dtype=bool)
    keep[starts] = False
    return np.concatenate([[0], np.cumsum(flat[starts])]), flat[keep]


def cells(offsets, connectivity):
    """Index arrays of cells given by offsets (from 0) into connectivity."""
    offsets = np.asarray(offsets).astype(np.int64)
    connectivity = np.asarray(connectivity).astype(np.int64)
    if len(offsets) and (offsets[0] != 0 or (np.diff(offsets) < 0).any() or offsets[-1] > len(connectivity)):
        raise ValueError("cell offsets are not increasing from 0 within the connectivity")
    return [connectivity[a:b] for a, b in zip(offsets[:-1], offsets[1:])]


def polygon_triangles(offsets, connectivity) -> np.ndarray:
    """Fan triangles of polygons (see :func:`cells`); fewer than 3 vertices are skipped."""
    sizes = np.diff(offsets)
    if len(sizes) and (sizes == 3).all() and offsets[0] == 0 and offsets[-1] <= len(connectivity):
        return np.asarray(connectivity[: offsets[-1]], dtype=np.int64).reshape(-1, 3)  # all triangles
    return fan_triangulate(cells(offsets, connectivity))


def strip_triangles(offsets, connectivity) -> np.ndarray:
    """Triangles of strips, every second one flipped to keep the winding, as VTK does."""
    tris = []
    for s in cells(offsets, connectivity):
        for i in range(len(s) - 2):
            tris.append((s[i], s[i + 1], s[i + 2]) if i % 2 == 0 else (s[i + 1], s[i], s[i + 2]))
    return np.array(tris, dtype=np.int64).reshape(-1, 3)
