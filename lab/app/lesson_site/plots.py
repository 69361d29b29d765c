"""Plots drawn from measured renders, and the ``scanlab-plot`` directive that puts them on a page.

In a lesson::

    ```{scanlab-plot} mach-bands
    :scene: sphere.toml
    :shadings: flat gouraud

    Caption.
    ```

Each kind is one function in :data:`PLOTS` taking the figure specs and the axes to draw
on; it measures through :func:`lab.app.lesson_site.measurement.measure_figure` like every figure.
matplotlib's object-oriented API only (a ``Figure`` of its own, no pyplot state); the
labels are in the page's language (Japanese with the IPAex Gothic font), so a plot is
cached once per language. The PNG bytes depend only on the data and the matplotlib
version (no dates in the file).
"""
from __future__ import annotations

import html
from pathlib import Path

import numpy as np
from docutils import nodes
from docutils.parsers.rst import directives
from sphinx.util.docutils import SphinxDirective

from lab.app.lesson_site import record
from lab.app.lesson_site.cache import cached, figure_key, source_files
from lab.app.lesson_site.i18n import _
from lab.app.lesson_site.measurement import FigureSpec, load, measure_figure

PLOTS: dict = {}
"""Plot kinds by name: ``fn(specs, ax, font, lang) -> None`` (``lang`` "en" or "ja")."""


def plot(name: str):
    def register(fn):
        PLOTS[name] = fn
        return fn
    return register


def lightness(rgb: np.ndarray) -> np.ndarray:
    """CIE L* (0..100) of 8-bit sRGB pixels, as the metrics compute it."""
    from compare.metrics import sRGB8_to_Lab

    return sRGB8_to_Lab(rgb)[..., 0]


@plot("mach-bands")
def mach_bands(specs: list[FigureSpec], ax, font, lang: str) -> None:
    """L* along the middle row of the image, ours (solid) and VTK's (dotted), one colour per variant.

    Across flat facets L* climbs in steps; the eye sees a bright and a dark band at each
    step (Mach bands). Gouraud's curve has no steps, only kinks at the edges."""
    from lab.app.lesson_site.figure import shading_label

    for spec, colour in zip(specs, ("tab:orange", "tab:blue", "tab:green")):
        m = measure_figure(spec)
        row = m.ours.rgb.shape[0] // 2
        cover = m.ours.coverage[row] & m.ref.coverage[row]
        x = np.nonzero(cover)[0]
        label = shading_label(spec.shading) if spec.shading else Path(spec.scene).stem
        ax.plot(x, lightness(m.ours.rgb[row, x]), color=colour, lw=1.4, label=_("{v}, ours").format(v=label))
        ax.plot(x, lightness(m.ref.rgb[row, x]), color=colour, lw=1.0, ls=":", label=_("{v}, VTK").format(v=label))
    ax.set_xlabel(_("pixel column x along the middle row"), fontproperties=font)
    ax.set_ylabel(_("lightness L* (0 black, 100 white)"), fontproperties=font)
    ax.legend(prop=font, fontsize=9)


@plot("delta-e-histogram")
def delta_e_histogram(specs: list[FigureSpec], ax, font, lang: str) -> None:
    """How many pixels have each ΔE2000: the intact pipeline and each broken one, log counts."""
    from renderer.breakages import BREAKAGES

    bins = np.linspace(0.0, 40.0, 81)
    for spec in specs:
        m = measure_figure(spec)
        de = m.de[m.shared]
        label = BREAKAGES[spec.breakage].label[lang] if spec.breakage else _("the rules kept")
        ax.hist(np.clip(de, 0, bins[-1]), bins=bins, histtype="step", lw=1.5, label=label)
    ax.set_yscale("log")
    ax.axvline(1.0, color="grey", lw=0.8, ls="--")
    ax.set_xlabel(_("ΔE2000 of a pixel (1 ≈ just noticeable; 40 and more in the last bin)"), fontproperties=font)
    ax.set_ylabel(_("pixels"), fontproperties=font)
    ax.legend(prop=font, fontsize=9)


def draw(kind: str, specs: list[FigureSpec], path: Path, japanese: bool) -> None:
    """Draw plot ``kind`` into the PNG ``path`` (720×360 pixels)."""
    from matplotlib.figure import Figure
    from matplotlib.font_manager import FontProperties

    from lab.atomic import atomic_file
    from lab.app.lesson_site.assets import japanese_font

    font = FontProperties(fname=str(japanese_font())) if japanese else FontProperties()
    fig = Figure(figsize=(7.2, 3.6), dpi=100, layout="constrained")
    PLOTS[kind](specs, fig.add_subplot(), font, "ja" if japanese else "en")
    with atomic_file(path) as f:
        fig.savefig(f, format="png", metadata={"Software": None})


class ScanlabPlot(SphinxDirective):
    """``{scanlab-plot} KIND`` with ``:scene:`` and optional ``:shadings:`` / ``:breaks:``."""

    required_arguments = 1
    has_content = True
    option_spec = {"scene": directives.unchanged_required, "shadings": directives.unchanged,
                   "breaks": directives.unchanged}

    def run(self) -> list[nodes.Node]:
        kind = self.arguments[0]
        if kind not in PLOTS:
            raise self.error(f"unknown plot {kind!r}; known: {', '.join(PLOTS)}")
        folder = Path(self.env.doc2path(self.env.docname)).parent
        scene = str(folder / self.options["scene"])
        shadings = self.options.get("shadings", "").split() or [None]
        breaks = [None if b == "none" else b for b in self.options.get("breaks", "").split()] or [None]
        specs = [FigureSpec(scene, shading=s, breakage=b) for s in shadings for b in breaks]
        japanese = (self.config.language or "en").startswith("ja")
        options = {"plot": kind, "shadings": shadings, "breaks": breaks, "language": "ja" if japanese else "en"}
        inputs = [scene, *load(specs[0]).inputs[1:]]
        key = figure_key(inputs, options)
        cached(Path(self.config.scanlab_figure_cache), key,
               lambda f: (draw(kind, specs, f / "plot.png", japanese), {"plot": kind})[1])
        record.figure(self.env, key)
        record.scene(self.env, scene)
        for path in [scene, *map(str, source_files())]:
            self.env.note_dependency(path)
        prefix = "../" * self.env.docname.count("/")
        alt = html.escape(_("plot: {kind}").format(kind=kind))
        opening = nodes.raw("", f'<figure class="scanlab-plot" id="plot-{kind}">'
                                f'<img src="{prefix}_figures/{key}/plot.png" alt="{alt}" loading="eager">',
                            format="html")
        caption = nodes.container(classes=["scanlab-caption"])
        self.state.nested_parse(self.content, self.content_offset, caption)
        return [opening, caption, nodes.raw("", "</figure>", format="html")]
