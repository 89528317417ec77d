"""Hidden tests of homework 3 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Answers arrive as plain data and are
normalized with ``course_lib.homework.answers`` (the feedback checks' code); the symbolic answer of q6 is
compared by its values at points chosen here.  Expected values are derived by hand (derivations
next to them) or with an independent formulation of seed 004 §19.6 (the joint point as
p_{3i-1} moved towards p_{3i+1} by the knot fraction), never with course_lib's mathematics or
the solution notebook's code.

Per-student variants (issue 19): ``VARIANTS = True``, so the grader calls ``qN(student, data)``
with the student's own data (``course_lib.homework.variants.data("hw03", code)``: the default data
without a course secret).  Every expected value is a generic formula of ``data``; the function
questions q2, q7 and the symbolic q6 are the same for everyone.  :func:`answers_for` gives the
worked answers of a variant (``tools/variant.py show``).
"""

from __future__ import annotations

import numpy as np

from course_lib.homework import answers

HOMEWORK = "hw03"
POINTS = {"q1": 2, "q2": 4, "q3": 3, "q4": 0, "q5": 2, "q6": 2, "q7": 2}  # multiple choice: feedback only

VARIANTS = True

#: The example data of the notebook (the default variant): Finn's G1 control points
#: d_-1 .. d_6, used by the function question's cases (the same for everyone).
DATA = {"D": np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]], dtype=float)}

_D3 = np.array([[0, 0, 1], [1, 1, 1], [2, 0, 0], [3, 1, 2], [4, 2, 1], [5, 0, 0], [6, 1, 1], [7, 2, 2.0]])
#: g1_bezier_control_points cases (other data than the feedback check's).
Q2_CASES = [
    (DATA["D"], (0.0, 4.0, 5.0, 7.0), "uneven knot spacing"),
    (_D3, (2.0, 2.5, 4.0, 4.25), "a space curve"),
    (DATA["D"][:6], (0.0, 1.0, 1.5), "two segments"),
]
#: knot_ratio_beta1 cases: knots and β1 at the interior joints, by hand (Δt_i / Δt_{i-1}).
Q7_CASES = [
    ((0.0, 2.0, 3.0, 7.0), (0.5, 4.0), "uneven knot spacing"),
    ((1.0, 4.0, 10.0), (2.0,), "a single joint"),
    ((0.0, 1.0, 2.0, 3.0, 4.0), (1.0, 1.0, 1.0), "uniform knots"),
]
Q6_SYMBOLS = ("t0", "t1", "t2", "p2", "p4")


def _q6_points() -> np.ndarray:
    """Admissible (t0, t1, t2, p2, p4): t0 < t1 < t2, any p2, p4."""
    rng = np.random.default_rng(11)
    t = np.sort(rng.uniform(-3.0, 3.0, size=(8, 3)), axis=1)
    t[:, 1] += 0.1
    t[:, 2] += 0.2  # strictly increasing
    return np.column_stack([t, rng.uniform(-5.0, 5.0, size=(8, 2))])


Q6_POINTS = _q6_points()


def _expected(d, knots):
    """p_0 .. p_{3L}: the joint p_{3i} is p_{3i-1} moved towards p_{3i+1} by the knot fraction."""
    t = np.asarray(knots, dtype=float)
    L = len(t) - 1
    rows = [d[0], d[1], d[2]]
    for i in range(1, L):
        before, after = rows[-1], d[2 * i + 1]
        fraction = (t[i] - t[i - 1]) / (t[i + 1] - t[i - 1])
        rows += [before + fraction * (after - before), after, d[2 * i + 2]]
    rows.append(d[2 * L + 1])
    return np.array(rows)


def _points_case(produce, expected, name, wrong):
    def run():
        got = answers.array(produce(), expected.shape, name, "an array of control points")
        assert answers.close(got, expected), wrong

    return run


def _points(data):
    return np.asarray(data["D"]["points"], dtype=float)


def _joint(data):
    D, (t0, t1, t2) = _points(data), data["q1"]["knots"]
    # default data: p3 = (2/3)(2, 3) + (1/3)(4, 3) = (8/3, 3)
    return D[2] + (t1 - t0) / (t2 - t0) * (D[3] - D[2])


def _uniform_letters(data):
    """The sequences whose joints are all midpoints: equal knot intervals (weights 1/2)."""
    out = []
    for x, k in sorted(data["q3"]["knots"].items()):
        steps = np.diff(np.asarray(k, dtype=float))
        if max(steps) - min(steps) < 1e-12:
            out.append(x)
    return ",".join(out)


def _derivatives(data):
    # default data, knots (0, 2, 3): p3 = (1/3)(2, 3) + (2/3)(4, 3) = (10/3, 3);
    # left 3 (p3 - p2)/2 = (2, 0), right 3 (p4 - p3)/1 = (2, 0)
    D, (t0, t1, t2) = _points(data), data["q5"]["knots"]
    p2, p4 = D[2], D[3]
    p3 = p2 + (t1 - t0) / (t2 - t0) * (p4 - p2)
    return np.array([3 * (p3 - p2) / (t1 - t0), 3 * (p4 - p3) / (t2 - t1)])


def answers_for(data):
    """The worked answers of a variant (for office hours: ``tools/variant.py show``)."""
    D = _points(data)
    return {
        "answer_q1": _joint(data).tolist(),
        "g1_bezier_control_points": "p_0..p_2 = d_-1..d_1, p_{3i±1} = d's, joints by the knots (any data)",
        "answer_q3": {x: _expected(D, k).tolist() for x, k in sorted(data["q3"]["knots"].items())},
        "answer_q4": _uniform_letters(data),
        "answer_q5": _derivatives(data).tolist(),
        "answer_q6": "3*(p4 - p2)/(t2 - t0) (the same for everyone)",
        "knot_ratio_beta1": "Δt_i / Δt_{i-1} at each interior joint (any data)",
    }


def q1(student, data):
    p = answers.array(student["answer_q1"], (2,), "answer_q1", "a plane point")
    assert answers.close(p, _joint(data)), "p_3 is wrong"


def q2(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("g1_bezier_control_points")
    return answers.partial_credit(
        [
            _points_case(
                lambda d=d, k=k: func(d.copy(), np.array(k)),
                _expected(d, k),
                "the result",
                f"wrong for {kind}",
            )
            for d, k, kind in Q2_CASES
        ]
    )


def q3(student, data):
    parts = answers.items(student["answer_q3"], 3, "answer_q3", "arrays [P_a, P_b, P_c]")
    return answers.partial_credit(
        [
            _points_case(lambda P=P: P, _expected(_points(data), data["q3"]["knots"][label]), f"P_{label}",
                         f"({label}) is wrong")
            for label, P in zip("abc", parts, strict=True)
        ]
    )


def q4(student, data):
    assert answers.choice(student["answer_q4"], "abc", "answer_q4") == _uniform_letters(data), "wrong choice"


def q5(student, data):
    v = answers.array(student["answer_q5"], (2, 2), "answer_q5", "an array [left, right]")
    assert answers.close(v, _derivatives(data)), "the derivatives are wrong"


def q6(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    # 3 (p3 - p2)/(t1 - t0) with p3 - p2 = (t1 - t0)/(t2 - t0) (p4 - p2)  ->  3 (p4 - p2)/(t2 - t0)
    free, values = student.expression("answer_q6", Q6_SYMBOLS, Q6_POINTS)
    t0, t2, p2, p4 = Q6_POINTS[:, 0], Q6_POINTS[:, 2], Q6_POINTS[:, 3], Q6_POINTS[:, 4]
    expected = 3 * (p4 - p2) / (t2 - t0)
    assert answers.expression_matches(free, values, expected.tolist(), Q6_SYMBOLS, "answer_q6"), (
        "the expression is wrong"
    )


def q7(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("knot_ratio_beta1")

    def case(knots, expected, kind):
        def run():
            got = answers.array(func(np.array(knots)), (len(expected),), "the result", "one β1 per joint")
            assert answers.close(got, expected), f"wrong for {kind}"

        return run

    return answers.partial_credit([case(*c) for c in Q7_CASES])
