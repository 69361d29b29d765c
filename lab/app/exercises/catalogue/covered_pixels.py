"""Exercise ``covered_pixels``: which pixel centres one triangle covers, under the renderer's
fill rule (the one VTK draws through llvmpipe).

Reference: :func:`renderer.coverage.triangle_coverage` — corners snapped to 1/256 pixel,
the scanline span of :func:`renderer.raster.scanline_span` with the top-left rule. The
student's function is called once per triangle of the test meshes
(:func:`lab.app.exercises.rastercases.raster_meshes`, about 400 triangles); every pixel of
every mesh is classified, and the mistakes with a known signature — ties taken both
ways or neither, the tie rule mirrored, rows upside down, pixel corners instead of
centres, clockwise triangles dropped, no snapping — are named when the student's masks
equal the masks that mistake gives, triangle for triangle.
"""
from __future__ import annotations

import numpy as np

from lab.app.exercises.diagnoses.codes import Finding
from lab.app.exercises.rastercases import CLASSES, classify, edge_function_masks, raster_meshes, to_fixed
from lab.app.exercises.exercise_registry import Case, Exercise, Judgement, Output, register
from lab.app.exercises.starters import starter

TITLE = {"en": "the pixels a triangle covers (the fill rule)", "ja": "三角形が覆う画素（塗りつぶし規則）"}

STATEMENT = {
    "en": "Decide which pixels one triangle covers, exactly as the renderer (and VTK) does: a pixel is drawn when its "
          "centre (x + 0.5, y + 0.5) lies inside the triangle. A centre exactly on an edge belongs to the triangle "
          "only for a left edge or a bottom edge (window y is up) — the top-left rule — so two triangles that share "
          "an edge never both draw a pixel on it, and never both miss it. First snap each corner to the 1/256-pixel "
          "grid, as the window stage does. Triangles may come clockwise or counter-clockwise. The checker calls your "
          "function on about 400 triangles (fans, shared edges through pixel centres, tiny and huge ones, zero-area "
          "ones), sorts every pixel into correct, missing, duplicated and unexpected, and names the first triangles "
          "and pixels of each.",
    "ja": "一つの三角形がどの画素を覆うかを、レンダラー（と VTK）と全く同じに決めてください。画素は中心 (x + 0.5, y + 0.5) が"
          "三角形の内側にあるとき塗られます。辺のちょうど上にある中心は、その辺が左の辺か下の辺（ウィンドウ座標は y が上向き）の"
          "ときだけ三角形に属します — トップレフト規則。これで、辺を共有する二つの三角形がその上の画素を二重に塗ることも、"
          "どちらも塗らないこともありません。ウィンドウ変換と同じく、まず各頂点を 1/256 画素の格子に丸めます。三角形は時計回りでも"
          "反時計回りでも与えられます。採点では約 400 個の三角形（扇形、画素中心を通る共有辺、ごく小さいもの・巨大なもの、面積 0 "
          "のもの）で関数を呼び、すべての画素を 正しい・欠け・重複・余分 に分類し、それぞれ最初の三角形と画素を示します。",
}

DOCSTRING = """The pixels whose centres the triangle (v0, v1, v2) covers, under the top-left rule.

Parameters
----------
v0, v1, v2 : float arrays of shape (2,): the corners (x, y) in window coordinates,
    pixels, y up; clockwise or counter-clockwise.
width, height : the window, in pixels.

Returns
-------
mask : bool array (height, width). mask[y, x] is True when the triangle covers pixel
    (x, y), the pixel whose centre is (x + 0.5, y + 0.5). Row 0 is the BOTTOM row
    (window y up).

Conventions
-----------
- First snap every corner to the 1/256-pixel grid, as the window stage does:
  x_fixed = round_half_even((x - 0.5) * 256), so that pixel centre (i, j) is the
  integer point (256 * i, 256 * j); do the test in these integers.
- A pixel centre strictly inside is covered. A centre exactly on an edge is covered
  only when that edge is a left edge or a bottom edge of the triangle (y up): the
  top-left rule. (With the corners counter-clockwise, a left edge goes down, dy < 0;
  a bottom edge is horizontal and goes right, dy = 0 and dx > 0.)
- A triangle of zero area covers nothing. Pixels outside the window are not in mask.
"""


def call(tri: np.ndarray, width: int, height: int) -> str:
    corners = ", ".join("(" + ", ".join(f"{c:.6g}" for c in v) + ")" for v in tri)
    return f"covered_pixels({corners}, {width}, {height})"


def cases() -> list[Case]:
    return [Case((list(map(float, tri[0])), list(map(float, tri[1])), list(map(float, tri[2])), m.width, m.height),
                 call(tri, m.width, m.height)) for m in raster_meshes() for tri in m.triangles]


def reference_masks(mesh) -> np.ndarray:
    from renderer.coverage import triangle_coverage

    return np.array([triangle_coverage(*tri, mesh.width, mesh.height) for tri in mesh.triangles]).reshape(
        -1, mesh.height, mesh.width)


def _signed_area(tri: np.ndarray) -> float:
    f = to_fixed(tri)
    return float((f[1, 0] - f[0, 0]) * (f[2, 1] - f[0, 1]) - (f[2, 0] - f[0, 0]) * (f[1, 1] - f[0, 1]))


def variants(mesh, reference: np.ndarray):
    """(code, masks) for every named mistake, for one mesh."""
    from renderer.coverage import triangle_coverage

    w, h, tris = mesh.width, mesh.height, mesh.triangles
    clockwise = np.array([_signed_area(t) < 0 for t in tris])
    each = lambda f: np.array([f(t) for t in tris]).reshape(-1, h, w)  # noqa: E731
    return [
        ("ties-drawn-twice", lambda: each(lambda t: edge_function_masks(t, w, h, "inclusive"))),
        ("ties-missed", lambda: each(lambda t: edge_function_masks(t, w, h, "exclusive"))),
        ("tie-rule-mirrored", lambda: each(lambda t: triangle_coverage(*t, w, h, "bottom-right"))),
        ("rows-flipped", lambda: reference[:, ::-1, :]),
        ("corners-not-centres", lambda: each(lambda t: triangle_coverage(*(t + 0.5), w, h))),
        ("clockwise-missed", lambda: np.where(clockwise[:, None, None], False, reference)),
        ("no-subpixel-snap", lambda: each(lambda t: edge_function_masks(t, w, h, snap=False))),
    ]


def first_of_each(meshes, references, students, classes) -> dict:
    """The first pixel of each wrong class (mesh order, then row by row from the bottom)
    with the triangles involved and their corners."""
    first = {}
    for cls in CLASSES[1:]:
        for mesh, ref, stu, c in zip(meshes, references, students, classes):
            ys, xs = np.nonzero(c[cls])
            if not len(ys):
                continue
            y, x = int(ys[0]), int(xs[0])
            owners = np.flatnonzero((ref if cls == "missing" else stu)[:, y, x])
            corners = " ".join("(" + ", ".join(f"{v:.6g}" for v in p) + ")" for p in mesh.triangles[owners[0]])
            first[cls] = {"x": x, "y": y, "mesh": mesh.name, "mesh_ja": mesh.name_ja,
                          "triangles": [int(k) for k in owners[:2]], "corners": corners}
            break
    return first


def judge(cases_: list[Case], results: list[list[np.ndarray]]) -> Judgement:
    from lab.app.exercises.rasterpanel import RasterPanel

    meshes = raster_meshes()
    masks = [r[0].astype(bool) for r in results]
    judgement = Judgement()
    references, students, classes, start = [], [], [], 0
    for mesh in meshes:
        k = len(mesh.triangles)
        references.append(reference_masks(mesh))
        students.append(np.array(masks[start:start + k]).reshape(-1, mesh.height, mesh.width))
        classes.append(classify(references[-1], students[-1]))
        start += k
        counts = {cls: int(classes[-1][cls].sum()) for cls in CLASSES}
        wrong = sum(counts[c] for c in CLASSES[1:])
        judgement.checked["en"].append(f"{mesh.name}: {k} triangles, {counts['correct']} pixels correct"
                                       + (f", {wrong} wrong" if wrong else ""))
        judgement.checked["ja"].append(f"{mesh.name_ja}: 三角形 {k}、正しい画素 {counts['correct']}"
                                       + (f"、誤り {wrong}" if wrong else ""))
    totals = {cls: int(sum(c[cls].sum() for c in classes)) for cls in CLASSES}
    judgement.panels.append(RasterPanel(meshes, references, students, classes))
    if not any(totals[c] for c in CLASSES[1:]):
        return judgement
    judgement.findings += name_the_mistake(meshes, references, students, totals)
    judgement.findings.append(Finding("coverage-differs", {
        "counts": totals, "triangles": len(masks), "meshes": len(meshes),
        "first": first_of_each(meshes, references, students, classes)}))
    return judgement


def name_the_mistake(meshes, references, students, totals) -> list[Finding]:
    """The named mistake whose masks equal the student's on every triangle of area, if any."""
    codes = None
    for mesh, ref, stu in zip(meshes, references, students):
        area = np.array([_signed_area(t) != 0 for t in mesh.triangles])
        matching = {code for code, masks in variants(mesh, ref)
                    if (codes is None or code in codes) and np.array_equal(masks()[area], stu[area])}
        codes = matching
        if not codes:
            return []
    details = {"ties-drawn-twice": {"count": totals["duplicated"]}, "ties-missed": {"count": totals["missing"]},
               "tie-rule-mirrored": {"missing": totals["missing"], "unexpected": totals["unexpected"]},
               "no-subpixel-snap": {"count": totals["missing"] + totals["unexpected"] + totals["duplicated"]}}
    clockwise = sum(int(np.sum([_signed_area(t) < 0 for t in m.triangles])) for m in meshes)
    details["clockwise-missed"] = {"count": clockwise}
    order = [code for code, _ in variants(meshes[0], references[0])]
    return [Finding(code, details.get(code, {})) for code in order if code in codes][:1]


register(Exercise(
    name="covered_pixels", lesson="05-scanline", title=TITLE, statement=STATEMENT,
    parameters=("v0", "v1", "v2", "width", "height"), outputs=(Output("mask", ("height", "width"), "biu"),),
    starter=starter("covered_pixels", "05-scanline", TITLE["en"],
                    "covered_pixels(v0, v1, v2, width: int, height: int)", DOCSTRING),
    cases=cases, judge=judge))
