"""Standard controls of a curve demo: shape-parameter sliders, joint selector, t slider,
knot slider, display switches, dragging.  Each control changes the state through a
guarded callback (errors become a visible warning) and never re-creates the figure."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from course_lib.widgets.assembly import (
    LABELLED,
    Demo,
    details_checkbox,
    observe,
    selector,
    slider,
    snap_to_step,
)
from course_lib.widgets.state import CurveDemoState, SliderSpec

__all__ = ["assemble_curve_demo"]


def _rounding_only(spec: SliderSpec, st: CurveDemoState, new: float, joint: int | None) -> bool:
    """True if ``new`` is within half a slider step of every value it would replace.

    The browser's slider only shows positions on its step grid (``min + k * step``; for
    a log slider, of the exponent): it snaps a value off the grid, e.g. an initial
    β1 = 1.5 to 10**0.18 = 1.5136, and sends the snapped value back.  That is not a
    move of the user (a move goes at least one step from the shown position, so more
    than half a step from the state's value), and must not change the state.
    """
    cur = np.atleast_1d(np.asarray(st.params[spec.name], dtype=float))
    if joint is not None and cur.size > 1:
        cur = cur[st.joint_of_param(spec.name, joint) : st.joint_of_param(spec.name, joint) + 1]
    if spec.log:
        if new <= 0 or np.any(cur <= 0):
            return False
        gap = np.abs(np.log10(cur) - np.log10(new))
    else:
        gap = np.abs(cur - new)
    return bool(np.all(gap < 0.5 * spec.step))


def assemble_curve_demo(
    demo: Demo,
    sliders: Sequence[SliderSpec] = (),
    *,
    knots: bool = False,
    draggable: bool = True,
    extra_rows: Sequence = (),
) -> Demo:
    """Add the standard widgets to ``demo`` (whose state is a :class:`CurveDemoState`)."""
    st: CurveDemoState = demo.state
    rows = []
    if st.n_joints >= 1:
        rows.append(_joint_row(demo, sliders))
    rows.extend(_parameter_slider(demo, spec) for spec in sliders)
    if knots and st.curve.n_segments >= 2:  # interior knots exist
        rows.append(_knot_row(demo))
    rows.append(_t_slider(demo))
    rows.extend(_switch_rows(demo))
    rows.extend(extra_rows)
    rows.append(details_checkbox(demo))
    if draggable:  # keyboard access to the points, and the live verdict (widgets/access.py)
        from course_lib.widgets.access import point_controls

        rows.append(point_controls(demo))
    demo.build_widgets(rows)
    if draggable:
        from course_lib.widgets.interactor import PointDragger

        demo.dragger = PointDragger(
            demo.view.ax,
            lambda: st.points,
            demo.guard(st.drag),
            on_press=demo.guard(lambda k: setattr(demo.view, "interacting", True)),
            on_release=demo.guard(lambda k: demo.view.end_interaction()),
        )
    return demo


def _joint_row(demo: Demo, sliders: Sequence[SliderSpec]):
    """The joint selector (and, with per-joint sliders, "same value at every joint")."""
    import ipywidgets as w

    st: CurveDemoState = demo.state
    nj = st.n_joints
    joint = selector([(f"joint {j}", j) for j in range(nj)], st.joint, "joint", "12em", "cl-joint")
    demo.controls["joint"] = joint

    def on_joint(change):
        st.select_joint(change["new"])

        def sync():
            for spec in sliders:
                if spec.per_joint:
                    demo.controls[spec.name].value = st.get_param(spec.name, st.joint)

        demo.sync(sync)

    joint.observe(demo.guard(on_joint), names="value")
    if not (any(s.per_joint for s in sliders) and nj > 1):
        return joint
    same = w.Checkbox(value=True, description="same value at every joint", indent=False)
    same.add_class("cl-same-beta")
    demo.controls["same"] = same
    return w.HBox([joint, same])


def _parameter_slider(demo: Demo, spec: SliderSpec):
    """A shape parameter's slider: the whole curve, or the selected joint when "same value
    at every joint" is off."""
    st: CurveDemoState = demo.state
    s = slider(spec, st.get_param(spec.name, st.joint if st.n_joints else None))
    demo.controls[spec.name] = s

    def on_value(change):
        same = demo.controls.get("same")
        j = None if (same is None or same.value or not spec.per_joint) else st.joint
        if _rounding_only(spec, st, change["new"], j):
            return
        st.set_param(spec.name, snap_to_step(spec, change["new"]), joint=j)

    observe(demo, s, on_value)
    return s


def _knot_row(demo: Demo):
    """An interior knot's selector and value slider (kept between its neighbours)."""
    import ipywidgets as w

    st: CurveDemoState = demo.state
    L = st.curve.n_segments
    ksel = selector([(f"t{i}", i) for i in range(1, L)], 1, "knot", "10em")
    kval = w.FloatSlider(
        description="value",
        readout_format=".3g",
        layout=w.Layout(width="22em"),
        continuous_update=True,
        **LABELLED,
    )
    kval.add_class("cl-slider-knot")
    demo.controls["knot_index"] = ksel
    demo.controls["knot"] = kval

    def knot_bounds(i: int) -> None:
        k = st.params["knots"]
        gap = k[i + 1] - k[i - 1]
        lo, hi = k[i - 1] + 0.02 * gap, k[i + 1] - 0.02 * gap
        # set in an order that never makes min > max
        if lo > kval.max:
            kval.max = hi
            kval.min = lo
        else:
            kval.min = lo
            kval.max = hi
        kval.step = gap / 200
        kval.value = float(k[i])

    demo.sync(lambda: knot_bounds(1))

    def on_knot_select(change):
        demo.sync(lambda: knot_bounds(change["new"]))

    def on_knot(change):
        if abs(change["new"] - st.params["knots"][ksel.value]) < 0.5 * kval.step:
            return  # the browser snapped the knot to its slider grid (see _rounding_only)
        st.set_param("knots", change["new"], joint=ksel.value)

    ksel.observe(demo.guard(on_knot_select), names="value")
    observe(demo, kval, on_knot)
    return w.HBox([ksel, kval])


def _t_slider(demo: Demo):
    """The moving point's parameter ``t`` over the curve's domain."""
    import ipywidgets as w

    st: CurveDemoState = demo.state
    a, b = st.curve.domain
    tsl = w.FloatSlider(
        value=st.t,
        min=a,
        max=b,
        step=(b - a) / 400,
        description="t",
        readout_format=".3g",
        continuous_update=True,
        layout=w.Layout(width="22em"),
        **LABELLED,
    )
    tsl.add_class("cl-slider-t")
    demo.controls["t"] = tsl
    observe(demo, tsl, lambda ch: st.set_t(ch["new"]))
    return tsl


def _switch_rows(demo: Demo) -> list:
    """The display switches, two per row."""
    import ipywidgets as w

    st: CurveDemoState = demo.state
    boxes = []
    for key, flag, text in (
        ("comb", "show_comb", "curvature comb"),
        ("tangents", "show_tangents", "T and dT/ds at t"),
        ("circle", "show_circle", "osculating circle"),
        ("curvature", "show_curvature", "κ(s) plot"),
    ):
        cb = w.Checkbox(
            value=getattr(st, flag), description=text, indent=False, layout=w.Layout(width="auto")
        )
        cb.add_class(f"cl-check-{key}")
        cb.observe(demo.guard(lambda ch, flag=flag: st.set_flag(flag, ch["new"])), names="value")
        demo.controls[key] = cb
        boxes.append(cb)
    return [w.HBox(boxes[:2]), w.HBox(boxes[2:])]
