"""Tests of course_lib.constructions.surfaces (seed 001 §3).

References: finite differences and a closed-form bilinear/biquadratic patch for the
partials; the cross-product definition of the normal; the explicit first-order
constraint G_u(0,v) = α F_u(1,v) + β(v) F_v(1,v) checked pointwise; sympy's own
chain rule on undefined functions (n <= 2) and the closed count 2 (#{(h,l): 1 <= h+l <= n})
for the shape-function count n(n+3).
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.surfaces import (
    BezierPatch,
    count_shape_functions,
    g1_neighbour_patch,
    tangent_plane_continuity,
)


def _net(seed, m=3, n=2):
    return np.random.default_rng(seed).normal(size=(m + 1, n + 1, 3))


def test_bilinear_closed_form():
    P = np.array([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], float)
    F = BezierPatch(P)
    u, v = np.array([0.25, 0.5]), np.array([0.1, 0.9, 1.0])
    pts = F.evaluate(u, v)
    U, W = np.meshgrid(u, v, indexing="ij")
    np.testing.assert_allclose(pts, np.stack([U, W, U * W], axis=-1), atol=1e-14)
    np.testing.assert_allclose(F.evaluate(u, v, 1, 1)[..., 2], 1.0)
    np.testing.assert_allclose(F.evaluate(0.5, 0.5, 2, 0), 0.0)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10**6), nu=st.integers(0, 2), nv=st.integers(0, 2))
def test_partials_by_finite_differences(seed, nu, nv):
    F = BezierPatch(_net(seed))
    u, v, h = 0.37, 0.61, 1e-3

    def D(f, k, axis):
        if k == 0:
            return f
        if axis == 0:
            return lambda a, b: (D(f, k - 1, 0)(a + h, b) - D(f, k - 1, 0)(a - h, b)) / (2 * h)
        return lambda a, b: (D(f, k - 1, 1)(a, b + h) - D(f, k - 1, 1)(a, b - h)) / (2 * h)

    fd = D(D(lambda a, b: F.evaluate(a, b), nu, 0), nv, 1)(u, v)
    np.testing.assert_allclose(F.evaluate(u, v, nu, nv), fd, atol=1e-4 * (1 + np.abs(fd).max()))


def test_pointwise_equals_grid_diagonal_and_normals():
    F = BezierPatch(_net(2))
    t = np.linspace(0, 1, 6)
    np.testing.assert_allclose(F.evaluate(t, t, grid=False), np.einsum("iid->id", F.evaluate(t, t)))
    N = F.normal(t, t, grid=False)
    cr = np.cross(F.evaluate(t, t, 1, 0, grid=False), F.evaluate(t, t, 0, 1, grid=False))
    np.testing.assert_allclose(N, cr / np.linalg.norm(cr, axis=1)[:, None])
    assert F.normal(t, t).shape == (6, 6, 3)


@settings(max_examples=25, deadline=None)
@given(
    seed=st.integers(0, 10**6),
    alpha=st.floats(0.1, 5.0),
    b0=st.floats(-3.0, 3.0),
    b1=st.floats(-3.0, 3.0),
    k=st.integers(1, 3),
)
def test_g1_neighbour_satisfies_shape_function_constraint(seed, alpha, b0, b1, k):
    F = BezierPatch(_net(seed))
    rest = np.random.default_rng(seed + 1).normal(size=(k - 1, 3, 3))
    G = g1_neighbour_patch(F, rest, alpha, (b0, b1))
    v = np.linspace(0, 1, 9)
    np.testing.assert_allclose(G.evaluate(0.0, v), F.evaluate(1.0, v), atol=1e-12)
    beta = b0 * (1 - v) + b1 * v
    want = alpha * F.evaluate(1.0, v, 1, 0) + beta[:, None] * F.evaluate(1.0, v, 0, 1)
    np.testing.assert_allclose(
        G.evaluate(0.0, v, 1, 0), want, atol=1e-10 * (1 + np.abs(want).max())
    )
    rep = tangent_plane_continuity(F, G)
    assert rep.g1 and rep.same_orientation and rep.max_angle < 1e-6 and rep.gap < 1e-12


def test_tangent_plane_report_detects_kink_and_flip():
    F = BezierPatch(_net(5))
    rest = np.random.default_rng(6).normal(size=(1, 3, 3))
    G = g1_neighbour_patch(F, rest, 1.0, 0.0)
    kinked = G.control_net.copy()
    kinked[1] += [0.0, 0.0, 0.5]  # rotate the cross-boundary derivative
    rep = tangent_plane_continuity(F, BezierPatch(kinked))
    assert rep.gap == 0.0 and rep.max_angle > 1.0 and not rep.g1
    flipped = G.control_net.copy()
    flipped[1] = 2 * flipped[0] - flipped[1]  # alpha = -1: same plane, opposite side
    rep = tangent_plane_continuity(F, BezierPatch(flipped))
    assert rep.max_angle == pytest.approx(180.0) and not rep.same_orientation and not rep.g1


@pytest.mark.parametrize("n", [1, 2, 3, 4])
def test_shape_function_count(n):
    pairs = [(h, l) for h in range(n + 1) for l in range(n + 1) if 1 <= h + l <= n]
    assert count_shape_functions(n) == 2 * len(pairs) == n * (n + 3)


@pytest.mark.parametrize("n", [1, 2])
def test_count_agrees_with_sympy_function_chain_rule(n):
    """Independent: sympy's chain rule on G(u(s,t), v(s,t)) with undefined functions."""
    sp = pytest.importorskip("sympy")
    s, t = sp.symbols("s t")
    u, v = sp.Function("u")(s, t), sp.Function("v")(s, t)
    G = sp.Function("G")(u, v)
    found = set()
    for i in range(n + 1):
        for j in range(n + 1 - i):
            if i + j:
                e = sp.diff(G, *([s] * i + [t] * j))
                found |= {d for d in e.atoms(sp.Derivative) if d.expr in (u, v)}
    assert len(found) == count_shape_functions(n)


@pytest.mark.parametrize(
    ("call", "exc", "match"),
    [
        (lambda: BezierPatch(np.zeros((3, 3, 2))), ValueError, r"shape \(m\+1, n\+1, 3\)"),
        (lambda: BezierPatch(np.zeros((1, 3, 3))), ValueError, "m, n >= 1"),
        (lambda: BezierPatch(np.full((2, 2, 3), np.nan)), ValueError, "finite"),
        (lambda: BezierPatch("abc"), TypeError, "control_net"),
        (
            lambda: BezierPatch(_net(1)).evaluate([0.1, 0.2], [0.3], grid=False),
            ValueError,
            "same length",
        ),
        (lambda: BezierPatch(np.zeros((2, 2, 3))).normal(0.5, 0.5), ValueError, "not regular"),
        (
            lambda: g1_neighbour_patch(BezierPatch(_net(1)), [], 0.0),
            ValueError,
            "alpha must be > 0",
        ),
        (
            lambda: g1_neighbour_patch(BezierPatch(_net(1)), [], -1.0),
            ValueError,
            "alpha must be > 0",
        ),
        (
            lambda: g1_neighbour_patch(BezierPatch(_net(1)), [], 1.0, (1.0, 2.0, 3.0)),
            ValueError,
            "beta must be a scalar or the two values",
        ),
        (
            lambda: g1_neighbour_patch(BezierPatch(_net(1)), np.zeros((1, 2, 3))),
            ValueError,
            r"rest must have shape \(k - 1, 3, 3\)",
        ),
        (lambda: g1_neighbour_patch(_net(1), []), TypeError, "F must be a BezierPatch"),
        (lambda: count_shape_functions(0), ValueError, "n must be >= 1"),
    ],
)
def test_bad_input(call, exc, match):
    with pytest.raises(exc, match=match):
        call()
