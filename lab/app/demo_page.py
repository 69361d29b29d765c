"""The page of a demo run (``OUT/index.html``): a summary table, then every panel.

One self-contained HTML file: its CSS and the few lines of JavaScript that sort the
table are inline, the images are the PNGs beside it, nothing comes from a CDN. Layout:
one column that reads from 400 px wide (the table scrolls sideways inside its box) to a
desktop; one type scale (:data:`TYPE_SCALE`, ratio 1.25); every image carries its width
and height, so the page does not move while images load and a link to ``#scene`` lands
on its panel.

Each row of ``rows`` is a ``metrics.json`` dict (with ``"verdict"``) plus ``description``,
``settings``, ``scene_file`` (relative link), ``scene_file_note``, ``command`` and
``panel_size`` ([width, height] of ``side_by_side.png``), as :func:`lab.app.demo.run_demo`
makes them.
"""
from __future__ import annotations

import html
import re

TYPE_SCALE = {"small": "0.8rem", "body": "1rem", "h3": "1.25rem", "h2": "1.563rem", "h1": "1.953rem"}
"""Every font size on the page: a modular scale of ratio 1.25 from the body's 1rem."""

OK_STATUSES = ("pass", "fails as meant")

_CSS = """
:root { --small: %(small)s; --body: %(body)s; --h3: %(h3)s; --h2: %(h2)s; --h1: %(h1)s;
        --ink: #1d1d1f; --muted: #555; --rule: #d8d8d8; --pass: #05620f; --fail: #b00020; }
* { box-sizing: border-box; }
html { font-size: 100%%; }
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, sans-serif; font-size: var(--body);
       line-height: 1.5; color: var(--ink); margin: 0 auto; max-width: 1800px; padding: 0 1rem 3rem; }
h1 { font-size: var(--h1); line-height: 1.2; margin: 1.5rem 0 0.5rem; }
h2 { font-size: var(--h2); line-height: 1.25; margin: 0 0 0.25rem; overflow-wrap: anywhere; }
h3 { font-size: var(--h3); margin: 1rem 0 0.25rem; }
p, dl, pre { margin: 0.5rem 0; }
small, .small, table, pre, dl { font-size: var(--small); }
a { color: #0645ad; }
.pass { color: var(--pass); font-weight: 600; }
.FAIL, .PASSES { color: var(--fail); font-weight: 600; }
.table-box { overflow-x: auto; border: 1px solid var(--rule); }
table { border-collapse: collapse; width: 100%%; font-variant-numeric: tabular-nums; }
th, td { padding: 0.3rem 0.5rem; border-bottom: 1px solid var(--rule); text-align: right; white-space: nowrap; }
th { white-space: normal; vertical-align: bottom; }
td.wrap { white-space: normal; overflow-wrap: anywhere; min-width: 8rem; }
th:first-child, td:first-child, th.text, td.text { text-align: left; }
th button { font: inherit; font-weight: 600; background: none; border: 0; padding: 0; cursor: pointer;
            color: inherit; }
th[aria-sort="ascending"] button::after { content: " ▲"; }
th[aria-sort="descending"] button::after { content: " ▼"; }
section.panel { border-top: 2px solid var(--rule); padding-top: 1rem; margin-top: 2rem; scroll-margin-top: 0.5rem; }
section.panel:target { border-top-color: #0645ad; }
figure { margin: 0.5rem 0; }
figure img { display: block; max-width: 100%%; height: auto; border: 1px solid var(--rule); }
dl { display: grid; grid-template-columns: max-content 1fr; gap: 0.1rem 0.75rem; }
dt { color: var(--muted); }
dd { margin: 0; overflow-wrap: anywhere; }
pre { background: #f4f4f4; padding: 0.5rem; overflow-x: auto; white-space: pre-wrap; word-break: break-all; }
.settings { color: var(--muted); }
.back { font-size: var(--small); }
"""

_SORT_JS = """
document.querySelectorAll("table.sortable").forEach(function (table) {
  var heads = table.querySelectorAll("thead th");
  heads.forEach(function (th, column) {
    var button = th.querySelector("button");
    if (!button) { return; }
    button.addEventListener("click", function () {
      var ascending = th.getAttribute("aria-sort") !== "ascending";
      heads.forEach(function (other) { other.removeAttribute("aria-sort"); });
      th.setAttribute("aria-sort", ascending ? "ascending" : "descending");
      var body = table.tBodies[0];
      var rows = Array.prototype.slice.call(body.rows);
      rows.sort(function (a, b) {
        var x = a.cells[column].getAttribute("data-sort"), y = b.cells[column].getAttribute("data-sort");
        var nx = parseFloat(x), ny = parseFloat(y);
        var order = (isNaN(nx) || isNaN(ny)) ? x.localeCompare(y) : nx - ny;
        return ascending ? order : -order;
      });
      rows.forEach(function (row) { body.appendChild(row); });
    });
  });
});
"""


def anchor(name: str) -> str:
    """The id of a scene's panel: its name with anything but letters, digits, - and _ made -."""
    return "scene-" + re.sub(r"[^A-Za-z0-9_-]+", "-", name)


def _e(text) -> str:
    return html.escape(str(text), quote=True)


def _status_class(status: str) -> str:
    return "pass" if status in OK_STATUSES else ("PASSES" if status == "PASSES?" else "FAIL")


COLUMNS = (  # heading, text or number, value of a row, shown as; scene and verdict first: seen at 400 px
    ("scene", True, lambda m: m["scene"], None),
    ("verdict", True, lambda m: m["verdict"]["status"], None),
    ("model / shading", True, lambda m: f"{m['model']} / {m['shading']}", None),
    ("reference", True, lambda m: m["reference"], None),
    ("mean ΔE2000", False, lambda m: m["delta_e_2000"]["mean"], "{:.4f}"),
    ("p99.9", False, lambda m: m["delta_e_2000"]["p999"], "{:.2f}"),
    ("max ΔE2000", False, lambda m: m["delta_e_2000"]["max"], "{:.2f}"),
    ("over 1", False, lambda m: 100 * m["pixels_over_1"], "{:.3f} %"),
    ("coverage mismatch", False, lambda m: 100 * m["coverage_mismatch"], "{:.3f} %"),
    ("depth Δ, max steps", False, lambda m: m["depth"]["max_steps"], "{:d}"),
)


def summary_table(rows: list[dict]) -> str:
    """The sortable table: one row per scene, its name linking to the panel."""
    head = "".join(f"<th scope='col' class='{'text' if text else 'num'}'><button type='button'>{_e(title)}"
                   f"</button></th>" for title, text, _, _ in COLUMNS)
    body = []
    for m in rows:
        cells = []
        for title, text, value, shown in COLUMNS:
            v = value(m)
            label = _e(v) if shown is None else _e(shown.format(v))
            if title == "scene":
                label = f"<a href='#{anchor(m['scene'])}'>{label}</a>"
            elif title == "verdict":
                label = f"<span class='{_status_class(v)}'>{label}</span>"
            kind = "text wrap" if title == "reference" else ("text" if text else "")
            cells.append(f"<td data-sort='{_e(v)}'{f' class={chr(39)}{kind}{chr(39)}' if kind else ''}>{label}</td>")
        body.append("<tr>" + "".join(cells) + "</tr>")
    return (f"<p class='small'>Click a heading to sort; click a scene to go to its panel.</p>"
            f"<div class='table-box'><table class='sortable' id='summary'><thead><tr>{head}</tr></thead>"
            f"<tbody>{''.join(body)}</tbody></table></div>")


def panel(m: dict) -> str:
    """One scene's section: verdict, description, settings, the panel, figures, scene file, command."""
    de, d, v = m["delta_e_2000"], m["depth"], m["verdict"]
    status = v["status"]
    why = "; ".join(v["failed"]) if v["failed"] else "every bar met"
    if v.get("meant_to_fail"):
        why += f" (meant to fail: {v['meant_to_fail']})"
    width, height = m["panel_size"]
    worst = m.get("worst_pixel")
    worst_text = "none, the two images are identical" if not worst else worst["caption"]
    figures = [
        ("ΔE2000", f"mean {de['mean']:.4f} · median {de['median']:.2f} · p99 {de['p99']:.2f} · p99.9 {de['p999']:.2f}"
                   f" · max {de['max']:.2f}, over {m['shared_pixels']:,} shared pixels"),
        ("ΔE2000 > 1", f"{100 * m['pixels_over_1']:.3f} % of the shared pixels"),
        ("coverage mismatch", f"{100 * m['coverage_mismatch']:.3f} % of all pixels ({m['mismatch_pixels']:,} px)"),
        ("max channel diff", f"{m['max_channel_diff']} / 255"),
        ("depth", f"max {d['max_steps']} step(s) of 24 bits, p99 {d['p99_steps']:g}; more than one step apart on "
                  f"{d['pixels_over_1_step']:,} of {d['compared_pixels']:,} pixels"),
        ("worst pixel", worst_text),
        ("scene file", f"<a href='{_e(m['scene_file'])}'>{_e(m['scene_file'])}</a> ({_e(m['scene_file_note'])})"),
    ]
    rows = "".join(f"<dt>{_e(k)}</dt><dd>{val if k == 'scene file' else _e(val)}</dd>" for k, val in figures)
    name = m["scene"]
    return (f"<section class='panel' id='{anchor(name)}' aria-labelledby='{anchor(name)}-h'>"
            f"<h2 id='{anchor(name)}-h'>{_e(name)} <span class='{_status_class(status)}'>{_e(status)}</span></h2>"
            f"<p>{_e(m['description'])}</p>"
            f"<p class='small'><span class='{_status_class(status)}'>{_e(status)}</span>: {_e(why)}</p>"
            f"<p class='settings small'>{_e(m['settings'])}</p>"
            f"<figure><a href='{_e(name)}/side_by_side.png'><img src='{_e(name)}/side_by_side.png' "
            f"width='{width}' height='{height}' alt='{_e(name)}: scanlab, VTK and the ΔE2000 map, "
            f"worst pixels ringed'></a></figure>"
            f"<dl>{rows}</dl>"
            f"<h3>Reproduce</h3><pre><code>{_e(m['command'])}</code></pre>"
            f"<p class='back'><a href='#summary'>↑ back to the summary</a></p></section>")


def demo_page(rows: list[dict]) -> str:
    """The whole ``index.html``."""
    counts: dict[str, int] = {}
    for m in rows:
        counts[m["verdict"]["status"]] = counts.get(m["verdict"]["status"], 0) + 1
    tally = ", ".join(f"<span class='{_status_class(s)}'>{n} {_e(s)}</span>" for s, n in sorted(counts.items()))
    bars = rows[0]["verdict"]["bars"] if rows else {}
    bar_text = ", ".join(f"{k} ≤ {v:g}" for k, v in bars.items())
    return ("<!doctype html><html lang='en'><head><meta charset='utf-8'>"
            "<meta name='viewport' content='width=device-width, initial-scale=1'>"
            f"<title>scanlab demo: {len(rows)} scenes compared with VTK</title>"
            f"<style>{_CSS % TYPE_SCALE}</style></head><body>"
            "<header><h1>scanlab: our scanline renderer beside VTK</h1>"
            "<p>Each panel shows scanlab's image, VTK's image of the same triangles, and the CIEDE2000 colour "
            "difference of every pixel; the worst pixels are ringed and the worst one is zoomed in underneath. "
            "A scene passes when coverage differs on at most 0.02 % of all pixels, at most 0.2 % of the shared "
            "pixels have ΔE2000 &gt; 1 and the mean ΔE2000 is at most 0.1"
            f" (bars: {_e(bar_text)}).</p>"
            f"<p>{len(rows)} scenes: {tally}.</p></header>"
            f"<nav aria-label='summary'><h2>Summary</h2>{summary_table(rows)}</nav>"
            f"<main>{''.join(panel(m) for m in rows)}</main>"
            f"<script>{_SORT_JS}</script></body></html>\n")
