"""Hidden tests of homework 2 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Answers arrive as plain data and are
normalized with ``course_lib.answers`` (the feedback checks' code).  The symbolic answer of q4
is compared by its values at points chosen here (``student.expression``): student text is never
parsed in the grader.  Expected values are derived by hand (derivations next to them), never
with course_lib's mathematics or the solution notebook's code.
"""

from __future__ import annotations

import numpy as np

from course_lib import answers

HOMEWORK = "hw02"
POINTS = {"q1": 1, "q2": 2, "q3": 3, "q4": 2, "q5": 2, "q6": 1, "q7": 2}

#: The question data as stated in the notebook (a per-student variant would replace it).
DATA = {
    "q1": {"q1": np.array([2.0, -1.0]), "r1": np.array([5.0, -2.5])},
    "q2": {
        "q1": np.array([1.0, 2.0]),
        "q2": np.array([0.0, 2.0]),
        "r1": np.array([3.0, 6.0]),
        "r2": np.array([-4.0, 10.0]),
    },
    "q5": {"q1": np.array([2.0, 0.0]), "q2": np.array([1.0, -3.0]), "beta1": 0.5, "beta2": 2.0},
}

#: is_g1 cases: (q'(1), r'(0), G1?) -- other data than the feedback check's.
Q3_CASES = [
    ((3.0, -1.0), (0.3, -0.1), True),
    ((3.0, -1.0), (-3.0, 1.0), False),
    ((3.0, -1.0), (3.0, -1.01), False),
    ((0.0, 0.0, 2.0), (0.0, 0.0, 7.0), True),
    ((1.0, 1.0, 1.0), (1.0, 1.0, -1.0), False),  # x, y parallel, z not
    ((2e-4, 1e-4), (2e4, 1e4), True),
    ((1e-5, 0.0, 0.0), (1e-5, 1e-5, 0.0), False),  # tiny and 45° apart
    ((1.0, 0.0), (0.0, 0.0), False),  # a zero vector is not regular
]

Q4_SYMBOLS = ("beta1", "beta2", "beta3", "beta4")
#: Admissible (β1, β2, β3, β4) at which the symbolic answer of q4 is evaluated.
Q4_POINTS = np.random.default_rng(7).uniform(0.3, 3.0, size=(8, 4))


def q1(student):
    d = DATA["q1"]
    # r1 = β1 q1: β1 = r1·q1 / q1·q1 = (10 + 2.5)/5 = 2.5
    b1 = answers.number(student["answer_q1"], "answer_q1", "one β1 for both coordinates")
    expected = float(d["r1"] @ d["q1"] / (d["q1"] @ d["q1"]))
    assert answers.close(b1, expected), "β1 is wrong"


def q2(student):
    d = DATA["q2"]
    q1, q2, r1, r2 = d["q1"], d["q2"], d["r1"], d["r2"]
    # (3, 6) = 3 (1, 2): β1 = 3; (-4, 10) - 9 (0, 2) = (-4, -8) = -4 (1, 2): β2 = -4
    b1 = float(r1 @ q1 / (q1 @ q1))
    b2 = float((r2 - b1**2 * q2) @ q1 / (q1 @ q1))
    got = answers.array(student["answer_q2"], (2,), "answer_q2", "a pair np.array([beta1, beta2])")
    if not answers.close(got[0], b1):
        return 0.0, "β1 is wrong"
    if not answers.close(got[1], b2):
        return 0.5, "β1 is right, β2 is wrong"
    return None


def q3(student):
    func = student.function("is_g1")

    def case(q, r, expected):
        def run():
            got = answers.boolean(func(np.array(q), np.array(r)), "is_g1's result")
            assert got == expected, f"wrong for q1={q}, r1={r}"

        return run

    return answers.partial_credit([case(*c) for c in Q3_CASES])


def q4(student):
    # d⁴/dt⁴ q(u(t)): the q''-terms are 4 u' u''' + 3 u''² (Faà di Bruno, partitions of 4
    # into two blocks: 4 of type {1,3}, 3 of type {2,2}) -> 4 β1 β3 + 3 β2²
    free, values = student.expression("answer_q4", Q4_SYMBOLS, Q4_POINTS)
    b1, b2, b3 = Q4_POINTS[:, 0], Q4_POINTS[:, 1], Q4_POINTS[:, 2]
    expected = 4 * b1 * b3 + 3 * b2**2
    if answers.expression_matches(free, values, expected.tolist(), Q4_SYMBOLS, "answer_q4"):
        return None
    if answers.expression_matches(free, values, (4 * b1 * b2 + 3 * b2**2).tolist(), Q4_SYMBOLS):
        return 0.0, "that is seed 001 eq. (2.7) as printed (a typo), not the chain rule's coefficient"
    return 0.0, "the coefficient is wrong"


def q5(student):
    d = DATA["q5"]
    # β1² q'' + β2 q' = 0.25 (1, -3) + 2 (2, 0) = (4.25, -0.75)
    v = answers.array(student["answer_q5"], (2,), "answer_q5", "a plane vector")
    assert answers.close(v, d["beta1"] ** 2 * d["q2"] + d["beta2"] * d["q1"]), "r''(0) is wrong"


def q6(student):
    letters = answers.choice(student["answer_q6"], "abcd", "answer_q6", single=True)
    assert letters == "a", "wrong choice"


def q7(student):
    letters = answers.choice(student["answer_q7"], "abc", "answer_q7", single=True)
    assert letters == "a", "wrong joint"
