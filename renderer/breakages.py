""""Break it": each rule the pipeline keeps, broken on purpose, one small named entry each.

A lesson that teaches a rule shows it broken and measured against VTK (which keeps the
rule): our renderer draws the *broken* scene and options, VTK draws the intact scene,
and the difference must fail the parity bars. The live lab (issue 16) offers the same
entries as toggles. Every breakage lives here, found by name in :data:`BREAKAGES`;
nothing else branches on the names.

A breakage is a function ``(scene, options) -> (scene, options)``: ``scene`` a
:class:`lab.scene.Scene`, ``options`` a :class:`renderer.pipeline.RenderOptions`. It
returns new objects (both are frozen dataclasses) and never touches its inputs.

Examples
--------
>>> from lab import load_scene
>>> from renderer.pipeline import RenderOptions
>>> scene, options = apply_breakage("fill-rule", load_scene("fill-rule"), RenderOptions())
>>> options.fill_rule
'bottom-right'
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Callable

from lab.mesh import Mesh


@dataclass(frozen=True)
class Breakage:
    """One rule broken on purpose.

    name : the key in :data:`BREAKAGES` (``--break NAME``).
    label : short title, English and Japanese (``{"en": ..., "ja": ...}``).
    rule : the rule it breaks, one sentence in each language.
    apply : ``(scene, options) -> (scene, options)``, the broken pair for our renderer.
    """

    name: str
    label: dict
    rule: dict
    apply: Callable


BREAKAGES: dict[str, Breakage] = {}
"""Every breakage by name, in the order the lessons meet them."""


def breakage(name: str, label: tuple[str, str], rule: tuple[str, str]):
    """Register the decorated ``(scene, options) -> (scene, options)`` function as ``name``."""
    def register(fn):
        BREAKAGES[name] = Breakage(name, {"en": label[0], "ja": label[1]}, {"en": rule[0], "ja": rule[1]}, fn)
        return fn
    return register


def apply_breakage(name: str, scene, options):
    """The scene and options of breakage ``name``; KeyError names the known ones."""
    if name not in BREAKAGES:
        raise KeyError(f"unknown breakage {name!r}; known: {', '.join(BREAKAGES)}")
    return BREAKAGES[name].apply(scene, options)


def _objects(scene, change) -> object:
    """``scene`` with ``change(obj)`` in place of every object."""
    return replace(scene, objects=tuple(change(o) for o in scene.objects))


@breakage("face-normals",
          ("face normals on a smooth surface", "滑らかな面に面の法線"),
          ("A smooth surface is shaded with point normals, so neighbouring triangles agree at shared points.",
           "滑らかな面は頂点の法線で陰影をつけ、隣り合う三角形が共有する頂点で明るさをそろえる。"))
def face_normals(scene, options):
    """Drop every object's point normals: each triangle is lit with its plane normal."""
    return _objects(scene, lambda o: replace(o, mesh=Mesh(o.mesh.points, o.mesh.triangles, None, o.mesh.tcoords))), \
        options


@breakage("transposed-matrix",
          ("the model matrix transposed", "モデル行列を転置"),
          ("Points are row vectors multiplied on the right, P' = P·M; VTK's column-vector matrix is the transpose.",
           "点は行ベクトルで右から行列を掛ける (P' = P·M)。VTK の列ベクトル用の行列はその転置である。"))
def transposed_matrix(scene, options):
    """Use every object's model matrix transposed (the column convention read as rows)."""
    return _objects(scene, lambda o: replace(o, model_to_world=o.model_to_world.T.copy())), options


@breakage("fill-rule",
          ("the fill rule taken as bottom-right", "塗りつぶし規則を右下に"),
          ("A pixel centre on an edge belongs to the triangle only if the edge is a top or a left edge.",
           "辺上の画素中心は、その辺が上辺か左辺のときだけ三角形に属する。"))
def fill_rule(scene, options):
    """Ties on edges go to bottom and right edges instead of top and left ones."""
    return scene, replace(options, fill_rule="bottom-right")


@breakage("painter",
          ("the painter's algorithm instead of the z-buffer", "Zバッファの代わりにペインタアルゴリズム"),
          ("Hidden surfaces are removed pixel by pixel with a depth buffer, not by sorting whole triangles.",
           "隠面消去は画素ごとに奥行きバッファで行い、三角形を丸ごと並べ替えるのではない。"))
def painter(scene, options):
    """Draw back to front by centroid depth with no depth test."""
    return replace(scene, render=replace(scene.render, hidden_surface="painter")), options


@breakage("light-frame",
          ("camera lights taken as scene lights", "カメラ光源をシーン光源として扱う"),
          ("A camera light is given in the camera's frame and moves with it; a scene light stays in the world.",
           "カメラ光源はカメラの座標系で与えられカメラと一緒に動く。シーン光源はワールドに固定される。"))
def light_frame(scene, options):
    """Read every camera (and eye) light's position and focal point as world coordinates."""
    lights = tuple(replace(li, kind="scene") if li.kind in ("camera", "eye") else li for li in scene.lights)
    return replace(scene, lights=lights), options


@breakage("screen-interpolation",
          ("screen-linear interpolation", "スクリーン上での線形補間"),
          ("Values across a perspective triangle are interpolated linearly in 3D, that is perspective-correctly.",
           "透視投影された三角形の内部の値は 3 次元で線形に、つまり透視補正して補間する。"))
def screen_interpolation(scene, options):
    """Colours, normals and positions interpolated linearly in screen space."""
    return scene, replace(options, interpolation="screen")
