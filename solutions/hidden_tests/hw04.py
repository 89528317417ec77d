"""Hidden tests of homework 4 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Answers arrive as plain data and are
normalized with ``course_lib.answers`` (the feedback checks' code).  Expected values are derived
by hand (derivations next to them) or checked through the defining properties -- Bézier end
derivatives (seed 000 eq. 8) put into the Beta-constraints (eq. 7) -- never with course_lib's
mathematics or the solution notebook's code.
"""

from __future__ import annotations

import numpy as np

from course_lib import answers

HOMEWORK = "hw04"
POINTS = {"q1": 1, "q2": 4, "q3": 2, "q4": 3, "q5": 1, "q6": 1}

#: The question data as stated in the notebook (a per-student variant would replace it).
DATA = {
    "q1": {"V_dm1": np.array([1.0, 2.0]), "V_d": np.array([3.0, 3.0]), "beta1": 1.5},
    "q3": {"V": np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 3.0], [4.0, 2.0]]), "beta1": 1.5, "beta2": 1.0},
    "q5": {"W_left": np.array([2.0, 1.0]), "W_right": np.array([5.0, 4.0]), "beta1": 2.0},
}

#: g2_stitch cases (V, β1, β2): degrees 3, 5 and 2, all with β2 ≠ 0, so that a missing β2 term
#: and a β2 divided by 2 instead of d − 1 both fail at least two cases.
Q2_CASES = [
    (np.array([[0.0, 1.0], [2.0, 3.0], [3.0, 1.0], [5.0, 2.0]]), 0.7, -1.5),
    (np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 4.0], [6.0, 1.0], [7.0, 2.0], [9.0, 0.0]]), 1.3, 2.5),
    (np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), 2.0, -0.8),
]
#: quadratic_beta_spline cases (V, β1 per leg).
Q4_CASES = [
    (np.array([[0.0, 0.0], [1.0, 1.0], [3.0, 0.0], [4.0, 2.0], [6.0, 2.0]]), np.array([2.0, 0.5, 1.0, 4.0])),
    (np.array([[0.0, 0.0], [0.0, 2.0], [2.0, 2.0]]), np.array([1.0, 3.0])),
]


def _end_derivatives(P, at_end):
    """First and second derivative of the Bézier curve P at u = 1 (at_end) or u = 0."""
    d = len(P) - 1
    if at_end:
        return d * (P[-1] - P[-2]), d * (d - 1) * (P[-1] - 2 * P[-2] + P[-3])
    return d * (P[1] - P[0]), d * (d - 1) * (P[2] - 2 * P[1] + P[0])


def q1(student):
    d = DATA["q1"]
    # W1 = V_d + β1 (V_d - V_{d-1}) = (3, 3) + 1.5 (2, 1) = (6, 4.5)
    W1 = answers.array(student["answer_q1"], (2,), "answer_q1", "a plane point")
    assert answers.close(W1, d["V_d"] + d["beta1"] * (d["V_d"] - d["V_dm1"])), "W1 is wrong"


def q2(student):
    func = student.function("g2_stitch")

    def case(V, b1, b2):
        def run():
            d = len(V) - 1
            W = answers.array(func(V.copy(), b1, b2), (3, V.shape[1]), "the result", "[W0, W1, W2]")
            # the next curve has the same degree; only W0, W1, W2 enter its start derivatives
            W_full = np.vstack([W, np.zeros((d - 2, V.shape[1]))])
            q1_, q2_ = _end_derivatives(V, True)
            r1_, r2_ = _end_derivatives(W_full, False)
            ok = (
                answers.close(W[0], V[-1])
                and answers.close(r1_, b1 * q1_)
                and answers.close(r2_, b1**2 * q2_ + b2 * q1_)
            )
            assert ok, f"not G2 for degree {d}, β1 = {b1}, β2 = {b2}"

        return run

    return answers.partial_credit([case(*c) for c in Q2_CASES])


def q3(student):
    # d = 3, β1 = 3/2, β2 = 1: γ = 2 (5/2) / (1 + (3/2) 2 (5/2)) = 10/17, β1² γ = 45/34,
    # T = (3, 3) + (45/34) (2, 1) = (96/17, 147/34)
    V, b1, b2 = DATA["q3"]["V"], DATA["q3"]["beta1"], DATA["q3"]["beta2"]
    d = len(V) - 1
    gamma = (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))  # seed 000 eq. (12.1)
    T = answers.array(student["answer_q3"], (2,), "answer_q3", "a plane point")
    assert answers.close(T, V[-2] + b1**2 * gamma * (V[-2] - V[-3])), "T is wrong"


def q4(student):
    func = student.function("quadratic_beta_spline")

    def case(V, b):
        def run():
            m = len(V) - 1
            W = answers.array(func(V.copy(), b.copy()), (m - 1, 3, 2), "the result", "the Bézier polygons")
            # junction on leg j: V_j + (V_{j+1} - V_j) / (1 + β_j) (divides it 1 : β_j)
            junction = [V[j] + (V[j + 1] - V[j]) / (1 + b[j]) for j in range(m)]
            expected = np.array([[junction[i - 1], V[i], junction[i]] for i in range(1, m)])
            assert answers.close(W, expected), f"wrong for m = {m}"

        return run

    return answers.partial_credit([case(*c) for c in Q4_CASES])


def q5(student):
    d = DATA["q5"]
    # J = (β1 W_left + W_right) / (1 + β1) = (2 (2, 1) + (5, 4)) / 3 = (3, 2)
    J = answers.array(student["answer_q5"], (2,), "answer_q5", "a plane point")
    expected = (d["beta1"] * d["W_left"] + d["W_right"]) / (1 + d["beta1"])
    assert answers.close(J, expected), "the junction vertex is wrong"


def q6(student):
    letters = answers.choice(student["answer_q6"], "abcd", "answer_q6", single=True)
    assert letters == "b", "wrong choice"
