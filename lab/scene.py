"""The scene model: dataclasses that both renderers read.

Every value here has already been validated by :mod:`lab.loading`; the renderers trust
it. Conventions:

- World space is right-handed; vectors are rows (``P' = P @ M``, as in the course).
- Colours are linear 0..1 RGB floats, already quantised to k/255 (what VTK keeps of a
  colour), so both renderers start from identical numbers.
- Angles are in degrees.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from functools import cached_property

import numpy as np

from lab.mesh import Mesh
from lab.texture import Texture

SHADINGS = ("flat", "gouraud", "phong")
MODELS = ("vtk", "opengl", "classic")
LIGHT_KINDS = ("scene", "camera", "headlight", "eye")
INTERPOLATIONS = ("perspective", "screen")
HIDDEN_SURFACES = ("zbuffer", "painter", "none")
TRANSPARENCIES = ("oit", "depth_peeling", "sorted")
MATERIAL_RANGES = {"ambient": (0.0, 1.0), "diffuse": (0.0, 1.0), "specular": (0.0, 1.0),
                   "specular_power": (0.0, 1000.0), "shininess": (0.0, 128.0), "opacity": (0.0, 1.0)}
"""A material's numbers and their closed ranges (the loader checks them, the live lab's fields too)."""
LIGHT_RANGES = {"intensity": (0.0, 1000.0), "exponent": (0.0, 128.0)}
"""A light's numbers with closed ranges; ``cone_angle`` is in (0, 180]."""

Vec3 = tuple[float, float, float]


@dataclass(frozen=True)
class Image:
    """Output image: ``size`` = (width, height) in pixels, ``background`` linear 0..1 RGB."""

    size: tuple[int, int] = (512, 384)
    background: Vec3 = (1.0, 1.0, 1.0)


@dataclass(frozen=True)
class Camera:
    """A VTK-style camera in world space.

    ``view_angle`` is the vertical field of view in degrees; ``clipping_range`` is
    (near, far) distances along the view direction, or None to fit it to the scene bounds
    as ``vtkRenderer::ResetCameraClippingRange`` does; ``parallel_scale`` is half the view
    height in world units (parallel projection only).
    """

    position: Vec3 = (0.0, 0.0, 1.0)
    focal_point: Vec3 = (0.0, 0.0, 0.0)
    view_up: Vec3 = (0.0, 1.0, 0.0)
    view_angle: float = 30.0
    clipping_range: tuple[float, float] | None = None
    parallel: bool = False
    parallel_scale: float = 1.0


@dataclass(frozen=True)
class Light:
    """A VTK light.

    ``kind``: "scene" (position/focal point in world space), "camera" (in the camera's
    frame: (0, 0, 1) is the camera, (0, 0, 0) the focal point, lengths in units of the
    camera distance), "headlight" (at the camera, aimed at the focal point; position and
    focal point ignored) or "eye" (position and focal point in eye = view coordinates,
    as a light set with glLightfv right after glLoadIdentity). ``color`` linear 0..1 RGB
    times ``intensity`` is the light's colour. ``positional`` makes a point light, a spot
    light when ``cone_angle`` < 90 (degrees, half-angle) with falloff ``cos^exponent``;
    ``attenuation`` = (constant, linear, quadratic) applies to positional lights only.
    A scene file's four-value ``position = [x, y, z, w]`` (OpenGL's) means a point light
    at (x, y, z)/w when w ≠ 0 and a directional light from (x, y, z) toward the origin
    when w = 0, i.e. ``positional = (w != 0)`` with the focal point at the origin.

    The OpenGL model alone also reads ``ambient_color`` (default black),
    ``diffuse_color`` and ``specular_color`` (default ``color × intensity``); the VTK
    model ignores them, as VTK does.
    """

    kind: str = "scene"
    position: Vec3 = (0.0, 0.0, 1.0)
    focal_point: Vec3 = (0.0, 0.0, 0.0)
    color: Vec3 = (1.0, 1.0, 1.0)
    intensity: float = 1.0
    positional: bool = False
    cone_angle: float = 90.0
    exponent: float = 1.0
    attenuation: Vec3 = (1.0, 0.0, 0.0)
    on: bool = True
    ambient_color: Vec3 = (0.0, 0.0, 0.0)
    diffuse_color: Vec3 | None = None
    specular_color: Vec3 | None = None

    @property
    def intensity_rgb(self) -> np.ndarray:
        """``color`` × ``intensity``, linear RGB: the light's intensity per channel (what VTK
        and the classic model use; ``color`` alone is the scene file's colour)."""
        return np.asarray(self.color) * self.intensity

    @property
    def gl_diffuse(self) -> np.ndarray:
        return self.intensity_rgb if self.diffuse_color is None else np.asarray(self.diffuse_color)

    @property
    def gl_specular(self) -> np.ndarray:
        return self.intensity_rgb if self.specular_color is None else np.asarray(self.specular_color)


@dataclass(frozen=True)
class Material:
    """VTK's surface property: coefficients 0..1, colours linear 0..1 RGB.

    ``specular_color`` None means the object colour (VTK's ``color=`` sets all three).
    ``lighting`` False draws ``ambient·color + diffuse·color`` unlit, whatever the
    ``model`` (see :attr:`reflection_model`).

    ``model`` chooses the reflection model (see ``renderer/reflection``): "vtk" (VTK's
    own), "opengl" (fixed-function OpenGL: material ``ambient_color`` and
    ``diffuse_color``, default ``color``; ``specular_color``, default black;
    ``shininess`` 0..128, Blinn's half vector) or "classic" (the course's
    ``Ka·O·A + Σ Kd·O·I·(L·N) + Ks·I·(R·V)^n`` with ``ambient``, ``diffuse``,
    ``specular``, ``specular_power``).
    """

    color: Vec3 = (1.0, 1.0, 1.0)
    ambient: float = 0.0
    diffuse: float = 1.0
    specular: float = 0.0
    specular_power: float = 1.0
    specular_color: Vec3 | None = None
    opacity: float = 1.0
    lighting: bool = True
    model: str = "vtk"
    ambient_color: Vec3 | None = None
    diffuse_color: Vec3 | None = None
    shininess: float = 0.0

    @property
    def effective_specular_color(self) -> Vec3:
        return self.color if self.specular_color is None else self.specular_color

    @property
    def reflection_model(self) -> str:
        """The model that colours the object: ``model``, or "vtk" when ``lighting`` is off,
        since an unlit object has no reflection model and draws VTK's unlit colour."""
        return self.model if self.lighting else "vtk"

    @property
    def gl_ambient(self) -> np.ndarray:
        return np.asarray(self.color if self.ambient_color is None else self.ambient_color)

    @property
    def gl_diffuse(self) -> np.ndarray:
        return np.asarray(self.color if self.diffuse_color is None else self.diffuse_color)

    @property
    def gl_specular(self) -> np.ndarray:
        return np.zeros(3) if self.specular_color is None else np.asarray(self.specular_color)


@dataclass(frozen=True)
class RenderSettings:
    """Scene-wide rendering choices (``[render]`` in a scene file).

    interpolation : "perspective" (GPUs, VTK) or "screen" (linear along edges and spans,
        as the course's scanline slides) for colours, normals and positions.
    global_ambient : OpenGL's light-model ambient, linear RGB (GL default 0.2 grey).
    local_viewer : OpenGL's GL_LIGHT_MODEL_LOCAL_VIEWER (default: infinite viewer).
    ambient : the classic model's ambient light colour A, linear RGB.
    hidden_surface : "zbuffer" (LEQUAL depth test), "painter" (back to front by centroid
        depth, no depth test) or "none" (draw order, no depth test).
    cull_backfaces : drop triangles that are clockwise on screen (VTK culls none by default).
    separate_specular : OpenGL's ``GL_SEPARATE_SPECULAR_COLOR`` for opengl-model objects: the
        specular colour is kept apart and added after the texture modulates the rest
        (default: one colour, ``GL_SINGLE_COLOR``).
    transparency : how objects with opacity < 1 are composited (:mod:`renderer.translucency`):
        "oit" (VTK's default weighted-average order-independent blend), "depth_peeling"
        (exact, front to back) or "sorted" (back to front, "over" per fragment).
    """

    interpolation: str = "perspective"
    global_ambient: Vec3 = (0.2, 0.2, 0.2)
    local_viewer: bool = False
    ambient: Vec3 = (1.0, 1.0, 1.0)
    hidden_surface: str = "zbuffer"
    cull_backfaces: bool = False
    transparency: str = "oit"
    separate_specular: bool = False


@dataclass(frozen=True, eq=False)
class SceneObject:
    """One mesh with its material, shading and model transform.

    ``model_to_world`` is a 4×4 row-vector matrix (``P_world = [P, 1] @ M``) built from
    the scene's scale, rotate and translate as ``S·Rx·Ry·Rz·T``. ``texture`` (with the
    mesh's ``tcoords``) multiplies the lit colour, as VTK does.
    """

    mesh: Mesh
    material: Material = field(default_factory=Material)
    shading: str = "flat"
    model_to_world: np.ndarray = field(default_factory=lambda: np.eye(4))
    name: str = "object"
    texture: Texture | None = None

    def world_mesh(self) -> Mesh:
        """The mesh carried to world space: points by ``model_to_world``, normals by its
        inverse-transpose (renormalised), texture coordinates unchanged."""
        m = self.model_to_world
        points = self.mesh.points @ m[:3, :3] + m[3, :3]
        normals = None
        if self.mesh.point_normals is not None:
            normals = self.mesh.point_normals @ np.linalg.inv(m[:3, :3]).T
            normals /= np.maximum(np.linalg.norm(normals, axis=1, keepdims=True), 1e-300)
        return Mesh(points, self.mesh.triangles, normals, self.mesh.tcoords)

    def world_bounds(self) -> np.ndarray:
        """World bounds as VTK's ``vtkProp3D::GetBounds`` gives them.

        The eight corners of the mesh's model-space bounding box are transformed and
        their extent taken, so a rotated object's bounds are larger than its points'.
        Order (xmin, xmax, ymin, ymax, zmin, zmax). Worked out once per object (an object,
        like its mesh, is not changed in place; every frame without a clipping range asks
        again, 20 µs each time); each call returns a fresh copy.
        """
        return self._world_bounds.copy()

    @cached_property
    def _world_bounds(self) -> np.ndarray:
        b = self.mesh.bounds()
        corners = np.array([[b[i], b[2 + j], b[4 + k], 1.0] for k in (0, 1) for j in (0, 1) for i in (0, 1)])
        w = corners @ self.model_to_world
        w = w[:, :3] / w[:, 3:]
        lo, hi = w.min(axis=0), w.max(axis=0)
        return np.array([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]])


@dataclass(frozen=True, eq=False)
class Scene:
    """Everything needed to draw one image. ``source`` names where it came from."""

    image: Image
    camera: Camera
    lights: tuple[Light, ...]
    objects: tuple[SceneObject, ...]
    source: str = "<scene>"
    render: RenderSettings = field(default_factory=RenderSettings)
    inputs: tuple[str, ...] = ()
    """The files the scene was read from (scene file, meshes, textures): never to be overwritten."""

    def world_bounds(self) -> np.ndarray:
        """Union of the objects' :meth:`SceneObject.world_bounds` (VTK's visible-prop bounds)."""
        if not self.objects:
            return np.array([-1.0, 1.0, -1.0, 1.0, -1.0, 1.0])
        b = np.array([o.world_bounds() for o in self.objects])
        return np.array([b[:, 0].min(), b[:, 1].max(), b[:, 2].min(), b[:, 3].max(), b[:, 4].min(), b[:, 5].max()])

    def world_mesh(self) -> Mesh:
        """All objects in world space as one mesh, in draw order (normals or tcoords only if all have them)."""
        meshes = [o.world_mesh() for o in self.objects]
        offsets = np.cumsum([0] + [m.n_points for m in meshes[:-1]])
        normals = tcoords = None
        if all(m.point_normals is not None for m in meshes):
            normals = np.concatenate([m.point_normals for m in meshes])
        if all(m.tcoords is not None for m in meshes):
            tcoords = np.concatenate([m.tcoords for m in meshes])
        return Mesh(np.concatenate([m.points for m in meshes]),
                    np.concatenate([m.triangles + off for m, off in zip(meshes, offsets)]), normals, tcoords)

    def with_overrides(self, shading: str | None = None, size: tuple[int, int] | None = None,
                       model: str | None = None) -> "Scene":
        """A copy with every object's shading and/or model, and/or the image size, replaced."""
        scene = self
        if shading is not None:
            objs = tuple(replace(o, shading=shading) for o in scene.objects)
            scene = replace(scene, objects=objs)
        if model is not None:
            objs = tuple(replace(o, material=replace(o.material, model=model)) for o in scene.objects)
            scene = replace(scene, objects=objs)
        if size is not None:
            scene = replace(scene, image=replace(scene.image, size=tuple(size)))
        return scene


def headlight() -> Light:
    """The single headlight VTK creates when a scene has no lights."""
    return Light(kind="headlight")
