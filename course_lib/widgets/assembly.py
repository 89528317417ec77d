"""The widgets around a demo: :class:`Demo` and the controls every demo builds from.

* :class:`Demo` -- a demo's state, its view and (unless static) its widgets: the report,
  the warning, the error output, the outer box; callbacks are guarded (an error becomes a
  visible warning, never a silent failure).  With ``static=True`` or without
  ipywidgets/ipympl (:func:`resolve_static`) it is just the figure.
* Control factories shared by every demo and by ``access.py``: :func:`slider` (from a
  :class:`~course_lib.widgets.state.SliderSpec`), :func:`selector` (a labelled dropdown),
  :func:`observe` (guarded and coalesced callbacks), :func:`details_checkbox`;
  :func:`readout_format` and :func:`snap_to_step` keep slider values on their grid.

No math here, and no drawing: the state computes, the view draws.
"""

from __future__ import annotations

import traceback
from collections.abc import Callable, Sequence

import numpy as np

from course_lib.widgets.report import warning_span
from course_lib.widgets.state import SliderSpec

__all__ = [
    "LABELLED",
    "Demo",
    "details_checkbox",
    "observe",
    "readout_format",
    "resolve_static",
    "selector",
    "slider",
    "snap_to_step",
    "widgets_available",
]

#: The style of a labelled control: descriptions 3em wide, so that controls line up.
LABELLED = {"style": {"description_width": "3em"}}


def widgets_available() -> bool:
    """True if ipywidgets and ipympl can be imported (checked without importing them)."""
    # find_spec, not import: importing ipympl would switch pyplot's backend
    from importlib.util import find_spec

    return find_spec("ipympl") is not None and find_spec("ipywidgets") is not None


def resolve_static(static: bool | None) -> bool:
    """A demo's ``static`` argument: as given, or (``None``) True when widgets are missing."""
    return (not widgets_available()) if static is None else bool(static)


def selector(options, value, description: str, width: str, css: str | None = None):
    """A labelled dropdown (joint, knot, point), with class ``css`` if given."""
    import ipywidgets as w

    drop = w.Dropdown(
        options=options, value=value, description=description, layout=w.Layout(width=width),
        **LABELLED,
    )  # fmt: skip
    if css:
        drop.add_class(css)
    return drop


def _decimals(step: float) -> int:
    """Decimals needed to write multiples of ``step`` (0.1 -> 1, 0.0025 -> 4)."""
    for d in range(0, 10):
        if abs(round(step, d) - step) <= 1e-9 * abs(step):
            return d
    return 10


def readout_format(spec: SliderSpec) -> str:
    """Fixed decimals from the step for a linear slider (``"0.0"``, never ``"-1.78e-15"``:
    d3-format writes a negative number that rounds to zero without its sign); three
    significant digits for a log slider."""
    return ".3g" if spec.log else f".{max(1, _decimals(spec.step))}f"


def snap_to_step(spec: SliderSpec, value: float) -> float:
    """``value`` without the float error of the slider's grid: a value within 1e-6 step of
    a position ``min + k * step`` (for a log slider, of the exponent grid) becomes that
    position rounded to the step's decimals (``-10 + 100 * 0.1 = -1.78e-15`` becomes 0.0,
    ``1.0999999999999996`` becomes 1.1); any other value (set from code) is kept."""
    v = float(value)
    d = _decimals(spec.step) + 2
    if spec.log:
        if v <= 0:
            return v
        lo = float(np.floor(np.log10(spec.min) / spec.step + 1e-9) * spec.step)
        e = float(np.log10(v))
        k = round((e - lo) / spec.step)
        if abs(e - (lo + k * spec.step)) > 1e-6 * spec.step:
            return v
        return float(10.0 ** round(lo + k * spec.step, d))
    k = round((v - spec.min) / spec.step)
    grid = spec.min + k * spec.step
    if abs(v - grid) > 1e-6 * spec.step:
        return v
    return round(grid, d) + 0.0  # + 0.0: no "-0"


def slider(spec: SliderSpec, value: float):
    """A FloatSlider (FloatLogSlider for ``spec.log``) for ``spec`` at ``value``, class
    ``spec.css``; ``ValueError`` if ``value`` is outside the slider (never clamped)."""
    import ipywidgets as w

    spec.check(value)  # never clamp silently

    common = {
        "value": float(value),
        "step": spec.step,
        "description": spec.description,
        "continuous_update": True,
        "readout_format": readout_format(spec),
        **LABELLED,
        "layout": w.Layout(width="22em"),
    }
    if spec.log:
        if spec.min <= 0:
            raise ValueError(f"a log slider needs min > 0; {spec.name} has min {spec.min}")
        # exponent bounds on the step grid, so that 10**0 = 1 is a slider position
        # (otherwise the browser snaps an initial β1 = 1 to 0.9976); rounded outwards, so
        # that the whole range [min, max] is on the slider
        lo = float(np.floor(np.log10(spec.min) / spec.step + 1e-9) * spec.step)
        hi = float(np.ceil(np.log10(spec.max) / spec.step - 1e-9) * spec.step)
        s = w.FloatLogSlider(base=10, min=lo, max=hi, **common)
    else:
        s = w.FloatSlider(min=spec.min, max=spec.max, **common)
    s.add_class(spec.css)
    return s


class Demo:
    """A demo: its state, its figure and (unless static) its widgets.

    Attributes
    ----------
    state : CurveDemoState (or the demo's own state object)
    view : the figure's view object; ``figure`` is its matplotlib Figure
    controls : dict of name -> widget (sliders ``"beta1"``, ``"beta2"``, ``"t"``,
        ``"knot"``, selectors ``"joint"``, checkboxes ``"comb"``, ``"tangents"``, ...)
    report, warning : ipywidgets.HTML (classes ``cl-report``, ``cl-warning``)
    output : ipywidgets.Output, where errors raised in callbacks are written
    widget : the outer ``VBox`` (class ``cl-demo``), None when static
    """

    def __init__(self, state, view, *, static: bool) -> None:
        self.state = state
        self.view = view
        self.static = static
        self.controls: dict = {}
        self.report = self.warning = self.output = self.widget = None
        self._busy = False

    @property
    def figure(self):
        return self.view.fig

    # ----------------------------------------------------------- callbacks
    def guard(self, fn: Callable) -> Callable:
        """Wrap a widget callback: any exception is shown in the warning and the output."""

        def wrapped(*args, **kwargs):
            if self._busy:
                return None
            try:
                return fn(*args, **kwargs)
            except Exception as exc:  # a callback must never fail silently
                self.show_error(exc)
                return None

        return wrapped

    def show_error(self, exc: BaseException) -> None:
        if self.warning is not None:
            self.warning.value = warning_span(f"{type(exc).__name__}: {exc}")
            self.warning.layout.display = None
        if self.output is not None:
            self.output.append_stderr("".join(traceback.format_exception(exc)))
        if self.widget is None:
            raise exc

    def refresh(self, state=None) -> None:
        """Copy the state's report and warning into the widgets."""
        if self.report is None:
            return
        st = self.state
        self.report.value = st.report_html()
        if st.warning:
            self.warning.value = warning_span(st.warning)
            self.warning.layout.display = None
        else:
            self.warning.value = ""
            self.warning.layout.display = "none"

    def sync(self, fn: Callable) -> None:
        """Run ``fn``, which changes widget values, without triggering their callbacks."""
        self._busy = True
        try:
            fn()
        finally:
            self._busy = False

    # ----------------------------------------------------------- assembly
    def build_widgets(self, rows: Sequence) -> None:
        import ipywidgets as w

        self.report = w.HTML(layout=w.Layout(width="auto"))
        self.report.add_class("cl-report")
        self.warning = w.HTML(layout=w.Layout(display="none"))
        self.warning.add_class("cl-warning")
        self.output = w.Output(layout=w.Layout(max_height="12em", overflow="auto"))
        self.output.add_class("cl-output")
        controls = w.VBox([r for r in rows if r is not None])
        side = w.VBox([self.warning, self.report], layout=w.Layout(margin="0 0 0 1em"))
        self.widget = w.VBox([self.view.fig.canvas, w.HBox([controls, side]), self.output])
        self.widget.add_class("cl-demo")
        if hasattr(self.state, "listeners"):
            self.state.listeners.append(self.refresh)
        self.refresh()

    # ----------------------------------------------------------- display
    def _repr_mimebundle_(self, **kwargs):
        if self.widget is not None:
            from course_lib.widgets.slider_names import publish_slider_names

            publish_slider_names()  # names the slider handles (ipywidgets leaves them unnamed)
            return self.widget._repr_mimebundle_(**kwargs)
        import io

        buf = io.BytesIO()
        self.view.fig.savefig(buf, format="png", dpi=100)
        import base64

        return {
            "image/png": base64.b64encode(buf.getvalue()).decode("ascii"),
            "text/plain": repr(self),
        }

    def __repr__(self) -> str:
        kind = "static figure" if self.widget is None else "interactive"
        return f"<{type(self).__name__} {getattr(self, 'name', '')} ({kind})>"


def observe(demo: Demo, widget, fn) -> None:
    """``widget.observe(fn)`` on ``value``, guarded (errors shown) and coalesced: a value
    from the browser that waited behind the previous redraw is superseded by the newest.
    A value set by code (ipywidgets holds no property lock for it) is handled at once."""
    from course_lib.widgets._coalesce import Coalescer

    def from_browser() -> bool:
        return "value" in getattr(widget, "_property_lock", {})

    c = Coalescer(demo.guard(fn), may_defer=from_browser)
    widget.observe(c, names="value")
    demo.coalescers = [*getattr(demo, "coalescers", []), c]


def details_checkbox(demo: Demo):
    """ "more detail" switch of the report (class ``cl-check-details``)."""
    import ipywidgets as w

    cb = w.Checkbox(
        value=bool(getattr(demo.state, "show_details", False)),
        description="more detail in the report (higher orders, residuals)",
        indent=False,
        layout=w.Layout(width="auto"),
    )
    cb.add_class("cl-check-details")
    cb.observe(demo.guard(lambda ch: demo.state.set_details(ch["new"])), names="value")
    demo.controls["details"] = cb
    return cb
