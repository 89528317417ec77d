"""Tests of course_lib.constructions.beta_splines (seed 000 §10).

References: the Beta-constraints typed in from seed 000 eq. (7.1)-(7.2) at every joint
with that joint's own, joint-varying shape parameters; scipy.interpolate.BSpline for
the uniform quadratic/cubic B-spline (β1 = 1, β2 = 0); course_lib.geometry.continuity for
"exactly G1/G2"; the linear-system construction of course_lib.constructions.beta_splines
(independent of the geometric one) for global parameters.
"""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import assert_g_order, check_joint, joint_fails
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import BSpline

from course_lib.constructions.beta_splines import (
    cubic_beta_spline,
    cubic_beta_spline_basis,
    design_beta_spline,
    gn_beta_spline_basis,
    quadratic_beta_spline,
    quadratic_beta_spline_basis,
)
from course_lib.constructions.beta_splines.quadratic_cubic import (
    _cubic_points,
    _cubic_polygons_from,
)
from course_lib.curves.curve import PiecewiseBezier

seeds = st.integers(0, 10**6)


def _bspline_curve(V, k, t):
    n = V.shape[0]
    return BSpline(np.arange(n + k + 1, dtype=float), V, k)(t + k)


@pytest.mark.parametrize("dim", [2, 3])
def test_uniform_reduction_quadratic_and_cubic(dim):
    rng = np.random.default_rng(1)
    V = rng.normal(size=(9, dim))
    q = quadratic_beta_spline(V, 1.0)
    t = np.linspace(0, q.n_segments, 41)
    np.testing.assert_allclose(q.evaluate(t), _bspline_curve(V, 2, t), atol=1e-12)
    c = cubic_beta_spline(V, 1.0, 0.0)
    t = np.linspace(0, c.n_segments, 41)
    np.testing.assert_allclose(c.evaluate(t), _bspline_curve(V, 3, t), atol=1e-12)


def test_uniform_reduction_of_bases():
    n = 7
    t = np.linspace(0, n - 3, 29)
    B = cubic_beta_spline_basis(n, 1.0, 0.0, t)
    want = BSpline.design_matrix(t + 3, np.arange(n + 4, dtype=float), 3).toarray()
    np.testing.assert_allclose(B, want, atol=1e-12)
    t = np.linspace(0, n - 2, 29)
    B = quadratic_beta_spline_basis(n, 1.0, t)
    want = BSpline.design_matrix(t + 2, np.arange(n + 3, dtype=float), 2).toarray()
    np.testing.assert_allclose(B, want, atol=1e-12)


@settings(max_examples=20, deadline=None)
@given(b1=st.lists(st.floats(0.2, 5.0), min_size=7, max_size=7, unique=True), seed=seeds)
def test_quadratic_g1_with_each_joints_own_beta1(b1, seed):
    V = np.random.default_rng(seed).normal(size=(8, 2))  # m = 7 legs, 6 segments
    c = quadratic_beta_spline(V, b1)
    assert c.n_segments == 6
    for j in range(c.n_joints):
        check_joint(c, j, [b1[j + 1]])  # joint j sits on leg j + 1
    np.testing.assert_allclose(c.info["beta1"], b1[1:-1])


@settings(max_examples=20, deadline=None)
@given(
    b1=st.lists(st.floats(0.3, 4.0), min_size=9, max_size=9, unique=True),
    b2=st.lists(st.floats(0.0, 6.0), min_size=9, max_size=9),
    seed=seeds,
)
def test_cubic_g2_with_each_joints_own_betas(b1, b2, seed):
    V = np.random.default_rng(seed).normal(size=(9, 3))  # m = 8, 6 segments
    c = cubic_beta_spline(V, b1, b2)
    assert c.n_segments == 6
    for j in range(c.n_joints):
        check_joint(c, j, [b1[j + 2], b2[j + 2]])  # joint j is near V_{j+2}
    np.testing.assert_allclose(c.info["beta1"], b1[2:-2])
    np.testing.assert_allclose(c.info["beta2"], b2[2:-2])


def test_cubic_negative_beta2_still_g2():
    V = np.random.default_rng(2).normal(size=(8, 2))
    b1 = [1.0, 0.8, 1.5, 0.6, 2.0, 1.2, 0.9, 1.1]
    b2 = [0.0, -1.0, -0.5, 2.0, -2.0, 0.3, 0.0, 0.0]
    c = cubic_beta_spline(V, b1, b2)
    for j in range(c.n_joints):
        check_joint(c, j, [b1[j + 2], b2[j + 2]])


def test_seed_leg_ratio_index_breaks_g2():
    """Seed 000 §10.2 (1b) as printed (beta1_i^2 gamma_{i+1}) fails G2 with local betas."""
    V = np.random.default_rng(4).normal(size=(8, 2))
    b1 = np.array([1.0, 0.7, 1.6, 0.5, 2.2, 1.3, 0.8, 1.0])
    b2 = np.array([0.0, 0.5, 1.0, 0.2, 3.0, 0.0, 1.0, 0.0])
    W1, W2, J, _ = _cubic_points(V, b1, b2, seed_indexing=True)
    seed_curve = PiecewiseBezier(list(_cubic_polygons_from(W1, W2, J)))
    fails = [joint_fails(seed_curve, j, [b1[j + 2], b2[j + 2]]) for j in range(seed_curve.n_joints)]
    assert all(fails)
    # ... while with one global beta1 the two readings agree
    seed_pts = _cubic_points(V, np.full(8, 1.4), b2, seed_indexing=True)
    ours = _cubic_points(V, np.full(8, 1.4), b2)
    for a, b in zip(seed_pts, ours, strict=True):
        np.testing.assert_allclose(a, b)


def test_exact_orders_generic():
    rng = np.random.default_rng(9)
    V = rng.normal(size=(8, 2))
    assert_g_order(quadratic_beta_spline(V, rng.uniform(0.5, 2, 7)), 1)
    assert_g_order(cubic_beta_spline(V, rng.uniform(0.5, 2, 8), rng.uniform(0, 3, 8)), 2)


@pytest.mark.parametrize(("b1", "b2"), [(1.0, 0.0), (1.7, 0.0), (0.6, 2.5), (2.0, -1.0)])
def test_global_parameters_match_linear_system(b1, b2):
    """Geometric construction == basis solved from the Beta-constraints (higher_order)."""
    n = 8
    t = np.linspace(0.0, 1.0, 11)
    B = cubic_beta_spline_basis(n, b1, b2, t + 2)  # a segment away from the ends
    ref = gn_beta_spline_basis(2, (b1, b2)).evaluate(t)  # b_0..b_3 on V_{j}..V_{j+3}
    np.testing.assert_allclose(B[:, 2:6], ref, atol=1e-12)
    B = quadratic_beta_spline_basis(n, b1, t + 2)
    ref = gn_beta_spline_basis(1, (b1,)).evaluate(t)
    np.testing.assert_allclose(B[:, 2:5], ref, atol=1e-12)


@settings(max_examples=25, deadline=None)
@given(
    b1=st.lists(st.floats(0.2, 5.0), min_size=8, max_size=8),
    b2=st.lists(st.floats(0.0, 10.0), min_size=8, max_size=8),
)
def test_bases_partition_of_unity_and_nonnegative(b1, b2):
    t = np.linspace(0, 5, 51)
    B = cubic_beta_spline_basis(8, b1, b2, t)
    np.testing.assert_allclose(B.sum(axis=1), 1.0, atol=1e-12)
    assert B.min() >= -1e-13  # convex hull property (beta1 > 0, beta2 >= 0)
    Q = quadratic_beta_spline_basis(8, b1[:7], np.linspace(0, 6, 61))
    np.testing.assert_allclose(Q.sum(axis=1), 1.0, atol=1e-12)
    assert Q.min() >= -1e-13


def test_basis_reproduces_curve_and_local_support():
    rng = np.random.default_rng(11)
    V = rng.normal(size=(8, 2))
    b1, b2 = rng.uniform(0.5, 2, 8), rng.uniform(0, 3, 8)
    c = cubic_beta_spline(V, b1, b2)
    t = np.linspace(0, c.n_segments, 37)
    B = cubic_beta_spline_basis(8, b1, b2, t)
    np.testing.assert_allclose(B @ V, c.evaluate(t), atol=1e-12)
    # segment s (t in (s, s+1)) only uses V_s .. V_{s+3}
    inner = (t > 2) & (t < 3)
    assert np.all(B[inner][:, [0, 1, 6, 7]] == 0)


@settings(max_examples=20, deadline=None)
@given(seed=seeds)
def test_affine_invariance(seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(7, 2))
    A, s = rng.normal(size=(2, 2)), rng.normal(size=2)
    b1, b2 = rng.uniform(0.3, 3, 7), rng.uniform(-0.5, 3, 7)
    for make in (
        lambda P: cubic_beta_spline(P, b1, b2),
        lambda P: quadratic_beta_spline(P, b1[:6]),
    ):
        c1, c2 = make(V @ A.T + s), make(V).transformed(A, s)
        for x, y in zip(c1.segments, c2.segments, strict=True):
            np.testing.assert_allclose(x, y, atol=1e-10)


@settings(max_examples=25, deadline=None)
@given(
    b1=st.lists(st.floats(0.3, 3.0), min_size=8, max_size=8),
    b2=st.lists(st.floats(-0.5, 6.0), min_size=8, max_size=8),
    seed=seeds,
)
def test_design_round_trip(b1, b2, seed):
    V = np.random.default_rng(seed).normal(size=(8, 2))
    c = cubic_beta_spline(V, b1, b2)
    d = design_beta_spline(V, c.info["interior_points"])
    np.testing.assert_allclose(d.info["beta1_vertices"], b1[1:-1], rtol=1e-7)
    np.testing.assert_allclose(d.info["beta2_vertices"], b2[1:-1], rtol=1e-6, atol=1e-6)
    for x, y in zip(c.segments, d.segments, strict=True):
        np.testing.assert_allclose(x, y, atol=1e-9)
    for j in range(d.n_joints):
        check_joint(d, j, [d.info["beta1"][j], d.info["beta2"][j]], rtol=1e-8)


def test_design_thirds_give_uniform_bspline():
    V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0], [6.0, 1.0]])
    legs = np.stack([V[:-1] + (V[1:] - V[:-1]) / 3, V[:-1] + 2 * (V[1:] - V[:-1]) / 3], axis=1)
    d = design_beta_spline(V, legs)
    np.testing.assert_allclose(d.info["beta1_vertices"], 1.0)
    np.testing.assert_allclose(d.info["beta2_vertices"], 0.0, atol=1e-12)


V5 = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0], [6.0, 1.0]])
LEGS = np.stack([V5[:-1] + (V5[1:] - V5[:-1]) / 3, V5[:-1] + 2 * (V5[1:] - V5[:-1]) / 3], axis=1)


def _swap(L, i):
    L = L.copy()
    L[i] = L[i, ::-1]
    return L


def _off(L, i):
    L = L.copy()
    leg = V5[i + 1] - V5[i]
    L[i, 0] += 0.1 * np.array([-leg[1], leg[0]])  # perpendicular to the leg
    return L


@pytest.mark.parametrize(
    ("call", "match"),
    [
        (lambda: quadratic_beta_spline(V5[:2]), "at least 3 points"),
        (lambda: quadratic_beta_spline(V5, 0.0), "beta1 must be > 0"),
        (lambda: quadratic_beta_spline(V5, [1.0, 1.0, -1.0, 1.0]), "at leg 2 it is -1.0"),
        (lambda: quadratic_beta_spline(V5, [1.0, -1.0]), "at joint 1 it is -1.0"),
        (lambda: quadratic_beta_spline(V5, [1.0, 1.0, 1.0]), r"one per leg V_i V_\(i\+1\) \(4\)"),
        (lambda: quadratic_beta_spline([[0, 0], [1, 1], [1, 1], [2, 0]]), "leg 1"),
        (lambda: cubic_beta_spline(V5[:3]), "at least 4 points"),
        (lambda: cubic_beta_spline(V5, [1, 1, -0.5, 1, 1]), "at vertex V_2 it is -0.5"),
        (lambda: cubic_beta_spline(np.vstack([V5, V5 + 9]), [1, -1, 1, 1, 1, 1]), "at joint 1"),
        (
            lambda: cubic_beta_spline(V5, [1, 1, 1, 0.5, 1], [0, 0, -4.0, -1.5, 0]),
            "gamma undefined at both V_2 and V_3",
        ),
        (lambda: cubic_beta_spline(V5, 1.0, [0.0, 0.0]), r"one per control vertex \(5\)"),
        (lambda: cubic_beta_spline(V5, 1.0, np.inf), "finite"),
        (lambda: cubic_beta_spline([[0, 0], [1, 0], [1, 0], [1, 0], [2, 0]]), "vertex V_2"),
        (lambda: cubic_beta_spline_basis(3, 1.0, 0.0, 0.5), "n_points must be >= 4"),
        (lambda: cubic_beta_spline_basis(5, 1.0, 0.0, 2.5), r"t must lie in the domain \[0, 2\]"),
        (lambda: design_beta_spline(V5, LEGS[:3]), r"interior must have shape \(4, 2, 2\)"),
        (lambda: design_beta_spline(V5, _swap(LEGS, 2)), r"interior\[1\] and interior\[2\]"),
        (lambda: design_beta_spline(V5, _off(LEGS, 1)), r"interior\[1\] must lie on leg 1"),
        (lambda: design_beta_spline(V5, np.full_like(LEGS, np.nan)), "finite"),
    ],
)
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_large_beta2_leg_ratio_zero_sum_raises():
    # gamma < 0 for beta2 < -2 beta1 (1 + beta1); choose values making 1 + g_i + b^2 g_{i+1} = 0
    b1 = np.ones(5)
    # gamma(beta2) = 4 / (beta2 + 4); want 1 + g0 + g1 = 0 with g0 = g1 = -1/2 -> beta2 = -12
    b2 = np.array([-12.0, -12.0, 0.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="leg 0"):
        cubic_beta_spline(V5, b1, b2)
