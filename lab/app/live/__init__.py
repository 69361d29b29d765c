"""The live lab (``scanlab app``): a local web page where every control re-renders both
renderers and the ΔE2000 map.

- :mod:`~lab.app.live.controls`: the state model and its one checking edge;
- :mod:`~lab.app.live.catalogue`: the scenes it may open;
- :mod:`~lab.app.live.drawing` and :mod:`~lab.app.live.render_service`: the worker
  processes and their newest-wins lanes;
- :mod:`~lab.app.live.orbit`: camera moves; :mod:`~lab.app.live.saving`: "Save scene";
- :mod:`~lab.app.live.wording`: every word, English and Japanese;
- :mod:`~lab.app.live.live_page`, :mod:`~lab.app.live.control_panels`,
  :mod:`~lab.app.live.image_views`: the page (trame + Vuetify);
- :mod:`~lab.app.live.live_server`: the server; :mod:`~lab.app.live.live_command`: its command line.

Importing the package loads nothing.
"""
