"""The live lab's controls, in the side drawer: scene, rendering, material, lights, camera, "break it".

Each control is bound to a key of the controls' state (:mod:`lab.app.live.controls`);
the lists of materials and lights are edited in place (``materials[object_index].ambient``)
and sent back whole with ``flushState``. Every field shows its own problem, if any, from
the state key ``problems`` (field path → message in the page's language), and every
word comes from ``tr`` (:mod:`lab.app.live.wording`).
"""
from __future__ import annotations

from trame.widgets import html
from trame.widgets import vuetify3 as v

from lab.app.live.controls import MATERIAL_RANGES

COMPACT = {"density": "compact", "hide_details": "auto"}
"""Props of a small field that still shows its error message."""


def _problem(path_js: str) -> tuple:
    """A field's error message, bound: ``path_js`` is a JavaScript expression of its path."""
    return (f"problems[{path_js}] || []",)


def _number(model: str, flush: str, path_js: str, label, **props):
    """A number field bound to ``model`` (sent as typed; checked on the server)."""
    return v.VTextField(v_model=model, update_modelValue=f"flushState('{flush}')", label=label,
                        error_messages=_problem(path_js), type="number", **COMPACT, **props)


def _slider(model: str, flush: str, path_js: str, label, lo: float, hi: float, step: float, name: str):
    """A slider with the exact value in a small field beside it."""
    with v.VSlider(v_model=model, update_modelValue=f"flushState('{flush}')", label=label, min=lo, max=hi,
                   step=step, error_messages=_problem(path_js), classes=f"slider-{name}", **COMPACT):
        with v.Template(v_slot_append=True):
            v.VTextField(v_model=model, update_modelValue=f"flushState('{flush}')", type="number",
                         style="width: 84px", single_line=True, density="compact", hide_details=True,
                         classes=f"field-{name}")


def _triple(model: str, flush: str, path_js: str, label, name: str):
    """Three number fields (x, y, z) for a vector."""
    html.Div(label, classes="text-caption mt-1")
    with v.VRow(dense=True):
        for i, axis in enumerate("xyz"):
            with v.VCol(cols=4):
                _number(f"{model}[{i}]", flush, f"{path_js} + '.{i}'", axis, classes=f"field-{name}-{axis}")


def _colour(model: str, flush: str, path_js: str, label, name: str):
    """A swatch that opens a colour picker (``#rrggbb``)."""
    with v.VMenu(close_on_content_click=False):
        with v.Template(v_slot_activator="{ props }"):
            with v.VBtn(v_bind="props", variant="outlined", size="small", classes=f"colour-{name} my-1"):
                html.Span(style=(f"`display:inline-block;width:18px;height:18px;margin-right:8px;"
                                 f"border:1px solid #888;background:${{{model}}}`",))
                html.Span("{{ %s }}: {{ %s }}" % (label[0], model))
        v.VColorPicker(v_model=model, update_modelValue=f"flushState('{flush}')", modes=("['hex']",),
                       mode="hex", show_swatches=False)
    html.Div(("{{ (problems[%s] || []).join(' ') }}" % path_js), classes="text-error text-caption")


def scene_panel():
    with v.VExpansionPanel(value="scene"):
        v.VExpansionPanelTitle("{{ tr.scene }}")
        with v.VExpansionPanelText():
            v.VAutocomplete(v_model=("source",), items=("picker_items",), item_props=True, label=("tr.scene_picker",),
                            error_messages=_problem("'source'"), classes="picker-source", **COMPACT)
            with v.VRow(dense=True, v_if="shape_fields.length"):
                with v.VCol(v_for="p in shape_fields", key="p.name", cols=6):
                    v.VTextField(v_model="shape_params[p.name]", update_modelValue="flushState('shape_params')",
                                 label=("p.label",), type="number", error_messages=_problem("'shape_params'"),
                                 **COMPACT)
            html.Div("{{ (problems['shape_params'] || []).join(' ') }}", classes="text-error text-caption")
            v.VSelect(v_model=("size",), items=("tr.choices.size",), label=("tr.size",), classes="select-size",
                      error_messages=_problem("'size'"), **COMPACT)


def rendering_panel():
    with v.VExpansionPanel(value="rendering"):
        v.VExpansionPanelTitle("{{ tr.rendering }}")
        with v.VExpansionPanelText():
            for name in ("shading", "model", "interpolation", "hidden_surface", "transparency"):
                v.VSelect(v_model=(name,), items=(f"tr.choices.{name}",), label=(f"tr.{name}",),
                          error_messages=_problem(f"'{name}'"), classes=f"select-{name}", **COMPACT)
            for name in ("cull_backfaces", "separate_specular"):
                v.VSwitch(v_model=(name,), label=(f"tr.{name}",), color="primary", classes=f"switch-{name}",
                          **COMPACT)


def material_panel():
    path = "'materials.' + object_index + '.{}'"
    model = "materials[object_index].{}"
    with v.VExpansionPanel(value="material"):
        v.VExpansionPanelTitle("{{ tr.material }}")
        with v.VExpansionPanelText(v_if="materials[object_index]"):
            v.VSelect(v_model=("object_index", 0), items=("object_items",), label=("tr.object",),
                      v_if="object_items.length > 1", **COMPACT)
            _colour(model.format("color"), "materials", path.format("color"), ("tr.color",), "material")
            steps = {"specular_power": (1.0, 128.0, 1.0), "shininess": (0.0, 128.0, 1.0)}
            for name in MATERIAL_RANGES:
                lo, hi, step = steps.get(name, (0.0, 1.0, 0.01))
                _slider(model.format(name), "materials", path.format(name), (f"tr.{name}",), lo, hi, step, name)


def lights_panel():
    path = "'lights.' + light_index + '.{}'"
    model = "lights[light_index].{}"
    with v.VExpansionPanel(value="lights"):
        v.VExpansionPanelTitle("{{ tr.lights }}")
        with v.VExpansionPanelText():
            with v.VRow(dense=True, align="center"):
                with v.VCol(cols=7):
                    v.VSelect(v_model=("light_index", 0), items=("light_items",), label=("tr.light",),
                              v_if="lights.length", **COMPACT)
                with v.VCol(cols=5):
                    v.VBtn("{{ tr.add_light }}", click="trigger('add_light')", size="small", classes="add-light",
                           disabled=("lights.length >= max_lights",))
                    v.VBtn("{{ tr.remove_light }}", click="trigger('remove_light')", size="small",
                           classes="remove-light ml-1", disabled=("!lights.length",))
            html.Div("{{ tr.no_lights }}", v_if="!lights.length", classes="text-caption")
            html.Div("{{ (problems['lights'] || []).join(' ') }}", classes="text-error text-caption")
            with html.Div(v_if="lights[light_index]"):
                v.VSwitch(v_model=model.format("on"), update_modelValue="flushState('lights')", label=("tr.on",),
                          color="primary", **COMPACT)
                v.VSelect(v_model=model.format("kind"), update_modelValue="flushState('lights')",
                          items=("tr.choices.kind",), label=("tr.kind",), error_messages=_problem(path.format("kind")),
                          **COMPACT)
                _triple(model.format("position"), "lights", path.format("position"), "{{ tr.position }}",
                        "light-position")
                _triple(model.format("focal_point"), "lights", path.format("focal_point"), "{{ tr.focal_point }}",
                        "light-focal")
                _colour(model.format("color"), "lights", path.format("color"), ("tr.color",), "light")
                _slider(model.format("intensity"), "lights", path.format("intensity"), ("tr.intensity",),
                        0.0, 2.0, 0.01, "intensity")
                v.VSwitch(v_model=model.format("positional"), update_modelValue="flushState('lights')",
                          label=("tr.positional",), color="primary", classes="switch-positional", **COMPACT)
                _slider(model.format("cone_angle"), "lights", path.format("cone_angle"), ("tr.cone_angle",),
                        1.0, 90.0, 1.0, "cone-angle")
                _slider(model.format("exponent"), "lights", path.format("exponent"), ("tr.exponent",),
                        0.0, 128.0, 1.0, "exponent")
                _triple(model.format("attenuation"), "lights", path.format("attenuation"), "{{ tr.attenuation }}",
                        "attenuation")


def camera_panel():
    with v.VExpansionPanel(value="camera"):
        v.VExpansionPanelTitle("{{ tr.camera }}")
        with v.VExpansionPanelText():
            html.Div("{{ tr.camera_hint }}", classes="text-caption mb-2")
            v.VBtn("{{ tr.zoom_in }}", click="trigger('zoom', [1.25])", size="small", classes="zoom-in")
            v.VBtn("{{ tr.zoom_out }}", click="trigger('zoom', [0.8])", size="small", classes="zoom-out ml-1")
            v.VBtn("{{ tr.reset_camera }}", click="trigger('reset_camera')", size="small", classes="reset-camera ml-1")
            v.VSwitch(v_model="camera.parallel", update_modelValue="flushState('camera')", label=("tr.parallel",),
                      color="primary", classes="switch-parallel", **COMPACT)
            _slider("camera.view_angle", "camera", "'camera.view_angle'", ("tr.view_angle",), 1.0, 120.0, 1.0,
                    "view-angle")
            html.Div("{{ ['camera.position', 'camera.view_up', 'camera.parallel_scale']"
                     ".map(k => (problems[k] || []).join(' ')).join(' ') }}", classes="text-error text-caption")


def break_panel():
    with v.VExpansionPanel(value="break"):
        v.VExpansionPanelTitle("{{ tr.break_it }}")
        with v.VExpansionPanelText():
            with v.VRadioGroup(v_model=("breakage",), classes="radio-breakage", **COMPACT):
                v.VRadio(v_for="b in tr.breakages", key="b.value", label=("b.title",), value=("b.value",))
            html.Div("{{ tr.the_rule }}: {{ tr.breakages.find(b => b.value === breakage).rule }}",
                     v_if="breakage !== 'none'", classes="text-caption")


def control_drawer():
    """The drawer with every control, its panels open at the start."""
    with v.VNavigationDrawer(permanent=True, width=380):
        with v.VExpansionPanels(multiple=True, v_model=("open_panels", ["scene", "rendering", "material"]),
                                variant="accordion"):
            scene_panel()
            rendering_panel()
            material_panel()
            lights_panel()
            camera_panel()
            break_panel()
