"""Stage 1, model → world (and on to view): points and normals through 4×4 matrices.

Points are row vectors, ``[x', y', z', 1] = [x, y, z, 1] @ M`` (the convention of
:mod:`lab.matrices`, where the matrices are built).
"""
from __future__ import annotations

import numpy as np


def to_homogeneous(points: np.ndarray) -> np.ndarray:
    """(N, 3) → (N, 4) with w = 1."""
    return np.concatenate([points, np.ones((len(points), 1))], axis=1)


def transform_points(points: np.ndarray, matrix: np.ndarray) -> np.ndarray:
    """Apply a row-vector 4×4 matrix to (N, 3) points; returns (N, 4) homogeneous rows."""
    return to_homogeneous(points) @ matrix


def normal_matrix(matrix: np.ndarray) -> np.ndarray:
    """The 3×3 that carries normals under ``matrix`` (row vectors): inverse-transpose of its 3×3."""
    return np.linalg.inv(matrix[:3, :3]).T
