"""Hidden tests of homework 2 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Answers arrive as plain data and are
normalized with ``course_lib.homework.answers`` (the feedback checks' code).  The symbolic answer of q4
is compared by its values at points chosen here (``student.expression``): student text is never
parsed in the grader.  Expected values are derived by hand (derivations next to them), never
with course_lib's mathematics or the solution notebook's code.

Per-student variants (issue 19): ``VARIANTS = True``, so the grader calls ``qN(student, data)``
with the student's own data (``course_lib.homework.variants.data("hw02", code)``: the default data
without a course secret).  Every expected value is a generic formula of ``data``; q3 (a
function) and q4 (symbolic, no data) are the same for everyone.  :func:`answers_for` gives the
worked answers of a variant (``tools/variant.py show``).
"""

from __future__ import annotations

import math

import numpy as np

from course_lib.homework import answers

HOMEWORK = "hw02"
POINTS = {
    "q1": 1,
    "q2": 2,
    "q3": 3,
    "q4": 2,
    "q5": 2,
    "q6": 0,
    "q7": 0,
}  # multiple choice: feedback only

VARIANTS = True

#: q6: the right statement (seed 000 eq. 7 with β1 = 1, β2 = 0: r'(0) = q'(1), r''(0) = q''(1),
#: the definition of C²).  The options are shuffled per student; the letter follows the label:
#: the one statement that claims C² (a short key: the labels are printed on the site, and
#: hidden-test strings must not appear there).
RIGHT_Q6 = "C²"


def _vec(v):
    return np.asarray(v, dtype=float)


def _beta1(d):
    # r1 = β1 q1:  β1 = r1·q1 / q1·q1 (exact when (7.1) holds)
    q1, r1 = _vec(d["q1"]), _vec(d["r1"])
    return float(r1 @ q1 / (q1 @ q1))


def _betas(d):
    # β1 as in q1; (7.2): r2 − β1² q2 = β2 q1, so β2 = (r2 − β1² q2)·q1 / q1·q1
    q1, q2, r2 = _vec(d["q1"]), _vec(d["q2"]), _vec(d["r2"])
    b1 = _beta1(d)
    return b1, float((r2 - b1**2 * q2) @ q1 / (q1 @ q1))


def _r2(d):
    # (7.2): r''(0) = β1² q''(1) + β2 q'(1)
    return d["beta1"] ** 2 * _vec(d["q2"]) + d["beta2"] * _vec(d["q1"])


def key_values(data):
    """The values the edition's answer key of q5 recognises: r''(0) and the usual mistakes,
    each with the tag its check explains (``tools/answer_keys.py`` hashes them)."""
    d = data["q5"]
    b1, b2, q1, q2 = d["beta1"], d["beta2"], _vec(d["q1"]), _vec(d["q2"])
    return {
        "q5": [
            ("right", _r2(d)),
            ("beta1-not-squared", b1 * q2 + b2 * q1),
            ("missing-term", b1**2 * q2),
            ("mixed-up", b1**2 * q2 + b2 * q2),
            ("mixed-up", b1**2 * q1 + b2 * q2),
        ]
    }


def _right_letter_q6(d):
    return "".join(x for x, label in sorted(d["options"].items()) if RIGHT_Q6 in label)


def _det(a, b):
    (ax, ay), (bx, by) = a, b
    return float(ax * by - ay * bx)


def _right_letter_q7(d):
    """The letter of the joint that is G1 but not G2, from the control points.

    A cubic Bézier segment P0..P3 has end tangents 3 (P1 − P0), 3 (P3 − P2) and end curvatures
    κ(0) = (2/3) det(P1 − P0, P2 − P1) / |P1 − P0|³, κ(1) = (2/3) det(P2 − P1, P3 − P2) / |P3 − P2|³
    (κ = det(c', c'') / |c'|³ with c'' = 6 (P2 − 2 P1 + P0) at 0, 6 (P3 − 2 P2 + P1) at 1).
    """
    segs = [np.asarray(s, dtype=float) for s in d["segments"]]
    found = []
    for i in range(len(segs) - 1):
        P, Q = segs[i], segs[i + 1]
        a, b = P[3] - P[2], Q[1] - Q[0]
        g1 = abs(_det(a, b)) <= 1e-12 * math.hypot(*a) * math.hypot(*b) and a @ b > 0
        k_left = 2 / 3 * _det(P[2] - P[1], a) / math.hypot(*a) ** 3
        k_right = 2 / 3 * _det(b, Q[2] - Q[1]) / math.hypot(*b) ** 3
        if g1 and abs(k_left - k_right) > 1e-6:
            found.append(i)
    assert len(found) == 1, "the picture must have exactly one G1-but-not-G2 joint"
    return d["labels"][found[0]].lower()


def answers_for(data):
    """The worked answers of a variant (for office hours: ``tools/variant.py show``)."""
    return {
        "answer_q1": _beta1(data["q1"]),
        "answer_q2": list(_betas(data["q2"])),
        "is_g1": "r1 = β1 q1 with β1 > 0: compare unit vectors (any data)",
        "answer_q4": "4*beta1*beta3 + 3*beta2**2 (the same for everyone)",
        "answer_q5": _r2(data["q5"]).tolist(),
        "answer_q6": _right_letter_q6(data["q6"]),
        "answer_q7": _right_letter_q7(data["q7"]).upper(),
    }


#: is_g1 cases: (q'(1), r'(0), G1?, the kind of case named in the feedback) -- other data than
#: the feedback check's.  The feedback names the kind, never the vectors or the verdict.
Q3_CASES = [
    ((3.0, -1.0), (0.3, -0.1), True, "tangents of very different lengths"),
    ((3.0, -1.0), (-3.0, 1.0), False, "tangents in opposite directions"),
    ((3.0, -1.0), (3.0, -1.01), False, "tangents at a small angle"),
    ((0.0, 0.0, 2.0), (0.0, 0.0, 7.0), True, "space curves"),
    ((1.0, 1.0, 1.0), (1.0, 1.0, -1.0), False, "space curves"),  # x, y parallel, z not
    ((2e-4, 1e-4), (2e4, 1e4), True, "a tiny and a huge tangent"),
    ((1e-5, 0.0, 0.0), (1e-5, 1e-5, 0.0), False, "tiny tangents"),  # tiny and 45° apart
    ((1.0, 0.0), (0.0, 0.0), False, "a zero tangent (not regular)"),
]

Q4_SYMBOLS = ("beta1", "beta2", "beta3", "beta4")
#: Admissible (β1, β2, β3, β4) at which the symbolic answer of q4 is evaluated.
Q4_POINTS = np.random.default_rng(7).uniform(0.3, 3.0, size=(8, 4))


def q1(student, data):
    # default data: (5, -2.5) = 2.5 (2, -1): β1 = 2.5
    b1 = answers.number(student["answer_q1"], "answer_q1", "one β1 for both coordinates")
    assert answers.close(b1, _beta1(data["q1"])), "β1 is wrong"


def q2(student, data):
    # default data: (3, 6) = 3 (1, 2): β1 = 3; (-4, 10) - 9 (0, 2) = (-4, -8) = -4 (1, 2): β2 = -4
    b1, b2 = _betas(data["q2"])
    got = answers.array(student["answer_q2"], (2,), "answer_q2", "a pair np.array([beta1, beta2])")
    if not answers.close(got[0], b1):
        return 0.0, "β1 is wrong"
    if not answers.close(got[1], b2):
        return 0.5, "β1 is right, β2 is wrong"
    return None


def q3(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("is_g1")

    def case(q, r, expected, kind):
        def run():
            got = answers.boolean(func(np.array(q), np.array(r)), "is_g1's result")
            assert got == expected, f"wrong for {kind}"

        return run

    return answers.partial_credit([case(*c) for c in Q3_CASES])


def q4(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    # d⁴/dt⁴ q(u(t)): the q''-terms are 4 u' u''' + 3 u''² (Faà di Bruno, partitions of 4
    # into two blocks: 4 of type {1,3}, 3 of type {2,2}) -> 4 β1 β3 + 3 β2²
    free, values = student.expression("answer_q4", Q4_SYMBOLS, Q4_POINTS)
    b1, b2, b3 = Q4_POINTS[:, 0], Q4_POINTS[:, 1], Q4_POINTS[:, 2]
    expected = 4 * b1 * b3 + 3 * b2**2
    if answers.expression_matches(free, values, expected.tolist(), Q4_SYMBOLS, "answer_q4"):
        return None
    if answers.expression_matches(free, values, (4 * b1 * b2 + 3 * b2**2).tolist(), Q4_SYMBOLS):
        return (
            0.0,
            "that is seed 001 eq. (2.7) as printed (a typo), not the chain rule's coefficient",
        )
    return 0.0, "the coefficient is wrong"


#: the feedback's words for q5's mistakes of ``key_values`` (the same the check names)
Q5_MISTAKES = {
    "beta1-not-squared": "β1 must enter squared",
    "missing-term": "the β2 term is missing",
    "mixed-up": "β1² and β2 multiply the wrong derivatives",
}


def q5(student, data):
    # default data: β1² q'' + β2 q' = 0.25 (1, -3) + 2 (2, 0) = (4.25, -0.75)
    v = answers.array(student["answer_q5"], (2,), "answer_q5", "a plane vector")
    assert answers.close(v, _r2(data["q5"])), answers.known_mistake(
        v, key_values(data)["q5"], Q5_MISTAKES, "r''(0) is wrong"
    )


def q6(student, data):
    letters = answers.choice(student["answer_q6"], "abcd", "answer_q6", single=True)
    assert letters == _right_letter_q6(data["q6"]), "wrong choice"


def q7(student, data):
    letters = answers.choice(student["answer_q7"], "abc", "answer_q7", single=True)
    assert letters == _right_letter_q7(data["q7"]), "wrong joint"
