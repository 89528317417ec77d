"""Item 7: the continuity report of one joint vs a direct numpy G2 check.

``curve_continuity`` (C-order and G-order by the three characterizations, orders up to
3 as the widgets ask) against the smallest honest reference: a direct numpy G2 check of
the same joint -- end derivatives from the control points (seed 000 eq. (8)), unit
tangents and curvature vectors (seed 004 §19.2) compared with ``np.allclose``.  Two
shapes of the question:

* a whole curve (a 9-segment cubic Beta-spline, 8 joints): time per joint, the reference
  looping the direct check over the joints;
* one joint as a widget frame asks it (as ``widgets._core.joint_report`` does: a
  two-segment curve is built and reported), the reference checking that one joint.

Goal (issue 14): <= 0.5 ms per joint and <= 5x the direct check.
"""

from __future__ import annotations

import numpy as np
from bench_common import Result, Sizes, median_time

GOAL_MS = 0.5
GOAL_RATIO = 5.0
MAX_ORDER = 3


def _frame(d1: np.ndarray, d2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    v = np.sqrt(d1 @ d1)
    T = d1 / v
    return T, (d2 - (d2 @ T) * T) / (v * v)


def direct_g2(P: np.ndarray, Q: np.ndarray, hq: float = 1.0, hr: float = 1.0) -> bool:
    """G2 of the joint P[-1] = Q[0] of two Bézier segments, straight from control points."""
    d, e = P.shape[0] - 1, Q.shape[0] - 1
    q1 = d * (P[-1] - P[-2]) / hq
    q2 = d * (d - 1) * (P[-1] - 2 * P[-2] + P[-3]) / hq**2
    r1 = e * (Q[1] - Q[0]) / hr
    r2 = e * (e - 1) * (Q[2] - 2 * Q[1] + Q[0]) / hr**2
    Tq, Kq = _frame(q1, q2)
    Tr, Kr = _frame(r1, r2)
    return bool(np.allclose(P[-1], Q[0]) and np.allclose(Tq, Tr) and np.allclose(Kq, Kr, atol=1e-8))


def _curve():
    from course_lib.constructions.beta_splines import cubic_beta_spline

    V = np.random.default_rng(0).normal(size=(12, 2))
    return cubic_beta_spline(V, 1.3, 0.7)


def joint_report(curve, j: int, max_order: int):
    """What ``course_lib.widgets._core.joint_report`` does on every frame (without importing
    the widget stack): build the two-segment curve around joint ``j`` and report it."""
    from course_lib.curves.curve import PiecewiseBezier
    from course_lib.geometry.continuity import curve_continuity

    k = curve.knots
    pair = PiecewiseBezier(curve.segments[j : j + 2], k[j : j + 3] if curve.has_knots else None)
    return curve_continuity(pair, max_order=max_order)[0]


def run(sizes: Sizes) -> list[Result]:
    from course_lib.geometry.continuity import curve_continuity

    c = _curve()
    segs = c.segments
    J = c.n_joints
    # correctness before timing: both say G2 at every joint
    reports = curve_continuity(c, MAX_ORDER)
    assert all(r.g_order >= 2 for r in reports)
    assert all(direct_g2(segs[j], segs[j + 1]) for j in range(J))
    repeats = max(5, 10 * sizes.repeats)

    ours = median_time(lambda: curve_continuity(c, MAX_ORDER), repeats) / J
    ref = median_time(lambda: [direct_g2(segs[j], segs[j + 1]) for j in range(J)], repeats) / J
    one = median_time(lambda: joint_report(c, 3, MAX_ORDER), repeats)
    ref1 = median_time(lambda: direct_g2(segs[3], segs[4]), repeats)
    rows = []
    for name, a, b, note in (
        (f"continuity report, whole curve ({J} joints), per joint", ours, ref, ""),
        (
            "continuity report of one joint (a widget frame)",
            one,
            ref1,
            "includes building the pair",
        ),
    ):
        rows.append(
            Result(
                "7",
                name,
                a,
                "direct numpy G2 check",
                b,
                f"<= {GOAL_MS} ms and <= {GOAL_RATIO:g}x",
                a <= GOAL_MS * 1e-3 and a / b <= GOAL_RATIO,
                note,
            )
        )
    return rows
