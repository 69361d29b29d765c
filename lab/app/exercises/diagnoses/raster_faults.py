"""Raster family: a triangle's pixel coverage that is not the renderer's (the one VTK draws)
(exit status 1).

Every pixel of every test mesh is classified (:mod:`lab.app.exercises.catalogue.covered_pixels`):
correct, missing (the reference draws it, you do not), duplicated (two triangles of one
mesh draw it), unexpected (you draw it, the reference does not). ``coverage-differs``
gives the counts and the first pixel of each class; the other codes name the mistake
when the mismatches have its signature.
"""
from __future__ import annotations

from lab.app.exercises.diagnoses.codes import register

_CLASS_EN = {"missing": "missing", "duplicated": "duplicated", "unexpected": "unexpected"}
_CLASS_JA = {"missing": "欠け", "duplicated": "重複", "unexpected": "余分"}


def _first_en(d: dict) -> str:
    lines = []
    for cls, first in d.get("first", {}).items():
        lines.append(f"{_CLASS_EN[cls]} {d['counts'][cls]}: first pixel ({first['x']}, {first['y']}) of mesh "
                     f"'{first['mesh']}', triangle{'s' if len(first['triangles']) > 1 else ''} "
                     f"{' and '.join(map(str, first['triangles']))} {first['corners']}")
    return "; ".join(lines)


def _first_ja(d: dict) -> str:
    lines = []
    for cls, first in d.get("first", {}).items():
        lines.append(f"{_CLASS_JA[cls]} {d['counts'][cls]} 画素: 最初はメッシュ「{first['mesh_ja']}」の三角形 "
                     f"{' と '.join(map(str, first['triangles']))} {first['corners']} の画素 ({first['x']}, {first['y']})")
    return "。".join(lines)


register("coverage-differs", "raster",
         lambda d: f"{d['counts']['correct']} pixels correct over {d['triangles']} triangles in {d['meshes']} meshes; "
                   + _first_en(d),
         lambda d: f"{d['meshes']} 個のメッシュ・{d['triangles']} 個の三角形で正しい画素 {d['counts']['correct']}。"
                   + _first_ja(d))

register("ties-drawn-twice", "raster",
         "pixel centres exactly on an edge are drawn by both triangles that share the edge ({count} pixels drawn "
         "twice): a centre on an edge belongs to the triangle only when the edge is a left edge or a bottom edge "
         "(window y up) — the top-left rule",
         "辺のちょうど上にある画素中心を、その辺を共有する両方の三角形が塗っています（二重に塗られた画素 {count}）。"
         "辺上の中心は、その辺が左の辺か下の辺（ウィンドウ座標は y が上向き）のときだけその三角形に属します — "
         "トップレフト規則")

register("ties-missed", "raster",
         "pixel centres exactly on an edge are drawn by neither triangle that shares it ({count} pixels missing): a "
         "centre on a left or bottom edge belongs to the triangle (the top-left rule)",
         "辺のちょうど上にある画素中心を、辺を共有するどちらの三角形も塗っていません（欠けた画素 {count}）。左の辺か"
         "下の辺の上にある中心はその三角形に属します（トップレフト規則）")

register("tie-rule-mirrored", "raster",
         "ties go to the right and top edges instead of the left and bottom ones: inside a mesh nothing is lost or "
         "doubled, but along the outlines {missing} pixels are missing and {unexpected} are drawn that VTK does not "
         "draw (window y is up: a bottom edge has the larger image row)",
         "辺上の画素中心を左・下ではなく右・上の辺に与えています。メッシュの内部では欠けも重複もありませんが、外周で "
         "{missing} 画素が欠け、VTK が塗らない {unexpected} 画素を塗っています（ウィンドウ座標は y が上向き）")

register("rows-flipped", "raster",
         "the mask is upside down: row 0 of mask is the bottom row (window y up), mask[y, x] is the pixel whose "
         "centre is (x + 0.5, y + 0.5)",
         "マスクが上下逆です。mask の 0 行目は一番下の行（ウィンドウ座標は y が上向き）で、mask[y, x] は中心が "
         "(x + 0.5, y + 0.5) の画素です")

register("corners-not-centres", "raster",
         "pixels are tested at their corner (x, y) instead of their centre (x + 0.5, y + 0.5): the coverage is "
         "shifted by half a pixel",
         "画素を中心 (x + 0.5, y + 0.5) ではなく角 (x, y) で判定しています。塗る範囲が半画素ずれます")

register("clockwise-missed", "raster",
         "{count} clockwise triangles drew nothing: a triangle given clockwise covers the same pixels (orient it "
         "counter-clockwise first, or accept the edge functions of either sign)",
         "時計回りに与えた三角形 {count} 個が何も塗っていません。時計回りでも同じ画素を覆います（先に反時計回りに並べ替えるか、"
         "辺関数の符号をどちらでも受け付けてください）")

register("no-subpixel-snap", "raster",
         "the corners were not snapped to the 1/256-pixel grid first: {count} pixels differ in the meshes whose "
         "corners lie off the grid (snap x to round((x − 0.5)·256)/256 + 0.5, as the window stage does)",
         "頂点を先に 1/256 画素の格子に丸めていません。格子外の頂点をもつメッシュで {count} 画素が違います"
         "（ウィンドウ変換と同じく x を round((x − 0.5)·256)/256 + 0.5 に丸めてください）")
