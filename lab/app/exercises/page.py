"""``index.html`` of a graded class: one row per submission — its verdict, diagnoses,
panel and what was checked — readable by a teacher, in English or Japanese.

Self-contained: inline CSS, no script, no request beyond the panels beside it (relative
paths). Everything a submission produced (its file name, what it printed) is escaped.
"""
from __future__ import annotations

import html

WORDS = {
    "en": {"title": "Grades", "right": "right", "wrong": "wrong", "cannot-judge": "cannot be judged",
           "file": "file", "verdict": "verdict", "feedback": "feedback", "seconds": "s", "checked": "what was checked",
           "printed": "last lines it printed", "panel": "yours (scanlab) | reference (VTK) | ΔE2000",
           "vtk": "your geometry drawn by VTK", "summary": "{n} submissions: {right} right, {wrong} wrong, "
           "{unjudged} cannot be judged; graded in {seconds:.1f} s with {workers} workers",
           "limits": "Limits per submission: {cpu:g} s CPU, {memory} MiB memory, {output:,} bytes of output.",
           "codes": "Diagnosis codes are stable; grades.csv lists them per file.", "no-panel": "no picture"},
    "ja": {"title": "採点結果", "right": "正解", "wrong": "不正解", "cannot-judge": "採点できません",
           "file": "ファイル", "verdict": "判定", "feedback": "講評", "seconds": "秒", "checked": "確認した内容",
           "printed": "最後の出力", "panel": "あなたの形（scanlab）| 参照（VTK）| ΔE2000",
           "vtk": "あなたの形を VTK で描画", "summary": "{n} 件: 正解 {right}、不正解 {wrong}、採点できません "
           "{unjudged}。ワーカー {workers} 個で {seconds:.1f} 秒",
           "limits": "1 件あたりの上限: CPU {cpu:g} 秒、メモリ {memory} MiB、出力 {output:,} バイト。",
           "codes": "診断コードは固定です。grades.csv にファイルごとに載っています。", "no-panel": "画像なし"},
}

STYLE = """
body{font-family:system-ui,sans-serif;max-width:1700px;margin:1.5em auto;padding:0 1em;color:#222}
h1{font-size:1.5em;margin-bottom:.2em} .lead{color:#444;max-width:70em}
table{border-collapse:collapse;width:100%} th,td{border-top:1px solid #ccc;padding:.6em;vertical-align:top;text-align:left}
th{background:#f4f4f4} .v{font-weight:bold;white-space:nowrap} .right{color:#0a6e1f} .wrong{color:#b3261e}
.cannot-judge{color:#8a5a00} code{background:#f2f2f2;padding:0 .2em} ul{margin:.2em 0;padding-left:1.2em}
li{margin:.25em 0} img{max-width:100%;border:1px solid #ddd} .panels{width:760px}
.panels img.small{max-width:240px;display:block;margin-top:.4em} pre{background:#f6f6f6;padding:.4em;white-space:pre-wrap}
details{margin-top:.4em;color:#333} .summary{font-size:1.05em;margin:.6em 0}
figure{margin:.4em 0 0 0} figcaption{font-size:.85em;color:#555}
"""


def _e(s) -> str:
    return html.escape(str(s), quote=True)


def _row(r: dict, lang: str) -> str:
    w = WORDS[lang]
    verdict = r["verdict"]
    feedback = "".join(f"<li>{_e(m)}</li>" for m in r["messages"][lang]) or f"<li>{_e(w['right'])}</li>"
    checked = "".join(f"<li>{_e(c)}</li>" for c in r["checked"].get(lang, []))
    extra = f"<details><summary>{_e(w['checked'])}</summary><ul>{checked}</ul></details>" if checked else ""
    if r.get("output"):
        extra += f"<details open><summary>{_e(w['printed'])}</summary><pre>{_e(chr(10).join(r['output']))}</pre></details>"
    pictures = []
    for path in r["panels"]:
        small = path.endswith("-vtk.png")
        label = w["vtk"] if small else w["panel"]
        image = (f"<a href='{_e(path)}'><img {'class=small ' if small else ''}src='{_e(path)}' "
                 f"alt='{_e(r['file'])}: {_e(label)}' title='{_e(label)}' loading='lazy'></a>")
        pictures.append(f"<figure>{image}<figcaption>{_e(label)}</figcaption></figure>" if small else image)
    panels = "".join(pictures) or f"<span class='cannot-judge'>{_e(w['no-panel'])}</span>"
    return (f"<tr id='{_e(r['file'])}'><td><code>{_e(r['file'])}</code></td>"
            f"<td class='v {_e(verdict)}'>{_e(w[verdict])}<br><small>{r['seconds']:.1f} {_e(w['seconds'])}</small></td>"
            f"<td><ul>{feedback}</ul>{extra}</td><td class='panels'>{panels}</td></tr>")


def grades_page(exercise, rows: list[dict], lang: str, seconds: float, workers: int, limits) -> str:
    """The page's HTML for the ``rows`` of :func:`lab.app.exercises.grader.grade_folder`."""
    w = WORDS[lang]
    count = {v: sum(r["verdict"] == v for r in rows) for v in ("right", "wrong", "cannot-judge")}
    summary = w["summary"].format(n=len(rows), right=count["right"], wrong=count["wrong"],
                                  unjudged=count["cannot-judge"], seconds=seconds, workers=workers)
    limits_text = w["limits"].format(cpu=limits.cpu_seconds, memory=limits.memory_mb, output=limits.output_bytes)
    return (f"<!doctype html><html lang='{lang}'><head><meta charset='utf-8'>"
            f"<meta name='viewport' content='width=device-width, initial-scale=1'>"
            f"<title>{_e(w['title'])}: {_e(exercise.name)}</title><style>{STYLE}</style></head><body>"
            f"<h1>{_e(w['title'])}: <code>{_e(exercise.name)}</code> — {_e(exercise.title[lang])}</h1>"
            f"<p class='lead'>{_e(exercise.statement[lang])}</p>"
            f"<p class='summary'><b>{_e(summary)}</b></p><p>{_e(limits_text)} {_e(w['codes'])}</p>"
            f"<table><thead><tr><th>{_e(w['file'])}</th><th>{_e(w['verdict'])}</th><th>{_e(w['feedback'])}</th>"
            f"<th>{_e(w['panel'])}</th></tr></thead><tbody>"
            + "".join(_row(r, lang) for r in rows) + "</tbody></table></body></html>\n")
