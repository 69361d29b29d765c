"""The lesson site's Sphinx extension (``extensions = ["lab.app.lesson_site"]`` in ``lessons/conf.py``).

It adds the ``scanlab-figure`` directive (:mod:`lab.app.lesson_site.figure`: both renderers at
build time, measured, cached), the ``scanlab-plot`` directive (:mod:`lab.app.lesson_site.plots`), the ``scanlab-exercise``
directive (:mod:`lab.app.lesson_site.exercise`: an exercise's page from the exercise registry),
the ``{src}`` role that names (and checks) the code and tests a lesson teaches
(:mod:`lab.app.lesson_site.code`), the words the directives generate in each language (:mod:`lab.app.lesson_site.i18n`), and the build-wide
steps of :mod:`lab.app.lesson_site.pages` (language switch, Japanese search, offline MathJax,
the check that every figure keeps its lesson's promise). Reading pages is parallel-safe:
``sphinx-build -j 2`` draws figures on both cores.

Importing this package loads nothing heavy; Sphinx calls :func:`setup`.
"""


def setup(app):
    from lab.app.lesson_site import code, exercise, figure, i18n, pages, plots, record

    app.add_config_value("scanlab_figure_cache", "", "env", types=[str])
    i18n.setup_catalog(app)
    app.add_directive("scanlab-figure", figure.ScanlabFigure)
    app.add_directive("scanlab-plot", plots.ScanlabPlot)
    app.add_directive("scanlab-exercise", exercise.ScanlabExercise)
    app.add_role("src", code.src_role)
    app.connect("config-inited", pages.on_config_inited)
    app.connect("builder-inited", pages.on_builder_inited)
    app.connect("html-page-context", pages.on_html_page_context)
    app.connect("env-purge-doc", record.purge)
    app.connect("env-merge-info", record.merge)
    app.connect("env-updated", pages.on_env_updated)
    app.connect("build-finished", pages.on_build_finished)
    app.add_css_file("scanlab.css")
    app.add_css_file("scanlab-fonts.css")
    app.add_js_file("scanlab.js", loading_method="defer")
    return {"version": "1", "parallel_read_safe": True, "parallel_write_safe": True, "env_version": 1}
