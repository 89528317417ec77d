"""Hidden tests of homework 3 (run by tools/grade.py; not shipped to students).

Expected values are derived by hand (derivations next to them) or with an independent
formulation of seed 004 §19.6 (the joint point as p_{3i-1} moved towards p_{3i+1} by the knot
fraction), never with course_lib or with the solution notebook's code.
"""

import numpy as np

HOMEWORK = "hw03"
POINTS = {"q1": 2, "q2": 4, "q3": 3, "q4": 1, "q5": 2, "q6": 2, "q7": 2}

D = np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]], dtype=float)


def _array(value, shape, name):
    assert value is not Ellipsis, f"{name} is not answered"
    arr = np.asarray(value, dtype=float)
    assert arr.shape == shape, f"{name} has shape {arr.shape}, expected {shape}"
    assert np.all(np.isfinite(arr)), f"{name} contains NaN or inf"
    return arr


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


def _partial(cases):
    """Partial credit: the fraction of cases answered right, and a note per wrong case.

    Each case is ``(note if wrong, answer producer, expected array, name of the answer)``;
    the producer is called here so that a shape problem costs that case only.
    """
    good, notes = 0, []
    for wrong, produce, exp, name in cases:
        try:
            got = _array(produce(), exp.shape, name)
        except AssertionError as exc:
            notes.append(str(exc))
            continue
        if np.allclose(got, exp):
            good += 1
        else:
            notes.append(wrong)
    return good / len(cases), "; ".join(notes)


def q1(ns):
    # p3 = (2/3)(2, 3) + (1/3)(4, 3) = (8/3, 3)
    p = _array(ns["answer_q1"], (2,), "answer_q1")
    assert np.allclose(p, [8 / 3, 3.0]), "p_3 is wrong"


def q2(ns):
    func = ns["g1_bezier_control_points"]
    d3 = np.array(
        [[0, 0, 1], [1, 1, 1], [2, 0, 0], [3, 1, 2], [4, 2, 1], [5, 0, 0], [6, 1, 1], [7, 2, 2.0]]
    )
    cases = [(D, [0.0, 4.0, 5.0, 7.0]), (d3, [2.0, 2.5, 4.0, 4.25]), (D[:6], [0.0, 1.0, 1.5])]
    return _partial(
        [
            (
                f"wrong for knots {k}",
                lambda d=d, k=k: func(d.copy(), np.array(k)),
                _expected(d, k),
                "the result",
            )
            for d, k in cases
        ]
    )


def q3(ns):
    answer = ns["answer_q3"]
    assert isinstance(answer, (list, tuple)) and len(answer) == 3, (
        "answer_q3 must be a list of three arrays"
    )
    knots = ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])
    return _partial(
        [
            (f"({label}) is wrong", lambda P=P: P, _expected(D, k), f"P_{label}")
            for label, P, k in zip("abc", answer, knots, strict=True)
        ]
    )


def q4(ns):
    value = ns["answer_q4"]
    assert isinstance(value, str), "answer with a letter"
    assert sorted(value.replace(",", " ").lower().split()) == ["b"], "wrong choice"


def q5(ns):
    # knots (0, 2, 3): p3 = (1/3)(2, 3) + (2/3)(4, 3) = (10/3, 3);
    # left 3 (p3 - p2)/2 = (2, 0), right 3 (p4 - p3)/1 = (2, 0)
    v = _array(ns["answer_q5"], (2, 2), "answer_q5")
    assert np.allclose(v, [[2.0, 0.0], [2.0, 0.0]]), "the derivatives are wrong"


def q6(ns):
    # 3 (p3 - p2)/(t1 - t0) with p3 - p2 = (t1 - t0)/(t2 - t0) (p4 - p2)  ->  3 (p4 - p2)/(t2 - t0)
    import sympy as sp

    expr = sp.sympify(ns["answer_q6"])
    sym = {n: sp.Symbol(n) for n in ("t0", "t1", "t2", "p2", "p4")}
    names = {str(s) for s in expr.free_symbols}
    assert names <= set(sym), f"unexpected symbols {sorted(names - set(sym))}"
    expr = expr.subs({s: sym[str(s)] for s in expr.free_symbols})
    expected = 3 * (sym["p4"] - sym["p2"]) / (sym["t2"] - sym["t0"])
    assert sp.simplify(expr - expected) == 0, "the expression is wrong"


def q7(ns):
    func = ns["knot_ratio_beta1"]
    cases = [
        ([0.0, 2.0, 3.0, 7.0], [0.5, 4.0]),
        ([1.0, 4.0, 10.0], [2.0]),
        ([0.0, 1.0, 2.0, 3.0, 4.0], [1.0, 1.0, 1.0]),
    ]
    return _partial(
        [
            (f"wrong for knots {k}", lambda k=k: func(np.array(k)), np.array(exp), "the result")
            for k, exp in cases
        ]
    )
