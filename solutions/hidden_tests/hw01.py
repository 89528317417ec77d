"""Hidden tests of homework 1 (run by tools/grade.py; not shipped to students).

Expected values come from hand derivations (written next to them) and finite differences,
never from course_lib or from the solution notebook's code.
"""

import math

import numpy as np

HOMEWORK = "hw01"
POINTS = {"q1": 2, "q2": 3, "q3": 1, "q4": 2, "q5": 2, "q6": 1, "q7": 2}


def _array(value, shape, name):
    assert value is not Ellipsis, f"{name} is not answered"
    arr = np.asarray(value, dtype=float)
    assert arr.shape == shape, f"{name} has shape {arr.shape}, expected {shape}"
    assert np.all(np.isfinite(arr)), f"{name} contains NaN or inf"
    return arr


def _choice(value):
    assert isinstance(value, str), "answer with a string of letters"
    return sorted(p for p in value.replace(",", " ").lower().split())


def q1(ns):
    # c(t) = (t² + t, t³ − 2t): c'(1) = (3, 1), so T(1) = (3, 1)/√10
    T = _array(ns["answer_q1"], (2,), "answer_q1")
    assert np.allclose(T, np.array([3.0, 1.0]) / math.sqrt(10)), "T(1) is wrong"


def q2(ns):
    func = ns["chain_rule_derivatives"]
    cases = [  # q(x), q'(x), q''(x) and f(s), f'(s), f''(s), s
        (lambda x: np.array([np.sin(x), x**3]), lambda x: np.array([np.cos(x), 3 * x**2]),
         lambda x: np.array([-np.sin(x), 6 * x]), lambda s: s**2 + 0.5 * s, 0.7),
        (lambda x: np.array([np.exp(x), x, x**2]), lambda x: np.array([np.exp(x), 1.0, 2 * x]),
         lambda x: np.array([np.exp(x), 0.0, 2.0]), lambda s: np.log(1 + s), 1.3),
    ]
    good = 0
    notes = []
    h = 1e-4
    for q, dq, ddq, f, s in cases:
        f1 = (f(s + h) - f(s - h)) / (2 * h)
        f2 = (f(s + h) - 2 * f(s) + f(s - h)) / h**2
        # derivatives of q(f(s)) by central differences
        d1 = (q(f(s + h)) - q(f(s - h))) / (2 * h)
        d2 = (q(f(s + h)) - 2 * q(f(s)) + q(f(s - h))) / h**2
        got = _array(func(dq(f(s)), ddq(f(s)), f1, f2), (2, d1.size), "the result")
        if np.allclose(got[0], d1, atol=1e-5) and np.allclose(got[1], d2, atol=1e-4):
            good += 1
        else:
            notes.append(f"wrong for dim {d1.size}")
    return good / len(cases), "; ".join(notes)


def q3(ns):
    assert _choice(ns["answer_q3"]) == ["d"], "wrong choice"


def q4(ns):
    # q = (u, u²): q'(1) = (1, 2), q''(1) = (0, 2); det = 2; |q'|³ = 5^(3/2)
    assert math.isclose(float(ns["answer_q4"]), 2 / 5**1.5, rel_tol=1e-8), "κ(1) is wrong"


def q5(ns):
    # q̃(s) = (f, f²), f = (s + s²)/2: x'' = 1, y'' = ((1 + 2s)² + 2(s + s²))/2 = 6.5 at s = 1
    v = _array(ns["answer_q5"], (2,), "answer_q5")
    assert np.allclose(v, [1.0, 6.5]), "q̃''(1) is wrong"


def q6(ns):
    assert _choice(ns["answer_q6"]) == ["b", "d"], "wrong choice"


def q7(ns):
    # ∫_0^1 sqrt(1 + 4u²) du = [u sqrt(1 + 4u²)/2 + asinh(2u)/4]_0^1 = (2√5 + asinh 2)/4
    expected = (2 * math.sqrt(5) + math.asinh(2)) / 4
    assert math.isclose(float(ns["answer_q7"]), expected, rel_tol=1e-6), "the arc length is wrong"
