"""Hidden tests of homework 2 (run by tools/grade.py; not shipped to students).

Expected values are derived by hand (derivations next to them) or by finite differences,
never with course_lib or with the solution notebook's code.
"""

import numpy as np

HOMEWORK = "hw02"
POINTS = {"q1": 1, "q2": 2, "q3": 3, "q4": 2, "q5": 2, "q6": 1, "q7": 2}


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
    # (5, -2.5) = 2.5 * (2, -1)
    b1 = float(_array(ns["answer_q1"], (), "answer_q1"))
    assert abs(b1 - 2.5) < 1e-9, "β1 is wrong"


def q2(ns):
    # (3, 6) = 3 (1, 2); (-4, 10) - 9 (0, 2) = (-4, -8) = -4 (1, 2)
    b = _array(ns["answer_q2"], (2,), "answer_q2")
    if abs(b[0] - 3) > 1e-9:
        return 0.0, "β1 is wrong"
    if abs(b[1] + 4) > 1e-9:
        return 0.5, "β1 is right, β2 is wrong"
    return None


def q3(ns):
    func = ns["is_g1"]
    cases = [
        ((3.0, -1.0), (0.3, -0.1), True),
        ((3.0, -1.0), (-3.0, 1.0), False),
        ((3.0, -1.0), (3.0, -1.01), False),
        ((0.0, 0.0, 2.0), (0.0, 0.0, 7.0), True),
        ((1.0, 1.0, 1.0), (1.0, 1.0, -1.0), False),
        ((2e-4, 1e-4), (2e4, 1e4), True),
        ((1.0, 0.0), (0.0, 0.0), False),
    ]
    wrong = []
    for q, r, expected in cases:
        got = func(np.array(q), np.array(r))
        if not isinstance(got, (bool, np.bool_)) or bool(got) != expected:
            wrong.append((q, r))
    if wrong:
        return 1 - len(wrong) / len(cases), f"wrong for q1={wrong[0][0]}, r1={wrong[0][1]}"
    return None


def q4(ns):
    # d⁴/dt⁴ q(u(t)): the q''-terms are 4 u' u''' + 3 u''² (Faà di Bruno, partitions of 4
    # into two blocks: 4 of type {1,3}, 3 of type {2,2}) -> 4 β1 β3 + 3 β2²
    import sympy as sp

    expr = sp.sympify(ns["answer_q4"])
    b = {f"beta{k}": sp.Symbol(f"beta{k}") for k in range(1, 5)}
    names = {str(s) for s in expr.free_symbols}
    assert names <= set(b), f"unexpected symbols {sorted(names - set(b))}"
    expr = expr.subs({s: b[str(s)] for s in expr.free_symbols})
    expected = 4 * b["beta1"] * b["beta3"] + 3 * b["beta2"] ** 2
    assert sp.expand(expr - expected) == 0, "the coefficient is wrong"


def q5(ns):
    # 0.25 (1, -3) + 2 (2, 0) = (4.25, -0.75)
    v = _array(ns["answer_q5"], (2,), "answer_q5")
    assert np.allclose(v, [4.25, -0.75]), "r''(0) is wrong"


def q6(ns):
    assert _choice(ns["answer_q6"]) == ["a"], "wrong choice"


def q7(ns):
    assert _choice(ns["answer_q7"]) == ["a"], "wrong joint"
