"""Normals family: point normals of a smooth-sided shape (cylinder, cone) that are not unit,
not where they should be, or shared between the side and the caps (exit status 1).

Measured by :func:`lab.app.exercises.meshcheck.normal_findings`.
"""
from __future__ import annotations

from lab.app.exercises.diagnoses.codes import register

register("normals-not-unit", "normals",
         "({case}) {count} normals are not of length 1 (e.g. length {length:.4g} at point {example}): divide each "
         "by its length",
         "（{case}）長さが 1 でない法線が {count} 本あります（例: 点 {example} で長さ {length:.4g}）。それぞれ長さで"
         "割ってください")

register("side-faceted", "normals",
         "({case}) the side is faceted: its points carry the flat normal of one side face instead of the direction "
         "away from the axis at that point ({count} points), so Gouraud and Phong shading show the facets. Give side "
         "point k the normal {formula}",
         "（{case}）側面が多角柱のように角張って見えます。側面の点 {count} 個が、その点での軸から外向きの方向ではなく"
         "一つの側面の平らな法線を持っています。側面の点 k の法線は {formula} にしてください")

register("caps-share-side-points", "normals",
         "({case}) {count} rim points are shared by the side and a cap: one normal cannot serve both, so either the "
         "side looks faceted at the rim or the cap looks curved. Give each cap its own centre and ring of points with "
         "the normal (0, 0, ±1)",
         "（{case}）縁の点 {count} 個を側面とふたが共有しています。一つの法線で両方は表せないので、縁で側面が角張るか、"
         "ふたが曲がって見えます。ふたには専用の中心点と縁の点を作り、法線 (0, 0, ±1) を与えてください")

register("cap-normals-wrong", "normals",
         "({case}) {count} cap points do not have the cap's normal (0, 0, {sign}1), e.g. {normal} at {point}",
         "（{case}）ふたの点 {count} 個がふたの法線 (0, 0, {sign}1) を持っていません（例: 点 {point} で {normal}）")

register("normals-inward", "normals",
         "({case}) {count} point normals point into the shape: flip them (outward normals are what the lights see)",
         "（{case}）点の法線 {count} 本が形の内側を向いています。向きを反転してください（光源が照らすのは外向きの法線です）")

register("cone-normals-not-tilted", "normals",
         "({case}) the cone's side normals are horizontal, as on a cylinder ({count} points): on a cone they tilt up "
         "toward the apex, n = (h·cos θ, h·sin θ, r) / √(h² + r²)",
         "（{case}）円錐の側面の法線が円柱のように水平です（{count} 点）。円錐では頂点側へ傾き、"
         "n = (h·cos θ, h·sin θ, r) / √(h² + r²) です")

register("side-normals-wrong", "normals",
         "({case}) {count} side normals are not the surface's direction at their point, e.g. {normal} at {point} "
         "where {expected} is expected",
         "（{case}）側面の法線 {count} 本がその点での面の向きになっていません（例: 点 {point} で {normal}、正しくは "
         "{expected}）")
