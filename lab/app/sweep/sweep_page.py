"""``DIR/index.html``: a sweep's page — what failed to finish, the worst cases with their
panels, histograms per setting, and every case in a table that sorts by any column.

Self-contained: inline CSS and a few lines of our own JavaScript (sorting), images beside
it in ``DIR``; nothing is fetched from elsewhere.
"""
from __future__ import annotations

import html
import json
from pathlib import Path

from compare.verdict import FAIL, FAILS_AS_MEANT, PASS, PASSES_UNEXPECTEDLY
from lab.app.sweep.panels import case_title
from lab.app.sweep.worst_cases import bar_ratio, worst_first
from lab.atomic import write_text

STYLE = """
body{font-family:system-ui,sans-serif;font-size:16px;line-height:1.45;max-width:1500px;margin:1.5em auto;padding:0 1em;color:#222}
h1{font-size:1.6em;margin:.2em 0}h2{font-size:1.3em;margin-top:1.6em;border-bottom:1px solid #ddd}h3{font-size:1.05em}
nav a{margin-right:1em}img{max-width:100%;height:auto}.fig,code{font-family:ui-monospace,monospace;font-size:.9em}
.pass{color:#176f2c;font-weight:600}.FAIL,.bad{color:#b3141b;font-weight:600}
.scroll{overflow-x:auto}table{border-collapse:collapse;font-size:.85em}th,td{padding:.2em .5em;border-bottom:1px solid #eee;text-align:left;white-space:nowrap}
td.num{text-align:right;font-variant-numeric:tabular-nums}th{cursor:pointer;background:#f4f4f4;position:sticky;top:0;user-select:none}
th[aria-sort=ascending]::after{content:" ▲"}th[aria-sort=descending]::after{content:" ▼"}
section.case{margin:1.2em 0 2em}.summary td{white-space:normal}
"""

SCRIPT = """
document.querySelectorAll('table.sortable').forEach(function (table) {
  table.querySelectorAll('th').forEach(function (th, column) {
    th.addEventListener('click', function () {
      var down = th.getAttribute('aria-sort') !== 'descending';
      table.querySelectorAll('th').forEach(function (h) { h.removeAttribute('aria-sort'); });
      th.setAttribute('aria-sort', down ? 'descending' : 'ascending');
      var numeric = th.dataset.type === 'number', body = table.tBodies[0];
      var rows = Array.prototype.slice.call(body.rows);
      function value(row) {
        var cell = row.cells[column], text = cell.dataset.value !== undefined ? cell.dataset.value : cell.textContent;
        if (!numeric) return text;
        var x = parseFloat(text);
        return isNaN(x) ? -Infinity : x;
      }
      rows.sort(function (a, b) {
        var x = value(a), y = value(b), order = x < y ? -1 : x > y ? 1 : 0;
        return down ? -order : order;
      });
      rows.forEach(function (row) { body.appendChild(row); });
    });
  });
});
"""


def _e(value) -> str:
    return html.escape(str(value), quote=True)


def _count(n: int, what: str, style: str) -> str:
    """``<span class='FAIL'>3 FAIL</span>``, plain text when ``n`` is 0 (only what matters is coloured)."""
    return f"<span class='{style}'>{n} {what}</span>" if n else f"{n} {what}"


def _percent(fraction) -> str:
    return "" if fraction is None else f"{100 * fraction:.3f}"


def _figures(row: dict) -> str:
    return (f"mean ΔE2000 {row['delta_e_2000_mean']:.4f} · p99.9 {row['delta_e_2000_p999']:.3f} · "
            f"max {row['delta_e_2000_max']:.3f} · over 1: {_percent(row['pixels_over_1'])} % · "
            f"coverage mismatch {_percent(row['coverage_mismatch'])} % · "
            f"ours {row['ours_ms']:.1f} ms, VTK {row['reference_ms']:.1f} ms")


def _verdict(row: dict) -> str:
    if row["status"] != "ok":
        return f"<span class='bad'>{_e(row['status'])}</span>"
    bars = f" ({_e(row['failed_bars'])})" if row.get("failed_bars") else ""
    return f"<span class='{_e(row['verdict'])}'>{_e(row['verdict'])}</span>{bars}"


def _unfinished(rows: list[dict]) -> str:
    bad = [r for r in rows if r["status"] != "ok"]
    if not bad:
        return "<p>Every case finished.</p>"
    body = "".join(f"<tr><td>{_e(r['status'])}</td><td>{_e(case_title(r))}</td><td>{_e(r.get('error') or '')}</td>"
                   f"<td>{_e(r.get('worker') or '')}</td></tr>" for r in bad)
    return (f"<p>{len(bad)} case(s) gave no comparison; the table's <code>traceback</code> column has the rest.</p>"
            f"<div class='scroll'><table class='summary'><thead><tr><th>status</th><th>case</th><th>what happened</th>"
            f"<th>worker</th></tr></thead><tbody>{body}</tbody></table></div>")


def _panels(shown: list[dict]) -> str:
    if not shown:
        return "<p>No compared case has its frames kept.</p>"
    items = []
    for rank, row in enumerate(shown, 1):
        cid = _e(row["case_id"])
        items.append(
            f"<section class='case' id='case-{cid}'><h3>{rank}. {_e(case_title(row))} — {_verdict(row)}</h3>"
            f"<p class='fig'>{_e(_figures(row))} · worst bar ratio {bar_ratio(row):.3g}</p>"
            f"<img loading='lazy' src='cases/{cid}/side_by_side.png' alt='{_e(case_title(row))}: ours, VTK, ΔE2000'>"
            f"<p><a href='cases/{cid}/delta_e.png'>ΔE2000 map</a> · <a href='cases/{cid}/frames.npz'>frames "
            f"(npz: ours, reference, delta_e, shared, mismatch)</a> · source <code>{_e(row['source'])}</code></p>"
            f"</section>")
    return "".join(items)


COLUMNS = (  # heading, type, cell
    ("rank", "number", lambda r, rank: (rank, str(rank) if rank else "")),
    ("source", "text", lambda r, rank: (None, r["name"])),
    ("settings", "text", lambda r, rank: (None, " ".join(f"{k}={v}" for k, v in json.loads(r["settings"]).items()))),
    ("verdict", "text", lambda r, rank: (None, r["verdict"] if r["status"] == "ok" else r["status"])),
    ("mean ΔE", "number", lambda r, rank: (r.get("delta_e_2000_mean"), _num(r.get("delta_e_2000_mean"), ".4f"))),
    ("p99.9 ΔE", "number", lambda r, rank: (r.get("delta_e_2000_p999"), _num(r.get("delta_e_2000_p999"), ".3f"))),
    ("max ΔE", "number", lambda r, rank: (r.get("delta_e_2000_max"), _num(r.get("delta_e_2000_max"), ".3f"))),
    ("over 1 %", "number", lambda r, rank: (r.get("pixels_over_1"), _percent(r.get("pixels_over_1")))),
    ("coverage %", "number", lambda r, rank: (r.get("coverage_mismatch"), _percent(r.get("coverage_mismatch")))),
    ("case s", "number", lambda r, rank: (r.get("case_s"), _num(r.get("case_s"), ".2f"))),
    ("worker", "text", lambda r, rank: (None, r.get("worker") or "")),
)


def _num(value, spec: str) -> str:
    return "" if value is None else format(value, spec)


def _table(rows: list[dict], ranks: dict[str, int], kept: set[str]) -> str:
    head = "".join(f"<th data-type='{kind}' scope='col'>{_e(name)}</th>" for name, kind, _ in COLUMNS)
    body = []
    for row in sorted(rows, key=lambda r: ranks.get(r["case_id"], len(ranks) + 1)):
        cells = []
        for name, kind, cell in COLUMNS:
            value, text = cell(row, ranks.get(row["case_id"]))
            if name == "source" and row["case_id"] in kept:
                text_html = f"<a href='#case-{_e(row['case_id'])}'>{_e(text)}</a>"
            else:
                text_html = _e(text)
            data = f" data-value='{_e(value)}'" if value is not None else ""
            cells.append(f"<td class='{'num' if kind == 'number' else ''}'{data}>{text_html}</td>")
        body.append(f"<tr>{''.join(cells)}</tr>")
    return (f"<div class='scroll'><table class='sortable' id='cases'><thead><tr>{head}</tr></thead>"
            f"<tbody>{''.join(body)}</tbody></table></div>")


def build_page(out: Path, rows: list[dict], kept: set[str], histograms: list[Path], facts: dict) -> Path:
    """Write ``out/index.html``. ``kept``: case ids whose panels exist; ``facts``: ``command``
    (the command line), ``throughput`` (text) and ``table`` (the Parquet file)."""
    ranked = worst_first(rows)
    ranks = {r["case_id"]: i for i, r in enumerate(ranked, 1)}
    shown = [r for r in ranked if r["case_id"] in kept]
    passed = sum(r["status"] == "ok" and r["verdict"] in (PASS, FAILS_AS_MEANT) for r in rows)
    failed = sum(r["status"] == "ok" and r["verdict"] in (FAIL, PASSES_UNEXPECTEDLY) for r in rows)
    unfinished = sum(r["status"] != "ok" for r in rows)
    figures = "".join(f"<p><img loading='lazy' src='histograms/{_e(p.name)}' alt='histograms {_e(p.stem)}'></p>"
                      for p in histograms) or "<p>No compared case yet.</p>"
    page = (
        "<!doctype html><html lang='en'><head><meta charset='utf-8'>"
        "<meta name='viewport' content='width=device-width, initial-scale=1'>"
        f"<title>scanlab sweep: {len(rows)} cases</title><style>{STYLE}</style></head><body>"
        f"<h1>scanlab sweep: {len(rows)} cases</h1>"
        f"<p>{_count(passed, 'pass', 'pass')} · {_count(failed, 'FAIL', 'FAIL')} · "
        f"{_count(unfinished, 'did not finish', 'bad')}. Bars: coverage mismatch ≤ 0.02 %, ΔE2000 &gt; 1 "
        f"on ≤ 0.2 % of the shared pixels, mean ΔE2000 ≤ 0.1. {_e(facts.get('throughput', ''))}</p>"
        f"<p class='fig'>{_e(facts.get('command', ''))}</p>"
        "<nav><a href='#unfinished'>Did not finish</a><a href='#worst'>Worst cases</a>"
        "<a href='#histograms'>Histograms</a><a href='#all'>All cases</a></nav>"
        f"<h2 id='unfinished'>Did not finish</h2>{_unfinished(rows)}"
        f"<h2 id='worst'>Worst cases ({len(shown)} with panels)</h2>"
        "<p>Ranked by the worst ratio of a figure to its bar (above 1 fails), then by ΔE2000 p99.9 and max.</p>"
        f"{_panels(shown)}"
        f"<h2 id='histograms'>Histograms per setting</h2>{figures}"
        f"<h2 id='all'>All cases</h2><p>Click a heading to sort. Rows link to their panels where kept. "
        f"Every column of the run is in <code>{_e(facts.get('table', 'results.parquet'))}</code>.</p>"
        f"{_table(rows, ranks, kept)}<script>{SCRIPT}</script></body></html>")
    path = out / "index.html"
    write_text(path, page)
    return path
