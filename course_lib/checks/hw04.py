"""Feedback checks of homework 4: G1/G2 stitching and Beta-splines (seed 000 §8, §10).

The checks test the defining properties -- the Beta-constraints (7.1), (7.2) evaluated
with the Bézier end derivatives (8.2), (8.3) -- on the student's points, and never print
an expected value.  The question data is stated in ``exercises/hw04_beta_splines.ipynb``
and repeated here; the solution notebook passes every check.
"""

from __future__ import annotations

import numpy as np

from ._core import (
    as_vector,
    call_answer,
    close,
    fail,
    ok,
    parallel,
    register,
    register_choice,
)

Q1 = {"V_dm1": np.array([1.0, 2.0]), "V_d": np.array([3.0, 3.0]), "beta1": 1.5}
Q3 = {"V": np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]]), "beta1": 1.5, "beta2": 1.0}
Q5 = {"W_left": np.array([2.0, 1.0]), "W_right": np.array([5.0, 4.0]), "beta1": 2.0}


def _ray_problem(point, origin, direction, name: str, origin_name: str, dir_name: str) -> str | None:
    """Why ``point`` is not on the open ray from ``origin`` along ``direction``."""
    v = point - origin
    if np.linalg.norm(v) < 1e-12 * max(1.0, np.linalg.norm(origin)):
        return f"{name} coincides with {origin_name}; it must lie on the ray beyond it (β1 > 0)."
    if not parallel(v, direction):
        return f"{name} must lie on the ray from {origin_name} in the direction {dir_name}; it is off that line."
    if np.dot(v, direction) < 0:
        return (
            f"{name} must lie on the ray from {origin_name} in the direction {dir_name}: yours points "
            "backwards -- is β1 positive?"
        )
    return None


@register("hw04.q1", "answer_q1", "G1 stitching: the control vertex W1 (eq. 9)")
def _q1(answer):
    W1 = as_vector(answer, (2,), "answer_q1", "a plane point np.array([x, y])")
    Vm, Vd, b1 = Q1["V_dm1"], Q1["V_d"], Q1["beta1"]
    why = _ray_problem(W1, Vd, Vd - Vm, "W1", "V_d", "V_d − V_{d−1}")
    if why:
        return fail(why)
    ratio = np.linalg.norm(W1 - Vd) / np.linalg.norm(Vd - Vm)
    if abs(ratio - b1) < 1e-9:
        return ok("correct: on the ray, with |W0 W1| = β1 |V_{d−1} V_d|.")
    if abs(ratio - 1 / b1) < 1e-9:
        return fail("on the ray, but β1 is inverted: |W0 W1| / |V_{d−1} V_d| must be β1.")
    return fail("on the right ray but at the wrong distance: |W0 W1| / |V_{d−1} V_d| must be β1.")


def _stitch_problem(V: np.ndarray, W: np.ndarray, b1: float, b2: float) -> str | None:
    """Which Beta-constraint the stitched polygon W violates (seed 000 eq. (7), (8))."""
    d = V.shape[0] - 1
    q1, q2 = d * (V[-1] - V[-2]), d * (d - 1) * (V[-3] - 2 * V[-2] + V[-1])
    r1, r2 = d * (W[1] - W[0]), d * (d - 1) * (W[0] - 2 * W[1] + W[2])
    if not close(W[0], V[-1]):
        return "W0 must be V_d: the curves must meet (G0)."
    if not close(r1, b1 * q1):
        why = _ray_problem(W[1], V[-1], V[-1] - V[-2], "W1", "V_d", "V_d − V_{d−1}")
        return why or "W1 is on the right ray but r'(0) ≠ β1 q'(1) (eq. 7.1): its distance is wrong."
    if not close(r2, b1 * b1 * q2 + b2 * q1):
        return "W0, W1 are right but W2 breaks the G2 constraint r''(0) = β1² q''(1) + β2 q'(1) (eq. 7.2)."
    return None


_Q2_CASES = [
    (np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]]), 1.5, 1.0),
    (np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]), 0.5, -2.0),
    (np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 1.0], [2.0, 1.0, 1.0], [2.0, 2.0, 0.0], [3.0, 2.0, 1.0]]), 2.0, 3.0),
]


@register("hw04.q2", "g2_stitch", "g2_stitch(V, beta1, beta2): W0, W1, W2 of the next segment")
def _q2(func):
    for V, b1, b2 in _Q2_CASES:
        d = V.shape[0] - 1
        res = call_answer(func, V.copy(), b1, b2, name="g2_stitch")
        W = as_vector(res, (3, V.shape[1]), "the result", "an array of the three points [W0, W1, W2]")
        why = _stitch_problem(V, W, b1, b2)
        if why:
            hint = " (it works for cubics: where does the degree d enter?)" if d != 3 else ""
            return fail(f"degree {d}, β1 = {b1}, β2 = {b2}: {why}{hint}")
    return ok(f"correct on {len(_Q2_CASES)} cases (degrees 2, 3, 4; plane and space).")


@register("hw04.q3", "answer_q3", "the Farin-Boehm point T (eq. 12.4)")
def _q3(answer):
    T = as_vector(answer, (2,), "answer_q3", "a plane point np.array([x, y])")
    V, b1, b2 = Q3["V"], Q3["beta1"], Q3["beta2"]
    d = V.shape[0] - 1
    why = _ray_problem(T, V[-2], V[-2] - V[-3], "T", "V_{d−1}", "V_{d−1} − V_{d−2}")
    if why:
        return fail(why)
    gamma = (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))
    W0 = V[-1]
    W1 = W0 + b1 * (V[-1] - V[-2])
    W2 = W1 + (W1 - T) / gamma
    if _stitch_problem(V, np.array([W0, W1, W2]), b1, b2) is None:
        return ok("correct: the W2 built from your T satisfies the G2 constraint (7.2).")
    return fail(
        "T is on the right ray, but W2 = W1 + (W1 − T)/γ then breaks the G2 constraint (7.2): "
        "check γ (eq. 12.1) and the factor β1²γ."
    )


_Q4_CASES = [
    (np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0]]), np.array([1.0, 2.0, 0.5])),
    (np.array([[0.0, 0.0], [2.0, 2.0], [4.0, 0.0], [6.0, 2.0], [8.0, 0.0]]), np.array([0.25, 1.0, 3.0, 1.5])),
]


@register("hw04.q4", "quadratic_beta_spline", "the Bézier polygons of a quadratic G1 Beta-spline")
def _q4(func):
    for V, beta1 in _Q4_CASES:
        m = V.shape[0] - 1
        res = call_answer(func, V.copy(), beta1.copy(), name="quadratic_beta_spline")
        W = as_vector(res, (m - 1, 3, 2), f"the result for m = {m}", "an array of the m − 1 quadratic polygons")
        for k in range(m - 1):  # segment i = k + 1
            i = k + 1
            if not close(W[k, 1], V[i]):
                return fail(f"segment {i}: the interior Bézier vertex W_{{i,1}} must be V_i (eq. 18).")
            for end, leg in ((0, i - 1), (2, i)):
                a, b = V[leg], V[leg + 1]
                s = np.dot(W[k, end] - a, b - a) / np.dot(b - a, b - a)
                if not (close(W[k, end], a + s * (b - a)) and 0 < s < 1):
                    return fail(f"segment {i}: its junction vertices must lie on the legs V_{{i−1}}V_i and V_iV_{{i+1}}.")
                if abs(s - 1 / (1 + beta1[leg])) > 1e-9:
                    return fail(
                        f"segment {i}: the junction vertex on leg V_{leg}V_{leg + 1} must divide it "
                        f"in the ratio 1 : β1_{leg} (eq. 19) -- check which end is which."
                    )
        for k in range(m - 2):  # G1 check at the joint between segments k+1 and k+2
            q1 = 2 * (W[k, 2] - W[k, 1])
            r1 = 2 * (W[k + 1, 1] - W[k + 1, 0])
            if not close(W[k, 2], W[k + 1, 0]) or not close(r1, beta1[k + 1] * q1):
                return fail(f"segments {k + 1} and {k + 2} do not meet with q'_{{i+1}}(0) = β1_i q'_i(1) (eq. 16).")
    return ok(f"correct on {len(_Q4_CASES)} control polygons with joint-wise β1.")


@register("hw04.q5", "answer_q5", "the junction vertex of a cubic G2 Beta-spline")
def _q5(answer):
    J = as_vector(answer, (2,), "answer_q5", "a plane point np.array([x, y])")
    A, B, b1 = Q5["W_left"], Q5["W_right"], Q5["beta1"]
    s = np.dot(J - A, B - A) / np.dot(B - A, B - A)
    if not close(J, A + s * (B - A)) or not 0 < s < 1:
        return fail("the junction vertex must lie on the segment W_{i−1,2} W_{i,1}.")
    if abs(s - 1 / (1 + b1)) < 1e-9:
        return ok("correct: it divides W_{i−1,2} W_{i,1} in the ratio 1 : β1.")
    if abs(s - b1 / (1 + b1)) < 1e-9:
        return fail("swapped: |W_{i−1,2} J| : |J W_{i,1}| must be 1 : β1, not β1 : 1.")
    return fail("on the segment, but it must divide it in the ratio 1 : β1.")


register_choice("hw04.q6", "answer_q6", "1aad7e631232e4b8", "β1 = 1, β2 = 0 in a cubic G2 Beta-spline")

