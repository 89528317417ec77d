"""Keyboard and screen-reader access to the demos (course_lib/widgets/access.py), driven
through the widgets without a browser (headless ipympl); the browser side is
tests/browser/test_accessibility.py."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import html

import numpy as np
import pytest

from course_lib.widgets import (
    beta_spline_demo,
    curvature_comb_demo,
    g2_stitch_demo,
    glyph_demo,
    reparametrization_demo,
)
from course_lib.widgets.access import SLIDER_NAMES_JS, slider_names_bundle, verdict


def all_widgets(w):
    out = [w]
    for c in getattr(w, "children", ()):
        out += all_widgets(c)
    return out


@pytest.fixture
def beta():
    return beta_spline_demo(beta1=1.0, beta2=0.0)


def test_every_draggable_demo_has_point_controls():
    for make in (beta_spline_demo, curvature_comb_demo, g2_stitch_demo, reparametrization_demo):
        demo = make()
        classes = {c for w in all_widgets(demo.widget) for c in w._dom_classes}
        want = {
            "cl-point-select",
            "cl-point-x",
            "cl-point-y",
            "cl-point-step",
            "cl-live",
            "cl-nudge-left",
            "cl-nudge-up",
        }
        assert want <= classes, make.__name__
    demo = glyph_demo()
    assert "cl-live" in {c for w in all_widgets(demo.widget) for c in w._dom_classes}


def test_selector_lists_every_point_and_fields_show_its_coordinates(beta):
    pc = beta.controls["points"]
    n = len(beta.state.points)
    assert [lab for lab, _ in pc.select.options] == [f"P{k}" for k in range(n)]
    pc.select_point(2)
    assert (pc.x.value, pc.y.value) == tuple(beta.state.points[2])
    assert "P2 selected" in pc.live.value


def test_typing_a_coordinate_moves_the_point_and_the_curve(beta):
    pc = beta.controls["points"]
    pc.select_point(1)
    before = beta.state.curve.segments[0].copy()
    pc.x.value = pc.x.value + 0.5
    assert beta.state.points[1, 0] == pytest.approx(pc.x.value)
    assert not np.allclose(before, beta.state.curve.segments[0])
    assert "P1 moved to" in pc.live.value


@pytest.mark.parametrize(
    ("button", "d"), [("left", (-1, 0)), ("right", (1, 0)), ("up", (0, 1)), ("down", (0, -1))]
)
def test_nudge_buttons_move_by_fine_and_coarse_steps(beta, button, d):
    pc = beta.controls["points"]
    pc.select_point(3)
    p0 = beta.state.points[3].copy()
    pc.buttons[button].click()
    np.testing.assert_allclose(beta.state.points[3] - p0, np.array(d) * pc.fine)
    pc.step.value = "coarse"
    assert pc.x.step == pc.coarse == pytest.approx(10 * pc.fine)
    pc.buttons[button].click()
    np.testing.assert_allclose(beta.state.points[3] - p0, np.array(d) * 11 * pc.fine)


def test_mouse_drag_updates_the_fields(beta):
    pc = beta.controls["points"]
    pc.select_point(0)
    beta.state.drag(0, -0.25, 0.75)  # what the PointDragger calls
    assert (pc.x.value, pc.y.value) == (-0.25, 0.75)


def test_live_region_is_a_polite_status_with_the_verdict(beta):
    pc = beta.controls["points"]
    assert "role='status'" in pc.live.value and "aria-live='polite'" in pc.live.value
    g = beta.state.report.g_order  # from the continuity analysis
    assert f"Joint 0: G{min(g, 2)}" in pc.live.value
    assert html.unescape(pc.live.value).count(verdict(beta.state)) == 1


def test_verdict_in_words():
    demo = g2_stitch_demo()
    text = verdict(demo.state)
    assert text.startswith("Joint 0: G2, as wanted")
    demo.controls["points"].select_point(len(demo.state.points) - 1)
    # drag W3 (the free point of r) far: G2 must survive (the demo's promise)
    demo.controls["points"].nudge(5, 5)
    assert "G2, as wanted" in demo.controls["points"].live.value


def test_verdict_says_when_a_joint_is_only_g1():
    demo = curvature_comb_demo()  # its default curve is G1 and not G2 at the joint
    assert "G1 only, not G2" in verdict(demo.state)


def test_slider_names_script_is_sent_once_per_display():
    bundle = slider_names_bundle()
    assert bundle["application/javascript"] == SLIDER_NAMES_JS
    for needle in (
        "aria-label",
        "aria-valuetext",
        ".widget-readout",
        ".noUi-handle",
        "data-lm-suppress-shortcuts",
    ):
        assert needle in SLIDER_NAMES_JS


def test_bad_point_index_names_the_rule(beta):
    with pytest.raises(ValueError, match=r"point must be in 0\.\."):
        beta.controls["points"].select_point(99)


def test_glyph_demo_selector_follows_the_glyph():
    demo = glyph_demo("S")
    pc = demo.controls["points"]
    assert len(pc.select.options) == len(demo.state.offcurve_points())
    demo.controls["char"].value = "o"
    n = len(demo.state.offcurve_points())
    assert len(pc.select.options) == n
    assert pc.select.options[-1] == (f"off-curve {n - 1}", n - 1)
    pc.select_point(n - 1)
    x0 = demo.state.offcurve_points()[n - 1, 0]
    pc.nudge(1, 0)
    assert demo.state.offcurve_points()[n - 1, 0] == pytest.approx(x0 + pc.fine)
