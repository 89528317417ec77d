"""Tests of course_lib.constructions.catmull_rom (seed 000 §9, eq. (13)-(14)).

References: sympy on the transcribed eq. (14); the classical uniform Catmull-Rom
matrix 0.5 [[0,2,0,0],[-1,0,1,0],[2,-5,4,-1],[-1,3,-3,1]] (monomial basis
1, u, u^2, u^3); explicit Beta-constraint (7.1); course_lib.geometry.continuity.
"""

from __future__ import annotations

import numpy as np
import pytest
from _spline_checks import assert_g_order, check_joint
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.catmull_rom import catmull_rom, catmull_rom_blending

CR = 0.5 * np.array([[0, 2, 0, 0], [-1, 0, 1, 0], [2, -5, 4, -1], [-1, 3, -3, 1]])


def test_eq_14_symbolic():
    """Interpolation, partition of unity and q_{i+1}'(0) = beta1 q_i'(1) for eq. (14)."""
    sp = pytest.importorskip("sympy")
    u, b = sp.symbols("u beta1", positive=True)
    phi = [
        -(b**2) * (u**3 - 2 * u**2 + u) / (b + 1),
        ((b**2 + b + 1) * u**3 - (2 * b**2 + 2 * b + 1) * u**2 + (b**2 - 1) * u + b + 1) / (b + 1),
        -((b**2 + b + 1) * u**3 - (2 * b**2 + b + 1) * u**2 - b * u) / (b * (b + 1)),
        (u**3 - u**2) / (b * (b + 1)),
    ]
    assert sp.cancel(sum(phi) - 1) == 0
    assert [sp.cancel(p.subs(u, 0)) for p in phi] == [0, 1, 0, 0]
    assert [sp.cancel(p.subs(u, 1)) for p in phi] == [0, 0, 1, 0]
    dphi = [sp.diff(p, u) for p in phi] + [sp.Integer(0)]
    # coefficient of V_{i+k} in q_{i+1}'(0) is phi_{k-1}'(0); in q_i'(1) it is phi_k'(1)
    for k in range(0, 5):  # k = offset + 1: V_{i-1} .. V_{i+3}
        left = dphi[k - 1].subs(u, 0) if k >= 1 else 0
        right = dphi[k].subs(u, 1) if k <= 3 else 0
        assert sp.cancel(left - b * right) == 0
    # the local (Hermite) form of the module with a = b is eq. (14)
    a, c = sp.symbols("a c", positive=True)
    h00, h10, h01, h11 = (
        2 * u**3 - 3 * u**2 + 1,
        u**3 - 2 * u**2 + u,
        -2 * u**3 + 3 * u**2,
        u**3 - u**2,
    )
    local = [
        -(a**2) / (1 + a) * h10,
        h00 + (a - 1) * h10 - c / (1 + c) * h11,
        h01 + h10 / (1 + a) + (c - 1) / c * h11,
        h11 / (c * (1 + c)),
    ]
    for p_loc, p_seed in zip(local, phi, strict=True):
        assert sp.cancel(p_loc.subs({a: b, c: b}) - p_seed) == 0
    # and the module's numeric weights are these
    for bv in (0.5, 1.0, 2.3):
        uu = np.linspace(0, 1, 7)
        want = np.array([[float(p.subs({u: x, b: bv})) for p in phi] for x in uu])
        np.testing.assert_allclose(catmull_rom_blending(uu, bv), want, atol=1e-13)


def test_beta1_one_is_classical_catmull_rom():
    rng = np.random.default_rng(3)
    V = rng.normal(size=(7, 2))
    c = catmull_rom(V, 1.0)
    u = np.linspace(0, 1, 9)
    U = np.vander(u, 4, increasing=True)
    for i in range(c.n_segments):
        want = U @ CR @ V[i : i + 4]
        np.testing.assert_allclose(c.evaluate_segment(i, u), want, atol=1e-12)


@settings(max_examples=20, deadline=None)
@given(b=st.floats(0.2, 4.0), seed=st.integers(0, 10**6))
def test_global_curve_matches_eq_13_14(b, seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(6, 3))
    c = catmull_rom(V, b)
    u = np.linspace(0, 1, 5)
    phi = catmull_rom_blending(u, b)
    for i in range(c.n_segments):
        np.testing.assert_allclose(c.evaluate_segment(i, u), phi @ V[i : i + 4], atol=1e-11)


@settings(max_examples=20, deadline=None)
@given(
    betas=st.lists(st.floats(0.2, 4.0), min_size=6, max_size=6, unique=True),
    seed=st.integers(0, 10**6),
)
def test_local_beta1_g1_with_own_parameter(betas, seed):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(8, 2))  # 5 segments, interpolated vertices V_1..V_6
    c = catmull_rom(V, betas)
    for j in range(c.n_joints):
        check_joint(c, j, [betas[j + 1]])
        np.testing.assert_allclose(c.joint_points[j], V[j + 2], atol=1e-12)  # interpolates
    np.testing.assert_allclose(c.info["beta1"], betas[1:-1])


def test_local_blending_reproduces_local_curve():
    rng = np.random.default_rng(12)
    V = rng.normal(size=(7, 2))
    b = np.array([0.6, 1.8, 1.1, 2.5, 0.9])  # at V_1 .. V_5
    c = catmull_rom(V, b)
    u = np.linspace(0, 1, 9)
    for i in range(c.n_segments):
        w = catmull_rom_blending(u, b[i], b[i + 1])
        np.testing.assert_allclose(w.sum(axis=1), 1.0, atol=1e-13)
        np.testing.assert_allclose(c.evaluate_segment(i, u), w @ V[i : i + 4], atol=1e-12)


def test_local_beta1_reduces_to_eq_14():
    rng = np.random.default_rng(5)
    V = rng.normal(size=(7, 2))
    a = catmull_rom(V, [1.7] * 5)
    b = catmull_rom(V, 1.7)
    for s, t in zip(a.segments, b.segments, strict=True):
        np.testing.assert_allclose(s, t, atol=1e-13)


def test_segment_depends_only_on_betas_at_its_ends():
    rng = np.random.default_rng(6)
    V = rng.normal(size=(8, 2))
    b = np.array([1.0, 1.2, 0.7, 2.0, 1.5, 0.9])
    c0 = catmull_rom(V, b)
    b2 = b.copy()
    b2[4] = 3.0  # beta at V_5: ends of segments 3 (V_4 V_5) and 4 (V_5 V_6)
    c1 = catmull_rom(V, b2)
    changed = [not np.allclose(s, t) for s, t in zip(c0.segments, c1.segments, strict=True)]
    assert changed == [False, False, False, True, True]


def test_exactly_g1_generic():
    rng = np.random.default_rng(8)
    V = rng.normal(size=(7, 2))
    assert_g_order(catmull_rom(V, [0.6, 1.4, 2.2, 0.8, 1.1]), 1)


def test_convex_hull_fails():
    """Honest counter-example: the segment from (0,0) to (1,0) dips below y = 0."""
    V = np.array([[0.0, 1.0], [0.0, 0.0], [1.0, 0.0], [1.0, 1.0]])
    c = catmull_rom(V, 1.0)
    pts = c.evaluate_segment(0, np.linspace(0, 1, 11))
    # hull of V is the unit square; closed form y(u) = (u^2 - u)/2 < 0 inside (0, 1)
    np.testing.assert_allclose(
        pts[:, 1], (np.linspace(0, 1, 11) ** 2 - np.linspace(0, 1, 11)) / 2, atol=1e-14
    )
    assert pts[5, 1] < -0.1
    w = catmull_rom_blending(np.linspace(0.05, 0.95, 19), 2.0)
    assert np.all(w[:, 0] < 0) and np.all(w[:, 3] < 0)


@settings(max_examples=20, deadline=None)
@given(b=st.floats(0.2, 4.0), u=st.floats(0, 1), seed=st.integers(0, 10**6))
def test_partition_of_unity_and_affine_invariance(b, u, seed):
    assert catmull_rom_blending(u, b).sum() == pytest.approx(1.0, abs=1e-12)
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(6, 2))
    A, t = rng.normal(size=(2, 2)), rng.normal(size=2)
    c1 = catmull_rom(V @ A.T + t, b)
    c2 = catmull_rom(V, b).transformed(A, t)
    for s1, s2 in zip(c1.segments, c2.segments, strict=True):
        np.testing.assert_allclose(s1, s2, atol=1e-10)


V = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0], [4.0, 0.0]])


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        ({"V": V[:3]}, "at least 4 points"),
        ({"V": V, "beta1": 0.0}, "beta1 must be > 0"),
        ({"V": V, "beta1": [1.0, -2.0, 1.0]}, "at V_2 it is -2.0"),
        ({"V": V, "beta1": [-2.0]}, "at joint 0 it is -2.0"),
        ({"V": V, "beta1": [1.0, 1.0]}, r"one value per interior joint \(1\)"),
        ({"V": V, "beta1": np.nan}, "finite"),
        ({"V": [[0, 0], [1, 0], [1, 0], [1, 0], [2, 0]]}, "tangent at V_2 vanishes"),
        ({"V": [[0, 0], [1, 0], [np.nan, 0], [3, 0]]}, "finite"),
    ],
)
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        catmull_rom(**kwargs)
