"""A mesh file given where a scene is expected: ``scanlab info suzanne.obj``.

The mesh is shown as a built-in shape is (:func:`lab.loading.framed_scene`): a grey-blue
material, flat shading, a camera that frames it as ``vtkRenderer::ResetCamera`` would and
one headlight. The file is read by :func:`lab.meshfiles.read_mesh` (its own one-line
errors become :class:`lab.loading.SceneError`); it is the scene's only input file.
"""
from __future__ import annotations

from pathlib import Path

from lab.loading import SceneError, framed_scene
from lab.scene import Scene
from lab.values import IS_A_FOLDER, file_problem


def mesh_file_scene(path) -> Scene:
    """The scene of one mesh file, framed with a headlight; SceneError if it cannot be read.

    >>> from lab.presets import SCENES_DIR
    >>> mesh_file_scene(SCENES_DIR / "models" / "torus.ply").objects[0].name
    'torus'
    """
    from lab.meshfiles import MeshFileError, read_mesh

    path = Path(path)
    if file_problem(path) == IS_A_FOLDER:
        raise SceneError(f"{path}: is a folder, not a scene file or mesh file")
    try:
        mesh = read_mesh(path)
    except MeshFileError as exc:
        raise SceneError(str(exc)) from None
    return framed_scene(mesh, path.stem, str(path), inputs=(str(path),))
