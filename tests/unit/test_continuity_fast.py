"""The vectorized continuity report (issue 14) against the generic protocol path, the Bell
table against sympy, and the benchmark item 7 harness on tiny sizes."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib.constructions.beta_splines import cubic_beta_spline
from course_lib.constructions.catmull_rom import catmull_rom
from course_lib.curves.curve import PiecewiseBezier
from course_lib.curves.parametrization import ParametricCurve
from course_lib.geometry.chain_rule import bell_table
from course_lib.geometry.continuity import curve_continuity, joint_continuity

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


def test_bell_table_matches_sympy():
    x = np.random.default_rng(1).normal(size=(6, 2))
    B = bell_table(x, 6)
    X = sp.symbols("x1:7")
    for c in range(2):
        values = dict(zip(X, map(sp.Float, x[:, c]), strict=True))
        for i in range(7):
            for k in range(7):
                if i == k == 0:
                    ref = 1.0
                elif 1 <= k <= i:
                    ref = float(sp.bell(i, k, X[: i - k + 1]).xreplace(values))
                else:
                    ref = 0.0
                assert B[i, k, c] == pytest.approx(ref, rel=1e-12, abs=1e-12)


def _global_pieces(curve, i):
    """Segment i alone, in the global parameter, through the generic protocol path."""
    k = curve.knots
    return PiecewiseBezier([curve.segments[i]], knots=[k[i], k[i + 1]])


@settings(max_examples=15, deadline=None)
@given(
    seed=st.integers(0, 10**6),
    kind=st.sampled_from(["beta", "catmull", "random"]),
    knots=st.booleans(),
    order=st.integers(1, 5),
)
def test_vectorized_report_equals_the_generic_path(seed, kind, knots, order):
    rng = np.random.default_rng(seed)
    V = rng.normal(size=(8, 2))
    if kind == "beta":
        c = cubic_beta_spline(V, rng.uniform(0.3, 3, 8), rng.uniform(-1, 5, 8))
    elif kind == "catmull":
        c = catmull_rom(V, rng.uniform(0.3, 3))
    else:
        c = PiecewiseBezier([V[:4], np.vstack([V[3], V[4:7]]), V[5:8]])
    if knots:
        c = c.with_knots(np.cumsum(np.r_[0.0, rng.uniform(0.5, 2, c.n_segments)]))
    fast = curve_continuity(c, order)
    for j, rep in enumerate(fast):
        ref = joint_continuity(_global_pieces(c, j), _global_pieces(c, j + 1), order, index=j)
        assert (rep.c_order, rep.g_order, rep.g_order_by) == (
            ref.c_order,
            ref.g_order,
            ref.g_order_by,
        )
        np.testing.assert_allclose(rep.betas, ref.betas, rtol=1e-9, atol=1e-9)
        assert rep.gap == pytest.approx(ref.gap, abs=1e-12)
        assert rep.tangent_angle == pytest.approx(ref.tangent_angle, abs=1e-9)
        assert rep.curvature_jump == pytest.approx(ref.curvature_jump, rel=1e-9, abs=1e-10)


def test_generic_path_still_works_for_parametric_curves():
    t = sp.Symbol("t")
    q = ParametricCurve.from_sympy([sp.cos(t), sp.sin(t)], t, (0.0, 1.0))
    r = ParametricCurve.from_sympy([sp.cos(1 + 2 * t), sp.sin(1 + 2 * t)], t, (0.0, 1.0))
    rep = joint_continuity(q, r, 4)
    assert rep.g_order == 4 and rep.characterizations_agree and rep.c_order == 0
    assert rep.betas[0] == pytest.approx(2.0)


def test_benchmark_item_7_runs_and_checks_first(monkeypatch):
    monkeypatch.syspath_prepend(str(BENCH))  # benchmarks/ is a folder of scripts, not a package
    import bench_common
    import bench_continuity

    rows = bench_continuity.run(bench_common.TINY)
    assert len(rows) == 2 and all(r.item == "7" and r.ours > 0 and r.reference > 0 for r in rows)
    V = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 1.0], [3.0, 0.0]])
    assert not bench_continuity.direct_g2(V, V[::-1] * [1, -1] + [6, 0])  # a corner


@pytest.mark.parametrize("beta1", [0.02, 1.0, 50.0])
@pytest.mark.parametrize("which", ["curvature", "tangent"])
def test_characterizations_agree_near_the_threshold(beta1, which):
    """Sweep a G2 joint's curvature jump (or G1 joint's tangent kink) through the tolerance:
    the three characterizations agree, or the report says the joint is borderline."""
    from course_lib.constructions.stitching import g2_stitch

    V = np.array([[0.0, 0.0], [1.0, 1.5], [2.5, 1.8], [3.5, 1.0]])
    base = g2_stitch(V, beta1, 0.3, np.array([[3.5 + 4 * beta1, 2.0]]))
    q, r = base.segments
    T = (r[1] - r[0]) / np.linalg.norm(r[1] - r[0])
    normal = np.array([-T[1], T[0]])
    k = 2 if which == "curvature" else 1
    seen_far = 0
    for eps in np.logspace(-14, -3, 45):
        r2 = r.copy()
        r2[k] = r2[k] + eps * np.linalg.norm(r[1] - r[0]) * normal
        rep = curve_continuity(PiecewiseBezier([q, r2]), 3)[0]
        assert rep.characterizations_agree or rep.borderline, (eps, rep.g_order_by)
        if eps < 2e-13 or eps > 1e-4:
            assert rep.characterizations_agree and not rep.borderline, (eps, rep.g_order_by)
            seen_far += 1
    assert seen_far >= 10


def test_benchmark_item_8_runs_and_checks_first(monkeypatch):
    monkeypatch.syspath_prepend(str(BENCH))  # benchmarks/ is a folder of scripts, not a package
    import bench_common
    import bench_large_curve

    rows = bench_large_curve.run(bench_common.TINY)
    assert len(rows) == 2 and all(r.item == "8" and r.ours > 0 and r.reference > 0 for r in rows)
