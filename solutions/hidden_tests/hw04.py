"""Hidden tests of homework 4 (run by tools/grade.py; not shipped to students).

Expected values are derived by hand (derivations next to them) or checked through the
defining properties -- Bézier end derivatives (seed 000 eq. 8) put into the Beta-constraints
(eq. 7) -- never with course_lib or with the solution notebook's code.
"""

import numpy as np

HOMEWORK = "hw04"
POINTS = {"q1": 1, "q2": 4, "q3": 2, "q4": 3, "q5": 1, "q6": 1}


def _array(value, shape, name):
    assert value is not Ellipsis, f"{name} is not answered"
    arr = np.asarray(value, dtype=float)
    assert arr.shape == shape, f"{name} has shape {arr.shape}, expected {shape}"
    assert np.all(np.isfinite(arr)), f"{name} contains NaN or inf"
    return arr


def _end_derivatives(P, at_end):
    """First and second derivative of the Bézier curve P at u = 1 (at_end) or u = 0."""
    d = len(P) - 1
    if at_end:
        return d * (P[-1] - P[-2]), d * (d - 1) * (P[-1] - 2 * P[-2] + P[-3])
    return d * (P[1] - P[0]), d * (d - 1) * (P[2] - 2 * P[1] + P[0])


def q1(ns):
    # W1 = V_d + 1.5 (V_d - V_{d-1}) = (3, 3) + 1.5 (2, 1) = (6, 4.5)
    W1 = _array(ns["answer_q1"], (2,), "answer_q1")
    assert np.allclose(W1, [6.0, 4.5]), "W1 is wrong"


def q2(ns):
    func = ns["g2_stitch"]
    cases = [
        (np.array([[0.0, 1.0], [2.0, 3.0], [3.0, 1.0], [5.0, 2.0]]), 0.7, -1.5),
        (np.array([[0.0, 0.0], [1.0, 3.0], [4.0, 4.0], [6.0, 1.0], [7.0, 2.0], [9.0, 0.0]]), 1.3, 2.5),
        (np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]), 2.0, 0.0),
    ]
    good, notes = 0, []
    for V, b1, b2 in cases:
        try:
            W = _array(func(V.copy(), b1, b2), (3, V.shape[1]), "the result")
        except AssertionError as exc:
            notes.append(str(exc))
            continue
        # the next curve has the same degree; only W0, W1, W2 enter its start derivatives
        d = len(V) - 1
        W_full = np.vstack([W, np.zeros((d - 2, V.shape[1]))])
        q1_, q2_ = _end_derivatives(V, True)
        r1_, r2_ = _end_derivatives(W_full, False)
        if (np.allclose(W[0], V[-1]) and np.allclose(r1_, b1 * q1_)
                and np.allclose(r2_, b1**2 * q2_ + b2 * q1_)):
            good += 1
        else:
            notes.append(f"not G2 for degree {d}, β1 = {b1}, β2 = {b2}")
    return good / len(cases), "; ".join(notes)


def q3(ns):
    # d = 3, β1 = 3/2, β2 = 1: γ = 2 (5/2) / (1 + (3/2) 2 (5/2)) = 10/17, β1² γ = 45/34,
    # T = (3, 3) + (45/34) (2, 1) = (96/17, 147/34)
    T = _array(ns["answer_q3"], (2,), "answer_q3")
    assert np.allclose(T, [96 / 17, 147 / 34]), "T is wrong"


def q4(ns):
    func = ns["quadratic_beta_spline"]
    cases = [
        (np.array([[0.0, 0.0], [1.0, 1.0], [3.0, 0.0], [4.0, 2.0], [6.0, 2.0]]), np.array([2.0, 0.5, 1.0, 4.0])),
        (np.array([[0.0, 0.0], [0.0, 2.0], [2.0, 2.0]]), np.array([1.0, 3.0])),
    ]
    good, notes = 0, []
    for V, b in cases:
        m = len(V) - 1
        try:
            W = _array(func(V.copy(), b.copy()), (m - 1, 3, 2), "the result")
        except AssertionError as exc:
            notes.append(str(exc))
            continue
        # junction on leg j: V_j + (V_{j+1} - V_j) / (1 + β_j) (divides it 1 : β_j)
        junction = [V[j] + (V[j + 1] - V[j]) / (1 + b[j]) for j in range(m)]
        exp = np.array([[junction[i - 1], V[i], junction[i]] for i in range(1, m)])
        if np.allclose(W, exp):
            good += 1
        else:
            notes.append(f"wrong for m = {m}")
    return good / len(cases), "; ".join(notes)


def q5(ns):
    # J = (2 (2, 1) + (5, 4)) / 3 = (3, 2)
    J = _array(ns["answer_q5"], (2,), "answer_q5")
    assert np.allclose(J, [3.0, 2.0]), "the junction vertex is wrong"


def q6(ns):
    value = ns["answer_q6"]
    assert isinstance(value, str), "answer with a letter"
    assert sorted(value.replace(",", " ").lower().split()) == ["b"], "wrong choice"
