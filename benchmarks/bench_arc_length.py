"""Item 2: arc length to 1e-12.

``course_lib.geometry.differential_geometry.arc_length`` against ``scipy.integrate.quad`` on
the speed function (``epsabs=0, epsrel=1e-12, limit=200``; the speed is a plain
Python function of the hodograph polynomial, the fastest integrand a user would
write).  Both errors are measured against mpmath's tanh-sinh quadrature at 40
significant digits on the exact polynomial speed (the control points are exact
binary fractions, so the mpmath integrand is the curve itself, not a rounding of it).

Issue 14's goal -- one cubic to 1e-12 in at most twice the time of the ``bezier``
package's compiled ``Curve.length`` (Fortran QUADPACK) -- is the row "vs the bezier
package": both curves built once, the two calls timed in alternation, many calls per
sample.  A second row times a near-cusp cubic, where course_lib's fast path refuses to
certify and the robust path runs.  ``bezier`` is a benchmark-only reference: when it is
not installed those rows carry a note instead of times.
"""

from __future__ import annotations

import math

import numpy as np
from bench_common import Result, Sizes, median_time, optional_module, paired_medians

GOAL_REL_ERROR = 1e-12
GOAL_RATIO_BEZIER = 2.0
# A cubic with an inflection and a strongly varying speed (speed ratio ~ 9 along it).
CUBIC = np.array([[0.0, 0.0], [0.25, 2.0], [3.0, -1.5], [4.0, 1.0]])
# A near-cusp: the hodograph (-3, 3), (0, -3 + 2^-23 * 3), (3, 3) passes at distance
# 3 * 2^-25 ~ 9e-8 from the origin at u = 1/2 exactly (the speed's minimum, where the
# mpmath reference splits), against a typical speed ~ 3.
NEAR_CUSP = np.array([[0.0, 0.0], [-1.0, 1.0], [-1.0, 2.0**-24], [0.0, 1.0 + 2.0**-24]])


def hodograph_polynomials(P: np.ndarray) -> tuple[list[float], list[float]]:
    """Power-basis coefficients (c0, c1, c2) of x'(u), y'(u) for a cubic Bézier ``P``."""
    d = 3 * np.diff(P, axis=0)  # quadratic hodograph control points D0, D1, D2
    c0 = d[0]
    c1 = 2 * (d[1] - d[0])
    c2 = d[0] - 2 * d[1] + d[2]
    return [c0[0], c1[0], c2[0]], [c0[1], c1[1], c2[1]]


def reference_length(P: np.ndarray, dps: int = 40) -> float:
    """Arc length by mpmath.quad at ``dps`` digits, split at u = 1/2."""
    import mpmath

    (a0, a1, a2), (b0, b1, b2) = hodograph_polynomials(P)
    with mpmath.workdps(dps):
        a0, a1, a2, b0, b1, b2 = (mpmath.mpf(float(v)) for v in (a0, a1, a2, b0, b1, b2))

        def speed(u):
            return mpmath.sqrt((a0 + u * (a1 + u * a2)) ** 2 + (b0 + u * (b1 + u * b2)) ** 2)

        return float(mpmath.quad(speed, [0, mpmath.mpf(1) / 2, 1]))


def scipy_length(P: np.ndarray) -> float:
    from scipy.integrate import quad

    (a0, a1, a2), (b0, b1, b2) = (map(float, c) for c in hodograph_polynomials(P))

    def speed(u: float) -> float:
        return math.hypot(a0 + u * (a1 + u * a2), b0 + u * (b1 + u * b2))

    return quad(speed, 0.0, 1.0, epsabs=0.0, epsrel=1e-12, limit=200)[0]


def _row(name, curve, segments, arc_length, sizes, repeats, note=""):
    exact = sum(reference_length(P) for P in segments)
    ours_value = arc_length(curve)
    ref_value = sum(scipy_length(P) for P in segments)
    err_ours = abs(ours_value - exact) / exact
    err_ref = abs(ref_value - exact) / exact
    ours = median_time(lambda: arc_length(curve), repeats)
    ref = median_time(lambda: sum(scipy_length(P) for P in segments), repeats)
    return Result(
        "2", name, ours, "scipy quad", ref, "error ≤ 1e-12", err_ours <= GOAL_REL_ERROR,
        f"rel. error vs mpmath (40 digits): course_lib {err_ours:.1e}, quad {err_ref:.1e}{note}",
        {"length": exact, "error_course_lib": err_ours, "error_scipy": err_ref},
    )


def bezier_rows(sizes: Sizes) -> list[Result]:
    """course_lib vs ``bezier.Curve(nodes, degree=3).length`` on CUBIC and NEAR_CUSP."""
    from course_lib import PiecewiseBezier
    from course_lib.geometry.differential_geometry import arc_length

    names = ("arc length of one cubic", "arc length of a near-cusp cubic")
    bezier = optional_module("bezier")
    if bezier is None:
        note = "bezier (dhermes' bezier, compiled) not installed: reference skipped"
        return [Result("2", f"{n} vs the bezier package", note=note) for n in names]
    number = 200 if sizes.name != "tiny" else 5
    rows = []
    for name, P in zip(names, (CUBIC, NEAR_CUSP), strict=True):
        curve = PiecewiseBezier([P])
        ref_curve = bezier.Curve(np.asfortranarray(P.T), degree=3)
        exact = reference_length(P)
        err_ours = abs(arc_length(curve) - exact) / exact
        err_bez = abs(ref_curve.length - exact) / exact
        n = number if P is CUBIC else max(1, number // 10)
        ours, ref = paired_medians(
            [lambda c=curve: arc_length(c), lambda r=ref_curve: r.length],
            max(5, 3 * sizes.repeats),
            n,
        )
        ratio_ok = ours / ref <= GOAL_RATIO_BEZIER
        rows.append(
            Result(
                "2",
                f"{name} vs the bezier package",
                ours,
                f"bezier {bezier.__version__} Curve.length",
                ref,
                f"≤ {GOAL_RATIO_BEZIER:g}, error ≤ 1e-12" if P is CUBIC else "error ≤ 1e-12",
                (ratio_ok if P is CUBIC else True) and err_ours <= GOAL_REL_ERROR,
                f"rel. error vs mpmath: course_lib {err_ours:.1e}, bezier {err_bez:.1e}; "
                f"samples of {n} calls, alternated",
                {"length": exact, "error_course_lib": err_ours, "error_bezier": err_bez},
            )
        )
    return rows


def run(sizes: Sizes) -> list[Result]:
    try:
        from course_lib.geometry.differential_geometry import arc_length
    except ImportError as exc:
        return [Result("2", "arc length of a cubic", note=f"TODO: {exc}")]
    from bench_evaluation import build_curves

    from course_lib import PiecewiseBezier

    one = _row(
        "arc length of one cubic", PiecewiseBezier([CUBIC]), [CUBIC], arc_length, sizes,
        5 * sizes.repeats,
    )
    spline = build_curves(sizes.arc_segments)[1]
    many = _row(
        f"arc length of a {sizes.arc_segments}-segment cubic spline", spline, spline.segments,
        arc_length, sizes, sizes.repeats, "; quad called once per segment",
    )
    return [one, *bezier_rows(sizes), many]
