"""The course's homogeneous 4×4 matrices: translation, scaling, rotations, the model matrix.

Convention (stated once, here): points are **row vectors** and matrices multiply on the
right, ``[x', y', z', 1] = [x, y, z, 1] @ M``, as in the course (``P' = P·A``). A chain
``P·S·Rx·Ry·Rz·T`` applies S first. VTK writes the same transforms as column vectors,
``p' = A^T p``: every matrix here is the transpose of VTK's (see
``tests/lab/test_matrices.py``). Angles are in degrees; rotations are
counter-clockwise looking down the axis toward the origin (right-handed).

On the ground floor: the scene loader builds each object's ``model_to_world`` with
:func:`model_matrix`; the renderer applies it (:mod:`renderer.transform`).
"""
from __future__ import annotations

import math

import numpy as np


def translation(tx: float, ty: float, tz: float) -> np.ndarray:
    """T: the translation sits in the bottom row (row-vector convention)."""
    m = np.eye(4)
    m[3, :3] = (tx, ty, tz)
    return m


def scaling(sx: float, sy: float, sz: float) -> np.ndarray:
    """S = diag(sx, sy, sz, 1)."""
    return np.diag([sx, sy, sz, 1.0])


def rotation_x(degrees: float) -> np.ndarray:
    """Rx: y' = y·cos − z·sin, z' = y·sin + z·cos."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return np.array([[1, 0, 0, 0], [0, c, s, 0], [0, -s, c, 0], [0, 0, 0, 1.0]])


def rotation_y(degrees: float) -> np.ndarray:
    """Ry: z' = z·cos − x·sin, x' = z·sin + x·cos."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return np.array([[c, 0, -s, 0], [0, 1, 0, 0], [s, 0, c, 0], [0, 0, 0, 1.0]])


def rotation_z(degrees: float) -> np.ndarray:
    """Rz: x' = x·cos − y·sin, y' = x·sin + y·cos."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return np.array([[c, s, 0, 0], [-s, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1.0]])


def model_matrix(scale=(1.0, 1.0, 1.0), rotate=(0.0, 0.0, 0.0), translate=(0.0, 0.0, 0.0)) -> np.ndarray:
    """model_to_world = S·Rx·Ry·Rz·T (row vectors: scale first, translate last).

    >>> model_matrix(translate=(1, 2, 3))[3, :3].tolist()
    [1.0, 2.0, 3.0]
    """
    return scaling(*scale) @ rotation_x(rotate[0]) @ rotation_y(rotate[1]) @ rotation_z(rotate[2]) @ translation(*translate)
