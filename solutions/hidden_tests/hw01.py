"""Hidden tests of homework 1 (run by tools/grade.py in the grader; never shipped to students).

Form: see ``solutions/hidden_tests/README.md``.  Each ``qN(student)`` reads the answer as plain
data (``student[...]``, ``student.function(...)``) and normalizes it with ``course_lib.homework.answers``,
the same code the feedback checks use.  Expected values are computed here from the question data
with closed forms derived by hand (derivations next to them), never with course_lib's
mathematics or the solution notebook's code.

Per-student variants (issue 19): ``VARIANTS = True``, so the grader calls ``qN(student, data)``
with the student's own data (``course_lib.homework.variants.data("hw01", code)``: the default data
without a course secret).  Every expected value is a generic formula of ``data``.
:func:`answers_for` gives the worked answers of a variant (``tools/variant.py show``).
"""

from __future__ import annotations

import math

import numpy as np

from course_lib.homework import answers

HOMEWORK = "hw01"
POINTS = {
    "q1": 2,
    "q2": 3,
    "q3": 0,
    "q4": 2,
    "q5": 2,
    "q6": 0,
    "q7": 2,
}  # multiple choice: feedback only

QUAD_HINT = "quad returns (value, error estimate): take the first"

VARIANTS = True

#: q6: the quantities that do not depend on the parametrization (seed 000 §4): derivatives with
#: respect to arc length.  The options are shuffled per student; the letters follow the labels.
#: Short keys, not the labels (which the site prints): hidden-test strings must not appear there.
INTRINSIC = ("unit tangent", "curvature vector")


def _poly(coef, x):
    """Σ c_i x^i (coefficients in ascending powers)."""
    return sum(c * x**i for i, c in enumerate(coef))


def _dpoly(coef):
    return [i * c for i, c in enumerate(coef)][1:] or [0.0]


def _unit_tangent(d):
    t = d["t"]
    # x = Σ a_i t^i, y = Σ b_i t^i:  c'(t) = (Σ i a_i t^(i−1), Σ i b_i t^(i−1))
    v = np.array([_poly(_dpoly(d["x"]), t), _poly(_dpoly(d["y"]), t)])
    return v / math.hypot(*v)


def _qualifies(coef):
    """f(0) = 0, f(1) = 1 and f' > 0 on [0, 1], f of degree ≤ 3 (exact, no sampling).

    f' = c1 + 2 c2 s + 3 c3 s² is a parabola in s: its minimum on [0, 1] is at an end or at
    its vertex s* = −c2/(3 c3) when c3 > 0 and 0 < s* < 1.
    """
    c = list(coef) + [0.0] * (4 - len(coef))
    if abs(c[0]) > 1e-12 or abs(sum(c) - 1) > 1e-12:
        return False
    candidates = [0.0, 1.0]
    if c[3] > 0 and 0 < -c[2] / (3 * c[3]) < 1:
        candidates.append(-c[2] / (3 * c[3]))
    return min(c[1] + 2 * c[2] * s + 3 * c[3] * s * s for s in candidates) > 0


def _right_letters_q3(d):
    return ",".join(x for x, coef in sorted(d["coefficients"].items()) if _qualifies(coef))


def _right_letters_q6(d):
    return ",".join(
        x for x, label in sorted(d["options"].items()) if any(key in label for key in INTRINSIC)
    )


def _kappa(d):
    k, u = d["k"], d["u"]
    # (u, k u²) has velocity (1, 2ku) and acceleration (0, 2k); det = 2k, so
    # κ(u) = 2k / (1 + 4k²u²)^(3/2) (the sign of k: left or right turn)
    return 2 * k / (1 + 4 * k * k * u * u) ** 1.5


def _second_derivative(d):
    k, s, c = d["k"], d["s"], d["f"]
    # q(f(s)) = (f, k f²):  x'' = f'',  y'' = 2k f'² + 2k f f''  (f = c0 + c1 s + c2 s²)
    f = c[0] + c[1] * s + c[2] * s * s
    f1, f2 = c[1] + 2 * c[2] * s, 2 * c[2]
    return np.array([f2, 2 * k * f1 * f1 + 2 * k * f * f2])


def _arc_length(d):
    k, b = abs(d["k"]), d["b"]
    # ∫_0^b sqrt(1 + 4k²u²) du; with 2ku = sinh z: [u sqrt(1 + 4k²u²)/2 + asinh(2ku)/(4k)]_0^b
    return b * math.sqrt(1 + 4 * k * k * b * b) / 2 + math.asinh(2 * k * b) / (4 * k)


def answers_for(data):
    """The worked answers of a variant (for office hours: ``tools/variant.py show``)."""
    return {
        "answer_q1": _unit_tangent(data["q1"]).tolist(),
        "chain_rule_derivatives": "[q'(f) f', q''(f) f'² + q'(f) f''] (any data)",
        "answer_q3": _right_letters_q3(data["q3"]),
        "answer_q4": _kappa(data["q4"]),
        "answer_q5": _second_derivative(data["q5"]).tolist(),
        "answer_q6": _right_letters_q6(data["q6"]),
        "answer_q7": _arc_length(data["q7"]),
    }


def key_values(data):
    """The values the edition's answer keys recognise, per keyed question: the right one and
    the usual mistakes, each with the tag its check explains (``tools/answer_keys.py`` hashes
    them; ``course_lib.homework.checks.hw01`` never sees a value)."""
    T = _unit_tangent(data["q1"])
    kappa = _kappa(data["q4"])
    k, u = data["q4"]["k"], data["q4"]["u"]
    speed = math.hypot(1.0, 2 * k * u)  # ‖q'(u)‖ = ‖(1, 2ku)‖
    d5 = data["q5"]
    k5, s, c = d5["k"], d5["s"], d5["f"]
    f = c[0] + c[1] * s + c[2] * s * s
    f1, f2 = c[1] + 2 * c[2] * s, 2 * c[2]
    q2 = np.array([0.0, 2 * k5])  # q'' of (u, k u²) at any u
    d7 = data["q7"]
    return {
        "q1": [("right", T), ("backwards", -T), ("swapped", T[::-1])],
        "q4": [
            ("right", kappa),
            ("sign-left" if kappa > 0 else "sign-right", -kappa),
            ("radius", 1 / kappa),
            ("radius", -1 / kappa),
            ("power", kappa * speed),  # det / ‖q'‖² instead of ‖q'‖³
        ],
        "q5": [
            ("right", _second_derivative(d5)),
            ("missing-term", q2 * f1 * f1),
            ("at-s", q2 * f1 * f1 + np.array([1.0, 2 * k5 * s]) * f2),  # q' at s, not at f(s)
            ("f1-not-squared", q2 * f1 + np.array([1.0, 2 * k5 * f]) * f2),
            ("original", q2),
        ],
        "q7": [("right", _arc_length(d7)), ("chord", math.hypot(d7["b"], d7["k"] * d7["b"] ** 2))],
    }


#: the feedback's words for the mistakes of ``key_values`` (the same the checks name)
MISTAKES = {
    "backwards": "T points backwards: against the direction of travel",
    "swapped": "the components of T are swapped",
    "sign-left": "the sign of κ is wrong: the parabola turns left there",
    "sign-right": "the sign of κ is wrong: the parabola turns right there",
    "radius": "that is the radius of curvature, not the curvature",
    "power": "the power of ‖q'‖ in the denominator of κ is wrong",
    "missing-term": "a term of the chain rule is missing",
    "at-s": "q' is evaluated at s instead of at f(s)",
    "f1-not-squared": "f' must enter squared",
    "original": "that is q'' of the curve before the change of variables",
    "chord": "that is the length of the chord, not of the arc",
}


def _wrong(q, value, data, note):
    """The feedback of a wrong value: ``note``, and the mistake it is if it is a known one."""
    return answers.known_mistake(value, key_values(data)[q], MISTAKES, note)


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


def q1(student, data):
    T = answers.array(student["answer_q1"], (2,), "answer_q1", "a plane vector")
    assert answers.close(T, _unit_tangent(data["q1"])), _wrong(
        "q1", T, data, f"T({data['q1']['t']:g}) is wrong"
    )


def q2(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("chain_rule_derivatives")

    def case(composite, s):
        def run():
            (q1_, q2_, f1, f2), expected = composite(s)
            got = answers.array(func(q1_, q2_, f1, f2), expected.shape, "the result")
            assert answers.close(got, expected), f"wrong for a curve in dimension {q1_.size}"

        return run

    return answers.partial_credit([case(c, s) for c, s in Q2_CASES])


def q3(student, data):
    letters = answers.choice(student["answer_q3"], "abcd", "answer_q3", single=True)
    assert letters == _right_letters_q3(data["q3"]), "wrong choice"


def q4(student, data):
    kappa = answers.number(student["answer_q4"], "answer_q4")
    assert answers.close(kappa, _kappa(data["q4"])), _wrong(
        "q4", kappa, data, f"κ({data['q4']['u']:g}) is wrong"
    )


def q5(student, data):
    v = answers.array(student["answer_q5"], (2,), "answer_q5", "a plane vector")
    assert answers.close(v, _second_derivative(data["q5"])), _wrong(
        "q5", v, data, f"q̃''({data['q5']['s']:g}) is wrong"
    )


def q6(student, data):
    letters = answers.choice(student["answer_q6"], "abcde", "answer_q6")
    assert letters == _right_letters_q6(data["q6"]), "wrong choice"


def q7(student, data):
    length = answers.number(student["answer_q7"], "answer_q7", QUAD_HINT)
    assert math.isclose(length, _arc_length(data["q7"]), rel_tol=1e-6), _wrong(
        "q7", length, data, "the arc length is wrong"
    )
