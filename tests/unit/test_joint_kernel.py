"""The joint kernel (course_lib.geometry.joint_kernel) against an independent computation.

Two cubic Bézier pieces written out in sympy as Bernstein polynomials; their derivatives
with respect to arc length are taken by hand (d/ds = |c'|^{-1} d/dt, applied k times), exactly,
and the G-order is read off them (seed 000 §6: G^n iff d^k q/ds^k = d^k r/ds^k, k <= n).
The kernel computes the same from the end derivatives as floats.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp

from course_lib.geometry.joint_kernel import joint_kernel, leading_order

t = sp.symbols("t", real=True)


def _cubic(points) -> sp.Matrix:
    P = [sp.Matrix([sp.nsimplify(x) for x in p]) for p in points]
    return sum(
        (sp.binomial(3, i) * t**i * (1 - t) ** (3 - i) * P[i] for i in range(4)),
        sp.zeros(len(P[0]), 1),
    )


def _arc_derivatives(c: sp.Matrix, at, n: int) -> list[sp.Matrix]:
    """d^k c/ds^k, k = 1..n, at t = at, exactly."""
    speed = sp.sqrt((c.diff(t).T * c.diff(t))[0])
    out, cur = [], c
    for _ in range(n):
        cur = cur.diff(t) / speed
        out.append(sp.simplify(cur.subs(t, at)))
    return out


def _end_derivatives(c: sp.Matrix, at, k: int) -> np.ndarray:
    return np.array([[float(x) for x in c.diff(t, i).subs(t, at)] for i in range(k)])


def _g2_pair(beta1, beta2, shift=(0, 0), turn=0):
    """q, and r built from q's end by the Beta-constraints r' = β1 q', r'' = β1² q'' + β2 q'
    (seed 000 eq. (6)), then optionally shifted (a gap) or its tangent turned (a corner)."""
    q = _cubic([(0, 0), (1, 2), (3, 3), (4, 1)])
    a0, a1, a2 = (q.diff(t, i).subs(t, 1) for i in range(3))
    r1 = beta1 * a1
    r2 = beta1**2 * a2 + beta2 * a1
    if turn:
        rot = sp.Matrix([[0, -1], [1, 0]])
        r1, r2 = rot * r1, rot * r2
    R0 = a0 + sp.Matrix(shift)
    R1 = R0 + r1 / 3
    R2 = 2 * R1 - R0 + r2 / 6
    r = _cubic([tuple(R0), tuple(R1), tuple(R2), (9, -2)])
    return q, r


def _kernel(q, r, max_order=3, **kw):
    k = max(max_order, 2) + 1
    return joint_kernel(
        _end_derivatives(q, 1, k)[None], _end_derivatives(r, 0, k)[None], max_order, **kw
    )


def test_arc_length_derivatives_and_curvature_match_sympy():
    q, r = _g2_pair(2, 1)
    J = _kernel(q, r, max_order=3)
    for side, c, at in (("in", q, 1), ("out", r, 0)):
        exact = np.array([[float(x) for x in v] for v in _arc_derivatives(c, at, 3)])
        np.testing.assert_allclose(getattr(J, f"arc_{side}")[0], exact, rtol=1e-12, atol=1e-14)
        d1, d2 = c.diff(t).subs(t, at), c.diff(t, 2).subs(t, at)
        kappa = (d1[0] * d2[1] - d1[1] * d2[0]) / (d1.T * d1)[0] ** sp.Rational(3, 2)
        assert getattr(J, f"curvature_{side}")[0] == pytest.approx(float(kappa), rel=1e-12)
        np.testing.assert_allclose(getattr(J, f"tangent_{side}")[0], exact[0], rtol=1e-12)
    assert J.gap[0] == 0 and J.angle[0] == pytest.approx(0, abs=1e-6)
    assert J.curvature_jump[0] == pytest.approx(0, abs=1e-12)


def test_g_order_is_the_number_of_equal_arc_length_derivatives():
    q, r = _g2_pair(2, 1)
    A, B = _arc_derivatives(q, 1, 3), _arc_derivatives(r, 0, 3)
    equal = [sp.simplify(a - b) == sp.zeros(2, 1) for a, b in zip(A, B, strict=True)]
    assert equal == [True, True, False]  # G2 and not G3, exactly
    assert _kernel(q, r, max_order=3).g_order.tolist() == [2]
    assert _kernel(q, r, max_order=2).g_order.tolist() == [2]  # capped: "at least 2"
    assert _kernel(q, r, max_order=1).g_order.tolist() == [1]


def test_corner_gap_and_g1():
    q, r = _g2_pair(2, 1, turn=1)
    corner = _kernel(q, r)
    assert corner.g_order.tolist() == [0] and corner.angle[0] == pytest.approx(90.0)
    q, r = _g2_pair(2, 1, shift=(sp.Rational(1, 1000), 0))
    assert _kernel(q, r).g_order.tolist() == [-1] and _kernel(q, r).gapped.tolist() == [True]
    q, r = _g2_pair(2, 5)  # β2 only changes r'' along the tangent: still G2
    assert _kernel(q, r).g_order.tolist() == [2]
    # r'' off the constraint: G1 only; the signed curvatures differ, rel_jump by hand
    q = _cubic([(0, 0), (1, 2), (3, 3), (4, 1)])
    a0, a1 = q.subs(t, 1), q.diff(t).subs(t, 1)
    R1 = a0 + a1 / 3
    r = _cubic([tuple(a0), tuple(R1), (6, -3), (9, -2)])
    J = _kernel(q, r)
    assert J.g_order.tolist() == [1]
    kq, kr = J.curvature_in[0], J.curvature_out[0]
    assert J.rel_jump[0] == pytest.approx(abs(kr - kq) / max(abs(kq), abs(kr), 1 / J.length[0]))


def test_many_joints_at_once_equal_one_at_a_time():
    pairs = [_g2_pair(2, 1), _g2_pair(2, 1, turn=1), _g2_pair(sp.Rational(1, 2), -3)]
    dq = np.stack([_end_derivatives(q, 1, 4) for q, _ in pairs])
    dr = np.stack([_end_derivatives(r, 0, 4) for _, r in pairs])
    J = joint_kernel(dq, dr, 3)
    assert J.g_order.tolist() == [2, 0, 2]
    for j, (q, r) in enumerate(pairs):
        one = _kernel(q, r)
        assert one.g_order[0] == J.g_order[j] and one.angle[0] == J.angle[j]


def test_space_curves_use_the_curvature_vector():
    q = _cubic([(0, 0, 0), (1, 0, 1), (2, 1, 1), (3, 1, 0)])
    a0, a1, a2 = (q.diff(t, i).subs(t, 1) for i in range(3))
    R0, R1 = a0, a0 + 3 * a1 / 3
    R2 = 2 * R1 - R0 + (9 * a2 + a1) / 6  # β1 = 3, β2 = 1
    r = _cubic([tuple(R0), tuple(R1), tuple(R2), (5, 0, 2)])
    J = _kernel(q, r)
    K = _arc_derivatives(q, 1, 2)[1]
    assert J.curvature_in[0] == pytest.approx(float(sp.sqrt((K.T * K)[0])), rel=1e-12)
    assert J.g_order.tolist() == [2]


def test_singular_side_and_directions():
    dq = np.array([[[1.0, 0], [0, 0], [2, 0]]])  # q' = 0: singular
    dr = np.array([[[1.0, 0], [1, 0], [0, 1]]])
    J = joint_kernel(dq, dr, 2, directions=(np.array([[1.0, 0]]), np.array([[1.0, 1]])))
    assert J.regular.tolist() == [False] and J.g_order.tolist() == [0]
    assert np.isnan(J.curvature_in[0]) and J.angle[0] == pytest.approx(45.0)


def test_leading_order_and_bad_shapes():
    assert leading_order(np.ones((3, 2), bool)).tolist() == [3, 3]
    with pytest.raises(ValueError, match="dq and dr"):
        joint_kernel(np.zeros((1, 2, 2)), np.zeros((1, 2, 2)))


@pytest.mark.parametrize("eps", [1e-3, 1e-5])
def test_measure_and_tolerance_of_order_two_by_hand(eps):
    """r'' moved by eps off the Beta-constraint along the normal: the curvature vector jumps
    by eps / |r'|^2, so delta_2 = eps l / |r'|^2 with l = max(|q'|, |r'|) (h = 1); the tolerance
    is rtol max(1, l max|K|), and the verdict flips with rtol between the two."""
    q = _cubic([(0, 0), (1, 2), (3, 3), (4, 1)])
    a0, a1, a2 = (q.diff(t, i).subs(t, 1) for i in range(3))
    normal = sp.Matrix([-a1[1], a1[0]]) / sp.sqrt((a1.T * a1)[0])
    r1, r2 = 2 * a1, 4 * a2 + a1 + sp.nsimplify(eps) * normal
    R1 = a0 + r1 / 3
    r = _cubic([tuple(a0), tuple(R1), tuple(2 * R1 - a0 + r2 / 6), (9, -2)])
    vq, vr = float(sp.sqrt((a1.T * a1)[0])), float(sp.sqrt((r1.T * r1)[0]))
    ell = max(vq, vr)
    delta = eps * ell / vr**2
    J = _kernel(q, r, max_order=2, rtol=1e-8)
    assert J.measure[0, 1] == pytest.approx(delta, rel=1e-6)
    kmax = max(abs(J.curvature_in[0]), abs(J.curvature_out[0]))
    assert J.tolerance[0, 1] == pytest.approx(1e-8 * max(1.0, ell * kmax), rel=1e-12)
    assert J.g_order.tolist() == [1]
    loose = delta / max(1.0, ell * kmax) * 1.01  # just above the measure: G2
    assert _kernel(q, r, max_order=2, rtol=loose).g_order.tolist() == [2]
    assert _kernel(q, r, max_order=2, rtol=loose / 1.02).g_order.tolist() == [1]
