"""Every word the live lab shows, in English and Japanese, in one place.

The page binds its labels to the state key ``tr`` (:func:`strings`); switching language
replaces ``tr`` and nothing else, so the controls keep their values. Japanese terms are
the course's (the lessons' glossary): 隠面消去, 後面除去, 環境光, 拡散反射光, 鏡面反射光,
点光源, スポットライト, 減衰, 平行投影, 透視補正. The "break it" entries bring their own
labels and rules (:data:`renderer.breakages.BREAKAGES`).
"""
from __future__ import annotations

from renderer.breakages import BREAKAGES

LANGUAGES = ("en", "ja")

TEXT = {
    "title": ("scanlab live lab", "scanlab ライブラボ"),
    "scene": ("Scene", "シーン"),
    "scene_picker": ("scene, preset or shape", "シーン・プリセット・形状"),
    "size": ("image size", "画像サイズ"),
    "rendering": ("Rendering", "描画"),
    "shading": ("shading", "シェーディング"),
    "model": ("reflection model", "反射モデル"),
    "interpolation": ("interpolation", "補間"),
    "hidden_surface": ("hidden-surface removal", "隠面消去"),
    "cull_backfaces": ("cull back faces", "後面除去"),
    "transparency": ("transparency", "半透明の合成"),
    "separate_specular": ("separate specular colour (OpenGL)", "鏡面反射色の分離 (OpenGL)"),
    "material": ("Material", "材質"),
    "object": ("object", "物体"),
    "color": ("colour", "色"),
    "ambient": ("ambient Ka", "環境光 Ka"),
    "diffuse": ("diffuse Kd", "拡散反射光 Kd"),
    "specular": ("specular Ks", "鏡面反射光 Ks"),
    "specular_power": ("specular power n", "鏡面反射の指数 n"),
    "shininess": ("shininess (OpenGL)", "shininess (OpenGL)"),
    "opacity": ("opacity", "不透明度"),
    "lights": ("Lights", "光源"),
    "light": ("light", "光源"),
    "add_light": ("add", "追加"),
    "remove_light": ("remove", "削除"),
    "no_lights": ("No lights: everything is dark but the ambient term.", "光源なし: 環境光の項のほかは暗い。"),
    "on": ("on", "点灯"),
    "kind": ("kind", "種類"),
    "position": ("position", "位置"),
    "focal_point": ("focal point", "注視点"),
    "intensity": ("intensity", "強さ"),
    "positional": ("positional (point light)", "位置をもつ (点光源)"),
    "cone_angle": ("cone angle (half, degrees)", "コーン角 (半角, 度)"),
    "exponent": ("spot exponent", "スポットの指数"),
    "attenuation": ("attenuation: constant, linear, quadratic", "減衰: 定数・1次・2次"),
    "camera": ("Camera", "カメラ"),
    "camera_hint": ("Drag on our image to orbit; the wheel zooms.", "私たちの画像をドラッグすると回り、ホイールで拡大・縮小する。"),
    "zoom_in": ("zoom in", "拡大"),
    "zoom_out": ("zoom out", "縮小"),
    "reset_camera": ("reset", "元に戻す"),
    "parallel": ("parallel projection", "平行投影"),
    "view_angle": ("view angle (degrees)", "視野角 (度)"),
    "break_it": ("Break it", "壊してみる"),
    "nothing_broken": ("nothing broken", "何も壊さない"),
    "the_rule": ("The rule", "規則"),
    "compare_tab": ("Compare", "比較"),
    "stages_tab": ("Stages", "段階"),
    "ours": ("scanlab (ours)", "scanlab(私たち)"),
    "ours_broken": ("ours, rule broken", "私たち(規則を破ったもの)"),
    "vtk": ("VTK (reference)", "VTK(参照)"),
    "delta_e": ("ΔE2000 map", "ΔE2000 の地図"),
    "colour_bar": ("ΔE2000 (1 ≈ just noticeable)", "ΔE2000(1 でやっと気づく程度)"),
    "mismatch": ("coverage differs", "被覆が食い違う画素"),
    "neither": ("neither drew", "どちらも描いていない画素"),
    "wipe": ("wipe: ours over VTK", "ワイプ: VTK の上に私たちの画像"),
    "wipe_amount": ("how much of our image covers VTK’s", "私たちの画像が VTK の画像を覆う割合"),
    "measuring": ("measuring…", "測定中…"),
    "waiting": ("starting the renderers…", "レンダラーを起動中…"),
    "mean": ("mean ΔE2000", "ΔE2000 の平均"),
    "p999": ("99.9th percentile ΔE2000", "ΔE2000 の 99.9 パーセンタイル"),
    "max": ("largest ΔE2000", "ΔE2000 の最大値"),
    "pixels_over_1": ("pixels with ΔE2000 > 1", "ΔE2000 が 1 を超える画素"),
    "coverage_mismatch": ("coverage mismatch", "被覆の食い違い"),
    "max_channel_diff": ("largest channel difference", "チャンネルの差の最大値"),
    "depth": ("largest depth difference (24-bit steps)", "奥行きの差の最大値 (24 ビットの段数)"),
    "reference": ("reference", "参照"),
    "verdict": ("verdict", "判定"),
    "failed_bars": ("bars missed", "満たさなかった基準"),
    "request": ("request", "リクエスト"),
    "timing": ("ours {ours} ms · measurement {measure} ms", "私たち {ours} ms · 測定 {measure} ms"),
    "stages_caption": ("Our z-buffer beside VTK's (read back from the same render) and their difference; the "
                       "triangle that won each pixel; the clipped triangles over our image, back faces marked.",
                       "私たちの Z バッファと VTK の Z バッファ (同じ描画から読み戻したもの) とその差、各画素を取った三角形、"
                       "クリッピング後の三角形を私たちの画像に重ねたもの (後面を印付け)。"),
    "stages_labels": ("The labels inside the figure are those of `scanlab stages`.",
                      "図の中の文字は `scanlab stages` のものです。"),
    "save": ("Save scene", "シーンを保存"),
    "save_name": ("file name", "ファイル名"),
    "saved": ("saved {path}", "{path} に保存した"),
    "reproduce": ("reproduce", "再現するコマンド"),
    "save_broken": ("The broken rule is not part of a scene file; the second command breaks it again.",
                    "壊した規則はシーンファイルに含まれない。2 つめのコマンドでもう一度壊せる。"),
    "fix_fields": ("Fix the marked fields; the images show the last values that worked.",
                   "印の付いた欄を直してください。画像は最後に使えた値のものです。"),
    "language": ("language", "言語"),
    "as_scene": ("as in the scene", "シーンのまま"),
}
"""Label key → (English, Japanese)."""

CHOICES = {
    "shading": {"scene": "as_scene", "flat": ("flat", "フラット"), "gouraud": ("Gouraud", "グロー"),
                "phong": ("Phong", "フォン")},
    "model": {"scene": "as_scene", "vtk": ("VTK's lighting", "VTK の照明"), "opengl": ("OpenGL (Blinn)", "OpenGL(ブリン)"),
              "classic": ("the course's (Phong r·v)", "講義のモデル(フォンの r·v)")},
    "interpolation": {"perspective": ("perspective-correct", "透視補正"),
                      "screen": ("linear on the screen", "スクリーン上で線形")},
    "hidden_surface": {"zbuffer": ("z-buffer", "Zバッファ法"), "painter": ("painter's algorithm", "ペインタアルゴリズム"),
                       "none": ("none (draw order)", "なし (描く順)")},
    "transparency": {"oit": ("order-independent blend", "順序に依存しない合成"),
                     "depth_peeling": ("depth peeling", "深度ピーリング"),
                     "sorted": ("sorted, back to front", "整列(奥から手前へ)")},
    "kind": {"scene": ("scene light (world)", "シーン光源 (ワールド)"), "camera": ("camera light", "カメラ光源"),
             "headlight": ("headlight", "ヘッドライト"), "eye": ("eye coordinates (OpenGL)", "視点座標 (OpenGL)")},
    "size": {"256x256": ("256 × 256", "256 × 256"), "512x512": ("512 × 512", "512 × 512"),
             "640x480": ("640 × 480", "640 × 480"), "800x600": ("800 × 600", "800 × 600"),
             "scene": ("the scene's own", "シーンのサイズ")},
}
"""Select → value → (English, Japanese), or the key of :data:`TEXT` for a shared wording."""

GROUPS = {"preset": ("presets", "プリセット"), "lesson": ("lesson scenes", "レッスンのシーン"),
          "shape": ("built-in shapes", "組み込みの形状"), "file": ("files you named", "指定したファイル"),
          "saved": ("saved here", "ここで保存したもの")}
"""The picker's groups (:data:`lab.app.live.catalogue.GROUPS`)."""

STATUS = {"pass": ("passes the parity bars", "一致の基準を満たす"),
          "fails as meant": ("fails the parity bars, as meant", "ねらいどおり一致の基準を満たさない"),
          "FAIL": ("FAILS the parity bars", "一致の基準を満たさない(失敗)"),
          "PASSES?": ("passes the bars, but should fail", "一致の基準を満たしてしまう(満たさないはずのもの)")}
"""A verdict's status (:mod:`compare.verdict`) in words."""

PROBLEMS = {
    "number": ("expected a number", "数値を入れてください"),
    "range": ("must be in {2}{0}, {1}{3}", "{2}{0}, {1}{3} の範囲で入れてください"),
    "vector": ("expected three numbers", "3 つの数値が必要です"),
    "choice": ("{0!r} is not one of the choices", "{0!r} は選択肢にありません"),
    "flag": ("expected on or off", "オンかオフを選んでください"),
    "colour": ("expected a colour such as #ff8800", "#ff8800 のような色を入れてください"),
    "attenuation": ("needs at least one positive coefficient", "少なくとも 1 つは正の係数が必要です"),
    "camera_at_focus": ("the camera sits on its focal point", "カメラが注視点と同じ位置にあります"),
    "camera_up": ("view up is parallel to the view direction", "上方向が視線と平行です"),
    "objects": ("the material list does not match the scene's {0} object(s)",
                "材質の数がシーンの物体の数 ({0}) と合いません"),
    "lights": ("at most {0} lights", "光源は {0} 個まで"),
    "scene": ("{0}", "{0}"),
    "name": ("use letters, digits, - and _ (up to 60)", "英数字と - と _ で 60 文字まで"),
    "exists": ("{0} exists and was not saved by this lab; choose another name",
               "{0} はすでにあり、このラボが保存したものではありません。別の名前にしてください"),
    "input": ("{0} is a file the scene is read from", "{0} はシーンの読み込み元です"),
    "not_saved": ("cannot write {0}", "{0} を書き込めません"),
}
"""A :class:`lab.app.live.controls.Problem` code → message template (English, Japanese)."""


def _pick(pair, lang: str) -> str:
    return pair[LANGUAGES.index(lang)]


def _word(value, lang: str) -> str:
    return _pick(TEXT[value] if isinstance(value, str) else value, lang)


def strings(lang: str) -> dict:
    """Everything the page shows in ``lang``: the labels of :data:`TEXT`, and under
    ``choices`` the items of each select (``{"title", "value"}``), under ``groups`` the
    picker's group titles, under ``status`` the verdicts, under ``breakages`` each
    "break it" entry's label and rule."""
    out = {key: _pick(pair, lang) for key, pair in TEXT.items()}
    out["choices"] = {name: [{"title": _word(words, lang), "value": value} for value, words in items.items()]
                      for name, items in CHOICES.items()}
    out["groups"] = {name: _pick(pair, lang) for name, pair in GROUPS.items()}
    out["status"] = {name: _pick(pair, lang) for name, pair in STATUS.items()}
    out["breakages"] = [{"title": out["nothing_broken"], "value": "none", "rule": ""}] + [
        {"title": b.label[lang], "value": name, "rule": b.rule[lang]} for name, b in BREAKAGES.items()]
    return out


def problem_text(problem, lang: str) -> str:
    """A :class:`lab.app.live.controls.Problem` as one line in ``lang``."""
    return _pick(PROBLEMS[problem.code], lang).format(*problem.args)
