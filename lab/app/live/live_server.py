"""The live lab's server: the trame app that ties the controls, the render service and the page.

:class:`LiveLab` owns the state (trame's, shared with the page). A change of any control
(:data:`lab.app.live.controls.KEYS`) is checked at the one edge
(:func:`lab.app.live.controls.to_render`): problems go back to the page beside their
fields, and a good state becomes a numbered request for the render service
(:mod:`lab.app.live.render_service`), which shows our image first, then VTK's, the ΔE map,
the metrics and the verdict. The camera moves (orbit, zoom, reset), the lights list (add,
remove), "Save scene" and the language are triggers and keys of their own.

:func:`run` starts it: it listens on ``host`` (loopback unless told otherwise), prints its
address, serves every asset from the installed wheels (trame, Vuetify, its icon font) and
stops cleanly on Ctrl-C, its worker processes with it.
"""
from __future__ import annotations

import base64
import math
import os
import sys
from dataclasses import replace

from lab.app.live.catalogue import Catalogue, initial_parameters, shape_defaults
from lab.app.live.controls import (MAX_LIGHTS, Controls, KEYS, Problem, Problems, camera_controls, controls_for,
                                   new_light, to_render)
from lab.app.live.drawing import Job
from lab.app.live.orbit import orbit, usable, zoom
from lab.app.live.render_service import RenderService
from lab.app.live.saving import Saver
from lab.app.live.wording import problem_text, strings
from lab.validation import SceneError


def data_url(png: bytes) -> str:
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def metrics_view(m: dict) -> dict:
    """The figures of a ``metrics.json`` dict as the page shows them (keys of
    :data:`lab.app.live.image_views.METRIC_ROWS`)."""
    de = m["delta_e_2000"]
    return {"mean": f"{de['mean']:.4f}", "p999": f"{de['p999']:.3f}", "max": f"{de['max']:.3f}",
            "pixels_over_1": f"{100 * m['pixels_over_1']:.3f} % ({round(m['pixels_over_1'] * m['shared_pixels']):,} "
                             f"/ {m['shared_pixels']:,} px)",
            "coverage_mismatch": f"{100 * m['coverage_mismatch']:.3f} % ({m['mismatch_pixels']:,} px)",
            "max_channel_diff": f"{m['max_channel_diff']} / 255", "depth": f"{m['depth']['max_steps']}",
            "reference": m["reference"]}


def _finite(*values) -> bool:
    return all(isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in values)


class LiveLab:
    """The app's behaviour over a trame ``server`` (see the module docstring)."""

    def __init__(self, server, catalogue: Catalogue, saver: Saver, start: str, service=None):
        self.server, self.state = server, server.state
        self.catalogue, self.saver = catalogue, saver
        self.counter = 0
        self.loaded = None   # (source, shape params) of self.base
        self.base = None     # the scene as loaded, which the controls change
        self.problems: dict[str, Problem] = {}
        self.submitted: Controls | None = None
        self.service = service if service is not None else RenderService(self.show)
        key = catalogue.key_for(start)
        params = initial_parameters(start) if key.startswith("shape:") else {}
        self.base = catalogue.load(key, params)
        self.loaded = (key, params)
        self.state.update({
            **controls_for(self.base, key, params).to_state(),
            "lang": "en", "tr": strings("en"), "max_lights": MAX_LIGHTS, "problems": {}, "request": 0,
            "ours_src": "", "vtk_src": "", "de_src": "", "stages_src": "", "ours_request": 0, "measure_request": 0,
            "ours_ms": "–", "measure_ms": "–", "metrics_view": {}, "verdict_status": "", "verdict_ok": False,
            "failed_bars": [], "render_error": "", "measure_error": "", "saved_path": "", "saved_commands": [],
            "object_index": 0, "light_index": 0, "trame__title": "scanlab live lab"})
        self._scene_lists()
        self.state.picker_items = self._picker_items()
        self.state.change(*KEYS)(self.on_controls)
        self.state.change("lang")(self.on_language)
        self.state.change("view")(self.on_view)
        for name in ("orbit", "zoom", "reset_camera", "add_light", "remove_light", "save"):
            server.controller.trigger(name)(getattr(self, name))

    # ------------------------------------------------------------------ requests
    def on_controls(self, **_) -> None:
        """Any control changed: check the controls; ask for new images if they are usable."""
        controls = Controls.from_state(self.state)
        if (controls.source, controls.shape_params) != self.loaded:
            controls = self._switch_scene(controls)
            if controls is None:
                return
        try:
            to_render(controls, self.base)
        except Problems as found:
            self._set_problems(found.found)
            return
        self._set_problems({})
        if controls != self.submitted:  # a change the server made itself comes back once more
            self._submit(controls)

    def _switch_scene(self, controls: Controls) -> Controls | None:
        """Load the scene the picker (or a shape's parameters) now names; the controls
        start from it (a shape's new parameters keep the controls but the camera)."""
        key, params = controls.source, controls.shape_params
        if key != self.loaded[0]:
            entry = self.catalogue.entries.get(key) if isinstance(key, str) else None
            shape = entry.shape if entry else None
            params = shape_defaults(shape) if shape else {}
        try:
            base = self.catalogue.load(key, params)
        except SceneError as exc:
            self._set_problems({"shape_params" if key == self.loaded[0] else "source": Problem("scene", (str(exc),))})
            return None
        if key == self.loaded[0]:
            controls = replace(controls, camera=camera_controls(base.camera))
        else:
            controls = controls_for(base, key, params, keep=controls)
            self.state.update({"object_index": 0, "light_index": 0})
        self.base, self.loaded = base, (key, params)
        self.state.update(controls.to_state())
        self._scene_lists()
        return controls

    def _submit(self, controls: Controls) -> None:
        self.submitted = controls
        self.counter += 1
        self.state.request = self.counter
        entry = self.catalogue.entries[controls.source]
        job = Job(self.counter, controls, self.catalogue.spec(controls.source, controls.shape_params),
                  entry.label.split(" — ")[0], stages=self.state.view == "stages")
        self.service.submit(job)

    def on_view(self, view, **_) -> None:
        """The stages tab opened: draw again with the stage views, if they are not there (a
        new request on both lanes, so every image on the page shows the same request)."""
        if view == "stages" and not self.state.stages_src and not self.problems:
            self._submit(Controls.from_state(self.state))

    def show(self, lane: str, kind: str, n: int, result) -> None:
        """A result from the render service (already filtered for staleness)."""
        with self.state:
            if lane == "ours":
                if kind == "error":
                    self.state.render_error = result
                    return
                self.state.update({"ours_src": data_url(result["png"]), "ours_request": n,
                                   "ours_ms": f"{result['ms']:.0f}", "render_error": ""})
                return
            if kind == "error":
                self.state.update({"measure_error": result, "measure_request": n})
                return
            m = result["metrics"]
            self.state.update({
                "vtk_src": data_url(result["vtk"]), "de_src": data_url(result["delta_e"]),
                "stages_src": data_url(result["stages"]) if result["stages"] else "",
                "metrics_view": metrics_view(m), "verdict_status": m["verdict"]["status"],
                "verdict_ok": m["verdict"]["ok"], "failed_bars": m["verdict"]["failed"], "measure_request": n,
                "measure_ms": f"{result['ms']:.0f}", "measure_error": ""})

    # ------------------------------------------------------------------ problems and words
    def _set_problems(self, found: dict[str, Problem]) -> None:
        self.problems = found
        self._show_problems()

    def _show_problems(self) -> None:
        lang = self.state.lang
        self.state.problems = {path: [problem_text(p, lang)] for path, p in self.problems.items()}

    def on_language(self, lang, **_) -> None:
        if lang not in ("en", "ja"):
            return
        self.state.tr = strings(lang)
        self.state.picker_items = self._picker_items()
        self._show_problems()
        self._scene_lists()

    def _picker_items(self) -> list[dict]:
        groups = self.state.tr["groups"]
        return [{"title": e.label, "value": e.key, "subtitle": groups[e.group]}
                for e in self.catalogue.entries.values()]

    def _scene_lists(self) -> None:
        """The object and light pickers, and the shape's parameter fields, for the scene shown."""
        kinds = {c["value"]: c["title"] for c in self.state.tr["choices"]["kind"]}
        self.state.object_items = [{"title": f"{i + 1}: {o.name}", "value": i} for i, o in enumerate(self.base.objects)]
        self.state.light_items = [{"title": f"{i + 1}: {kinds.get(li.get('kind'), '?')}", "value": i}
                                  for i, li in enumerate(self.state.lights) if isinstance(li, dict)]
        shape = self.catalogue.entries[self.loaded[0]].shape
        self.state.shape_fields = [{"name": p, "label": p} for p in shape_defaults(shape)] if shape else []

    # ------------------------------------------------------------------ triggers
    def orbit(self, right=0.0, down=0.0) -> None:
        """Drag on our image: ``right`` and ``down`` as fractions of its width and height."""
        if _finite(right, down) and abs(right) <= 2 and abs(down) <= 2 and usable(self.state.camera):
            self.state.camera = orbit(self.state.camera, right, down)

    def zoom(self, factor=1.0) -> None:
        if _finite(factor) and 0.1 <= factor <= 10 and usable(self.state.camera) \
                and _finite(self.state.camera.get("parallel_scale")):
            self.state.camera = zoom(self.state.camera, factor)

    def reset_camera(self) -> None:
        self.state.camera = camera_controls(self.base.camera)

    def add_light(self) -> None:
        lights = list(self.state.lights)
        if len(lights) < MAX_LIGHTS:
            self.state.lights = lights + [new_light()]
            self.state.light_index = len(lights)
            self._scene_lists()

    def remove_light(self) -> None:
        lights = list(self.state.lights)
        i = self.state.light_index
        if isinstance(i, int) and 0 <= i < len(lights):
            del lights[i]
            self.state.lights = lights
            self.state.light_index = max(0, min(i, len(lights) - 1))
            self._scene_lists()

    def save(self) -> None:
        """"Save scene": the scene on screen into the save folder, as the name field says."""
        try:
            checked = to_render(Controls.from_state(self.state), self.base)
            saved = self.saver.write(checked.scene, self.state.save_name, checked.breakage)
        except Problems as found:
            self._set_problems({**self.problems, **found.found})
            return
        self._set_problems({k: p for k, p in self.problems.items() if k != "save_name"})
        self.catalogue.add_saved(saved.path)
        self.state.update({"saved_path": str(saved.path), "saved_commands": saved.commands,
                           "picker_items": self._picker_items()})


def _session_route(wslink_server) -> None:
    """Answer the page's first question (``POST paraview/``: where is the session?) with this
    server's own websocket, instead of a 405 that the browser logs as an error."""
    from aiohttp import web

    async def session(_request):
        return web.json_response({"sessionURL": "ws://USE_HOST/ws"})

    wslink_server.app.router.add_post("/paraview/", session)


def run(start: str, files: tuple[str, ...], host: str, port: int, save_dir) -> int:
    """Serve the live lab until Ctrl-C; 0 when stopped."""
    os.environ["TRAME_ARGS"] = ""  # trame reads its own options from here, not from scanlab's command line
    from trame.app import get_server
    from trame_server.utils.asynchronous import get_event_loop

    from lab.app.live.live_page import build_page

    server = get_server("scanlab-live", client_type="vue3")
    lab = LiveLab(server, Catalogue(files), Saver(save_dir), start)
    build_page(server)

    def ready(**_):
        lab.service.attach(get_event_loop())
        shown = "127.0.0.1" if host in ("127.0.0.1", "localhost") else f"[{host}]" if ":" in host else host
        print(f"scanlab live lab: http://{shown}:{server.port}/  (Ctrl-C stops it)", flush=True)
        if host not in ("127.0.0.1", "localhost", "::1"):
            print(f"listening on {host}: anyone who can reach this machine can use the lab", flush=True)
        lab.on_controls()

    server.controller.on_server_ready.add(ready)
    server.controller.on_server_bind.add(_session_route)
    try:
        server.start(host=host, port=port, open_browser=False, show_connection_info=False, timeout=0,
                     disable_logging=True)
    finally:
        lab.service.stop()
    print("scanlab live lab: stopped", file=sys.stderr, flush=True)
    return 0
