"""Matrices family: a 4×4 matrix of the camera or the projection that is not the course's
(exit status 1). Each code names one recognisable mistake; the exercises detect it by
building the mistaken matrix themselves and finding it equal to the student's on every case.

Details: ``case`` is the call (e.g. ``look_at(eye=(3, 2, 4), …)``).
"""
from __future__ import annotations

from lab.app.exercises.diagnoses.codes import register

register("matrix-transposed", "matrices",
         "({case}) the matrix is transposed: that is the column-vector form (p' = M·p). The course multiplies row "
         "vectors, p' = [x, y, z, 1] @ M: swap its rows and columns",
         "（{case}）行列が転置されています。それは列ベクトル形式（p' = M·p）です。本講義は行ベクトル "
         "p' = [x, y, z, 1] @ M なので、行と列を入れ替えてください")

register("camera-mirrored", "matrices",
         "({case}) the camera frame is mirrored: one of U and V points the wrong way (a cross product taken in the "
         "wrong order), so the picture is mirrored — the frame is left-handed, its determinant is −1. U = up × N, "
         "V = N × U",
         "（{case}）カメラ座標系が鏡像になっています。U と V の一方が逆向きで（外積の順序の誤り）、画像が鏡像になります。"
         "座標系が左手系で行列式が −1 です。U = up × N、V = N × U としてください")

register("camera-upside-down", "matrices",
         "({case}) U = N × up instead of up × N: U points left, and V = N × U then points down, so the picture is "
         "turned upside down (rotated by 180°)",
         "（{case}）U = up × N ではなく N × up になっています。U が左を向き、V = N × U は下を向くので、画像が上下逆さ"
         "（180° 回転）になります")

register("view-direction-reversed", "matrices",
         "({case}) N points from the eye to the focal point; in the U-V-N frame N = (eye − focal point) / |…| points "
         "back toward the eye, and the camera looks down −N",
         "（{case}）N が視点から注視点へ向いています。U-V-N 座標系では N = (視点 − 注視点) / |…| で視点の側を向き、"
         "カメラは −N の方向を見ます")

register("translation-not-rotated", "matrices",
         "({case}) the bottom row is −eye as it is; it must be the eye's position in the camera frame, "
         "(−eye·U, −eye·V, −eye·N)",
         "（{case}）最下行が −eye のままです。カメラ座標系で表した視点の位置 (−eye·U, −eye·V, −eye·N) にしてください")

register("up-not-orthogonalised", "matrices",
         "({case}) V is the up hint itself, which is not perpendicular to N when the hint is tilted: take V = N × U",
         "（{case}）V に上方向のヒントをそのまま使っています。ヒントが傾いていると N と直交しません。V = N × U としてください")

register("axes-not-normalised", "matrices",
         "({case}) U, V and N point the right way but are not of length 1: normalise them",
         "（{case}）U・V・N の向きは正しいのですが長さが 1 ではありません。正規化してください")

register("depth-range-0-1", "matrices",
         "({case}) the near plane goes to depth 0 (Direct3D's range); OpenGL's clip space puts near at −1 and far at "
         "+1 after the division by w",
         "（{case}）前方クリップ面が深度 0 に写っています（Direct3D の範囲）。OpenGL のクリップ空間では w で割った後に"
         "前方が −1、後方が +1 です")

register("w-sign-flipped", "matrices",
         "({case}) w_clip = +z_view; the eye looks down −z, so w_clip = −z_view (the entry in row 2, column 3 is −1)",
         "（{case}）w_clip = +z_view になっています。視線は −z 方向なので w_clip = −z_view（2 行 3 列の要素が −1）です")

register("fov-not-halved", "matrices",
         "({case}) tan(view_angle) was used; view_angle is the whole vertical angle, so the half-height is "
         "near·tan(view_angle / 2)",
         "（{case}）tan(view_angle) を使っています。view_angle は縦の画角全体なので、半分の高さは "
         "near·tan(view_angle / 2) です")

register("fov-in-degrees", "matrices",
         "({case}) degrees were passed to tan: convert the angle with math.radians first",
         "（{case}）度のまま tan に渡しています。先に math.radians でラジアンに変換してください")

register("aspect-inverted", "matrices",
         "({case}) the x scale uses height / width; aspect is width / height and x is scaled by 1 / (t·aspect)",
         "（{case}）x の拡大率に 高さ/幅 を使っています。aspect は 幅/高さ で、x は 1 / (t·aspect) 倍です")

register("matrix-wrong", "matrices",
         "({case}) entry [{row}, {col}] is {got:.6g}, expected {expected:.6g} (largest of {count} wrong entries)",
         "（{case}）要素 [{row}, {col}] が {got:.6g} ですが、正しくは {expected:.6g} です（誤った要素 {count} 個のうち"
         "最大の差）")
