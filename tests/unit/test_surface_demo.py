"""Lecture 10's tangent-plane demo, driven through its state and widgets (no browser).

The expected verdicts are computed here independently: the neighbour patch is built with
the math layer's ``g1_neighbour_patch``, the point is lifted by hand, and the verdict is
``tangent_plane_continuity`` of that pair -- the demo's own state is not consulted.
"""

from __future__ import annotations

import html

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from course_lib.constructions.surfaces import (
    BezierPatch,
    g1_neighbour_patch,
    tangent_plane_continuity,
)
from course_lib.widgets import TangentPlaneState, tangent_plane_demo

HILL = [[0, 0.5, 0.5, 0], [0.3, 1.6, 1.3, 0.2], [0.2, 1.3, 1.8, 0.4], [0, 0.4, 0.7, 0.2]]


def expected(alpha, beta0, beta1, lift, lifted=2):
    """The pair as lecture 10 builds it (nb10-025b, nb10-041), one point of G lifted."""
    xy = np.stack(np.meshgrid(range(4), range(4), indexing="ij"), axis=-1)
    F = BezierPatch(np.concatenate([xy, np.array(HILL)[..., None]], axis=-1))
    rest = F.control_net[3] + np.array([[[1.5, 0, 0.3]], [[3.0, 0, -0.2]]])
    net = g1_neighbour_patch(F, rest, alpha=alpha, beta=(beta0, beta1)).control_net.copy()
    net[1, lifted, 2] += lift
    return tangent_plane_continuity(F, BezierPatch(net))


@pytest.fixture(scope="module")
def demo():
    return tangent_plane_demo()


def test_the_lift_slider_breaks_g1_exactly_when_the_point_leaves_the_plane(demo):
    st = demo.state
    slider = demo.controls["lift"]
    verdicts = []
    for lift in (0.0, 0.05, -0.05, 0.5, -1.0, 0.0, 1.0, 0.0):
        slider.value = lift  # the widget path: slider -> state -> report -> live region
        want = expected(1.2, 0.4, -0.3, lift)
        assert st.report.g1 is want.g1 and st.g1 is want.g1
        assert st.report.max_angle == pytest.approx(want.max_angle, abs=1e-9)
        assert want.g1 is (lift == 0.0)  # the condition breaks exactly when lifted
        verdicts.append(st.verdict().split(":")[0])
        live = html.unescape(demo.controls["live"].value)
        assert "role='status'" in live and "aria-live='polite'" in live
        assert st.verdict() in live and st.verdict() in demo.view.ax.get_title()
        assert ("G1 ✓" in demo.report.value) is want.g1
    assert verdicts == ["G1", "Not G1", "Not G1", "Not G1", "Not G1", "G1", "Not G1", "G1"]


@pytest.mark.parametrize(
    ("name", "values"),
    [("alpha", (0.2, 1.0, 3.0)), ("beta0", (-1.0, 0.0, 1.0)), ("beta1", (-1.0, 0.55, 1.0))],
)
def test_the_shape_function_sliders_keep_g1(demo, name, values):
    st = demo.state
    demo.controls["lift"].value = 0.0
    for v in values:
        demo.controls[name].value = v
        p = st.params
        assert p[name] == v
        want = expected(p["alpha"], p["beta0"], p["beta1"], p["lift"])
        assert want.g1 and st.g1 and st.verdict().startswith("G1")
    demo.controls["lift"].value = 0.3  # and the lift still breaks it, whatever α and β
    p = st.params
    assert not expected(p["alpha"], p["beta0"], p["beta1"], 0.3).g1 and not st.g1


def test_the_demo_has_its_hooks_and_a_view_turned_by_the_user_stays_turned():
    demo = tangent_plane_demo()
    kids, todo = [], [demo.widget]
    while todo:
        w = todo.pop()
        kids.append(w)
        todo += list(getattr(w, "children", ()))
    css = {c for w in kids for c in w._dom_classes}
    assert {"cl-demo", "cl-report", "cl-canvas", "cl-live", "cl-slider-alpha",
            "cl-slider-beta0", "cl-slider-beta1", "cl-slider-lift"} <= css  # fmt: skip
    demo.view.ax.view_init(elev=40, azim=10)
    demo.state.set_param("lift", 0.4)
    assert (demo.view.ax.elev, demo.view.ax.azim) == (40, 10)


def test_static_mode_draws_a_figure_with_the_verdict():
    demo = tangent_plane_demo(lift=0.5, static=True)
    assert demo.widget is None
    fig = demo.figure
    assert fig.axes[0].name == "3d" and fig.axes[0].collections  # the surfaces
    assert fig.axes[0].get_title().startswith("Not G1")
    bundle = demo._repr_mimebundle_()
    assert bundle["image/png"]


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [({"alpha": 0.0}, "alpha must lie in"), ({"lift": 2.0}, "lift must lie in"),
     ({"beta1": -1.5}, "beta1 must lie in")],
)  # fmt: skip
def test_initial_values_outside_the_sliders_are_refused(kwargs, match):
    with pytest.raises(ValueError, match=match):
        tangent_plane_demo(static=True, **kwargs)


def test_state_refuses_unknown_names_and_values_off_the_slider():
    st = TangentPlaneState()
    with pytest.raises(KeyError, match="unknown parameter"):
        st.set_param("gamma", 1.0)
    with pytest.raises(ValueError, match="alpha must lie in"):
        st.set_param("alpha", -1.0)
    assert st.params["alpha"] == 1.2 and st.g1  # the old value is kept
    with pytest.raises(ValueError, match="lifted must be"):
        TangentPlaneState(lifted=4)
