"""Hidden tests of homework 1 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Each ``qN(student)`` reads the answer as plain
data (``student[...]``, ``student.function(...)``) and normalizes it with ``course_lib.answers``,
the same code the feedback checks use.  Expected values are computed here from the question data
with closed forms derived by hand (derivations next to them), never with course_lib's
mathematics or the solution notebook's code.
"""

from __future__ import annotations

import math

import numpy as np

from course_lib import answers

HOMEWORK = "hw01"
POINTS = {"q1": 2, "q2": 3, "q3": 1, "q4": 2, "q5": 2, "q6": 1, "q7": 2}

QUAD_HINT = "quad returns (value, error estimate): take the first"

#: The question data as stated in the notebook.  Expected values are computed from it, so a
#: per-student variant (issue 19) can replace it without touching the tests.
DATA = {
    "q1": {"t": 1.0},  # c(t) = (t² + t, t³ − 2t)
    "q4": {"u": 1.0},  # the parabola q(u) = (u, u²)
    "q5": {"s": 0.75},  # q(f(s)) with f(s) = (s + s²)/2
}


def _composite_a(s):
    """q(x) = (sin x, x³), f(s) = s² + s/2; the derivatives of q(f(s)) differentiated by hand."""
    g, g1, g2 = s * s + s / 2, 2 * s + 0.5, 2.0
    inputs = (np.array([math.cos(g), 3 * g * g]), np.array([-math.sin(g), 6 * g]), g1, g2)
    # x = sin(g(s)):  x' = cos(g) g',  x'' = −sin(g) g'² + cos(g) g''
    # y = g(s)³:      y' = 3 g² g',    y'' = 6 g g'² + 3 g² g''
    first = [math.cos(g) * g1, 3 * g * g * g1]
    second = [-math.sin(g) * g1**2 + math.cos(g) * g2, 6 * g * g1**2 + 3 * g * g * g2]
    return inputs, np.array([first, second])


def _composite_b(s):
    """q(x) = (eˣ, x, x²), f(s) = ln(1 + s): q(f(s)) = (1 + s, ln(1 + s), ln(1 + s)²)."""
    L, a = math.log(1 + s), 1 + s
    inputs = (np.array([a, 1.0, 2 * L]), np.array([a, 0.0, 2.0]), 1 / a, -1 / a**2)
    first = [1.0, 1 / a, 2 * L / a]
    second = [0.0, -1 / a**2, (2 - 2 * L) / a**2]
    return inputs, np.array([first, second])


Q2_CASES = [(_composite_a, 0.7), (_composite_b, 1.3)]


def q1(student):
    T = answers.array(student["answer_q1"], (2,), "answer_q1", "a plane vector")
    t = DATA["q1"]["t"]
    c1 = np.array([2 * t + 1, 3 * t * t - 2])  # c'(t) = (2t + 1, 3t² − 2); c'(1) = (3, 1)
    assert answers.close(T, c1 / math.hypot(*c1)), "T(1) is wrong"  # (3, 1)/√10


def q2(student):
    func = student.function("chain_rule_derivatives")

    def case(composite, s):
        def run():
            (q1_, q2_, f1, f2), expected = composite(s)
            got = answers.array(func(q1_, q2_, f1, f2), expected.shape, "the result")
            assert answers.close(got, expected), f"wrong for a curve in dimension {q1_.size}"

        return run

    return answers.partial_credit([case(c, s) for c, s in Q2_CASES])


def q3(student):
    letters = answers.choice(student["answer_q3"], "abcd", "answer_q3", single=True)
    assert letters == "d", "wrong choice"


def q4(student):
    u = DATA["q4"]["u"]
    # q' = (1, 2u), q'' = (0, 2): κ = det(q', q'')/‖q'‖³ = 2/(1 + 4u²)^(3/2); at u = 1: 2/5^(3/2)
    kappa = answers.number(student["answer_q4"], "answer_q4")
    assert answers.close(kappa, 2 / (1 + 4 * u * u) ** 1.5), "κ(1) is wrong"


def q5(student):
    s = DATA["q5"]["s"]
    # q(f(s)) = (f, f²): x'' = f'' = 1, y'' = 2 f'² + 2 f f''; f = (s + s²)/2, f' = (1 + 2s)/2.
    # At s = 3/4: f = 21/32, f' = 5/4, so y'' = 25/8 + 21/16 = 71/16.
    f, f1 = (s + s * s) / 2, (1 + 2 * s) / 2
    v = answers.array(student["answer_q5"], (2,), "answer_q5", "a plane vector")
    assert answers.close(v, [1.0, 2 * f1 * f1 + 2 * f]), "q̃''(3/4) is wrong"


def q6(student):
    assert answers.choice(student["answer_q6"], "abcde", "answer_q6") == "b,d", "wrong choice"


def q7(student):
    # ∫_0^1 sqrt(1 + 4u²) du = [u sqrt(1 + 4u²)/2 + asinh(2u)/4]_0^1 = (2√5 + asinh 2)/4
    expected = (2 * math.sqrt(5) + math.asinh(2)) / 4
    length = answers.number(student["answer_q7"], "answer_q7", QUAD_HINT)
    assert math.isclose(length, expected, rel_tol=1e-6), "the arc length is wrong"
