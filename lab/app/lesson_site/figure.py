"""The ``scanlab-figure`` directive: a lesson figure drawn by both renderers when the site is built.

In a lesson (MyST)::

    ```{scanlab-figure} fill-rule.toml
    :shadings: flat gouraud phong
    :break: fill-rule

    The caption (translated with the page).
    ```

The argument names one or more scene files beside the page; ``:shadings:`` and
``:models:`` override every object's shading or model; each combination is one
*variant*, and a switch under the figure shows one variant at a time. ``:break:`` names
a "break it" entry (:mod:`renderer.breakages`) applied to our render only;
``:reference: vtk-native`` forces VTK's own lighting; ``:depth:`` adds the depth
buffers; ``:expect: fail`` says the figure is meant to differ from VTK (a "break it"
figure or a native reference implies it). Each variant shows ours | VTK | the ΔE2000 map with its colour bar, a wipe
slider that lays ours over VTK's, the metrics and verdict, the scene file and the
command that reproduces it. All words are generated in the page's language
(:mod:`lab.app.lesson_site.i18n`); the images carry none.

Every variant is measured (:func:`lab.app.lesson_site.measurement.measure_figure`) and cached
(:mod:`lab.app.lesson_site.cache`). A variant whose verdict is not the one the lesson promises
(a passing figure outside the bars, a "break it" figure inside them) is recorded, and
the build fails (:mod:`lab.app.lesson_site.pages`).
"""
from __future__ import annotations

import html
from pathlib import Path

from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.util.docutils import SphinxDirective

from lab.app.lesson_site import record
from lab.app.lesson_site.cache import ROOT, cached, figure_key, source_files
from lab.app.lesson_site.i18n import _
from lab.app.lesson_site.figure_images import DEPTH_VMAX_LSB, colour_bar_stops, depth_metrics, write_figure_images
from lab.app.lesson_site.measurement import EXPECTATIONS, FigureSpec, as_expected, command, load, measure_figure, verdict


def shading_label(name: str) -> str:
    return {"flat": _("flat"), "gouraud": _("Gouraud"), "phong": _("Phong")}[name]


def model_label(name: str) -> str:
    return {"vtk": _("VTK's lighting"), "opengl": _("OpenGL (Blinn)"), "classic": _("the course's (Phong r·v)")}[name]


def light_kind(light) -> str:
    if not light.positional:
        return "directional"
    return "spot" if light.cone_angle < 90 else "point"


def colour_name(rgb) -> str:
    """"white" for a grey light, else the name of its strongest channel."""
    rgb = [float(c) for c in rgb]
    return "white" if max(rgb) - min(rgb) < 0.1 else ("red", "green", "blue")[rgb.index(max(rgb))]


AXES = {
    "shading": (lambda s: "+".join(sorted({o.shading for o in s.objects})),
                lambda v: " + ".join(shading_label(x) for x in v.split("+"))),
    "model": (lambda s: "+".join(sorted({o.material.model for o in s.objects})),
              lambda v: " + ".join(model_label(x) for x in v.split("+"))),
    "projection": (lambda s: "parallel" if s.camera.parallel else "perspective",
                   lambda v: {"parallel": _("parallel projection"), "perspective": _("perspective projection")}[v]),
    "lights": (lambda s: "+".join(light_kind(li) for li in s.lights if li.on),
               lambda v: " + ".join({"directional": _("directional light"), "point": _("point light"),
                                     "spot": _("spot light")}[x] for x in v.split("+"))),
    "colour": (lambda s: "+".join(colour_name(li.gl_diffuse) for li in s.lights if li.on),
               lambda v: " + ".join({"white": _("white light"), "red": _("red light"), "green": _("green light"),
                                     "blue": _("blue light")}[x] for x in v.split("+"))),
    "transparency": (lambda s: s.render.transparency if any(o.material.opacity < 1 for o in s.objects) else "opaque",
                     lambda v: {"oit": _("order-independent blend"), "depth_peeling": _("depth peeling"),
                                "sorted": _("sorted, back to front"), "opaque": _("opaque")}[v]),
    "specular": (lambda s: "separate" if s.render.separate_specular else "single",
                 lambda v: {"separate": _("separate specular colour"), "single": _("single colour")}[v]),
    "triangles": (lambda s: sum(o.mesh.n_triangles for o in s.objects),
                  lambda v: _("{n} triangles").format(n=f"{v:,}")),
}
"""What can tell one variant of a figure from another: name → (value of a scene, label of a value).
A variant's label names the axes whose values differ between the figure's variants."""


def describe(scene) -> dict:
    """The value of every axis of :data:`AXES` for ``scene`` (JSON-able)."""
    return {name: value(scene) for name, (value, _label) in AXES.items()}


def variant_labels(descriptions: list[dict]) -> list[str]:
    """One label per variant, naming only what differs between the variants (in the page's language)."""
    keys = [k for k in AXES if len({d[k] for d in descriptions}) > 1]
    return [" · ".join(AXES[k][1](d[k]) for k in keys) or _("figure") for d in descriptions]


def percent(fraction: float) -> str:
    if fraction == 0:
        return "0 %"
    return "< 0.01 %" if fraction < 1e-4 else f"{100 * fraction:.2f} %"


def verdict_text(v: str, failed: list[str]) -> str:
    text = {"pass": _("passes the parity bars"), "fails as meant": _("fails the parity bars, as meant"),
            "FAIL": _("FAILS the parity bars"), "PASSES?": _("passes the bars, but should fail")}[v]
    return text if not failed else f"{text} ({'; '.join(failed)})"


def measure_variant(spec: FigureSpec, cache_root: Path, depth: bool) -> tuple[str, dict]:
    """The cache key and result of one variant, drawn and measured if not cached."""
    scene = load(spec)
    options = {"shading": spec.shading, "model": spec.model, "break": spec.breakage, "reference": spec.reference,
               "depth": depth}

    def make(folder: Path) -> dict:
        m = measure_figure(spec)
        images = write_figure_images(m, folder, depth=depth)
        result = {"metrics": m.metrics, "images": images, "size": list(scene.image.size), "describe": describe(scene)}
        if depth:
            result["depth"] = depth_metrics(m)
        return result

    key = figure_key([spec.scene, *scene.inputs[1:]], options)
    return key, cached(cache_root, key, make)[1]


def _img(src: str, alt: str, cls: str = "") -> str:
    return f'<img src="{html.escape(src)}" alt="{html.escape(alt)}" class="{cls}" loading="eager">'


def _panel(title: str, image: str) -> str:
    return f'<div class="scanlab-panel"><div class="scanlab-panel-title">{html.escape(title)}</div>{image}</div>'


def colour_bar(vmax: float, unit: str) -> str:
    """The heat map's scale in HTML: a gradient and ticks 0 .. ≥vmax."""
    stops = ", ".join(colour_bar_stops())
    ticks = "".join(f"<span>{t:g}</span>" for t in range(int(vmax))) + f"<span>≥{vmax:g}</span>"
    return (f'<div class="scanlab-bar" style="background: linear-gradient(to right, {stops})"></div>'
            f'<div class="scanlab-ticks">{ticks}</div><div class="scanlab-unit">{html.escape(unit)}</div>')


def legend(mismatch_px: int) -> str:
    return (f'<div class="scanlab-legend"><span class="scanlab-swatch mismatch"></span>'
            f'{html.escape(_("coverage differs ({n} px)").format(n=f"{mismatch_px:,}"))}'
            f'<span class="scanlab-swatch empty"></span>{html.escape(_("neither drew"))}</div>')


def metrics_table(m: dict, expect: str, depth: dict | None) -> str:
    de = m["delta_e_2000"]
    v = verdict(m, expect)
    rows = [(_("mean ΔE2000"), f"{de['mean']:.3f}"), (_("99.9th percentile ΔE2000"), f"{de['p999']:.2f}"),
            (_("pixels with ΔE2000 > 1"), percent(m["pixels_over_1"])),
            (_("coverage mismatch"), f"{percent(m['coverage_mismatch'])} ({m['mismatch_pixels']:,} px)"),
            (_("largest channel difference"), f"{m['max_channel_diff']} / 255")]
    if depth is not None:
        rows.append((_("largest depth difference"), _("{n} steps of 2⁻²⁴").format(n=f"{depth['max_lsb']:.2f}")))
    rows += [(_("reference"), m["reference"]), (_("verdict"), verdict_text(v, m["failed_bars"]))]
    cls = "ok" if as_expected(m, expect) else "bad"
    body = "".join(f"<tr><th>{html.escape(k)}</th><td>{html.escape(val)}</td></tr>" for k, val in rows)
    return f'<table class="scanlab-metrics {cls}" data-verdict="{html.escape(v)}">{body}</table>'


class ScanlabFigure(SphinxDirective):
    """``{scanlab-figure} SCENE.toml [SCENE.toml ...]`` (see the module docstring)."""

    required_arguments = 1
    optional_arguments = 20
    has_content = True
    option_spec = {"shadings": directives.unchanged, "models": directives.unchanged, "break": directives.unchanged,
                   "reference": directives.unchanged, "depth": directives.flag,
                   "expect": lambda v: directives.choice(v, EXPECTATIONS)}

    def specs(self) -> list[FigureSpec]:
        folder = Path(self.env.doc2path(self.env.docname)).parent
        shadings = self.options.get("shadings", "").split() or [None]
        models = self.options.get("models", "").split() or [None]
        brk = self.options.get("break") or None
        reference = self.options.get("reference") or None
        expect = self.options.get("expect")
        return [FigureSpec(str(folder / name), s, mo, brk, reference, expect)
                for name in self.arguments for s in shadings for mo in models]

    def run(self) -> list[nodes.Node]:
        from renderer.breakages import BREAKAGES

        brk = self.options.get("break")
        if brk and brk not in BREAKAGES:
            raise self.error(f"unknown breakage {brk!r}; known: {', '.join(BREAKAGES)}")
        depth = "depth" in self.options
        root = Path(self.config.scanlab_figure_cache)
        prefix = "../" * self.env.docname.count("/")
        specs = self.specs()
        results = [measure_variant(spec, root, depth) for spec in specs]
        labels = variant_labels([r["describe"] for _k, r in results])
        figure_id = "figure-" + "-".join([Path(self.arguments[0]).stem] + [v for v in (brk, specs[0].reference) if v])
        for path in {s.scene for s in specs}:
            self.env.note_dependency(path)
            record.scene(self.env, path)
        for path in source_files():
            self.env.note_dependency(str(path))

        parts = []
        for i, (spec, (key, result)) in enumerate(zip(specs, results)):
            record.figure(self.env, key)
            m = result["metrics"]
            if not as_expected(m, spec.expect):
                record.problem(self.env, f"{self.env.docname}: {figure_id} [{Path(spec.scene).name}"
                                         f"{' ' + spec.shading if spec.shading else ''}"
                                         f"{' ' + spec.model if spec.model else ''}]: "
                                         f"{verdict(m, spec.expect)} ({'; '.join(m['failed_bars']) or 'within the bars'})")
            parts.append(self.variant_html(i, spec, key, result, prefix, labels[i]))
        switch = ""
        if len(specs) > 1:
            buttons = "".join(f'<button type="button" data-variant="{i}" aria-pressed="{str(i == 0).lower()}">'
                              f"{html.escape(label)}</button>" for i, label in enumerate(labels))
            switch = f'<div class="scanlab-switch" role="group" aria-label="{html.escape(_("variant"))}">{buttons}</div>'
        kind = "scanlab-break" if brk else ("scanlab-contrast" if specs[0].expect == "fail" else "")
        heading = ""
        if brk:
            heading = (f'<div class="scanlab-break-title">{html.escape(_("Break it"))}: '
                       f'{html.escape(BREAKAGES[brk].label[self.lang()])}</div>'
                       f'<div class="scanlab-rule">{html.escape(_("The rule"))}: '
                       f'{html.escape(BREAKAGES[brk].rule[self.lang()])}</div>')
        elif specs[0].expect == "fail":
            heading = f'<div class="scanlab-break-title">{html.escape(_("Meant to differ from VTK"))}</div>'
        opening = nodes.raw("", f'<figure class="scanlab-figure {kind}" id="{figure_id}">{heading}{switch}'
                                + "".join(parts), format="html")
        caption = nodes.container(classes=["scanlab-caption"])
        self.state.nested_parse(self.content, self.content_offset, caption)
        closing = nodes.raw("", "</figure>", format="html")
        return [opening, caption, closing]

    def lang(self) -> str:
        return "ja" if (self.config.language or "en").startswith("ja") else "en"

    def variant_html(self, i: int, spec: FigureSpec, key: str, result: dict, prefix: str, label: str) -> str:
        src = f"{prefix}_figures/{key}/"
        m = result["metrics"]
        ours_title = _("ours, rule broken") if spec.breakage else _("scanlab (ours)")
        panels = (_panel(ours_title, _img(src + "ours.png", ours_title))
                  + _panel(_("VTK (reference)"), _img(src + "vtk.png", _("VTK (reference)")))
                  + _panel(_("ΔE2000 map"), _img(src + "delta_e.png", _("ΔE2000 map"))
                           + colour_bar(5.0, _("ΔE2000 (1 ≈ just noticeable)")) + legend(m["mismatch_pixels"])))
        depth = ""
        if "depth" in result:
            depth = ('<div class="scanlab-panels scanlab-depth">'
                     + _panel(_("our depth buffer"), _img(src + "depth-ours.png", _("our depth buffer")))
                     + _panel(_("VTK's depth buffer"), _img(src + "depth-vtk.png", _("VTK's depth buffer")))
                     + _panel(_("depth difference"), _img(src + "depth-diff.png", _("depth difference"))
                              + colour_bar(DEPTH_VMAX_LSB, _("|Δdepth| in steps of 2⁻²⁴")))
                     + "</div>")
        w, h = result["size"]
        wipe = (f'<div class="scanlab-wipe"><div class="scanlab-wipe-title">{html.escape(_("wipe: ours over VTK"))}</div>'
                f'<div class="scanlab-wipe-stage" style="aspect-ratio: {w} / {h}; max-width: {max(w, 320)}px">'
                f'{_img(src + "vtk.png", _("VTK (reference)"), "scanlab-wipe-base")}'
                f'{_img(src + "ours.png", ours_title, "scanlab-wipe-over")}</div>'
                f'<input type="range" min="0" max="100" value="50" class="scanlab-wipe-range" '
                f'aria-label="{html.escape(_("how much of our image covers VTK’s"))}"></div>')
        scene_name = Path(spec.scene).name
        docdir = Path(self.env.docname).parent.as_posix()
        scene_href = f"{prefix}_scenes/{docdir}/{scene_name}"
        cmd = command(spec, ROOT, out=f"out/{Path(scene_name).stem}")
        foot = (f'<div class="scanlab-source">{html.escape(_("scene file"))}: '
                f'<a href="{html.escape(scene_href)}" download>{html.escape(scene_name)}</a> · '
                f'{html.escape(_("reproduce"))}: <code>{html.escape(cmd)}</code></div>')
        hidden = "" if i == 0 else " hidden"
        return (f'<div class="scanlab-variant" data-variant="{i}" data-label="{html.escape(label)}"{hidden}>'
                f'<div class="scanlab-panels">{panels}</div>{depth}{wipe}'
                f'{metrics_table(m, spec.expect, result.get("depth"))}{foot}</div>')
