"""onto_change_of_variables: onto [0, 1], increasing, prescribed derivatives at the joint."""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.geometry.joint_reparametrization import onto_change_of_variables, smoothstep


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_smoothstep_end_conditions(n):
    s = sp.Symbol("s")
    S = sum(float(c) * s**k for k, c in enumerate(smoothstep(n).coef))
    assert abs(S.subs(s, 0)) < 1e-12 and abs(S.subs(s, 1) - 1) < 1e-12
    for j in range(1, n + 1):
        assert abs(sp.diff(S, s, j).subs(s, 0)) < 1e-9 and abs(sp.diff(S, s, j).subs(s, 1)) < 1e-9


@settings(max_examples=30, deadline=None)
@given(
    st.floats(0.2, 5),
    st.lists(st.floats(-20, 20), min_size=0, max_size=3),
)
def test_onto_unit_interval_increasing_with_the_betas(b1, others):
    betas = [b1, *others]
    u = onto_change_of_variables(betas)
    assert u.domain == pytest.approx((1 - 1 / b1, 1.0)) and u.image == (0.0, 1.0)
    assert np.allclose(u.derivatives(1.0, len(betas)), betas, rtol=1e-9, atol=1e-9)
    xs = np.linspace(*u.domain, 2001)
    assert np.all(u(xs, 1) > 0)


def test_derivatives_are_continuous_where_the_blend_starts():
    betas = [1.5, 0.5, -2.0]
    u = onto_change_of_variables(betas, width=0.25)
    x0, eps = 0.75, 1e-9
    for k in range(4):  # C^3 needs order-3 continuity of u  (n = 3)
        left = u(x0 - eps, k)
        right = u(x0 + eps, k)
        assert abs(left - right) < 1e-5  # a jump would stay O(1)


@pytest.mark.parametrize(
    "betas, width, match",
    [([0.0], None, "beta1"), ([np.nan], None, "finite"), ([2.0], 0.9, "width")],
)
def test_bad_input(betas, width, match):
    with pytest.raises(ValueError, match=match):
        onto_change_of_variables(betas, width)
