"""Feedback checks of homework 3: Finn's G1 Bézier splines from control points and knots.

Seed 004 §19.6-19.8: the joint point ``p_{3i}`` has the barycentric coordinates of
``t_i`` with respect to ``t_{i-1}, t_{i+1}``.  The question data is stated in
``exercises/hw03_g1_knot_bezier_splines.ipynb`` and repeated here; the solution notebook
passes every check, which keeps the two in step.  No expected value is ever printed.
"""

from __future__ import annotations

import numpy as np

from ..knot_splines import bezier_points_from_g1
from ._core import (
    AnswerProblem,
    as_sympy_expression,
    as_vector,
    call_answer,
    close,
    cross2,
    fail,
    ok,
    register,
    register_choice,
)

#: Finn's G1 control points d_{-1}, d_0, ..., d_{2L} of the homework (L = 3).
D = np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]], dtype=float)
KNOTS_Q1 = (0.0, 1.0, 3.0)
KNOTS_Q3 = ((0.0, 1.0, 2.0, 4.0), (0.0, 3.0, 6.0, 9.0), (0.0, 2.0, 3.0, 6.0))


def _joint_problem(p_prev, p_joint, p_next, a: float, b: float) -> str | None:
    """Why p_joint is not the barycentric joint point of knot intervals a (before), b (after)."""
    chord = p_next - p_prev
    if abs(cross2(p_joint - p_prev, chord)) > 1e-9 * float(np.dot(chord, chord)):
        return "the joint point must lie on the segment from p_{3i-1} to p_{3i+1}."
    s = float(np.dot(p_joint - p_prev, chord) / np.dot(chord, chord))
    if s < 0 or s > 1:
        return "the joint point is on the line but outside the segment p_{3i-1} p_{3i+1}."
    if abs(s - a / (a + b)) < 1e-9:
        return None
    if abs(s - b / (a + b)) < 1e-9:
        return (
            "the ratio is swapped: |p_{3i-1} p_{3i}| : |p_{3i} p_{3i+1}| must equal "
            "(t_i - t_{i-1}) : (t_{i+1} - t_i)."
        )
    return (
        "wrong place on the segment: |p_{3i-1} p_{3i}| : |p_{3i} p_{3i+1}| must equal "
        "(t_i - t_{i-1}) : (t_{i+1} - t_i)."
    )


@register("hw03.q1", "answer_q1", "the joint point p_3 from p_2, p_4 and three knots")
def _q1(answer):
    p3 = as_vector(answer, (2,), "answer_q1", "a plane point np.array([x, y])")
    t0, t1, t2 = KNOTS_Q1
    why = _joint_problem(D[2], p3, D[3], t1 - t0, t2 - t1)
    return fail(why) if why else ok("correct: p_3 has the barycentric coordinates of t_1.")


def _compare_points(p: np.ndarray, d: np.ndarray, knots) -> str | None:
    ref = bezier_points_from_g1(d, knots)
    L = len(knots) - 1
    for k in range(ref.shape[0]):
        if k % 3 == 0 and 0 < k < 3 * L:
            i = k // 3
            why = _joint_problem(p[k - 1], p[k], p[k + 1], knots[i] - knots[i - 1], knots[i + 1] - knots[i])
            if why and close(p[k - 1], ref[k - 1]) and close(p[k + 1], ref[k + 1]):
                return f"joint {i} (p_{k}): {why}"
        elif not close(p[k], ref[k]):
            return (
                f"p_{k} is not the right G1 control point: p_0, p_1, p_2 = d_-1, d_0, d_1, then "
                "p_{3i+1}, p_{3i+2} = d_{2i}, d_{2i+1}, and p_{3L} = d_{2L}."
            )
    return None


_Q2_CASES = [
    (D, (0.0, 1.0, 3.0, 4.0)),
    (D[:6], (0.0, 0.5, 2.0)),
    (np.array([[0, 0, 0], [1, 0, 1], [2, 1, 1], [3, 3, 0], [4, 3, 2], [5, 2, 2.0]]), (1.0, 4.0, 5.0)),
]


@register("hw03.q2", "g1_bezier_control_points", "all C0 Bézier control points of a G1 spline")
def _q2(func):
    for d, knots in _Q2_CASES:
        L = len(knots) - 1
        res = call_answer(func, d.copy(), np.array(knots), name="g1_bezier_control_points")
        p = as_vector(
            res,
            (3 * L + 1, d.shape[1]),
            f"the result for L = {L} segments",
            "an array of the 3L + 1 control points p_0 .. p_{3L}",
        )
        why = _compare_points(p, d, knots)
        if why:
            return fail(f"with knots {knots}: {why}")
    return ok(f"correct on {len(_Q2_CASES)} cases (2-D and 3-D, 2 and 3 segments).")


@register("hw03.q3", "answer_q3", "Finn's exercise 19.8.2 with three knot sequences")
def _q3(answer):
    if answer is Ellipsis:
        raise AnswerProblem("not answered yet (replace the ... by your answer).", unanswered=True)
    if not isinstance(answer, (list, tuple)) or len(answer) != 3:
        raise AnswerProblem("answer_q3 must be a list of three arrays [P_a, P_b, P_c].")
    for label, P, knots in zip("abc", answer, KNOTS_Q3, strict=True):
        p = as_vector(P, (10, 2), f"P_{label}", "an array of the 10 control points p_0 .. p_9")
        why = _compare_points(p, D, knots)
        if why:
            return fail(f"({label}) knots {knots}: {why}")
    return ok("correct for all three knot sequences.")


register_choice("hw03.q4", "answer_q4", "499d39e459116bc7", "which knot sequence gives C1 in local parameters")

_Q5_KNOTS = KNOTS_Q3[2]


@register("hw03.q5", "answer_q5", "left and right derivatives at t_1 in the global parameter")
def _q5(answer):
    v = as_vector(answer, (2, 2), "answer_q5", "an array [left derivative, right derivative]")
    p = bezier_points_from_g1(D, _Q5_KNOTS)
    t = _Q5_KNOTS
    left = 3 * (p[3] - p[2]) / (t[1] - t[0])
    right = 3 * (p[4] - p[3]) / (t[2] - t[1])
    if close(v[0], left) and close(v[1], right):
        return ok("correct -- and they are equal: the spline is C1 in the global parameter t.")
    if close(v[0], 3 * (p[3] - p[2])) or close(v[1], 3 * (p[4] - p[3])):
        return fail(
            "that is a derivative in the local parameter s; in the global t, ds/dt = "
            "1 / (t_i - t_{i-1}) multiplies it."
        )
    if close(v[0], v[1]):
        return fail("your two derivatives agree, but they are not the spline's: recompute p_3 first.")
    return fail("not the one-sided derivatives at t_1: differentiate each cubic segment in t.")


@register("hw03.q6", "answer_q6", "sympy: the left derivative at t_1 in closed form")
def _q6(answer):
    import sympy as sp

    t0, t1, t2, p2, p4 = sp.symbols("t0 t1 t2 p2 p4")
    expr = as_sympy_expression(answer, "answer_q6", {str(s): s for s in (t0, t1, t2, p2, p4)})
    p3 = ((t2 - t1) * p2 + (t1 - t0) * p4) / (t2 - t0)
    left = 3 * (p3 - p2) / (t1 - t0)
    if sp.cancel(sp.together(expr - left)) == 0:
        return ok("correct: t1 cancels, and the right derivative gives the same expression.")
    if sp.cancel(sp.together(expr - 3 * (p3 - p2))) == 0:
        return fail("that is the derivative in the local parameter; divide by t1 - t0 (chain rule).")
    return fail("not the left derivative 3 (p3 - p2) / (t1 - t0) with p3 from the knots; simplify it.")


_Q7_CASES = [(0.0, 1.0, 3.0, 4.0), (0.0, 2.0, 4.0), (1.0, 1.5, 3.5, 4.0, 8.0)]


@register("hw03.q7", "knot_ratio_beta1", "β1 at each interior joint from the knots")
def _q7(func):
    for knots in _Q7_CASES:
        t = np.array(knots)
        res = call_answer(func, t.copy(), name="knot_ratio_beta1")
        b = as_vector(res, (t.size - 2,), f"the result for {t.size} knots", "one β1 per interior joint")
        dt = np.diff(t)
        if close(b, dt[1:] / dt[:-1]):
            continue
        if close(b, dt[:-1] / dt[1:]):
            return fail(
                "upside down: r'(0) = β1 q'(1) in local parameters, and the segment after the joint "
                "is traced over the interval t_{i+1} - t_i."
            )
        return fail(f"knots {knots}: not the ratio of consecutive knot intervals at each joint.")
    return ok(f"correct on {len(_Q7_CASES)} knot sequences.")
