"""The live lab's page, assembled: the top bar, the drawer of controls, the images.

Built with trame's Vuetify 3 widgets; everything the page loads (Vue, Vuetify, the
Material Design icon font) is served by the server from the installed wheels, so the
lab works with no network.
"""
from __future__ import annotations

from trame.ui.vuetify3 import VAppLayout

from lab.app.live.control_panels import control_drawer
from lab.app.live.image_views import main_area, top_bar


def build_page(server):
    """The page of ``server`` (its state set up by :class:`lab.app.live.live_server.LiveLab`)."""
    with VAppLayout(server, full_height=True) as layout:
        top_bar()
        control_drawer()
        main_area()
    return layout
