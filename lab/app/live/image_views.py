"""The live lab's page: the bar at the top, and the images — ours | VTK | ΔE2000 with the
metrics and the verdict, a wipe between ours and VTK, and the stage views.

Every image is drawn on the server (our renderer; VTK offscreen; the ΔE map in the
colours of the comparison panels) and arrives as a PNG data URL in the state. Each
``<img>`` carries the number of the request it shows (``data-request``), so a test can
tell which change is on screen. Our image takes the pointer: dragging orbits the camera
(``trigger('orbit', [right, down])`` as fractions of the image), the wheel zooms.
"""
from __future__ import annotations

from trame.widgets import html
from trame.widgets import vuetify3 as v

from lab.app.lesson_site.figure_images import colour_bar_stops

METRIC_ROWS = ("mean", "p999", "max", "pixels_over_1", "coverage_mismatch", "max_channel_diff", "depth", "reference")
"""The figures under the images, in order (keys of the state's ``metrics_view``)."""

IMAGE_STYLE = "width: 100%; height: auto; display: block; image-rendering: pixelated; touch-action: none; user-select: none;"
DIMMED = "opacity: 0.45;"


def _image(src: str, request: str, ident: str, alt: str, dim: str | None = None, **events):
    """An ``<img>`` of state key ``src``, tagged with the request it shows."""
    style = f"`{IMAGE_STYLE}` + ({dim} ? `{DIMMED}` : ``)" if dim else f"`{IMAGE_STYLE}`"
    html.Img(src=(src,), id=ident, alt=alt, draggable="false", style=(style,),
             __properties=[("data_request", "data-request")], data_request=(request,), v_if=src, **events)
    v.VProgressCircular(indeterminate=True, v_if=f"!{src}", classes="ma-4")


def top_bar():
    with v.VAppBar(density="compact", elevation=1):
        v.VToolbarTitle("{{ tr.title }}")
        html.Span("{{ tr.request }} {{ request }}", classes="text-caption mr-4 request-counter")
        v.VTextField(v_model=("save_name", "my-scene"), label=("tr.save_name",), error_messages=("problems.save_name || []",),
                     density="compact", hide_details="auto", style="max-width: 200px", classes="field-save-name mr-2")
        v.VBtn("{{ tr.save }}", click="trigger('save')", variant="tonal", classes="save-scene mr-4")
        with v.VBtnToggle(v_model=("lang", "en"), mandatory=True, density="compact", classes="lang-toggle mr-2"):
            v.VBtn("English", value="en", classes="lang-en")
            v.VBtn("日本語", value="ja", classes="lang-ja")


def _metrics_table():
    with v.VTable(density="compact", classes="metrics"):
        with html.Tbody():
            with html.Tr(v_for=f"key in {list(METRIC_ROWS)}", key="key"):
                html.Td("{{ tr[key] }}")
                html.Td("{{ metrics_view[key] }}", id=("`metric-${key}`",))
            with html.Tr():
                html.Td("{{ tr.verdict }}")
                with html.Td():
                    v.VChip("{{ tr.status[verdict_status] || verdict_status }}",
                            color=("verdict_ok ? 'success' : 'error'",), size="small", id="verdict",
                            v_if="verdict_status")
                    html.Div("{{ failed_bars.join('; ') }}", classes="text-caption failed-bars")


def _colour_bar():
    stops = ", ".join(colour_bar_stops())
    with html.Div(classes="text-caption mt-1"):
        html.Div(style=f"height: 10px; background: linear-gradient(to right, {stops}); border: 1px solid #aaa")
        with html.Div(style="display: flex; justify-content: space-between"):
            html.Span("0")
            html.Span("{{ tr.colour_bar }}")
            html.Span("≥5")
        with html.Div():
            html.Span(style="display:inline-block;width:10px;height:10px;background:#ff00ff;margin-right:4px")
            html.Span("{{ tr.mismatch }}", classes="mr-3")
            html.Span(style="display:inline-block;width:10px;height:10px;background:#d9d9d9;margin-right:4px;"
                            "border:1px solid #aaa")
            html.Span("{{ tr.neither }}")


def compare_view():
    measuring = "measure_request < request"
    with v.VRow(dense=True):
        with v.VCol(cols=12, md=4):
            with v.VCard(variant="outlined"):
                v.VCardTitle("{{ breakage !== 'none' ? tr.ours_broken : tr.ours }}", classes="text-subtitle-1")
                _image("ours_src", "ours_request", "ours", "scanlab",
                       pointerdown="$event.target.setPointerCapture($event.pointerId)",
                       pointermove=("$event.buttons === 1 && trigger('orbit', [$event.movementX / "
                                    "$event.target.clientWidth, $event.movementY / $event.target.clientHeight])"),
                       wheel="$event.preventDefault(); trigger('zoom', [$event.deltaY < 0 ? 1.1 : 1 / 1.1])",
                       __events=["pointerdown", "pointermove", "wheel"])
                html.Div("{{ tr.camera_hint }}", classes="text-caption pa-1")
        with v.VCol(cols=12, md=4):
            with v.VCard(variant="outlined"):
                v.VCardTitle("{{ tr.vtk }}", classes="text-subtitle-1")
                _image("vtk_src", "measure_request", "vtk", "VTK", dim=measuring)
        with v.VCol(cols=12, md=4):
            with v.VCard(variant="outlined"):
                v.VCardTitle("{{ tr.delta_e }}", classes="text-subtitle-1")
                _image("de_src", "measure_request", "delta-e", "ΔE2000", dim=measuring)
                _colour_bar()
    with v.VRow(dense=True):
        with v.VCol(cols=12, md=6):
            v.VAlert("{{ tr.measuring }}", v_if=measuring, density="compact", type="info", variant="tonal",
                     classes="measuring")
            v.VAlert("{{ measure_error }}", v_if="measure_error", density="compact", type="error", classes="measure-error")
            _metrics_table()
            html.Div("{{ tr.timing.replace('{ours}', ours_ms).replace('{measure}', measure_ms) }}",
                     classes="text-caption")
        with v.VCol(cols=12, md=6):
            wipe_view()


def wipe_view():
    with v.VCard(variant="outlined"):
        v.VCardTitle("{{ tr.wipe }}", classes="text-subtitle-1")
        with html.Div(style="position: relative; max-width: 420px; margin: auto", classes="wipe",
                      v_if="ours_src && vtk_src"):
            html.Img(src=("vtk_src",), style=f"{IMAGE_STYLE}", alt="VTK", classes="wipe-base")
            html.Img(src=("ours_src",), alt="scanlab", classes="wipe-top",
                     style=(f"`{IMAGE_STYLE} position: absolute; top: 0; left: 0; "
                            "clip-path: inset(0 ${100 - wipe}% 0 0)`",))
        v.VSlider(v_model=("wipe", 50), min=0, max=100, step=1, label=("tr.wipe_amount",), hide_details=True,
                  density="compact", classes="slider-wipe px-2")


def stages_view():
    with v.VCard(variant="outlined"):
        v.VCardText("{{ tr.stages_caption }} {{ tr.stages_labels }}")
        html.Img(src=("stages_src",), id="stages", alt="stages", v_if="stages_src",
                 style="max-width: 100%; height: auto; display: block",
                 __properties=[("data_request", "data-request")], data_request=("measure_request",))
        v.VProgressCircular(indeterminate=True, v_if="!stages_src", classes="ma-4")


def main_area():
    with v.VMain():
        with v.VContainer(fluid=True):
            v.VAlert("{{ tr.fix_fields }}", v_if="Object.keys(problems).length", type="warning", density="compact",
                     classes="problems mb-2")
            v.VAlert("{{ render_error }}", v_if="render_error", type="error", density="compact", classes="render-error mb-2")
            with v.VAlert(v_if="saved_path", type="success", density="compact", closable=True, classes="saved mb-2"):
                html.Div("{{ tr.saved.replace('{path}', saved_path) }}")
                html.Div("{{ tr.reproduce }}:")
                html.Pre("{{ saved_commands.join('\\n') }}", classes="saved-commands")
                html.Div("{{ tr.save_broken }}", v_if="saved_commands.length > 1", classes="text-caption")
            with v.VTabs(v_model=("view", "compare"), density="compact"):
                v.VTab("{{ tr.compare_tab }}", value="compare", classes="tab-compare")
                v.VTab("{{ tr.stages_tab }}", value="stages", classes="tab-stages")
            with v.VWindow(v_model=("view",)):
                with v.VWindowItem(value="compare"):
                    compare_view()
                with v.VWindowItem(value="stages"):
                    stages_view()
