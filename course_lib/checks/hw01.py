"""Feedback checks of homework 1: parametrizations, the unit tangent, reparametrization.

The question data is stated in the notebook (``exercises/hw01_reparametrization.ipynb``)
and repeated here; the solution notebook, executed by the test suite, passes every
check, which keeps the two in step.  Checks derive what they need at check time
(seed 000 §1-4, seed 004 §19.2) and never print an expected value.
"""

from __future__ import annotations

import math

import numpy as np

from ._core import (
    as_number,
    as_vector,
    call_answer,
    close,
    cross2,
    fail,
    ok,
    register,
    register_choice,
)

DATA = {
    # q1: c(t) = (t^2 + t, t^3 - 2 t), unit tangent at t = 1
    "q1": {"t": 1.0},
    # q4, q5, q7: the parabola q(u) = (u, u^2), u in [0, 1]; f(s) = (s + s^2) / 2
    "q4": {"u": 1.0},
    "q5": {"s": 1.0},
}


def _c1_derivative(t: float) -> np.ndarray:
    return np.array([2 * t + 1, 3 * t**2 - 2])


@register("hw01.q1", "answer_q1", "unit tangent of c(t) = (t² + t, t³ − 2t) at t = 1")
def _q1(answer):
    T = as_vector(answer, (2,), "answer_q1", "a plane vector np.array([x, y])")
    d = _c1_derivative(DATA["q1"]["t"])
    n = float(np.linalg.norm(T))
    if abs(n - 1) > 1e-9:
        return fail(
            f"a unit tangent has length 1, yours has length {n:.6g}: divide c'(t) by its length ‖c'(t)‖."
        )
    if abs(cross2(T, d)) > 1e-9 * np.linalg.norm(d):
        return fail("T is not parallel to the velocity c'(1): differentiate each coordinate, then normalize.")
    if np.dot(T, d) < 0:
        return fail(
            "T is parallel to the tangent line but points backwards: T = c'/‖c'‖ points the way "
            "the curve is traced."
        )
    return ok("correct: unit length, along c'(1), in the direction of travel.")


_Q2_CASES = [
    # q'(f(s)), q''(f(s)), f'(s), f''(s)
    (np.array([1.0, 2.0]), np.array([0.0, 2.0]), 1.5, 1.0),
    (np.array([3.0, -1.0, 2.0]), np.array([1.0, 0.5, -2.0]), 0.25, -3.0),
    (np.array([-2.0, 4.0]), np.array([5.0, 1.0]), 2.0, 0.0),
]


@register("hw01.q2", "chain_rule_derivatives", "derivatives of q(f(s)) by the chain rule")
def _q2(func):
    for q1, q2, f1, f2 in _Q2_CASES:
        dim = q1.size
        res = call_answer(func, q1.copy(), q2.copy(), f1, f2, name="chain_rule_derivatives")
        res = as_vector(res, (2, dim), "the returned value", "an array [first derivative, second derivative]")
        if not close(res[0], q1 * f1):
            return fail(
                "the first derivative of q(f(s)) is wrong: by the chain rule it is q'(f(s)) times f'(s)."
            )
        if close(res[1], q2 * f1**2) and not close(res[1], q2 * f1**2 + q1 * f2):
            return fail(
                "the second derivative misses a term: differentiate q'(f(s)) f'(s) with the product "
                "rule -- two terms."
            )
        if close(res[1], q2 * f1 + q1 * f2) and not close(res[1], q2 * f1**2 + q1 * f2):
            return fail("the second derivative: differentiating q'(f(s)) gives q''(f(s)) f'(s) -- one more f'.")
        if not close(res[1], q2 * f1**2 + q1 * f2):
            return fail("the second derivative is wrong: apply the chain rule to q'(f(s)) f'(s).")
    return ok(f"correct on {len(_Q2_CASES)} test cases (plane and space).")


register_choice("hw01.q3", "answer_q3", "0dcc2129482c5605", "orientation-preserving change of variables")


def _kappa_parabola(u: float) -> float:
    # q(u) = (u, u^2): q' = (1, 2u), q'' = (0, 2); kappa = (x'y'' - y'x'') / |q'|^3
    return 2.0 / (1.0 + 4.0 * u * u) ** 1.5


@register("hw01.q4", "answer_q4", "signed curvature of (u, u²) at u = 1")
def _q4(answer):
    k = as_number(answer, "answer_q4")
    expected = _kappa_parabola(DATA["q4"]["u"])
    if math.isclose(k, expected, rel_tol=1e-9):
        return ok("correct.")
    if math.isclose(k, -expected, rel_tol=1e-9):
        return fail("the size is right but the sign is not: the parabola turns left (counter-clockwise).")
    if math.isclose(k, 1 / expected, rel_tol=1e-9) or math.isclose(k, -1 / expected, rel_tol=1e-9):
        return fail("that is the radius of curvature 1/|κ|, not the curvature κ.")
    if math.isclose(k, expected * 5**0.5, rel_tol=1e-9):
        return fail("the power of ‖q'‖ in the denominator: κ = det(q', q'') / ‖q'‖³.")
    return fail("not the signed curvature: κ = det(q', q'') / ‖q'‖³ at u = 1.")


@register("hw01.q5", "answer_q5", "second derivative of the reparametrized parabola at s = 1")
def _q5(answer):
    v = as_vector(answer, (2,), "answer_q5", "a plane vector np.array([x, y])")
    s = DATA["q5"]["s"]
    f, f1, f2 = (s + s * s) / 2, (1 + 2 * s) / 2, 1.0
    q1, q2 = np.array([1.0, 2 * f]), np.array([0.0, 2.0])
    if close(v, q2 * f1**2 + q1 * f2):
        return ok("correct: q''(f) f'² + q'(f) f''.")
    if close(v, q2 * f1**2):
        return fail("one term is missing: the chain rule gives q''(f) f'² + q'(f) f''.")
    if close(v, q2):
        return fail("that is q''(1) of the original curve; the reparametrization changes it.")
    return fail("not q̃''(1): evaluate q', q'' at u = f(1) and f', f'' at s = 1, then use your chain rule.")


register_choice("hw01.q6", "answer_q6", "a98d57c2f9308dc0", "which quantities are intrinsic")


@register("hw01.q7", "answer_q7", "arc length of the parabola (u, u²), 0 ≤ u ≤ 1")
def _q7(answer):
    s = as_number(answer, "answer_q7")
    expected = (2 * 5**0.5 + math.asinh(2.0)) / 4
    if math.isclose(s, expected, rel_tol=1e-6):
        return ok("correct.")
    if math.isclose(s, 2**0.5, rel_tol=1e-6):
        return fail("that is the length of the chord from (0, 0) to (1, 1); the arc is longer.")
    if s < 2**0.5:
        return fail("too short: no curve between two points is shorter than the straight chord.")
    return fail("not the arc length: integrate the speed ‖q'(u)‖ from 0 to 1.")

