"""Pictures of a submission: the student's mesh drawn by scanlab's renderer and by VTK,
against the reference solution drawn by VTK, through the parity bars used everywhere
(:func:`compare.metrics.failed_bars`).

A :class:`View` fixes the camera, light (VTK's headlight), material and shading; the scene
is built from :mod:`lab.scene` dataclasses, so both renderers get the same triangles and
normals. The reference frame of each (exercise, case) is drawn once per process.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from lab.mesh import Mesh
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject

COLOUR = (0.8, 0.8, 0.2)
"""The textbook's yellow (its shaded cube and Menger sponge), linear RGB."""


@dataclass(frozen=True)
class View:
    """How a mesh exercise is drawn: camera position (world units; looking at the origin,
    +y up, 30° vertical angle), shading ("flat", "gouraud", "phong"), image size in pixels."""

    position: tuple[float, float, float]
    shading: str = "flat"
    size: tuple[int, int] = (240, 240)
    view_up: tuple[float, float, float] = (0.0, 1.0, 0.0)


def scene_of(mesh: Mesh, view: View, material: Material | None = None) -> Scene:
    """One object lit by VTK's headlight, the camera of ``view``; the clipping range fitted
    to the mesh as VTK fits it."""
    material = material or Material(color=COLOUR, ambient=0.1, diffuse=0.8, specular=0.3, specular_power=20.0)
    obj = SceneObject(mesh=mesh, material=material, shading=view.shading, name="submission")
    camera = Camera(position=view.position, focal_point=(0.0, 0.0, 0.0), view_up=view.view_up, view_angle=30.0)
    return Scene(image=Image(size=view.size, background=(1.0, 1.0, 1.0)), camera=camera, lights=(Light(kind="headlight"),),
                 objects=(obj,), source="exercise")


def renderable(mesh: Mesh, reference: Mesh) -> bool:
    """Whether the student's mesh can be drawn safely: triangles, finite points, indices in
    range, not absurdly large or far (within 100 times the reference's size)."""
    if mesh.n_triangles == 0 or mesh.n_triangles > 4 * max(reference.n_triangles, 1000):
        return False
    if not np.isfinite(mesh.points).all() or mesh.triangles.min() < 0 or mesh.triangles.max() >= mesh.n_points:
        return False
    if mesh.point_normals is not None and not np.isfinite(mesh.point_normals).all():
        return False
    size = float(np.max(np.abs(reference.points)))
    return float(np.max(np.abs(mesh.points[mesh.triangles]))) <= 100.0 * size


_REFERENCE_FRAMES: dict = {}


def _reference_frame(key, scene: Scene):
    """VTK's frame of a reference scene, drawn once per process for each ``key``."""
    from compare.reference import render_reference

    if key not in _REFERENCE_FRAMES:
        _REFERENCE_FRAMES[key] = render_reference(scene)
    return _REFERENCE_FRAMES[key]


@dataclass
class Comparison:
    """The three frames and the verdict of the bars (student by scanlab vs reference by VTK)."""

    call: str
    ours_student: object
    vtk_student: object
    vtk_reference: object
    metrics: dict
    failed: list[str]

    def write(self, folder: Path, stem: str) -> list[Path]:
        """``stem-panel.png`` (yours by scanlab | reference by VTK | ΔE) and ``stem-vtk.png``
        (yours drawn by VTK); returns the paths."""
        from compare.images import PanelText, side_by_side_figure
        from compare.metrics import compare_frames, coverage_masks
        from lab.png import write_png

        folder.mkdir(parents=True, exist_ok=True)
        _, de = compare_frames(self.ours_student, self.vtk_reference)
        shared, mismatch = coverage_masks(self.ours_student, self.vtk_reference)
        panel, vtk = folder / f"{stem}-panel.png", folder / f"{stem}-vtk.png"
        side_by_side_figure(self.ours_student.rgb, self.vtk_reference.rgb, de, mismatch, self.metrics, panel,
                            PanelText(title=self.call, labels=("yours (scanlab)", "reference (VTK)")), shared=shared)
        write_png(vtk, self.vtk_student.rgb)
        return [panel, vtk]

    def figures(self) -> str:
        """The comparison's figures in one line (the same in both languages)."""
        return (f"mean ΔE2000 {self.metrics['delta_e_2000']['mean']:.3f}, ΔE > 1 on "
                f"{100 * self.metrics['pixels_over_1']:.2f} %, coverage mismatch "
                f"{100 * self.metrics['coverage_mismatch']:.3f} %")


def compare_scenes(call: str, student: Scene, reference: Scene, key) -> Comparison:
    """Draw the student's scene with scanlab and with VTK and the reference scene with VTK
    (cached by ``key``); measure scanlab's picture of the student's scene against VTK's
    reference through :func:`compare.metrics.failed_bars`."""
    from compare.metrics import compare_frames, failed_bars
    from compare.reference import render_reference
    from renderer import render

    ours = render(student)
    vtk_student = render_reference(student)
    vtk_reference = _reference_frame(key, reference)
    metrics, _ = compare_frames(ours, vtk_reference)
    return Comparison(call, ours, vtk_student, vtk_reference, metrics, failed_bars(metrics))


def compare_meshes(call: str, student: Mesh, reference: Mesh, view: View, key) -> Comparison:
    """:func:`compare_scenes` of two meshes in the scene of ``view``."""
    return compare_scenes(call, scene_of(student, view), scene_of(reference, view), (key, view))
