"""Exact scaling (issue 14): geometry is affine invariant, so results scale with the data
over the whole float range.  Reference: the same computation on the unscaled curve (a
different floating-point path for every intermediate quantity), compared relatively."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.beta_splines import cubic_beta_spline, design_beta_spline
from course_lib.curves.curve import PiecewiseBezier
from course_lib.geometry.continuity import curve_continuity
from course_lib.geometry.differential_geometry import (
    arc_length,
    cumulative_arc_length,
    parameter_at_arc_length,
)

# an overflow or underflow warning anywhere is a failure: "never a wrong number silently"
pytestmark = pytest.mark.filterwarnings("error::RuntimeWarning")

V = np.array([[0.0, 0.0], [0.25, 2.0], [3.0, -1.5], [4.0, 1.0]])
BASE = PiecewiseBezier([V, V[::-1] * [1.0, -1.0] + [8.0, 0.0]])
L = arc_length(BASE)
T = np.array([0.0, 0.3, 1.0, 1.7, 2.0])
S_AT = cumulative_arc_length(BASE, T)
FRACTIONS = np.array([0.0, 0.1, 0.45, 0.9, 1.0])
T_AT = parameter_at_arc_length(BASE, FRACTIONS * L)

scales = st.builds(lambda e, m: m * 10.0**e, st.integers(-150, 150), st.floats(1.0, 9.99))


@settings(max_examples=30, deadline=None)
@given(scale=scales)
def test_arc_length_scales_exactly(scale):
    c = BASE.transformed(np.eye(2) * scale)
    assert arc_length(c) == pytest.approx(L * scale, rel=1e-13)
    np.testing.assert_allclose(cumulative_arc_length(c, T), S_AT * scale, rtol=1e-13)
    t = parameter_at_arc_length(c, FRACTIONS * arc_length(c))
    np.testing.assert_allclose(t, T_AT, atol=1e-13)


@pytest.mark.parametrize("scale", [1e-300, 1e-160, 1e155, 1e160, 1e200, 1e300])
def test_far_outside_the_usual_range_still_exact(scale):
    c = BASE.transformed(np.eye(2) * scale)
    assert arc_length(c) == pytest.approx(L * scale, rel=1e-13)
    t = parameter_at_arc_length(c, 0.3 * arc_length(c))
    assert t == pytest.approx(parameter_at_arc_length(BASE, 0.3 * L), abs=1e-13)


@settings(max_examples=20, deadline=None)
@given(scale=scales, b1=st.floats(0.3, 3.0), b2=st.floats(-1.0, 5.0))
def test_beta_spline_design_and_report_scale(scale, b1, b2):
    P = np.random.default_rng(5).normal(size=(7, 2))
    c1 = cubic_beta_spline(P, b1, b2)
    cs = cubic_beta_spline(P * scale, b1, b2)
    for x, y in zip(c1.segments, cs.segments, strict=True):
        np.testing.assert_allclose(y / scale, x, rtol=1e-12, atol=1e-12)
    d = design_beta_spline(P * scale, cs.info["interior_points"])
    np.testing.assert_allclose(d.info["beta1_vertices"], c1.info["beta1_vertices"][1:-1], rtol=1e-9)
    r1 = curve_continuity(c1, 3)
    rs = curve_continuity(cs, 3)
    assert [r.g_order_by for r in rs] == [r.g_order_by for r in r1]
    np.testing.assert_allclose([r.betas for r in rs], [r.betas for r in r1], rtol=1e-8, atol=1e-8)


@pytest.mark.parametrize("scale", [1e-150, 1e-6, 1.0, 1e6, 1e150])
def test_report_gap_and_atol_are_scale_free(scale):
    """A relative gap of 1e-6 is a gap at every scale; atol is in the curve's units."""
    q = V
    r = q[-1] + np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
    r = r + np.array([0.0, 4e-6])  # a gap of 1e-6 of the size
    c = PiecewiseBezier([q, r]).transformed(np.eye(2) * scale)
    rep = curve_continuity(c, 2)[0]
    assert rep.g_order == -1 and rep.gap == pytest.approx(4e-6 * scale, rel=1e-9)
    rep = curve_continuity(c, 2, atol=1e-5 * scale)[0]
    assert rep.g_order >= 0
