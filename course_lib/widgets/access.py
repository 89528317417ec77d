"""Keyboard and screen-reader access to the demos (WCAG 2.1 AA: 2.1.1, 4.1.2, 4.1.3).

A mouse drags a control point on the canvas; a keyboard (or a switch, or a screen reader)
cannot.  :func:`point_controls` adds what it needs, next to the canvas:

* a point selector ``P0 … Pn`` (``Dropdown``, class ``cl-point-select``);
* the selected point's coordinates as two labelled number fields ``x`` and ``y``
  (``BoundedFloatText``, classes ``cl-point-x``, ``cl-point-y``): type a value, or press
  the arrow keys in a field to nudge the point by one step;
* four nudge buttons (``left``, ``right``, ``up``, ``down``, class ``cl-nudge-<dir>``) and a
  step switch ``fine``/``coarse`` (class ``cl-point-step``; coarse is ten fine steps);
* a live region (an ``HTML`` widget, class ``cl-live``, holding ``role="status"
  aria-live="polite"``): the selected point and its coordinates, and the continuity
  report's one-line verdict (:func:`verdict`), announced by screen readers when it changes.

The selected point is ringed in the picture.  Every move goes through the state's own
``drag(k, x, y)``, as a mouse drag does; nothing here touches the drag code.

ipywidgets 8 draws a slider with noUiSlider and does not link the slider's description to
its handle: the handle has no accessible name, and a log slider reports its exponent as
its value.  :data:`SLIDER_NAMES_JS` (sent with each interactive demo, see
:func:`slider_names_bundle`) names every slider handle inside a demo by its description and
gives it the readout's text as its value text ("1.5", not "0.18"); it also marks the demo's
controls ``data-lm-suppress-shortcuts``, so that JupyterLab's notebook shortcuts (arrow keys, Enter)
leave the keys to the demo's controls while one of them has the focus.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from course_lib.widgets.assembly import selector
from course_lib.widgets.report import live_html
from course_lib.widgets.slider_names import (
    SLIDER_NAMES_JS,
    publish_slider_names,
    slider_names_bundle,
)
from course_lib.widgets.view import BlitView, ring_marker

__all__ = [
    "SLIDER_NAMES_JS",
    "PointControls",
    "point_controls",
    "publish_slider_names",
    "slider_names_bundle",
    "verdict",
]

#: Front-end fix-up for ipywidgets' sliders inside course demos (idempotent; one
#: MutationObserver per page): ``aria-label`` from the description, ``aria-valuetext`` from
#: the readout; the canvas gets a name (``role="img"``).
def verdict(state) -> str:
    """The continuity report's verdict in one sentence (what a screen reader announces).

    >>> from course_lib.widgets import beta_spline_demo
    >>> verdict(beta_spline_demo(static=True).state)
    'Joint 0: G2, as wanted; parametric C2.'
    """
    report = getattr(state, "report", None)
    if report is None or not hasattr(report, "g_order"):
        warning = getattr(state, "warning", "")
        return f"Warning: {warning}" if warning else ""
    n = max(0, min(int(getattr(state, "order", report.max_order)), report.max_order))
    g, c = report.g_order, report.c_order
    where = "Joint" if report.index is None else f"Joint {report.index}"
    if g < 0:
        geo = "the pieces do not meet (not G0)"
    elif g >= n:
        geo = f"G{n}, as wanted"
    else:
        geo = f"G{g} only, not G{g + 1} (G{n} wanted)"
    par = "not C0" if c < 0 else f"C{min(c, n)}"
    text = f"{where}: {geo}; parametric {par}."
    if getattr(state, "warning", ""):
        text += f" Warning: {state.warning}"
    return text


def _nice_step(extent: float) -> float:
    """A round fine step, about 1/200 of ``extent`` (1, 2 or 5 times a power of ten)."""
    raw = max(float(extent), 1e-12) / 200
    p = 10.0 ** math.floor(math.log10(raw))
    return min((m * p for m in (1, 2, 5, 10)), key=lambda s: abs(s - raw))


def _fmt(x: float, step: float) -> str:
    d = max(0, -math.floor(math.log10(step))) if step > 0 else 2
    return f"{x:.{d}f}"


class PointControls:
    """Keyboard control of a demo's points (see the module docstring).

    Parameters
    ----------
    demo : Demo
        An interactive demo (its widgets not yet assembled).
    points : callable
        Returns the current draggable points, shape ``(n, 2)``.
    move : callable ``(k, x, y)``
        Moves point ``k`` (the state's ``drag``); errors are shown by ``demo.guard``.
    describe : callable ``(state) -> str``, optional
        The one-line verdict (default :func:`verdict`).
    label : str
        Point names are ``f"{label}{k}"`` (default ``"P"``).
    """

    def __init__(
        self,
        demo,
        points: Callable[[], np.ndarray],
        move: Callable[[int, float, float], None],
        describe: Callable[[object], str] = verdict,
        label: str = "P",
    ) -> None:
        import ipywidgets as w

        self.demo, self.points, self.move, self.describe = demo, points, move, describe
        self.label = label
        P = np.asarray(points(), dtype=float)
        if P.ndim != 2 or P.shape[1] != 2 or len(P) == 0:
            raise ValueError(f"points must return an (n, 2) array with n >= 1; got {P.shape}")
        lo, hi = P.min(axis=0), P.max(axis=0)
        extent = float(max(hi - lo)) or 1.0
        self.fine = _nice_step(extent)
        self.coarse = 10 * self.fine
        pad = 2 * extent
        self.selected = 0
        self.message = ""
        self.select = selector(self._options(len(P)), 0, "point", "9em", "cl-point-select")
        common = dict(
            step=self.fine,
            continuous_update=True,
            style={"description_width": "1.2em"},
            layout=w.Layout(width="9.5em"),
        )
        self.x = w.BoundedFloatText(
            value=float(P[0, 0]),
            min=float(lo[0] - pad),
            max=float(hi[0] + pad),
            description="x",
            **common,
        )
        self.y = w.BoundedFloatText(
            value=float(P[0, 1]),
            min=float(lo[1] - pad),
            max=float(hi[1] + pad),
            description="y",
            **common,
        )
        self.x.add_class("cl-point-x")
        self.y.add_class("cl-point-y")
        self.step = w.ToggleButtons(
            options=["fine", "coarse"],
            value="fine",
            description="step",
            tooltips=[f"{_fmt(self.fine, self.fine)} per press", f"{self.coarse:g} per press"],
            style={"description_width": "3em", "button_width": "4.5em"},
        )
        self.step.add_class("cl-point-step")
        self.buttons = {}
        for name, (dx, dy), sym in (
            ("left", (-1, 0), "←"),
            ("right", (1, 0), "→"),
            ("down", (0, -1), "↓"),
            ("up", (0, 1), "↑"),
        ):
            b = w.Button(
                description=f"{sym} {name}",
                tooltip=f"move the selected point {name} by one step",
                layout=w.Layout(width="6.5em"),
            )
            b.add_class(f"cl-nudge-{name}")
            b.on_click(demo.guard(lambda _b, dx=dx, dy=dy: self.nudge(dx, dy)))
            self.buttons[name] = b
        self.live = w.HTML(layout=w.Layout(width="auto", min_height="1.5em"))
        self.live.add_class("cl-live")
        self.ring = None
        view = getattr(demo, "view", None)
        if view is not None and getattr(view, "ax", None) is not None:
            from course_lib.plotting.style import OKABE_ITO

            self.ring = ring_marker(
                view.ax, OKABE_ITO["black"], ms=17, mew=2.0, zorder=9, label="_selected point"
            )
            if isinstance(view, BlitView):
                view.add_dynamic(self.ring)
        self.select.observe(demo.guard(self._on_select), names="value")
        self.x.observe(demo.guard(self._on_field), names="value")
        self.y.observe(demo.guard(self._on_field), names="value")
        self.step.observe(demo.guard(self._on_step), names="value")
        listeners = getattr(demo.state, "listeners", None)
        if listeners is not None:
            listeners.append(self.refresh)
        self.message = self._where("selected")
        self.refresh()
        self.widget = w.VBox(
            [
                w.HBox([self.select, self.x, self.y]),
                w.HBox([self.step, *self.buttons.values()]),
                self.live,
            ]
        )
        self.widget.add_class("cl-point-controls")

    # ------------------------------------------------------------------ helpers
    def _options(self, n: int) -> list[tuple[str, int]]:
        return [(f"{self.label}{k}", k) for k in range(n)]

    def _where(self, what: str) -> str:
        P = np.asarray(self.points(), dtype=float)
        x, y = P[self.selected]
        s = self.fine
        return f"{self.label}{self.selected} {what}: x = {_fmt(x, s)}, y = {_fmt(y, s)}."

    def live_text(self) -> str:
        """What the live region says: the last keyboard action, then the verdict."""
        return " ".join(t for t in (self.message, self.describe(self.demo.state)) if t)

    # ---------------------------------------------------------------- actions
    def select_point(self, k: int) -> None:
        """Select point ``k`` (the selector, the fields and the ring follow)."""
        n = len(self.points())
        if not 0 <= int(k) < n:
            raise ValueError(f"point must be in 0..{n - 1}; got {k}")
        self.select.value = int(k)

    def nudge(self, dx: int, dy: int) -> None:
        """Move the selected point by ``(dx, dy)`` steps of the current size."""
        s = self.coarse if self.step.value == "coarse" else self.fine
        x, y = np.asarray(self.points(), dtype=float)[self.selected]
        self._move(x + dx * s, y + dy * s)

    def _move(self, x: float, y: float) -> None:
        self.move(self.selected, float(x), float(y))
        self.message = self._where("moved to")
        self.refresh()

    def _on_select(self, change) -> None:
        self.selected = int(change["new"])
        self.message = self._where("selected")
        self.refresh()

    def _on_field(self, change) -> None:
        self._move(self.x.value, self.y.value)

    def _on_step(self, change) -> None:
        s = self.coarse if change["new"] == "coarse" else self.fine

        def steps():
            self.x.step = self.y.step = s

        self.demo.sync(steps)

    def refresh(self, state=None) -> None:
        """Bring the fields, the ring and the live region up to date with the state."""
        P = np.asarray(self.points(), dtype=float)
        if len(self.select.options) != len(P):  # e.g. another glyph was chosen
            self.selected = min(self.selected, len(P) - 1)

            def options():
                self.select.options = self._options(len(P))
                self.select.value = self.selected

            self.demo.sync(options)
        x, y = P[self.selected]

        def fields():
            for f, v in ((self.x, x), (self.y, y)):
                if abs(f.value - v) > 1e-12:
                    f.min, f.max = min(f.min, v), max(f.max, v)
                    f.value = float(v)

        self.demo.sync(fields)
        if self.ring is not None:
            self.ring.set_data([x], [y])
            view = self.demo.view
            if state is None and hasattr(view, "render"):
                view.render()
        text = self.live_text()
        value = live_html(text)
        if self.live.value != value:
            self.live.value = value


def point_controls(demo, points=None, move=None, describe: Callable = verdict, label: str = "P"):
    """Add :class:`PointControls` to ``demo`` (``demo.controls["points"]``); returns its box.

    ``points`` defaults to ``lambda: demo.state.points`` and ``move`` to ``demo.state.drag``.
    """
    pc = PointControls(
        demo,
        points if points is not None else (lambda: demo.state.points),
        move if move is not None else demo.state.drag,
        describe,
        label,
    )
    demo.controls["points"] = pc
    return pc.widget
