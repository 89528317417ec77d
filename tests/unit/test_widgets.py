"""Demos driven through their state and widgets, without a browser (Agg / headless ipympl).

Expected values come from closed forms or from the continuity analysis of the math
layer (which measures β's independently of the construction that used them).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.backend_bases import MouseEvent

from course_lib import PiecewiseBezier
from course_lib.widgets import (
    CurveDemoState,
    Demo,
    PointDragger,
    curvature_comb_demo,
    reparametrization_demo,
)

CSS = {"cl-demo", "cl-slider-t", "cl-report", "cl-canvas", "cl-warning"}


def all_widgets(w):
    out = [w]
    for c in getattr(w, "children", ()):
        out += all_widgets(c)
    return out


def classes(demo: Demo) -> set:
    return {c for w in all_widgets(demo.widget) for c in w._dom_classes}


def mouse(canvas, kind, xy_px, button=1):
    ev = MouseEvent(kind, canvas, float(xy_px[0]), float(xy_px[1]), button=button)
    canvas.callbacks.process(kind, ev)


# -------------------------------------------------------------- comb demo
@pytest.fixture(scope="module")
def comb():
    return curvature_comb_demo()


def test_comb_demo_has_the_css_hooks(comb):
    assert CSS <= classes(comb)
    assert type(comb.figure.canvas).__name__ == "Canvas"  # ipympl
    assert comb.report.value.startswith("<table")


def test_t_slider_moves_the_point_in_place(comb):
    pt = comb.view.frame.point
    comb.controls["t"].value = 1.25
    assert comb.view.frame.point is pt
    np.testing.assert_allclose(np.column_stack(pt.get_data())[0], comb.state.curve.evaluate(1.25))


def test_checkboxes_hide_and_show(comb):
    comb.controls["comb"].value = False
    assert not any(a.get_visible() for a in comb.view.comb.artists)
    comb.controls["comb"].value = True
    assert all(a.get_visible() for a in comb.view.comb.artists)
    comb.controls["curvature"].value = False
    assert not comb.view.kax.get_visible()
    comb.controls["curvature"].value = True


def test_report_of_the_default_joint_is_g1_not_g2(comb):
    rep = comb.state.report
    assert rep.g_order == 1 and rep.curvature_jump > 0.1
    assert "G1" in comb.report.value


def test_drag_with_the_mouse():
    demo = curvature_comb_demo()
    ax, canvas = demo.view.ax, demo.figure.canvas
    k = 5  # W2, free
    start = ax.transData.transform(demo.state.points[k])
    target = np.array([6.0, 1.5])
    mouse(canvas, "button_press_event", start + [3, -2])  # within the 10 px tolerance
    assert demo.dragger.active == k
    mouse(canvas, "motion_notify_event", ax.transData.transform(target))
    mouse(canvas, "button_release_event", ax.transData.transform(target))
    assert demo.dragger.active is None
    np.testing.assert_allclose(demo.state.points[k], target, atol=1e-9)
    np.testing.assert_allclose(demo.state.curve.segments[1][2], target, atol=1e-9)
    drawn = np.column_stack(demo.view.design.line.get_data())
    np.testing.assert_allclose(drawn[k], target, atol=1e-9)
    # a click far from every point grabs nothing
    mouse(canvas, "button_press_event", ax.transData.transform([1.0, -2.5]))
    assert demo.dragger.active is None


def test_dragging_a_shared_joint_moves_both_segments():
    demo = curvature_comb_demo()
    demo.state.drag(3, 4.5, 1.2)
    a, b = demo.state.curve.segments
    np.testing.assert_allclose(a[-1], [4.5, 1.2])
    np.testing.assert_allclose(b[0], [4.5, 1.2])


def test_degenerate_drag_warns_instead_of_raising():
    demo = curvature_comb_demo()
    demo.state.drag(4, 4.0, 1.0)  # W1 onto the joint W0: r'(0) = 0
    assert "not regular" in demo.state.warning
    assert demo.warning.layout.display != "none" and "⚠" in demo.warning.value
    assert "⚠" in demo.report.value
    assert not any(a.get_visible() for a in demo.view.comb.artists)
    demo.state.drag(4, 5.0, 0.5)  # pulled away again: healthy
    assert demo.state.warning == "" and demo.warning.layout.display == "none"
    assert all(a.get_visible() for a in demo.view.comb.artists)


def test_callback_errors_are_visible(monkeypatch):
    demo = curvature_comb_demo()

    def boom(t):
        raise RuntimeError("something broke")

    monkeypatch.setattr(demo.state, "set_t", boom)
    demo.controls["t"].value = 0.3  # must not raise out of the callback
    assert "RuntimeError: something broke" in demo.warning.value
    assert demo.warning.layout.display != "none"
    assert any("something broke" in o.get("text", "") for o in demo.output.outputs)


def test_static_demo_is_a_figure():
    demo = curvature_comb_demo(static=True)
    assert demo.widget is None and demo.controls == {}
    assert type(demo.figure.canvas).__name__ == "FigureCanvasAgg"
    bundle = demo._repr_mimebundle_()
    assert bundle["image/png"] and "static figure" in bundle["text/plain"]
    demo.state.set_t(0.5)  # the state still drives the static figure
    np.testing.assert_allclose(
        np.column_stack(demo.view.frame.point.get_data())[0], demo.state.curve.evaluate(0.5)
    )


def test_comb_demo_bad_input():
    with pytest.raises(TypeError, match="PiecewiseBezier"):
        curvature_comb_demo(curve=[[0, 0], [1, 1]])
    with pytest.raises(ValueError, match="plane curve"):
        curvature_comb_demo(curve=PiecewiseBezier([[[0, 0, 0], [1, 1, 1]]]), static=True)


# ------------------------------------------------------------- the state
def test_state_rejects_bad_initial_data_with_the_constructions_error():
    def build(P, params):
        if params["beta1"] <= 0:
            raise ValueError(f"beta1 must be > 0, got {params['beta1']}")
        return PiecewiseBezier([P])

    with pytest.raises(ValueError, match="beta1 must be > 0"):
        CurveDemoState(build, [[0, 0], [1, 1], [2, 0]], {"beta1": -1.0})
    st = CurveDemoState(build, [[0, 0], [1, 1], [2, 0]], {"beta1": 1.0})
    with pytest.raises(ValueError, match="beta1 must be > 0"):
        st.set_param("beta1", 0.0)
    assert st.params["beta1"] == 1.0  # unchanged
    with pytest.raises(KeyError):
        st.set_param("beta3", 1.0)
    with pytest.raises(ValueError, match="at least 2 points"):
        CurveDemoState(build, [[0, 0]], {"beta1": 1.0})


def test_point_dragger_hit_test_in_pixels():
    demo = curvature_comb_demo(static=True)
    ax = demo.view.ax
    moves = []
    drag = PointDragger(ax, lambda: demo.state.points, lambda k, x, y: moves.append(k),
                        tolerance=4)
    p = ax.transData.transform(demo.state.points[2])
    assert drag.hit(*(p + [3, 0])) == 2
    assert drag.hit(*(p + [5, 0])) is None
    drag.disconnect()


# ------------------------------------------------------ reparametrization
def test_reparametrization_demo_chain_rule_and_intrinsic_quantities():
    demo = reparametrization_demo()
    assert {"cl-demo", "cl-slider-t", "cl-report", "cl-canvas"} <= classes(demo)
    demo.controls["a"].value = 0.5
    demo.controls["t"].value = 0.2
    F = demo.state.facts
    fprime = 1 + 0.5 * (1 - 2 * 0.2)  # f(v) = v + a v (1 - v)
    np.testing.assert_allclose(F["fprime"], fprime)
    np.testing.assert_allclose(F["speed_r"], fprime * F["speed_q"], rtol=1e-12)
    np.testing.assert_allclose(F["T_r"], F["T_q"], atol=1e-12)
    np.testing.assert_allclose(F["kappa_r"], F["kappa_q"], rtol=1e-9)
    np.testing.assert_allclose(demo.state.u, 0.2 + 0.5 * 0.2 * 0.8)
    assert "chain rule" in demo.report.value
    assert -1 < demo.controls["a"].min and demo.controls["a"].max < 1


def test_reparametrization_demo_rejects_a_reversing_change():
    with pytest.raises(ValueError):
        reparametrization_demo(a=1.5, static=True)
