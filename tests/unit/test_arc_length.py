"""Arc length of whole Bézier curves (``course_lib.geometry.arc_length``): the fixed-grid fast
path, its certificate, and the fallbacks it hands the hard segments to.

References are independent of the code under test: mpmath's tanh-sinh quadrature at 40
digits on the exact polynomial speed (control points are binary fractions, converted
exactly), split at the critical points of the speed found by mpmath's own polynomial
root finder, so that a cusp or near-cusp sits at the end of a piece.
"""

from __future__ import annotations

import warnings
from math import comb

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import course_lib.geometry.arc_length as bl
from course_lib.curves.bezier import subdivide
from course_lib.curves.curve import PiecewiseBezier
from course_lib.geometry.arc_length import integrate_speed
from course_lib.geometry.differential_geometry import (
    arc_length,
    cumulative_arc_length,
    parameter_at_arc_length,
)

mpmath = pytest.importorskip("mpmath")

# the benchmark's cubic: an inflection, speed varying ~9x
CUBIC = np.array([[0.0, 0.0], [0.25, 2.0], [3.0, -1.5], [4.0, 1.0]])


def reference_length(P: np.ndarray, dps: int = 40, lo: float = 0.0, hi: float = 1.0) -> float:
    """int_lo^hi |q'(u)| du by mpmath, split at the real critical points of |q'|^2 between."""
    P = np.asarray(P, dtype=float)
    d, dim = P.shape[0] - 1, P.shape[1]
    with mpmath.workdps(dps):
        Pm = [[mpmath.mpf(float(x)) for x in row] for row in P]
        H = [[d * (Pm[i + 1][k] - Pm[i][k]) for k in range(dim)] for i in range(d)]
        # power-basis coefficients (exact in mpf) of each coordinate of q'
        coef = [[mpmath.mpf(0)] * d for _ in range(dim)]
        for i in range(d):
            for j in range(i, d):
                c = comb(d - 1, j) * comb(j, i) * (-1) ** (j - i)
                for k in range(dim):
                    coef[k][j] += c * H[i][k]

        def poly(cs, u):
            return mpmath.polyval(cs[::-1], u)

        # (|q'|^2)' = 2 sum_k x_k x_k': coefficients by convolution
        g = [mpmath.mpf(0)] * max(1, 2 * d - 2)
        for k in range(dim):
            der = [j * coef[k][j] for j in range(1, d)]
            for a, ca in enumerate(coef[k]):
                for b, cb in enumerate(der):
                    g[a + b] += ca * cb
        while len(g) > 1 and g[-1] == 0:
            g.pop()
        splits = []
        if len(g) > 1:
            roots = mpmath.polyroots(g[::-1], maxsteps=200, extraprec=200)
            splits = sorted(
                mpmath.re(r) for r in roots if abs(mpmath.im(r)) < 1e-20 and lo < mpmath.re(r) < hi
            )

        def speed(u):
            return mpmath.sqrt(sum(poly(coef[k], u) ** 2 for k in range(dim)))

        ends = [mpmath.mpf(float(lo)), *splits, mpmath.mpf(float(hi))]
        return float(mpmath.quad(speed, ends, maxdegree=12))


def _near_cusp(u0: float, eps: float) -> np.ndarray:
    """A cubic whose hodograph passes within about ``eps`` of the origin at ``u = u0``."""
    P = np.array([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.5, -0.5]])
    H = 3 * np.diff(P, axis=0)
    b = np.array([(1 - u0) ** 2, 2 * u0 * (1 - u0), u0**2])
    H[1] = (np.array([eps, 0.5 * eps]) - b[0] * H[0] - b[2] * H[2]) / b[1]
    return np.vstack([P[0], P[0] + np.cumsum(H / 3, axis=0)])


EASY = {
    "benchmark cubic": CUBIC,
    "loop": np.array([[0.0, 0.0], [2.0, 1.0], [-1.0, 1.0], [1.0, 0.0]]),
    "space cubic": np.array([[0.0, 0.0, 0.0], [1.0, 0.5, 1.0], [2.0, -0.5, 0.25], [3.0, 1.0, 0.5]]),
    "quintic": np.array([[0, 0], [1, 2], [2, -1], [3, 3], [4, 0], [5, 1.0]]),
    "far from the origin": CUBIC + np.array([1e6, -3e6]),
}
HARD = {
    "exact cusp at 1/2": np.array([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0], [1.0, 0.0]]),
    "collinear reversal": np.array([[0.0, 0.0], [2.0, 1.0], [-1.0, -0.5], [1.0, 0.5]]),
    "near cusp 1e-3 at 0.37": _near_cusp(0.37, 1e-3),
    "near cusp 1e-7 at 0.62": _near_cusp(0.62, 1e-7),
    "near cusp 1e-10 at 0.5": _near_cusp(0.5, 1e-10),
    "near-zero speed at u = 0": np.array(
        [[0.5, 0.25], [0.5 + 2**-20, 0.25 - 2**-21], [2, 1], [3, 0.0]]
    ),
    "near-zero speed at u = 1": np.array([[0, 0], [1, 2], [3, 1], [3 + 2**-24, 1 + 2**-23]]),
    # two rules that agree to 1e-16 and are both wrong by 7e-12 (a dip narrower than the
    # node spacing next to u = 0): the certificate's second condition rejects it
    "dip narrower than the nodes": np.array(
        [
            [-0.5517314171911221, 0.5236229236448857],
            [-0.5517328732504352, 0.523619853642955],
            [0.1234024109925685, 1.4932835413920167],
            [0.507558865172029, -0.9991131085398876],
        ]
    ),
}


@pytest.fixture
def robust_calls(monkeypatch):
    """Count the segments handed to the robust path."""
    calls = []
    orig = bl.robust_hodograph_length

    def spy(P):
        calls.append(np.array(P))
        return orig(P)

    monkeypatch.setattr(bl, "robust_hodograph_length", spy)
    return calls


@pytest.mark.parametrize("name", EASY)
def test_fast_path_matches_mpmath(name, robust_calls):
    P = EASY[name]
    exact = reference_length(P)
    assert abs(arc_length(PiecewiseBezier([P])) - exact) <= 1e-14 * exact
    assert not robust_calls, "the fast path should certify this segment"


@pytest.mark.parametrize("name", HARD)
def test_nearly_degenerate_cubics_fall_back_and_match_mpmath(name, robust_calls):
    P = HARD[name]
    exact = reference_length(P)
    assert abs(arc_length(PiecewiseBezier([P])) - exact) <= 1e-14 * exact
    assert len(robust_calls) == 1, "the fast path must not certify a (near-)cusp"


def test_two_agreeing_rules_are_not_enough():
    """Why the certificate has its second condition: on this cubic both fixed rules agree
    to RTOL and are wrong by more than 1e-12; the speed-separation condition rejects it."""
    P = HARD["dip narrower than the nodes"]
    exact = reference_length(P)
    for pieces in (bl.PIECES, bl.FINER_PIECES):
        G, W, reach = bl._rule(3, pieces)
        v = bl._norms_1((P[1:] - P[:-1]).T @ G)
        coarse, fine, bound = v @ W
        assert abs(fine - coarse) <= bl.RTOL * fine
        assert abs(fine - exact) > 1e-12 * exact
        assert v[:-2].min() < bl.SEPARATION * reach * bound
    for pieces in (bl.PIECES, bl.FINER_PIECES):
        fine, ok, in_range = bl._fixed_grid(np.diff(P, axis=0)[None], pieces)
        assert in_range[0] and not ok[0]


def test_robust_path_alone_matches_mpmath(monkeypatch):
    """The graded mesh certifies every case here; the adaptive bisection behind it is
    checked on its own by forcing the graded mesh to refuse."""
    def no_bisection(*args, **kwargs):
        raise AssertionError("the graded mesh should have certified this segment")

    with monkeypatch.context() as mp:
        mp.setattr(bl, "integrate_speed", no_bisection)
        for P in [*EASY.values(), *HARD.values()]:
            exact = reference_length(P)
            assert abs(bl.robust_length(np.asarray(P, float)) - exact) <= 1e-14 * exact
    monkeypatch.setattr(bl, "_graded", lambda H, grid: None)
    for P in HARD.values():
        exact = reference_length(P)
        assert abs(bl.robust_length(np.asarray(P, float)) - exact) <= 1e-14 * exact


def test_spline_lengths_are_the_sum_of_the_segments_and_match_the_general_path(robust_calls):
    rng = np.random.default_rng(7)
    segs = np.cumsum(rng.standard_normal((30, 4, 2)), axis=1)
    curve = PiecewiseBezier(segs, knots=np.cumsum(rng.uniform(0.5, 2.0, 31)))
    fast = arc_length(curve)
    k = curve.knots
    general = float(integrate_speed(curve, k[:-1], k[1:]).sum())
    assert fast == pytest.approx(general, rel=1e-12)
    assert arc_length(curve, k[0], k[-1]) == fast  # explicit ends take the same path
    assert arc_length(curve, k[-1], k[0]) == -fast
    mixed = PiecewiseBezier(
        [CUBIC, HARD["exact cusp at 1/2"] + CUBIC[-1], [[5.0, 1.0], [6.0, 2.0]]]
    )
    expected = reference_length(CUBIC) + reference_length(HARD["exact cusp at 1/2"]) + np.sqrt(2.0)
    assert arc_length(mixed) == pytest.approx(expected, rel=1e-13)
    s = cumulative_arc_length(mixed, np.array([0.5, 1.0, 1.5, 2.0, 2.5, 3.0]))
    assert s[-1] == pytest.approx(expected, rel=1e-15)
    half_cusp = reference_length(HARD["exact cusp at 1/2"], hi=0.5)
    assert s[2] - s[1] == pytest.approx(half_cusp, rel=1e-14)


@pytest.mark.parametrize("name", ["benchmark cubic", *HARD])
def test_cumulative_and_inverse_arc_length_agree_with_arc_length(name):
    """Partial arcs are Bézier pieces measured by the same certified rules (the general
    adaptive path used to be off by up to 2e-7 on near-cusps, and then
    parameter_at_arc_length refused s = arc_length(curve) as beyond its own L)."""
    P = HARD.get(name, CUBIC)
    q = PiecewiseBezier([P], knots=[2.0, 2.5])
    L = arc_length(q)
    t = np.array([2.0, 2.1, 2.25, 2.31, 2.5])
    s = cumulative_arc_length(q, t)
    for ti, si in zip(t[1:], s[1:], strict=True):
        exact = reference_length(P, hi=(ti - 2.0) / 0.5)
        assert abs(si - exact) <= 1e-14 * L
    assert abs(s[-1] - L) <= 1e-15 * L
    assert parameter_at_arc_length(q, L) == pytest.approx(2.5, abs=1e-13)
    np.testing.assert_allclose(
        cumulative_arc_length(q, parameter_at_arc_length(q, s)), s, atol=1e-13 * L
    )


@pytest.mark.filterwarnings("error::RuntimeWarning")
@pytest.mark.parametrize("exponent", [-1000, -600, 600, 1000])
def test_extreme_scales_go_through_the_scaled_path_without_warnings(exponent):
    """Coordinates near the ends of the float range (2^±1000): exact powers of two scale the
    length exactly; no overflow or underflow warning, never inf or 0."""
    base = arc_length(PiecewiseBezier([CUBIC]))
    for P in (CUBIC, HARD["near cusp 1e-7 at 0.62"]):
        ref = arc_length(PiecewiseBezier([P]))
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            got = arc_length(PiecewiseBezier([np.ldexp(P, exponent)]))
        assert np.ldexp(got, -exponent) == pytest.approx(ref, rel=1e-14)
    assert base > 0


def test_lines_and_points():
    line = PiecewiseBezier([[[0.0, 0.0], [3.0, 4.0]], [[3.0, 4.0], [3.0, 4.0]]])
    assert arc_length(line) == 5.0
    still = PiecewiseBezier([np.zeros((4, 2))])
    assert arc_length(still) == 0.0


cubics = st.lists(st.floats(-4.0, 4.0, width=32), min_size=8, max_size=8).map(
    lambda xs: np.array(xs, dtype=float).reshape(4, 2)
)


@settings(max_examples=60, deadline=None)
@given(P=cubics, u=st.floats(0.05, 0.95))
def test_length_is_additive_under_subdivision_and_rigid_motion(P, u):
    """Invariants over random cubics (easy ones and near-degenerate ones, whichever path
    each takes): L = L(left) + L(right) for a de Casteljau split, and a rotation with an
    exact power-of-two scale leaves L / scale unchanged."""
    L = arc_length(PiecewiseBezier([P]))
    left, right = subdivide(P, u)
    parts = arc_length(PiecewiseBezier([left])) + arc_length(PiecewiseBezier([right]))
    assert parts == pytest.approx(L, rel=1e-12, abs=1e-12)
    c, s = 0.6, 0.8  # exact rotation by atan2(0.8, 0.6)
    moved = P @ np.array([[c, -s], [s, c]]).T * 0.25 + [3.0, -7.0]
    assert arc_length(PiecewiseBezier([moved])) / 0.25 == pytest.approx(L, rel=1e-12, abs=1e-12)
