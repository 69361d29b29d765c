"""Mesh family: the surface is not the right one — its values, its closure, its orientation,
its size, its area and volume, its picture (exit status 1).

Details: ``case`` names the case (e.g. ``level 2``); the other keys are the figures each
message quotes. Measured by :mod:`lab.app.exercises.meshcheck` and :mod:`lab.app.exercises.views`.
"""
from __future__ import annotations

from lab.app.exercises.diagnoses.codes import register

register("no-triangles", "mesh",
         "({case}) the mesh has no triangles",
         "（{case}）三角形が一つもありません")

register("nonfinite-values", "mesh",
         "({case}) {count} {what} values are NaN or infinite: look for a division by zero",
         "（{case}）{what} に NaN または無限大の値が {count} 個あります。ゼロ除算を探してください")

register("index-out-of-range", "mesh",
         "({case}) {count} triangle corners name points that do not exist (e.g. index {example}; "
         "there are {n_points} points, indices 0 to {last})",
         "（{case}）三角形の頂点番号 {count} 個が存在しない点を指しています（例: {example}。点は {n_points} 個で、"
         "番号は 0〜{last}）")

register("degenerate-triangles", "mesh",
         "({case}) {count} triangles have no area (a repeated corner or three corners on a line), e.g. triangle "
         "{example}",
         "（{case}）面積のない三角形が {count} 個あります（同じ頂点の重複か、一直線上の 3 点）。例: 三角形 {example}")

register("too-many-triangles", "mesh",
         "({case}) {count:,} triangles, more than {limit:,}: the surface needs far fewer",
         "（{case}）三角形が {count:,} 個あり、上限 {limit:,} を超えています。この面にはずっと少なくて足ります")

register("wrong-scale", "mesh",
         "({case}) the shape is {size} across but should be {expected} across (scaled by {factor:.4g}): check the "
         "size of the first cube or sphere and the factor applied at each step",
         "（{case}）形の大きさが {size} ですが、正しくは {expected} です（{factor:.4g} 倍）。最初の立方体・球の大きさと、"
         "各段で掛ける倍率を確かめてください")

register("not-centred", "mesh",
         "({case}) the shape is centred at {centre} instead of {expected}: shift it so that its middle is the origin",
         "（{case}）形の中心が {expected} ではなく {centre} にあります。原点が中心になるよう平行移動してください")

register("not-closed", "mesh",
         "({case}) the surface has holes: {count} edges belong to one triangle only (e.g. the edge from {a} to {b})",
         "（{case}）面に穴があります。三角形 1 枚にしか属さない辺が {count} 本あります（例: {a} から {b} への辺）")

register("cracks", "mesh",
         "({case}) points not merged, and not at exactly the same place: {count} edges meet only after moving points "
         "by up to {gap:.2g}, so the renderer can show cracks. Compute each shared point once and reuse its index",
         "（{case}）点が共有されておらず、位置もわずかにずれています。点を最大 {gap:.2g} 動かしてようやく閉じる辺が "
         "{count} 本あり、描画にひびが出ます。共有する点は一度だけ計算し、その番号を使い回してください")

register("points-not-merged", "mesh",
         "({case}) points not merged: {points} points where {expected} suffice; triangles that meet must share the "
         "index of their common points (the surface is closed by its indices, not only by its positions)",
         "（{case}）点が共有されていません。{expected} 個で足りるところに {points} 個の点があります。接する三角形は"
         "共通の点の番号を共有してください（位置だけでなく番号で閉じた面にします）")

register("faces-inward", "mesh",
         "{count} of {total} triangles ({case}) point inward: seen from outside they are clockwise. List their corners "
         "counter-clockwise seen from outside, so that (v1 − v0) × (v2 − v0) points out",
         "（{case}）{total} 個の三角形のうち {count} 個が内向きです（外から見て時計回り）。外から見て反時計回りに頂点を"
         "並べ、(v1 − v0) × (v2 − v0) が外を向くようにしてください")

register("internal-faces-kept", "mesh",
         "({case}) internal faces kept: {count} triangles lie inside the solid, where two cubes touch, and {edges} "
         "edges are used by four triangles or more. Remove each face shared by two cubes (both copies)",
         "（{case}）内部の面が残っています。立方体どうしが接する所の三角形 {count} 個が立体の内側にあり、4 枚以上の三角形が"
         "使う辺が {edges} 本あります。二つの立方体が共有する面は両方とも取り除いてください")

register("stray-faces", "mesh",
         "({case}) {count} triangles lie where the solid has no surface (outside it on both sides)",
         "（{case}）立体の表面でない所（両側とも立体の外）に三角形が {count} 個あります")

def _subcubes_en(d: dict) -> str:
    if "misplaced" in d:
        said = (f"the right number of cubes ({d['cells']}) but not the right ones: {d['misplaced']} triangles lie "
                "where the sponge has no surface")
    else:
        said = (f"the volume {d['volume']:.6g} is that of {d['cells']} cubes of side 1/{d['side']}, not of "
                f"{d['expected']} ({d['expected_volume']:.6g})")
    return (f"({d['case']}) wrong sub-cube selection: {said}. Each step keeps the 20 sub-cubes with at most one "
            "middle coordinate: drop the 6 face centres and the body centre")


def _subcubes_ja(d: dict) -> str:
    if "misplaced" in d:
        said = (f"立方体の数（{d['cells']} 個）は正しいのですが、位置が違います。スポンジの表面がない所に三角形が "
                f"{d['misplaced']} 個あります")
    else:
        said = (f"体積 {d['volume']:.6g} は一辺 1/{d['side']} の立方体 {d['cells']} 個分で、正しくは {d['expected']} 個"
                f"（{d['expected_volume']:.6g}）です")
    return (f"（{d['case']}）残す小立方体の選び方が違います。{said}。各段で、座標のうち中央（1）が高々一つの 20 個を残し、"
            "面の中心 6 個と体の中心 1 個を除きます")


register("wrong-subcubes", "mesh", _subcubes_en, _subcubes_ja)

register("wrong-scale-factor", "mesh",
         "({case}) the copies are scaled by {factor:.4g} per step; the flake needs s = 1/(1 + φ) ≈ {expected:.4g}, "
         "so that neighbouring copies share an edge",
         "（{case}）各段の縮小率が {factor:.4g} になっています。隣り合うコピーが辺を共有するには s = 1/(1 + φ) ≈ "
         "{expected:.4g} が必要です")

register("points-off-sphere", "mesh",
         "({case}) {count} points are not on the unit sphere (e.g. at distance {distance:.6g} from the centre): push "
         "every new edge midpoint out onto the sphere, m / |m|",
         "（{case}）単位球面上にない点が {count} 個あります（例: 中心からの距離 {distance:.6g}）。新しい辺の中点はすべて"
         "球面上へ押し出してください（m / |m|）")

register("wrong-triangle-count", "mesh",
         "({case}) {count} triangles; this surface has {expected}",
         "（{case}）三角形が {count} 個ですが、この面は {expected} 個です")

register("wrong-area", "mesh",
         "({case}) surface area {area:.6g}, expected {expected:.6g}",
         "（{case}）表面積が {area:.6g} ですが、正しくは {expected:.6g} です")

register("wrong-volume", "mesh",
         "({case}) enclosed volume {volume:.6g}, expected {expected:.6g}",
         "（{case}）囲む体積が {volume:.6g} ですが、正しくは {expected:.6g} です")

register("render-differs", "mesh",
         "({case}) drawn, your shape does not match the reference: {failed} (see the panel: yours | reference | ΔE)",
         "（{case}）描画すると参照と一致しません: {failed}（パネル: あなたの形 | 参照 | ΔE を見てください）")
