"""Sphinx configuration of the lesson site (built by ``scanlab lessons build``).

English is the source language; Japanese comes from ``locales/ja/LC_MESSAGES/*.po``
(``-D language=ja``). Everything a page loads is served from the site itself: the theme's
files, MathJax 3 from npm (``package.json``), our figure script, the figures.
"""
project = "scanlab lessons"
author = "scanlab"
copyright = "scanlab"

extensions = ["myst_parser", "lab.app.lesson_site"]
myst_enable_extensions = ["dollarmath", "amsmath", "deflist", "colon_fence"]
myst_heading_anchors = 3

root_doc = "index"
exclude_patterns = ["README.md", "node_modules", "figures", "locales", "_build", "**/__pycache__"]
templates_path = ["_templates"]
html_static_path = ["_static"]

language = "en"
locale_dirs = ["locales/"]
gettext_compact = True
gettext_uuid = False
gettext_location = False

html_theme = "furo"
html_title = "scanlab lessons"
html_copy_source = False
html_use_index = False                 # no index entries: an empty index page helps no one
html_show_search_summary = False       # a summary is fetched from each result page, which file:// forbids
html_show_sourcelink = False
html_last_updated_fmt = None
html_sidebars = {"**": ["sidebar/brand.html", "lang-switch.html", "sidebar/search.html", "sidebar/scroll-start.html",
                        "sidebar/navigation.html", "sidebar/scroll-end.html"]}
html_theme_options = {"top_of_page_buttons": []}

mathjax_path = "mathjax/tex-chtml.js"  # _static/mathjax/, copied from npm's mathjax@3 (lab.app.lesson_site.assets)
