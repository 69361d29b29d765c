"""The raster exercise's picture: pixel classes of the test meshes, with the triangles drawn over.

Up to four meshes side by side (those with the most wrong pixels, else the first four), each
pixel coloured by class — correct (grey), missing (red), duplicated (orange), unexpected
(blue) — and every triangle's edges on top, in window coordinates (y up, pixel (x, y)
spanning [x, x + 1] × [y, y + 1]). Written with matplotlib's object API, atomically.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np

from lab.app.exercises.rastercases import CLASSES

COLOURS = {"background": (1.0, 1.0, 1.0), "correct": (0.78, 0.80, 0.78), "missing": (0.86, 0.12, 0.12),
           "duplicated": (1.0, 0.60, 0.0), "unexpected": (0.15, 0.35, 0.95)}
SHOWN = 4


class RasterPanel:
    """Per-mesh reference and student masks (K, H, W) and their pixel classes."""

    def __init__(self, meshes, references, students, classes):
        self.meshes, self.references, self.students, self.classes = meshes, references, students, classes

    def chosen(self) -> list[int]:
        wrong = [sum(int(c[k].sum()) for k in CLASSES[1:]) for c in self.classes]
        if not any(wrong):
            return list(range(min(SHOWN, len(self.meshes))))
        return sorted(sorted((i for i in range(len(wrong)) if wrong[i]), key=lambda i: -wrong[i])[:SHOWN])

    def image(self, i: int) -> np.ndarray:
        """(H, W, 3) float colours of mesh ``i``'s pixel classes, window rows (y up)."""
        c = self.classes[i]
        rgb = np.empty(c["correct"].shape + (3,))
        rgb[:] = COLOURS["background"]
        for cls in CLASSES:
            rgb[c[cls]] = COLOURS[cls]
        return rgb

    def write(self, folder: Path, stem: str) -> list[Path]:
        from matplotlib.figure import Figure
        from matplotlib.patches import Patch

        from lab.atomic import atomic_file

        chosen = self.chosen()
        fig = Figure(figsize=(4.2 * len(chosen), 4.6), dpi=100)
        for slot, i in enumerate(chosen):
            mesh, c = self.meshes[i], self.classes[i]
            ax = fig.add_subplot(1, len(chosen), slot + 1)
            ax.imshow(self.image(i), origin="lower", interpolation="nearest",
                      extent=(0, mesh.width, 0, mesh.height))
            for tri in mesh.triangles:
                closed = np.vstack([tri, tri[:1]])
                ax.plot(closed[:, 0], closed[:, 1], color="black", linewidth=0.6)
            ax.set_xlim(0, mesh.width)
            ax.set_ylim(0, mesh.height)
            ax.set_aspect("equal")
            ax.set_xticks(range(0, mesh.width + 1, 4))
            ax.set_yticks(range(0, mesh.height + 1, 4))
            ax.tick_params(labelsize=7)
            counts = ", ".join(f"{cls} {int(c[cls].sum())}" for cls in CLASSES if c[cls].any())
            ax.set_title(f"{mesh.name}\n{counts or 'nothing drawn'}", fontsize=9)
        fig.legend(handles=[Patch(color=COLOURS[cls], label=cls) for cls in CLASSES], loc="lower center",
                   ncols=4, frameon=False, fontsize=9)
        fig.subplots_adjust(left=0.03, right=0.99, top=0.86, bottom=0.14, wspace=0.15)
        folder.mkdir(parents=True, exist_ok=True)
        path = Path(folder) / f"{stem}-panel.png"
        with atomic_file(path) as f:
            fig.savefig(f, format="png", dpi=100)
        return [path]
