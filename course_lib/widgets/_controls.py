"""Standard controls of a curve demo: shape-parameter sliders, joint selector, t slider,
knot slider, display switches, dragging.  Each control changes the state through a
guarded callback (errors become a visible warning) and never re-creates the figure."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from course_lib.widgets._core import CurveDemoState, Demo, SliderSpec

__all__ = ["assemble_curve_demo", "readout_format", "snap_to_step"]


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


def make_slider(spec: SliderSpec, value: float):
    import ipywidgets as w

    spec.check(value)  # never clamp silently

    common = {
        "value": float(value),
        "step": spec.step,
        "description": spec.description,
        "continuous_update": True,
        "readout_format": readout_format(spec),
        "style": {"description_width": "3em"},
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
    import ipywidgets as w

    from course_lib.widgets.interactor import PointDragger

    st: CurveDemoState = demo.state
    rows = []
    nj = st.n_joints
    per_joint = any(s.per_joint for s in sliders) and nj > 1
    if nj >= 1:
        joint = w.Dropdown(
            options=[(f"joint {j}", j) for j in range(nj)],
            value=st.joint,
            description="joint",
            style={"description_width": "3em"},
            layout=w.Layout(width="12em"),
        )
        joint.add_class("cl-joint")
        demo.controls["joint"] = joint
        if per_joint:
            same = w.Checkbox(value=True, description="same value at every joint", indent=False)
            same.add_class("cl-same-beta")
            demo.controls["same"] = same
            rows.append(w.HBox([joint, same]))
        else:
            rows.append(joint)
    for spec in sliders:
        s = make_slider(spec, st.get_param(spec.name, st.joint if nj else None))
        demo.controls[spec.name] = s

        def on_value(change, spec=spec):
            same = demo.controls.get("same")
            j = None if (same is None or same.value or not spec.per_joint) else st.joint
            if _rounding_only(spec, st, change["new"], j):
                return
            st.set_param(spec.name, snap_to_step(spec, change["new"]), joint=j)

        observe(demo, s, on_value)
        rows.append(s)

    if knots and st.curve.n_segments >= 2:  # interior knots exist
        L = st.curve.n_segments
        ksel = w.Dropdown(
            options=[(f"t{i}", i) for i in range(1, L)],
            value=1,
            description="knot",
            style={"description_width": "3em"},
            layout=w.Layout(width="10em"),
        )
        kval = w.FloatSlider(
            description="value",
            readout_format=".3g",
            style={"description_width": "3em"},
            layout=w.Layout(width="22em"),
            continuous_update=True,
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

        demo._sync(lambda: knot_bounds(1))

        def on_knot_select(change):
            demo._sync(lambda: knot_bounds(change["new"]))

        def on_knot(change):
            if abs(change["new"] - st.params["knots"][ksel.value]) < 0.5 * kval.step:
                return  # the browser snapped the knot to its slider grid (see _rounding_only)
            st.set_param("knots", change["new"], joint=ksel.value)

        ksel.observe(demo.guard(on_knot_select), names="value")
        observe(demo, kval, on_knot)
        rows.append(w.HBox([ksel, kval]))

    a, b = st.curve.domain
    tsl = w.FloatSlider(
        value=st.t,
        min=a,
        max=b,
        step=(b - a) / 400,
        description="t",
        readout_format=".3g",
        continuous_update=True,
        style={"description_width": "3em"},
        layout=w.Layout(width="22em"),
    )
    tsl.add_class("cl-slider-t")
    demo.controls["t"] = tsl
    observe(demo, tsl, lambda ch: st.set_t(ch["new"]))
    rows.append(tsl)

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
    rows.append(w.HBox(boxes[:2]))
    rows.append(w.HBox(boxes[2:]))
    rows.extend(extra_rows)
    rows.append(details_checkbox(demo))
    if draggable:  # keyboard access to the points, and the live verdict (widgets/access.py)
        from course_lib.widgets.access import point_controls

        rows.append(point_controls(demo))

    if nj >= 1:

        def on_joint(change):
            st.select_joint(change["new"])

            def sync():
                for spec in sliders:
                    if spec.per_joint:
                        demo.controls[spec.name].value = st.get_param(spec.name, st.joint)

            demo._sync(sync)

        demo.controls["joint"].observe(demo.guard(on_joint), names="value")

    demo.build_widgets(rows)
    if draggable:
        demo.dragger = PointDragger(
            demo.view.ax,
            lambda: st.points,
            demo.guard(st.drag),
            on_press=demo.guard(lambda k: setattr(demo.view, "interacting", True)),
            on_release=demo.guard(lambda k: demo.view.end_interaction()),
        )
    return demo


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
