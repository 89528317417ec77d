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
    mouse(canvas, "button_press_event", start + np.array([3, -2]))  # within the 10 px tolerance
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
    drag = PointDragger(ax, lambda: demo.state.points, lambda k, x, y: moves.append(k), tolerance=4)
    p = ax.transData.transform(demo.state.points[2])
    assert drag.hit(*(p + np.array([3, 0]))) == 2
    assert drag.hit(*(p + np.array([5, 0]))) is None
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


# ---------------------------------------------------- construction demos
from course_lib.widgets import (  # noqa: E402
    beta_spline_demo,
    catmull_rom_demo,
    g2_stitch_demo,
    knot_spline_demo,
)


@pytest.fixture(scope="module")
def beta():
    return beta_spline_demo(beta1=1.0, beta2=0.0)


def test_beta_demo_css_and_slider_ranges(beta):
    assert CSS | {"cl-slider-beta1", "cl-slider-beta2"} <= classes(beta)
    s1, s2 = beta.controls["beta1"], beta.controls["beta2"]
    assert 10.0**s1.min > 0  # log slider: β1 can never reach 0
    assert s2.min >= 0


def test_beta1_slider_reaches_the_curve_and_the_report(beta):
    from course_lib.constructions.beta_splines import cubic_beta_spline

    beta.controls["same"].value = True
    beta.controls["beta1"].value = 2.0
    st = beta.state
    ref = cubic_beta_spline(st.points, beta1=2.0, beta2=0.0)
    for a, b in zip(st.curve.segments, ref.segments, strict=True):
        np.testing.assert_allclose(a, b)
    # the continuity analysis measures β1 = 2 at the joint, independently of the construction
    assert st.report.g_order >= 2
    np.testing.assert_allclose(st.report.betas[:2], [2.0, 0.0], atol=1e-9)
    assert "β1 = 2" in beta.report.value


def test_per_joint_beta_with_the_joint_selector(beta):
    beta.controls["beta1"].value = 1.0
    beta.controls["same"].value = False
    beta.controls["joint"].value = 1
    beta.controls["beta2"].value = 5.0
    st = beta.state
    np.testing.assert_allclose(st.report.betas[:2], [1.0, 5.0], atol=1e-8)
    assert st.params["beta2"][0] == 0.0 and st.params["beta2"][1] == 5.0
    beta.controls["joint"].value = 0  # the sliders follow the selected joint
    assert beta.controls["beta2"].value == 0.0
    np.testing.assert_allclose(st.report.betas[:2], [1.0, 0.0], atol=1e-8)
    beta.controls["same"].value = True


def test_beta_demo_drag_and_degenerate_drag():
    demo = beta_spline_demo(degree=2, beta1=1.5)
    P = demo.state.points
    demo.state.drag(3, P[3, 0] + 0.5, P[3, 1])
    np.testing.assert_allclose(demo.state.curve.segments[2][1], demo.state.points[3])  # W_i,1 = V_i
    demo.state.drag(3, *P[4])  # two coincident vertices: the construction refuses
    assert "construction failed" in demo.state.warning
    assert demo.warning.layout.display != "none"


@pytest.mark.parametrize(
    ("factory", "kwargs", "match"),
    [
        (beta_spline_demo, {"beta1": -0.5}, "beta1"),
        (beta_spline_demo, {"beta1": 0.0, "degree": 2}, "beta1"),
        (beta_spline_demo, {"points": [[0, 0], [1, 1], [2, 0]]}, "at least 4"),
        (beta_spline_demo, {"degree": 4}, "degree"),
        (catmull_rom_demo, {"beta1": -1.0}, "beta1"),
        (catmull_rom_demo, {"points": [[0, 0], [1, 1], [2, 0]]}, "at least 4"),
        (g2_stitch_demo, {"beta1": 0.0}, "beta1"),
        (g2_stitch_demo, {"V": [[0, 0], [1, 1], [2, 0]]}, "at least 4"),
        (g2_stitch_demo, {"V": [[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]]}, "4 control points"),
        (knot_spline_demo, {"knots": [0, 2, 1, 3]}, "strictly increasing"),
        (knot_spline_demo, {"knots": [0, 1, 2]}, "knots must have"),
        (reparametrization_demo, {"a": 1.0}, "orientation preserving"),
    ],
)
def test_bad_initial_data_fails_at_construction(factory, kwargs, match):
    with pytest.raises(ValueError, match=match):
        factory(static=True, **kwargs)


def test_catmull_rom_demo_report_g1_not_c1():
    demo = catmull_rom_demo(static=True)
    demo.state.set_param("beta1", 0.5)
    rep = demo.state.report
    assert rep.g_order == 1 and rep.c_order == 0
    np.testing.assert_allclose(rep.betas[0], 0.5, rtol=1e-9)


def test_g2_stitch_demo_is_g2_for_every_setting():
    demo = g2_stitch_demo()
    assert {"cl-slider-beta1", "cl-slider-beta2"} <= classes(demo)
    for b1, b2 in ((0.5, 0.0), (2.0, 3.0), (1.2, 10.0)):
        demo.controls["beta1"].value = b1
        demo.controls["beta2"].value = b2
        rep = demo.state.report
        assert rep.g_order >= 2
        np.testing.assert_allclose(rep.betas[:2], [b1, b2], rtol=1e-9, atol=1e-9)
    # T drawn by the diagram: on the extension of V1 V2 (collinear)
    diagram_T = next(a for a in demo.view.ax.texts if a.get_text() == "$T$").xy
    V = demo.state.curve.segments[0]
    a, b = V[2] - V[1], np.asarray(diagram_T) - V[2]
    assert abs(a[0] * b[1] - a[1] * b[0]) < 1e-9 and a @ b > 0
    demo.state.drag(2, *demo.state.points[3])  # V2 = V3: no end tangent
    assert "construction failed" in demo.state.warning


def test_knot_demo_slider_keeps_the_knots_in_order():
    demo = knot_spline_demo()
    assert "cl-slider-knot" in classes(demo)
    ks, ksel = demo.controls["knot"], demo.controls["knot_index"]
    k = demo.state.params["knots"]
    assert k[0] < ks.min and ks.max < k[2]
    ks.value = 1.6
    k = demo.state.params["knots"]
    np.testing.assert_allclose(k, [0, 1.6, 2, 3])
    ksel.value = 2
    assert 1.6 < ks.min and ks.max < 3 and ks.value == 2.0
    ks.value = 1.0  # below the slider's range: clamped, the order survives
    assert np.all(np.diff(demo.state.params["knots"]) > 0)
    # Finn's joint rule, checked on the curve: p_3 divides p_2 p_4 as t_1 divides [t_0, t_2]
    t = demo.state.params["knots"]
    s0, s1 = demo.state.curve.segments[:2]
    lam = np.linalg.norm(s0[3] - s0[2]) / np.linalg.norm(s1[1] - s0[2])
    np.testing.assert_allclose(lam, (t[1] - t[0]) / (t[2] - t[0]), rtol=1e-12)
    rep = demo.state.report  # C1 in the global parameter (seed 004 exercise 19.8.3)
    assert rep.c_order >= 1 and rep.g_order >= 1


def test_demos_run_in_a_kernel():
    """What nbval does: create every demo in a real kernel (headless ipympl) and display it."""
    import nbformat
    from nbclient import NotebookClient

    code = (
        "from course_lib.widgets import *\n"
        "demos = [catmull_rom_demo(), beta_spline_demo(), beta_spline_demo(degree=2),\n"
        "         g2_stitch_demo(), knot_spline_demo(), reparametrization_demo(),\n"
        "         curvature_comb_demo()]\n"
        "demos[1].controls['beta1'].value = 2.0\n"
        "print(demos[1].state.report.g_order, type(demos[1].figure.canvas).__name__)\n"
        "display(*demos)\n"
    )
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(code)])
    NotebookClient(nb, timeout=60, kernel_name="python3").execute()
    outs = nb.cells[0].outputs
    assert not [o for o in outs if o.output_type == "error"]
    assert "".join(o.get("text", "") for o in outs if o.output_type == "stream").split() == [
        "2",
        "Canvas",
    ]
    views = [o for o in outs if "application/vnd.jupyter.widget-view+json" in o.get("data", {})]
    assert len(views) == 7


def test_automatic_static_fallback_without_widgets(monkeypatch):
    import course_lib.widgets.assembly as assembly
    import course_lib.widgets.demos as demos

    monkeypatch.setattr(assembly, "widgets_available", lambda: False)
    demo = demos.beta_spline_demo()
    assert demo.widget is None and type(demo.figure.canvas).__name__ == "FigureCanvasAgg"
    assert "image/png" in demo._repr_mimebundle_()


# ------------------------------------------------- arrows, ranges, layout, speed
def _arrow_length(vectors) -> float:
    q = vectors.quiver
    return float(np.hypot(q.U[0], q.V[0]))


@pytest.mark.parametrize("v", [0.3, 0.9])  # f'(0.3) = 1.24 > 1, f'(0.9) = 0.52 < 1
def test_reparametrization_demo_draws_the_shorter_velocity_on_top(v):
    demo = reparametrization_demo(v=v, static=True)
    vq, vr = demo.view.vel_q, demo.view.vel_r
    fprime = 1 + 0.6 * (1 - 2 * v)  # f(v) = v + a v (1 - v), a = 0.6
    np.testing.assert_allclose(_arrow_length(vr), fprime * _arrow_length(vq), rtol=1e-12)
    short, long_ = (vq, vr) if fprime > 1 else (vr, vq)
    assert short.quiver.get_zorder() > long_.quiver.get_zorder()
    demo.state.set_t(1.2 - v)  # the other side of v = 1/2: the order flips
    short, long_ = long_, short
    assert short.quiver.get_zorder() > long_.quiver.get_zorder()


def test_g2_stitch_demo_accepts_a_negative_beta2():
    demo = g2_stitch_demo(beta2=-1.0)
    s2 = demo.controls["beta2"]
    assert s2.min <= -10 and s2.value == -1.0 == demo.state.params["beta2"]
    np.testing.assert_allclose(demo.state.report.betas[:2], [1.0, -1.0], atol=1e-9)
    # β2 = -2 β1 (1 + β1) = -4 at β1 = 1: γ undefined, T at infinity -- the stitch is still G2
    s2.value = -4.0
    assert demo.state.report.g_order >= 2 and "⚠" not in demo.warning.value
    T_label = next(a for a in demo.view.ax.texts if a.get_text() == "$T$")
    assert not T_label.get_visible()
    s2.value = 2.0
    assert T_label.get_visible()


@pytest.mark.parametrize(
    ("factory", "kwargs", "match"),
    [
        (beta_spline_demo, {"beta2": -1.0}, r"beta2 must lie in \[0, 50\]"),
        (beta_spline_demo, {"beta2": [0.0, 0.0, 60.0, 0.0]}, "got 60 at joint 2"),
        (beta_spline_demo, {"beta1": 30.0, "degree": 2}, r"beta1 must lie in \[0.05, 20\]"),
        (catmull_rom_demo, {"beta1": 0.01}, "beta1 must lie in"),
        (g2_stitch_demo, {"beta2": 60.0}, r"beta2 must lie in \[-10, 50\]"),
        (g2_stitch_demo, {"beta2": -11.0}, r"beta2 must lie in \[-10, 50\]"),
        (reparametrization_demo, {"a": 0.95}, r"a must lie in \[-0.9, 0.9\]"),
    ],
)
@pytest.mark.parametrize("static", [True, False])
def test_initial_values_outside_the_slider_range_are_rejected(factory, kwargs, match, static):
    with pytest.raises(ValueError, match=match):
        factory(static=static, **kwargs)


def test_slider_range_ends_are_reachable():
    demo = beta_spline_demo(beta1=0.05, beta2=50.0)
    assert demo.controls["beta1"].value == 0.05 and demo.controls["beta2"].value == 50.0
    assert beta_spline_demo(beta1=20.0).controls["beta1"].value == 20.0


def test_state_rejects_an_initial_t_outside_the_domain():
    with pytest.raises(ValueError, match=r"t must lie in the curve's domain \[0, 1\]"):
        CurveDemoState(lambda P, p: PiecewiseBezier([P]), [[0, 0], [1, 1], [2, 0]], t=1.5)


def test_interactive_canvas_fits_a_jupyterlab_column():
    # JupyterLab 4.6 at 1400 px with the file browser open: 968 px of output width
    for demo in (curvature_comb_demo(), reparametrization_demo()):
        fig = demo.figure
        assert fig.get_size_inches()[0] * fig.dpi <= 900
    static = curvature_comb_demo(static=True).figure
    assert static.dpi == 100  # saved and static pictures keep their resolution


def test_moving_t_does_not_recompute_the_curve_pictures(monkeypatch):
    demo = curvature_comb_demo(static=True)
    view, st = demo.view, demo.state
    calls = []
    for name in ("comb", "profile", "curve_artists"):
        art = getattr(view, name)
        monkeypatch.setattr(
            art,
            "update",
            lambda *a, _n=name, _f=art.update, **k: (calls.append(_n), _f(*a, **k))[1],
        )
    st.set_t(0.4)
    st.select_joint(0)
    assert calls == []
    np.testing.assert_allclose(
        np.column_stack(view.frame.point.get_data())[0], st.curve.evaluate(0.4)
    )
    st.set_flag("show_comb", False)
    st.drag(5, 6.0, 1.2)  # new curve while the comb is hidden
    assert sorted(calls) == ["curve_artists", "profile"]
    st.set_flag("show_comb", True)  # shown again: recomputed for the new curve
    teeth = view.comb.tooth_array()
    from course_lib.geometry.differential_geometry import curvature_vector
    from course_lib.geometry.sampling import segment_grid

    t = segment_grid(st.curve, view.comb.per_segment).ravel()
    K = curvature_vector(st.curve, t[1:-1])  # interior samples (joints are one-sided)
    tooth = teeth[1:-1, 1] - teeth[1:-1, 0]
    np.testing.assert_allclose(tooth, -view.comb.scale * K, rtol=1e-8, atol=1e-9)


def test_degenerate_drag_keeps_warning_while_t_moves():
    demo = curvature_comb_demo(static=True)
    demo.state.drag(4, 4.0, 1.0)  # W1 onto W0: not regular, comb hidden with a warning
    assert "not regular" in demo.state.warning
    demo.state.set_t(0.7)  # same curve: the remembered problem is reported again
    assert "not regular" in demo.state.warning
    assert not any(a.get_visible() for a in demo.view.comb.artists)


def test_the_browsers_rounding_to_the_slider_grid_leaves_the_state_alone():
    """Measured in JupyterLab (headless Chromium): an initial β1 = 1.5 is shown at the log
    slider's nearest position 10**0.18 = 1.5136, and that value comes back to the kernel."""
    demo = g2_stitch_demo(beta1=1.5, beta2=1.23)
    s1, s2 = demo.controls["beta1"], demo.controls["beta2"]
    s1.value = 10**0.18  # what the browser sends back
    s2.value = 1.2  # β2 grid: -10 + k * 0.1
    assert demo.state.params["beta1"] == 1.5 and demo.state.params["beta2"] == 1.23
    np.testing.assert_allclose(demo.state.report.betas[:2], [1.5, 1.23], rtol=1e-9)
    s1.value = 10**0.17  # one step to the left of the shown position: a real move
    s2.value = 1.1
    assert demo.state.params["beta1"] == 10**0.17 and demo.state.params["beta2"] == 1.1
    kd = knot_spline_demo(knots=[0.0, 1.234, 2.0, 3.0])
    kd.controls["knot"].value = kd.controls["knot"].value + 0.4 * kd.controls["knot"].step
    np.testing.assert_array_equal(kd.state.params["knots"], [0.0, 1.234, 2.0, 3.0])


# ------------------------------------------------- quartic G3 Beta-spline
from course_lib.widgets import quartic_beta_spline_demo  # noqa: E402

P5 = np.array([[0, 0], [1, 2.4], [3, 3], [4, 0.6], [6, 0.2], [7, 2.6], [9, 3], [10, 0.4]])


def test_quartic_demo_beta2_slider_keeps_g3_with_the_measured_betas():
    demo = quartic_beta_spline_demo()
    assert CSS | {"cl-slider-beta1", "cl-slider-beta2", "cl-slider-beta3"} <= classes(demo)
    assert "same" not in demo.controls  # global shape parameters: no per-joint switch
    assert 10.0 ** demo.controls["beta1"].min > 0  # log slider: β1 can never reach 0
    st = demo.state
    before = np.array(st.curve.segments)
    demo.controls["beta2"].value = 20.0  # as if the slider moved
    after = np.array(st.curve.segments)
    assert st.params["beta2"] == 20.0 and np.max(np.abs(after - before)) > 0.1
    # the continuity analysis measures β = (1, 20, 0) at every joint, independently of the
    # construction; β1 = 1 and β2 != 0: C1 but not C2 (seed 001 Fig. 5, middle)
    for j in range(st.n_joints):
        demo.controls["joint"].value = j
        rep = st.report
        assert rep.g_order == 3 and rep.c_order == 1
        np.testing.assert_allclose(rep.betas[:3], [1.0, 20.0, 0.0], atol=1e-6)
    assert "G3" in demo.report.value and "β2 = 20" in demo.report.value
    demo.controls["beta3"].value = -5.0
    demo.controls["beta1"].value = 2.0
    np.testing.assert_allclose(st.report.betas[:3], [2.0, 20.0, -5.0], rtol=1e-6, atol=1e-6)
    assert st.report.g_order == 3 and st.report.c_order == 0 and st.warning == ""


def test_quartic_demo_default_is_the_uniform_quartic_b_spline():
    # at β = (1, 0, 0) a joint is (V_{j+1} + 11 V_{j+2} + 11 V_{j+3} + V_{j+4}) / 24
    demo = quartic_beta_spline_demo(static=True)
    jp = demo.state.curve.joint_points
    ref = (P5[1:4] + 11 * P5[2:5] + 11 * P5[3:6] + P5[4:7]) / 24
    np.testing.assert_allclose(jp, ref, atol=1e-12)
    assert demo.state.report.g_order == 3 and demo.state.report.c_order == 3


def test_quartic_demo_degenerate_drag_warns_instead_of_raising():
    # uniform quartic B-spline: the end tangent of segment 0 is (-V1 - 3 V2 + 3 V3 + V4) / 6
    demo = quartic_beta_spline_demo()
    demo.state.drag(4, *(P5[1] + 3 * P5[2] - 3 * P5[3]))
    assert "construction failed" in demo.state.warning and "not be regular" in demo.state.warning
    assert demo.warning.layout.display != "none" and "⚠" in demo.warning.value
    demo.state.drag(4, *P5[4])  # back: healthy again
    assert demo.state.warning == "" and demo.warning.layout.display == "none"


def test_quartic_demo_singular_shape_parameters_show_a_warning():
    # β1 = 1/2, β2 = 0: the normalizing denominator 29.53125 + (1 - β1²) β3 vanishes at
    # β3 = -39.375 (sympy, notebook 07's blending_equations(3, ...))
    demo = quartic_beta_spline_demo(beta1=0.5)
    demo.controls["beta3"].value = -39.375  # must not raise out of the callback
    assert "⚠" in demo.warning.value and demo.state.params["beta3"] == 0.0


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"beta1": -1.0}, "beta1 must be > 0"),
        ({"beta1": 30.0}, r"beta1 must lie in \[0.05, 20\]"),
        ({"beta2": -1.0}, r"beta2 must lie in \[0, 100\]"),
        ({"beta2": 120.0}, r"beta2 must lie in \[0, 100\]"),
        ({"beta3": 60.0}, r"beta3 must lie in \[-50, 50\]"),
        ({"beta3": float("nan")}, "beta3 must be finite"),
        ({"points": P5[:4]}, "at least 5"),
    ],
)
@pytest.mark.parametrize("static", [True, False])
def test_quartic_demo_bad_initial_data(kwargs, match, static):
    with pytest.raises(ValueError, match=match):
        quartic_beta_spline_demo(static=static, **kwargs)


def test_quartic_demo_rejects_a_per_joint_shape_parameter():
    with pytest.raises(TypeError, match="beta2 must be a real number"):
        quartic_beta_spline_demo(beta2=[0.0, 1.0, 2.0], static=True)


def test_quartic_demo_static_is_a_figure():
    demo = quartic_beta_spline_demo(P5 + 1.0, beta2=100.0, static=True)
    assert demo.widget is None and demo.controls == {}
    assert type(demo.figure.canvas).__name__ == "FigureCanvasAgg"
    assert demo._repr_mimebundle_()["image/png"]
    joints = demo.view.curve_artists.joints
    before = np.column_stack(joints.get_data())
    demo.state.set_param("beta3", 10.0)  # the state still drives the static figure
    drawn = np.column_stack(joints.get_data())
    np.testing.assert_allclose(drawn, demo.state.curve.joint_points)
    assert np.max(np.abs(drawn - before)) > 1e-5  # small: β2 = 100 dominates
    np.testing.assert_allclose(demo.state.report.betas[:3], [1.0, 100.0, 10.0], atol=1e-6)


def test_a_demo_does_not_turn_later_figures_into_widgets():
    """Importing ipympl switches pyplot's backend; a demo must put the inline one back."""
    nbformat = pytest.importorskip("nbformat")
    from nbclient import NotebookClient

    cells = [
        "from course_lib.plotting import new_figure\nfrom course_lib.widgets import beta_spline_demo",
        "fig, ax = new_figure(); ax.plot([0, 1], [0, 1]);",
        "beta_spline_demo()",
        "fig, ax = new_figure(); ax.plot([0, 1], [1, 0]);",
    ]
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    NotebookClient(nb, timeout=120, kernel_name="python3").execute()
    kinds = [{k for o in c.outputs for k in o.get("data", {})} for c in nb.cells]
    assert "application/vnd.jupyter.widget-view+json" in kinds[2]
    assert "image/png" in kinds[1] and "image/png" in kinds[3]
    assert "application/vnd.jupyter.widget-view+json" not in kinds[3]


# ------------------------------------------- demos that follow the hand (issue 16)
def _render_log(view, monkeypatch):
    """Record what each redraw of ``view`` was: "blit" (moving artists only) or a full frame."""
    log = []
    orig = view.render
    monkeypatch.setattr(view, "render", lambda: log.append(orig()) or log[-1])
    return log


@pytest.mark.parametrize("factory", [reparametrization_demo, curvature_comb_demo])
def test_slider_and_drag_redraw_only_the_moving_artists(factory, monkeypatch):
    demo = factory()
    view, canvas = demo.view, demo.figure.canvas
    canvas.draw()  # what the browser's first frame does: caches the background
    assert view.blit and view.background is not None
    log = _render_log(view, monkeypatch)
    demo.controls["t"].value = 0.4
    k = 1
    x, y = demo.state.points[k] + 0.1
    demo.state.drag(k, x, y)
    assert log == ["blit", "blit"]
    # the frames, ticks and the legend are background: never animated
    legend = view.ax.get_legend()
    static = [view.ax.patch, view.ax.xaxis, *([legend] if legend else [])]
    assert not any(a in view.dynamic for a in static)


@pytest.mark.parametrize("factory", [reparametrization_demo, curvature_comb_demo])
def test_release_lands_under_the_mouse_and_sends_a_full_frame(factory, monkeypatch):
    """ipympl may drop the last motion event: the release event's position is used."""
    demo = factory()
    ax, canvas, view = demo.view.ax, demo.figure.canvas, demo.view
    canvas.draw()
    k = 1
    p = demo.state.points[k].copy()
    mid, end = p + np.array([0.2, 0.1]), p + np.array([0.45, -0.3])
    mouse(canvas, "button_press_event", ax.transData.transform(p))
    mouse(canvas, "motion_notify_event", ax.transData.transform(mid))
    canvas._force_full = False
    log = _render_log(view, monkeypatch)
    mouse(canvas, "button_release_event", ax.transData.transform(end))  # no motion to `end`
    np.testing.assert_allclose(demo.state.points[k], end, atol=1e-9)
    drawn = np.column_stack(view.design.line.get_data())
    np.testing.assert_allclose(drawn[k], end, atol=1e-9)
    assert log[-1] in ("idle", "full") and canvas._force_full  # a complete image follows


def test_release_outside_the_axes_keeps_the_point_at_the_edge():
    demo = curvature_comb_demo()
    ax, canvas = demo.view.ax, demo.figure.canvas
    k = 5
    mouse(canvas, "button_press_event", ax.transData.transform(demo.state.points[k]))
    right = ax.bbox.x1 + 40, ax.bbox.y0 + 0.5 * ax.bbox.height
    mouse(canvas, "button_release_event", right)
    x_edge = ax.transData.inverted().transform((ax.bbox.x1, 0))[0]
    np.testing.assert_allclose(demo.state.points[k][0], x_edge, rtol=1e-9)


def test_sliders_lose_the_float_error_of_their_grid():
    from course_lib.widgets.assembly import readout_format, snap_to_step
    from course_lib.widgets.demos import BETA1, BETA2_STITCH

    demo = g2_stitch_demo(beta1=1.0, beta2=1.0)
    s2 = demo.controls["beta2"]
    s2.value = -1.7763568394002505e-15  # what the browser sent for the position "0"
    assert s2.value != 0.0 and demo.state.params["beta2"] == 0.0
    assert "β2 = 0" in demo.report.value and "e-" not in demo.report.value
    s2.value = 1.0999999999999996
    assert demo.state.params["beta2"] == 1.1
    assert s2.readout_format == readout_format(BETA2_STITCH) == ".1f"
    assert snap_to_step(BETA2_STITCH, 1.23) == 1.23  # off the grid (set from code): kept
    assert snap_to_step(BETA1, 10 ** (0.17 + 1e-12)) == 10**0.17
    assert snap_to_step(BETA1, 2.0) == 2.0


def test_report_shows_the_demos_order_and_details_on_request():
    from course_lib.widgets.report import DETAIL_NOTE

    demo = g2_stitch_demo(beta1=1.5, beta2=1.0)
    html_ = demo.report.value
    assert "G2 ✓" in html_ and "β1 = 1.5" in html_ and "β2 = 1" in html_
    assert "β3" not in html_ and "residual" not in html_ and "G3" not in html_
    rep = demo.state.report
    demo.controls["details"].value = True
    assert demo.state.report is rep  # a switch of the report only: nothing recomputed
    html_ = demo.report.value
    assert "β3" in html_ and "residual" in html_
    import html as h

    assert h.escape(DETAIL_NOTE) in html_
    # a G1 demo reports G1 and no curvature row unless asked
    kd = knot_spline_demo()
    assert "G1 ✓" in kd.report.value and "curvature jump" not in kd.report.value
    # a joint below the demo's order says which order it reaches
    comb = curvature_comb_demo()  # G1, not G2
    assert "G1 only (not G2)" in comb.report.value


def test_rotating_the_3d_pair_uses_coarse_surfaces_until_release():
    from course_lib.constructions.surfaces import BezierPatch, g1_neighbour_patch
    from course_lib.plotting.surfaces3d import plot_patch_pair

    xy = np.stack(np.meshgrid(np.arange(4.0), np.arange(4.0), indexing="ij"), axis=-1)
    hill = [[0, 0.5, 0.5, 0], [0.3, 1.6, 1.3, 0.2], [0.2, 1.3, 1.8, 0.4], [0, 0.4, 0.7, 0.2]]
    F = BezierPatch(np.concatenate([xy, np.array(hill)[..., None]], axis=-1))
    G = g1_neighbour_patch(F, F.control_net[3] + np.array([[[1.5, 0, 0.3]], [[3.0, 0, -0.2]]]))
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(layout="constrained")
    FigureCanvasAgg(fig)
    assert plot_patch_pair(fig.add_subplot(projection="3d"), F, G).motion is None  # static
    from ipympl.backend_nbagg import Canvas, FigureManager

    fig = Figure(layout="constrained")
    FigureManager(Canvas(fig), 0)
    ax = fig.add_subplot(projection="3d")
    art = plot_patch_pair(ax, F, G, net=False)
    c = fig.canvas
    c.draw()
    engine = fig.get_layout_engine()
    light = art.motion.light
    assert not any(a.get_visible() for a in light)
    centre = ax.bbox.x0 + 0.5 * ax.bbox.width, ax.bbox.y0 + 0.5 * ax.bbox.height
    mouse(c, "button_press_event", centre)
    assert all(a.get_visible() for a in light) and not art.F.surface.get_visible()
    assert fig.get_layout_engine() is not engine  # layout frozen while turning
    assert not ax._axis3don  # no panes, ticks, labels while turning
    mouse(c, "motion_notify_event", (centre[0] + 30, centre[1]))
    c._force_full = False
    mouse(c, "button_release_event", (centre[0] + 30, centre[1]))
    assert not any(a.get_visible() for a in light) and art.F.surface.get_visible()
    assert fig.get_layout_engine() is engine and c._force_full and ax._axis3don


def test_saving_replaces_widget_views_by_a_placeholder():
    from course_lib.widgets.saving import (
        WIDGET_MIME,
        WIDGET_PLACEHOLDER,
        pre_save_hook,
        strip_widget_outputs,
    )

    png = {"output_type": "display_data", "data": {"image/png": "iVBOR"}, "metadata": {}}
    view = {"output_type": "execute_result", "execution_count": 3, "metadata": {},
            "data": {WIDGET_MIME: {"model_id": "abc"}, "text/plain": "VBox(...)"}}
    nb = {"cells": [{"cell_type": "code", "outputs": [png, view]},
                    {"cell_type": "markdown", "source": "x"}],
          "metadata": {"widgets": {"state": {}}, "kernelspec": {"name": "python3"}}}
    assert strip_widget_outputs(nb) == 1
    assert view["data"] == {"text/plain": WIDGET_PLACEHOLDER}
    assert png["data"] == {"image/png": "iVBOR"} and "widgets" not in nb["metadata"]
    assert nb["metadata"]["kernelspec"] == {"name": "python3"}
    model = {"type": "notebook", "content": {"cells": [{"cell_type": "code",
             "outputs": [{"data": {WIDGET_MIME: {}}, "metadata": {}}]}], "metadata": {}}}
    pre_save_hook(model, path="x.ipynb", contents_manager=None)
    assert model["content"]["cells"][0]["outputs"][0]["data"] == {"text/plain": WIDGET_PLACEHOLDER}
    pre_save_hook({"type": "file", "content": "text"})  # other files: untouched, no error


def test_coalescer_draws_the_newest_of_queued_events():
    import asyncio
    import threading

    from course_lib.widgets._coalesce import Coalescer

    seen = []

    def slow(x):
        seen.append(x)
        import time

        time.sleep(0.01)  # a redraw

    async def run():
        c = Coalescer(slow, gap=0.05, delay=0.01)
        for x in range(6):  # handled back to back: all but the first waited in the queue
            c(x)
        await asyncio.sleep(0.03)  # the newest (5) was handled at ~0.02 s
        c(99)  # later, but within `gap` of the last call: queued again, then handled
        await asyncio.sleep(0.05)
        code = Coalescer(slow, gap=0.05, may_defer=lambda: False)  # values set by code
        for x in range(3):
            code(x)
        return c

    # a loop of its own, in a thread: an earlier test of the session may have left this
    # thread's event loop running (asyncio.run refuses to nest)
    box = {}
    worker = threading.Thread(target=lambda: box.update(c=asyncio.run(run())))
    worker.start()
    worker.join()
    c = box["c"]
    assert seen == [0, 5, 99, 0, 1, 2] and c.dropped == 4
    # without an event loop (tests, scripts) every event is handled at once (again in a thread
    # of its own: this one's loop may be running)
    seen.clear()

    def plain():
        c = Coalescer(slow, gap=10.0)
        c(1)
        c(2)

    worker = threading.Thread(target=plain)
    worker.start()
    worker.join()
    assert seen == [1, 2]


def test_dragging_keeps_the_curvature_axes_until_release():
    demo = g2_stitch_demo(beta1=1.5, beta2=1.0)
    ax, canvas, view = demo.view.ax, demo.figure.canvas, demo.view
    canvas.draw()
    lim = view.kax.get_ylim()
    k = 3  # the joint: the curvature changes a lot
    p = demo.state.points[k]
    mouse(canvas, "button_press_event", ax.transData.transform(p))
    assert view.interacting
    mouse(canvas, "motion_notify_event", ax.transData.transform(p + np.array([0.0, -0.6])))
    small = view.kax.get_ylim()
    assert small[0] <= lim[0] and small[1] >= lim[1]  # may grow while dragging, never shrink
    mouse(canvas, "button_release_event", ax.transData.transform(p + np.array([0.0, -0.6])))
    assert not view.interacting


def test_report_shows_rounding_noise_as_zero():
    """A G2 Beta-spline joint: the computed angle, jump and β2 = 0 carry ~1e-15 of noise."""
    from dataclasses import replace

    from course_lib.widgets.report import demo_report_html

    demo = beta_spline_demo(beta1=1.07, beta2=0.0)
    rep = replace(demo.state.report, tangent_angle=3.25e-15, curvature_jump=1.57e-16,
                  betas=(1.072, -2.747e-15, 5.0))
    html_ = demo_report_html(rep, 2)
    assert "e-1" not in html_ and "0°" in html_ and "β2 = 0<" in html_.replace(",", "<")
