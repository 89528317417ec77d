"""Item 8: building and first evaluation of a 10^5-segment cubic curve vs scipy's BSpline.

The uniform cubic B-spline of 10^5 + 3 random control points, in Bézier form (one
``(S, 4, 2)`` array).  Timed, each repeat from scratch: ``PiecewiseBezier(segments)`` and
its first ``evaluate(t)`` at 10^3 and at 10^6 parameters, against ``BSpline(knots, V, 3)``
and its evaluation at the same parameters.  The two curves are checked to agree before
anything is timed.  Goal (issue 14): <= 2x scipy.  Uniform-degree curves are stored as one
array; with few parameters per segment no O(segments) table is built.
"""

from __future__ import annotations

import numpy as np
from bench_common import Result, Sizes, median_time

GOAL_RATIO = 2.0
BSPLINE_TO_BEZIER = np.array([[1, 4, 1, 0], [0, 4, 2, 0], [0, 2, 4, 0], [0, 1, 4, 1]]) / 6.0


def data(S: int):
    V = np.random.default_rng(0).normal(size=(S + 3, 2))
    win = np.lib.stride_tricks.sliding_window_view(V, 4, axis=0)  # (S, 2, 4)
    segs = np.einsum("rk,sdk->srd", BSPLINE_TO_BEZIER, win)
    knots = np.arange(-3, S + 4, dtype=float)
    return V, segs, knots


def run(sizes: Sizes, S: int | None = None) -> list[Result]:
    from scipy.interpolate import BSpline

    from course_lib.curves.curve import PiecewiseBezier

    S = S or (10**5 if sizes.name != "tiny" else 2000)
    V, segs, knots = data(S)
    rows = []
    for m in (10**3, 10 * S):
        t = np.linspace(0.0, S, m)
        ours = PiecewiseBezier(segs).evaluate(t)
        err = float(np.max(np.abs(ours - BSpline(knots, V, 3)(t))))
        assert err < 1e-12, err
        repeats = max(3, sizes.repeats)
        a = median_time(lambda t=t: PiecewiseBezier(segs).evaluate(t), repeats)
        b = median_time(lambda t=t: BSpline(knots, V, 3)(t), repeats)
        rows.append(
            Result(
                "8",
                f"build + first evaluation, {S:.0e} cubic segments, {m:.0e} params",
                a,
                "scipy BSpline (build + evaluate)",
                b,
                f"<= {GOAL_RATIO:g}",
                a / b <= GOAL_RATIO,
                f"agree to {err:.1e}",
            )
        )
    return rows
