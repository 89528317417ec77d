"""Feedback checks of homework 2: the Beta-constraints (seed 000 §5 eq. (7), seed 001 eq. (2.7)).

The question data is stated in ``exercises/hw02_beta_constraints.ipynb`` and repeated
here; the solution notebook passes every check, which keeps the two in step.  Checks test
the constraints themselves with the student's numbers and never print an expected value.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from ._core import (
    AnswerProblem,
    as_number,
    as_sympy_expression,
    as_vector,
    call_answer,
    close,
    fail,
    ok,
    register,
    register_choice,
)

Q1 = {"q1": np.array([2.0, -1.0]), "r1": np.array([5.0, -2.5])}
Q2 = {
    "q1": np.array([1.0, 2.0]),
    "q2": np.array([0.0, 2.0]),
    "r1": np.array([3.0, 6.0]),
    "r2": np.array([-4.0, 10.0]),
}
Q5 = {"q1": np.array([2.0, 0.0]), "q2": np.array([1.0, -3.0]), "beta1": 0.5, "beta2": 2.0}


@register("hw02.q1", "answer_q1", "β1 from two first derivative vectors")
def _q1(answer):
    b1 = as_number(answer, "answer_q1")
    if b1 <= 0:
        return fail(
            "β1 must be > 0: it is the derivative u'(1) of an orientation-preserving change of "
            "variables."
        )
    if close(b1 * Q1["q1"], Q1["r1"]):
        return ok("correct: r'(0) = β1 q'(1) holds (7.1).")
    if close(Q1["q1"] / b1, Q1["r1"]) or close(b1 * Q1["r1"], Q1["q1"]):
        return fail("upside down: (7.1) reads r'(0) = β1 q'(1), so β1 = ‖r'(0)‖ / ‖q'(1)‖.")
    return fail("with your β1, r'(0) = β1 q'(1) (eq. 7.1) does not hold.")


@register("hw02.q2", "answer_q2", "β1 and β2 from first and second derivatives")
def _q2(answer):
    b = as_vector(answer, (2,), "answer_q2", "a pair np.array([beta1, beta2])")
    b1, b2 = b
    if b1 <= 0:
        return fail("β1 must be > 0 (orientation-preserving change of variables).")
    if not close(b1 * Q2["q1"], Q2["r1"]):
        return fail("the first constraint r'(0) = β1 q'(1) (7.1) fails with your β1.")
    if close(b1 * b1 * Q2["q2"] + b2 * Q2["q1"], Q2["r2"]):
        return ok("correct: both (7.1) and (7.2) hold.")
    if close(b1 * b1 * Q2["q2"] - b2 * Q2["q1"], Q2["r2"]):
        return fail("the sign of β2: (7.2) reads r''(0) = β1² q''(1) + β2 q'(1).")
    return fail("β1 is right; with your β2, r''(0) = β1² q''(1) + β2 q'(1) (7.2) fails -- β1 squared?")


_Q3_CASES = [
    ((1.0, 2.0), (2.0, 4.0), True),
    ((1.0, 2.0), (-1.0, -2.0), False),
    ((1.0, 2.0), (2.0, 3.0), False),
    ((1.0, 0.0, 1.0), (3.0, 0.0, 3.0), True),
    ((1e-3, 2e-3), (5e3, 1e4), True),
    ((0.0, 1.0), (0.0, 0.5), True),
]


@register("hw02.q3", "is_g1", "is_g1: do two end tangents meet with G1 continuity?")
def _q3(func):
    for q1, r1, expected in _Q3_CASES:
        got = call_answer(func, np.array(q1), np.array(r1), name="is_g1")
        if not isinstance(got, (bool, np.bool_)):
            raise AnswerProblem(f"is_g1 must return True or False; it returned a {type(got).__name__}.")
        if bool(got) != expected:
            why = {
                True: "they are positive multiples of each other (β1 > 0 exists)",
                False: "no β1 > 0 gives r'(0) = β1 q'(1)",
            }[expected]
            return fail(f"is_g1(q1={q1}, r1={r1}) returned {bool(got)}, but {why}.")
    return ok(f"correct on {len(_Q3_CASES)} cases (including 3-D and very different lengths).")


@cache
def _chain_rule_coefficient(order: int, k: int):
    """Coefficient of q^{(k)}(1) in r^{(order)}(0), derived here by differentiating q(u(t))."""
    import sympy as sp

    t = sp.Symbol("t")
    u = sp.Function("u")(t)
    qs = sp.symbols(f"Q1:{order + 1}")  # stand-ins for q^{(k)}(u(t))
    expr = qs[0] * u.diff(t)  # first derivative of q(u(t))
    for _ in range(order - 1):
        # d/dt of Q_k is Q_{k+1} u'
        expr = sum(expr.diff(Qk) * qs[i + 1] * u.diff(t) for i, Qk in enumerate(qs[:-1])) + expr.diff(t)
    betas = sp.symbols(f"beta1:{order + 1}")
    for j in range(order, 0, -1):
        expr = expr.subs(u.diff(t, j), betas[j - 1])
    return sp.expand(sp.expand(expr).coeff(qs[k - 1])), betas


@register("hw02.q4", "answer_q4", "coefficient of q''(1) in the fourth Beta-constraint (sympy)")
def _q4(answer):
    import sympy as sp

    expected, betas = _chain_rule_coefficient(4, 2)
    expr = as_sympy_expression(answer, "answer_q4", {str(b): b for b in betas})
    if sp.expand(expr - expected) == 0:
        return ok("correct -- and it is what the chain rule gives, not what seed 001 eq. (2.7) prints.")
    b1, b2 = betas[0], betas[1]
    if sp.expand(expr - (4 * b1 * b2 + 3 * b2**2)) == 0:
        return fail(
            "that is seed 001 eq. (2.7) as transcribed -- which has a typo.  Derive it yourself: "
            "differentiate q(u(t)) four times."
        )
    return fail("not the coefficient of q''(1) in r''''(0); collect the q''-terms after four differentiations.")


@register("hw02.q5", "answer_q5", "r''(0) from q'(1), q''(1), β1, β2")
def _q5(answer):
    v = as_vector(answer, (2,), "answer_q5", "a plane vector np.array([x, y])")
    b1, b2, q1, q2 = Q5["beta1"], Q5["beta2"], Q5["q1"], Q5["q2"]
    if close(v, b1**2 * q2 + b2 * q1):
        return ok("correct (eq. 7.2).")
    if close(v, b1 * q2 + b2 * q1):
        return fail("β1 enters the second derivative squared: β1² q''(1) + β2 q'(1).")
    if close(v, b1**2 * q2 + b2 * q2) or close(v, b1**2 * q1 + b2 * q2):
        return fail("β1² multiplies q''(1) and β2 multiplies q'(1) -- you mixed them up.")
    return fail("not β1² q''(1) + β2 q'(1) (eq. 7.2).")


register_choice("hw02.q6", "answer_q6", "d73c296c813d278a", "β1 = 1, β2 = 0 at a joint")
register_choice("hw02.q7", "answer_q7", "9fea3db0a9c4d70b", "read the picture: G1 but not G2")


