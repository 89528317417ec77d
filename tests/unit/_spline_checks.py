"""Shared checks for the spline-construction tests (not a test module).

The Beta-constraints are typed in from seed 000 eq. (7.1)-(7.4) explicitly, independent
of course_lib.geometry.beta_constraints; derivatives come from the Bézier control points
(``PiecewiseBezier.end_derivatives``, seed 000 eq. (8.1)-(8.3) and their analogues).
"""

from __future__ import annotations

import numpy as np

from course_lib.geometry.continuity import curve_continuity


def explicit_beta_rhs(q: np.ndarray, b: list[float]) -> np.ndarray:
    """r^(1..n)(0) prescribed by seed 000 eq. (7.1)-(7.4); q[k-1] = q^(k)(1), n = len(b) <= 4."""
    n = len(b)
    b = list(b) + [0.0] * (4 - n)
    q = np.vstack([q, np.zeros((4 - q.shape[0], q.shape[1]))]) if q.shape[0] < 4 else q
    b1, b2, b3, b4 = b
    rows = [
        b1 * q[0],
        b1**2 * q[1] + b2 * q[0],
        b1**3 * q[2] + 3 * b1 * b2 * q[1] + b3 * q[0],
        b1**4 * q[3] + 6 * b1**2 * b2 * q[2] + (4 * b1 * b3 + 3 * b2**2) * q[1] + b4 * q[0],
    ]
    return np.array(rows[:n])


def check_joint(curve, j: int, betas: list[float], rtol: float = 1e-9) -> None:
    """Assert C0 and the Beta-constraints of order len(betas) at joint j (local parameters)."""
    n = len(betas)
    q = curve.end_derivatives(j, 1, n)
    r = curve.end_derivatives(j + 1, 0, n)
    scale = max(1.0, float(np.abs(q).max()), float(np.abs(r).max()))
    np.testing.assert_allclose(r[0], q[0], atol=rtol * scale, err_msg=f"gap at joint {j}")
    want = explicit_beta_rhs(q[1:], betas)
    np.testing.assert_allclose(
        r[1:],
        want,
        atol=rtol * scale * max(1.0, max(abs(x) for x in betas)) ** n,
        err_msg=f"Beta-constraints fail at joint {j}",
    )


def joint_fails(curve, j: int, betas: list[float], rtol: float = 1e-6) -> bool:
    n = len(betas)
    q = curve.end_derivatives(j, 1, n)
    r = curve.end_derivatives(j + 1, 0, n)
    want = explicit_beta_rhs(q[1:], betas)
    return bool(np.abs(r[1:] - want).max() > rtol * max(1.0, float(np.abs(r).max())))


def assert_g_order(curve, order: int) -> None:
    """course_lib.geometry.continuity reports exactly G^order (not more) at every joint."""
    reports = curve_continuity(curve, max_order=order + 1, rtol=1e-7)
    assert reports, "no joint to check"
    got = [r.g_order for r in reports]
    assert got == [order] * len(reports), got
