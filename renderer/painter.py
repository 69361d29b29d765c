"""The painter's algorithm: hidden surfaces removed by drawing far triangles first.

The course's alternative to the z-buffer: sort the triangles by depth and paint them back
to front, each over what is already there. The depth of a triangle is taken at one point,
its **centroid** (the mean window depth of its three vertices, after clipping); the
farthest is drawn first and equal depths keep their draw order (a stable sort). One depth
per triangle cannot order triangles that interpenetrate or overlap cyclically, which is
where the algorithm visibly fails (``lab/scenes/painter-fails.toml``).
"""
from __future__ import annotations

import numpy as np


def painter_order(tri_window: np.ndarray) -> np.ndarray:
    """Indices of (K, 3, 3) window-space triangles, farthest centroid first (stable)."""
    centroid_depth = tri_window[:, :, 2].mean(axis=1)
    return np.argsort(-centroid_depth, kind="stable")
