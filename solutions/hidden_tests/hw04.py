"""Hidden tests of homework 4 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Answers arrive as plain data and are
normalized with ``course_lib.homework.answers`` (the feedback checks' code).  Expected values are derived
by hand (derivations next to them) or checked through the defining properties -- Bézier end
derivatives (seed 000 eq. 8) put into the Beta-constraints (eq. 7) -- never with course_lib's
mathematics or the solution notebook's code.

Per-student variants (issue 19): ``VARIANTS = True``, so the grader calls ``qN(student, data)``
with the student's own data (``course_lib.homework.variants.data("hw04", code)``: the default data
without a course secret).  Every expected value is a generic formula of ``data``; the function
questions q2 and q4 are the same for everyone.  q6 (multiple choice) is feedback only: worth 0
points, since its letter can be found by trying each one in ``check()``; its test still reports
right or wrong.  :func:`answers_for` gives the worked answers of a variant (``tools/variant.py show``).
"""

from __future__ import annotations

import numpy as np

from course_lib.homework import answers

HOMEWORK = "hw04"
POINTS = {"q1": 1, "q2": 4, "q3": 2, "q4": 3, "q5": 1, "q6": 0}

VARIANTS = True

#: q6: the true statement (seed 000 §10.2 with β1 = 1, β2 = 0: γ = 1, the interior vertices
#: trisect the legs and the junction vertex is (V_{i-1} + 4 V_i + V_{i+1})/6, the Bézier points of
#: the uniform cubic B-spline).  The options are shuffled per student; the letter follows the
#: label: the one statement that names the B-spline (a short key: the labels are printed in the
#: notebook, and hidden-test strings must not appear there).
RIGHT_Q6 = "B-spline"

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


def _vec(v):
    return np.asarray(v, dtype=float)


def _w1(d):
    # default data: W1 = V_d + β1 (V_d - V_{d-1}) = (3, 3) + 1.5 (2, 1) = (6, 4.5)
    Vm, Vd = _vec(d["V_dm1"]), _vec(d["V_d"])
    return Vd + d["beta1"] * (Vd - Vm)


def _farin_boehm_t(d):
    # default data: d = 3, β1 = 3/2, β2 = 1: γ = 2 (5/2) / (1 + (3/2) 2 (5/2)) = 10/17,
    # β1² γ = 45/34, T = (3, 3) + (45/34) (2, 1) = (96/17, 147/34)
    V, b1, b2 = _vec(d["V"]), d["beta1"], d["beta2"]
    n = len(V) - 1
    gamma = (n - 1) * (1 + b1) / (b2 + b1 * (n - 1) * (1 + b1))  # seed 000 eq. (12.1)
    return V[-2] + b1**2 * gamma * (V[-2] - V[-3])


def _junction(d):
    # default data: J = (β1 W_left + W_right) / (1 + β1) = (2 (2, 1) + (5, 4)) / 3 = (3, 2)
    return (d["beta1"] * _vec(d["W_left"]) + _vec(d["W_right"])) / (1 + d["beta1"])


def _right_letter_q6(d):
    # default order: (b) names the uniform cubic B-spline
    return "".join(x for x, label in sorted(d["options"].items()) if RIGHT_Q6 in label)


def answers_for(data):
    """The worked answers of a variant (for office hours: ``tools/variant.py show``)."""
    return {
        "answer_q1": _w1(data["q1"]).tolist(),
        "g2_stitch": "W0 = V_d, W1 = V_d + β1 (V_d - V_{d-1}), W2 from (7.2) (any data)",
        "answer_q3": _farin_boehm_t(data["q3"]).tolist(),
        "quadratic_beta_spline": "[junction, V_i, junction] with junctions dividing legs 1 : β1 (any data)",
        "answer_q5": _junction(data["q5"]).tolist(),
        "answer_q6": _right_letter_q6(data["q6"]),
    }


def q1(student, data):
    W1 = answers.array(student["answer_q1"], (2,), "answer_q1", "a plane point")
    assert answers.close(W1, _w1(data["q1"])), "W1 is wrong"


def q2(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
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
            where = "a space curve" if V.shape[1] == 3 else "a plane curve"
            assert ok, f"not G2 for {where} of degree {d}"

        return run

    return answers.partial_credit([case(*c) for c in Q2_CASES])


def q3(student, data):
    T = answers.array(student["answer_q3"], (2,), "answer_q3", "a plane point")
    assert answers.close(T, _farin_boehm_t(data["q3"])), "T is wrong"


def q4(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("quadratic_beta_spline")

    def case(V, b):
        def run():
            m = len(V) - 1
            W = answers.array(func(V.copy(), b.copy()), (m - 1, 3, 2), "the result", "the Bézier polygons")
            # junction on leg j: V_j + (V_{j+1} - V_j) / (1 + β_j) (divides it 1 : β_j)
            junction = [V[j] + (V[j + 1] - V[j]) / (1 + b[j]) for j in range(m)]
            expected = np.array([[junction[i - 1], V[i], junction[i]] for i in range(1, m)])
            assert answers.close(W, expected), (
                "wrong for a single segment" if m == 2 else "wrong for several segments"
            )

        return run

    return answers.partial_credit([case(*c) for c in Q4_CASES])


def q5(student, data):
    J = answers.array(student["answer_q5"], (2,), "answer_q5", "a plane point")
    assert answers.close(J, _junction(data["q5"])), "the junction vertex is wrong"


def q6(student, data):
    # feedback only (0 points): right or wrong is reported, the score is 0 either way
    letters = answers.choice(student["answer_q6"], "abcd", "answer_q6", single=True)
    assert letters == _right_letter_q6(data["q6"]), "wrong choice"
