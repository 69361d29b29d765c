"""scanlab's lab: the scene model, scene files, built-in shapes, mesh files and the CLI."""
from lab.frame import Frame
from lab.loading import SceneError, load_scene
from lab.scene import Camera, Image, Light, Material, Scene, SceneObject

__all__ = ["Camera", "Frame", "Image", "Light", "Material", "Scene", "SceneError", "SceneObject", "load_scene"]
