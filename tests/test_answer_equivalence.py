"""The feedback check and the grade agree, question by question, for every homework.

For every question of every homework, a table of

* accepted forms of the right answer: the check says ✓ **and** the hidden test, run through
  :class:`LocalStudent` (the grader's JSON encoding, in-process), gives full points;
* typical wrong answers: the check says ✗ **and** the hidden test gives less than full points.

The right answers here are derived by hand (derivations in comments), independently of the
checks, the hidden tests and the solution notebooks.  Also: the solution notebooks' code,
executed in-process, scores full marks, and the blank exercises score zero with "not answered"
notes.
"""

from __future__ import annotations

import functools
import math
from pathlib import Path

import matplotlib
import numpy as np
import pytest
import sympy as sp
from _homework_support import load

matplotlib.use("Agg")

from course_lib.homework import answers, variants
from course_lib.homework.checks import HOMEWORKS, check, questions, registry
from tools import build_homework as build
from tools.grading.protocol import LocalStudent, run_question

ROOT = Path(__file__).resolve().parents[1]

HIDDEN = {hw: load(f"hidden_{hw}", ROOT / "solutions" / "hidden_tests" / f"{hw}.py") for hw in HOMEWORKS}

B1, B2, B3, B4 = sp.symbols("beta1:5")
BP1, BP2, BP3 = sp.symbols("beta1:4", positive=True)
T0, T1, T2, P2, P4 = sp.symbols("t0 t1 t2 p2 p4")
D = np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]], dtype=float)
SQ10 = math.sqrt(10)
KAPPA = 2 / 5**1.5  # q = (u, u²) at u = 1: det((1, 2), (0, 2)) / ‖(1, 2)‖³
ARC = (2 * math.sqrt(5) + math.asinh(2)) / 4  # ∫_0^1 sqrt(1 + 4u²) du


# ------------------------------------------------------------------ right functions, by hand
def chain(q1, q2, f1, f2):
    return np.array([q1 * f1, q2 * f1**2 + q1 * f2])


def chain_as_list(q1, q2, f1, f2):  # a list of arrays, from plain lists
    q1, q2 = np.asarray(q1), np.asarray(q2)
    return [list(q1 * f1), list(q2 * f1 * f1 + q1 * f2)]


def chain_as_tuple(q1, q2, f1, f2):
    return (q1 * f1, q2 * f1**2 + q1 * f2)


def is_g1_unit(q, r, tol=1e-9):
    nq, nr = np.linalg.norm(q), np.linalg.norm(r)
    return bool(nq > 0 and nr > 0 and np.linalg.norm(q / nq - r / nr) <= tol)


def is_g1_cauchy_schwarz(q, r, tol=1e-9):  # q·r = ‖q‖‖r‖ exactly when r = β q, β > 0
    nq, nr = np.linalg.norm(q), np.linalg.norm(r)
    return nq > 0 and nr > 0 and np.dot(q, r) >= nq * nr * (1 - 1e-12)  # numpy bool


def g1_points(d, knots):
    d, t = np.asarray(d, float), np.asarray(knots, float)
    L = t.size - 1
    rows = [d[0], d[1], d[2]]
    for i in range(1, L):
        a, b = t[i] - t[i - 1], t[i + 1] - t[i]
        rows += [(b * rows[-1] + a * d[2 * i + 1]) / (a + b), d[2 * i + 1], d[2 * i + 2]]
    rows.append(d[2 * L + 1])
    return np.array(rows)


def g1_points_vectorized(d, knots):
    d, t = np.asarray(d, float), np.asarray(knots, float)
    L = t.size - 1
    p = np.empty((3 * L + 1, d.shape[1]))
    p[:3] = d[:3]
    idx = np.arange(1, L)
    p[3 * idx + 1], p[3 * idx + 2], p[3 * L] = d[2 * idx + 1], d[2 * idx + 2], d[2 * L + 1]
    w = ((t[idx] - t[idx - 1]) / (t[idx + 1] - t[idx - 1]))[:, None]
    p[3 * idx] = (1 - w) * p[3 * idx - 1] + w * p[3 * idx + 1]
    return p


def knot_ratio(t):
    dt = np.diff(np.asarray(t, float))
    return dt[1:] / dt[:-1]


def knot_ratio_list(t):
    return [(t[i + 1] - t[i]) / (t[i] - t[i - 1]) for i in range(1, len(t) - 1)]


def g2_stitch(V, b1, b2):
    V = np.asarray(V, float)
    d = len(V) - 1
    W1 = V[-1] + b1 * (V[-1] - V[-2])
    W2 = 2 * W1 - V[-1] + b1**2 * (V[-3] - 2 * V[-2] + V[-1]) + b2 * (V[-1] - V[-2]) / (d - 1)
    return np.array([V[-1], W1, W2])


def g2_stitch_from_derivatives(V, b1, b2):  # solve r'' = β1² q'' + β2 q' for W2
    V = np.asarray(V, float)
    d = len(V) - 1
    q1, q2 = d * (V[-1] - V[-2]), d * (d - 1) * (V[-1] - 2 * V[-2] + V[-3])
    W0, W1 = V[-1], V[-1] + b1 * q1 / d
    return [W0, W1, (b1**2 * q2 + b2 * q1) / (d * (d - 1)) + 2 * W1 - W0]


def quad_spline(V, b):
    V = np.asarray(V, float)
    m = len(V) - 1
    j = [V[k] + (V[k + 1] - V[k]) / (1 + b[k]) for k in range(m)]
    return np.array([[j[i - 1], V[i], j[i]] for i in range(1, m)])


def quad_spline_vectorized(V, b):
    V, b = np.asarray(V, float), np.asarray(b, float)
    J = (b[:, None] * V[:-1] + V[1:]) / (1 + b[:, None])
    return np.stack([J[:-1], V[1:-1], J[1:]], axis=1)


# hw05, by hand: G2 at an implied point iff (B - A) x (P2 - P0) = 0 (lecture 09 §2), relative;
# a G2 run: the uniform cubic B-spline on 2V0 - V1, V0..Vn, 2Vn - Vn-1, each span a, b, c, d
# converted to Bézier form (a + 4b + c)/6, (2b + c)/3, (b + 2c)/3, (b + 4c + d)/6.
def _cross2(u, w):
    return u[0] * w[1] - u[1] * w[0]


def implied_is_g2(P0, A, B, P2):
    u, w = np.subtract(B, A), np.subtract(P2, P0)
    return bool(abs(_cross2(u, w)) <= 1e-9 * np.linalg.norm(u) * np.linalg.norm(w))


def implied_is_g2_sine(P0, A, B, P2):  # the sine of the angle between unit vectors
    u, w = np.subtract(B, A), np.subtract(P2, P0)
    return abs(_cross2(u / np.linalg.norm(u), w / np.linalg.norm(w))) < 1e-9


def g2_run(V):
    V = np.asarray(V, float)
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    return np.array(
        [[(a + 4 * b + c) / 6, (2 * b + c) / 3, (b + 2 * c) / 3, (b + 4 * c + d) / 6] for a, b, c, d in zip(E, E[1:], E[2:], E[3:], strict=False)]
    )


def g2_run_matrix(V):  # the uniform B-spline to Bézier matrix, as nested lists
    V = np.asarray(V, float)
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    M = np.array([[1, 4, 1, 0], [0, 4, 2, 0], [0, 2, 4, 0], [0, 1, 4, 1]]) / 6
    return [(M @ E[i : i + 4]).tolist() for i in range(len(E) - 3)]


# ------------------------------------------------------------------ typical wrong functions
def chain_missing_term(q1, q2, f1, f2):
    return np.array([q1 * f1, q2 * f1**2])


def chain_f1_not_squared(q1, q2, f1, f2):
    return np.array([q1 * f1, q2 * f1 + q1 * f2])


def chain_swapped(q1, q2, f1, f2):
    return np.array([q2 * f1**2 + q1 * f2, q1 * f1])


def chain_first_only(q1, q2, f1, f2):
    return q1 * f1


def is_g1_plane_cross(q, r, tol=1e-9):  # forgets z
    return bool(abs(q[0] * r[1] - q[1] * r[0]) <= tol * np.linalg.norm(q) * np.linalg.norm(r) and q @ r > 0)


def is_g1_ignores_direction(q, r, tol=1e-9):
    nq, nr = np.linalg.norm(q), np.linalg.norm(r)
    if nq == 0 or nr == 0:
        return False
    return bool(min(np.linalg.norm(q / nq - r / nr), np.linalg.norm(q / nq + r / nr)) <= tol)


def is_g1_first_component_ratio(q, r, tol=1e-9):
    with np.errstate(all="ignore"):
        b = r[0] / q[0]
        return bool(b > 0 and np.allclose(r, b * q))


def is_g1_absolute_tolerance(q, r, tol=1e-9):  # compares unnormalized vectors
    nq = np.linalg.norm(q)
    return bool(nq > 0 and np.linalg.norm(np.cross(np.append(q, 0)[:3], np.append(r, 0)[:3])) < tol and q @ r > 0)


def is_g1_loose_tolerance(q, r, tol=1e-9):  # ignores tol: 1 % on unit vectors
    nq, nr = np.linalg.norm(q), np.linalg.norm(r)
    return bool(nq > 0 and nr > 0 and np.linalg.norm(q / nq - r / nr) <= 1e-2)


def is_g1_returns_int(q, r, tol=1e-9):
    return int(is_g1_unit(q, r, tol))


def is_g1_zero_is_fine(q, r, tol=1e-9):  # cross = 0 and q·r >= 0: a zero vector passes
    c = np.cross(np.append(q, 0)[:3], np.append(r, 0)[:3])
    return bool(np.linalg.norm(c) <= tol * max(1.0, np.linalg.norm(q) * np.linalg.norm(r)) and q @ r >= 0)


def g1_points_swapped(d, knots):
    d, t = np.asarray(d, float), np.asarray(knots, float)
    p = g1_points(d, t)
    for i in range(1, t.size - 1):
        a, b = t[i] - t[i - 1], t[i + 1] - t[i]
        p[3 * i] = (a * p[3 * i - 1] + b * p[3 * i + 1]) / (a + b)  # ratio the wrong way round
    return p


def g1_points_midpoints(d, knots):
    return g1_points(d, np.arange(len(knots), dtype=float))


def g1_points_plane_only(d, knots):
    p = g1_points(np.asarray(d, float)[:, :2], knots)
    return p


def knot_ratio_upside_down(t):
    dt = np.diff(np.asarray(t, float))
    return dt[:-1] / dt[1:]


def knot_ratio_differences(t):
    return np.diff(np.asarray(t, float))[1:]


def g2_stitch_cubic_only(V, b1, b2):
    V = np.asarray(V, float)
    W1 = V[-1] + b1 * (V[-1] - V[-2])
    W2 = 2 * W1 - V[-1] + b1**2 * (V[-3] - 2 * V[-2] + V[-1]) + b2 * (V[-1] - V[-2]) / 2
    return np.array([V[-1], W1, W2])


def g2_stitch_no_beta2(V, b1, b2):
    return g2_stitch(V, b1, 0.0)


def g2_stitch_beta1_not_squared(V, b1, b2):
    V = np.asarray(V, float)
    d = len(V) - 1
    W1 = V[-1] + b1 * (V[-1] - V[-2])
    W2 = 2 * W1 - V[-1] + b1 * (V[-3] - 2 * V[-2] + V[-1]) + b2 * (V[-1] - V[-2]) / (d - 1)
    return np.array([V[-1], W1, W2])


def g2_stitch_g1_only(V, b1, b2):
    V = np.asarray(V, float)
    W1 = V[-1] + b1 * (V[-1] - V[-2])
    return np.array([V[-1], W1, 2 * W1 - V[-1]])


def quad_spline_swapped(V, b):
    V = np.asarray(V, float)
    m = len(V) - 1
    j = [(b[k] * V[k + 1] + V[k]) / (1 + b[k]) for k in range(m)]  # 1 : β from the wrong end
    return np.array([[j[i - 1], V[i], j[i]] for i in range(1, m)])


def quad_spline_one_beta(V, b):  # uses β of the segment's first leg at both ends
    V = np.asarray(V, float)
    m = len(V) - 1
    return np.array(
        [
            [V[i - 1] + (V[i] - V[i - 1]) / (1 + b[i - 1]), V[i], V[i] + (V[i + 1] - V[i]) / (1 + b[i - 1])]
            for i in range(1, m)
        ]
    )


def raises(*args, **kwargs):
    raise ZeroDivisionError("division by zero")


def returns_none(*args, **kwargs):
    return None


def implied_is_g2_exact(P0, A, B, P2):  # no tolerance: rounding makes G2 look G1
    u, w = np.subtract(B, A), np.subtract(P2, P0)
    return bool(_cross2(u, w) == 0)


def implied_is_g2_absolute(P0, A, B, P2):  # absolute tolerance: a tiny glyph is all G2
    u, w = np.subtract(B, A), np.subtract(P2, P0)
    return bool(abs(_cross2(u, w)) <= 1e-9)


def implied_is_g2_same_direction(P0, A, B, P2):  # forgets that antiparallel is parallel
    u, w = np.subtract(B, A), np.subtract(P2, P0)
    return bool(np.linalg.norm(u / np.linalg.norm(u) - w / np.linalg.norm(w)) < 1e-9)


def implied_is_g2_wrong_legs(P0, A, B, P2):  # compares the outer legs A - P0 and P2 - B
    u, w = np.subtract(A, P0), np.subtract(P2, B)
    return bool(abs(_cross2(u, w)) <= 1e-9 * np.linalg.norm(u) * np.linalg.norm(w))


def g2_run_no_phantoms(V):  # the B-spline on V itself: n - 2 segments, corners lost
    return g2_run(np.asarray(V, float)[1:-1]) if len(V) > 3 else np.zeros((0, 4, 2))


def g2_run_doubled_ends(V):  # repeats the corners instead of reflecting: starts off the corner
    V = np.asarray(V, float)
    return g2_run(np.vstack([V[0], V, V[-1]]))[1:-1]


def g2_run_reversed(V):
    return g2_run(np.asarray(V, float)[::-1])


# ------------------------------------------------------------------ the table
_KAPPA_B = np.array([-24148.0, -23862.0]) * 2048 / 40738**1.5  # hw05.q3, derived at its row

# hw02.q3 / q5 data: the homework's own
_Q5_HW02 = 0.25 * np.array([1.0, -3.0]) + 2 * np.array([2.0, 0.0])  # β1² q'' + β2 q' = (4.25, -0.75)
# hw03: p3 for knots (0, 2, 3) is (10/3, 3); left 3 (p3 - p2)/2 = (2, 0), right 3 (p4 - p3) = (2, 0)
_P_C = g1_points(D, [0, 2, 3, 6])
# hw04.q3: T = (96/17, 147/34) (derived in tests/unit/test_checks.py exactly)
_T = np.array([96 / 17, 147 / 34])
_P3_LEFT = 3 * ((((T2 - T1) * P2 + (T1 - T0) * P4) / (T2 - T0)) - P2)

TABLE = {
    "hw01.q1": (
        [
            np.array([3.0, 1.0]) / SQ10,  # c'(1) = (3, 1)
            [3 / SQ10, 1 / SQ10],
            (3 / SQ10, 1 / SQ10),
            sp.Matrix([3, 1]) / sp.sqrt(10),  # a sympy column
            np.array([[3.0], [1.0]]) / SQ10,
            [3 / sp.sqrt(10), 1 / sp.sqrt(10)],
        ],
        [
            np.array([3.0, 1.0]),
            -np.array([3.0, 1.0]) / SQ10,
            np.array([1.0, 3.0]) / SQ10,
            np.array([1.0, 0.0]),
            np.array([3.0, 1.0, 0.0]) / SQ10,
            "0.9487, 0.3162",
            0.5,
        ],
    ),
    "hw01.q2": (
        [chain, chain_as_list, chain_as_tuple],
        [chain_missing_term, chain_f1_not_squared, chain_swapped, chain_first_only, returns_none, raises],
    ),
    "hw01.q3": (["d", "D", "(d)", " d ", ["d"], ("D",), "d."], ["a", "b", "c", "b, d", "e", 4, None]),
    "hw01.q4": (
        [KAPPA, 2 * sp.sqrt(5) / 25, np.float64(KAPPA), np.array([KAPPA]), [KAPPA], np.array([[KAPPA]])],
        [-KAPPA, 1 / KAPPA, KAPPA * math.sqrt(5), "0.17888543819998318", True, [KAPPA, 0.0], sp.Symbol("u") / 5],
    ),
    "hw01.q5": (
        # q(f(s)) = (f, f²) at s = 3/4: x'' = f'' = 1, y'' = 2 f'² + 2 f f'' = 2·25/16 + 2·21/32 = 71/16
        [np.array([1.0, 71 / 16]), [1, 4.4375], (1.0, 4.4375), sp.Matrix([1, sp.Rational(71, 16)])],
        [
            np.array([1.0, 6.5]),  # the old data, s = 1
            np.array([1.0, 2 * 25 / 16 + 2 * 0.75]),  # q'(s) instead of q'(f(s))
            np.array([0.0, 2 * 25 / 16]),  # q'' f'² only
            np.array([1.0, 2 * 5 / 4 + 2 * 21 / 32]),  # f' not squared
            np.array([0.0, 2.0]),
            np.array([1.0, 71 / 16, 0.0]),
        ],
    ),
    "hw01.q6": (
        ["b, d", "bd", "b,d", "(b) and (d)", ["b", "d"], "D B", ("d", "b"), "b; d"],
        ["b", "d", "a, b, d", "b, d, e", "b, f", "bd and more", 2],
    ),
    "hw01.q7": (
        [ARC, np.float64(ARC), np.array([ARC]), (2 * sp.sqrt(5) + sp.asinh(2)) / 4, [ARC]],
        [math.sqrt(2), (ARC, 1e-12), 1.0, 1.5, "1.4789"],
    ),
    "hw02.q1": (
        # (5, -2.5) = 2.5 (2, -1)
        [2.5, np.float64(2.5), np.array([2.5]), [2.5], sp.Rational(5, 2), np.array([[2.5]]), 5 / 2],
        [0.4, -2.5, np.array([2.5, 2.5]), "2.5", 2, np.array([0.4])],
    ),
    "hw02.q2": (
        # (3, 6) = 3 (1, 2); (-4, 10) - 9 (0, 2) = (-4, -8) = -4 (1, 2)
        [np.array([3.0, -4.0]), [3, -4], (3.0, -4.0), sp.Matrix([3, -4]), np.array([[3.0, -4.0]])],
        [np.array([3.0, 4.0]), np.array([-4.0, 3.0]), np.array([1 / 3, -4.0]), [3.0], np.array([3.0, -4 / 9])],
    ),
    "hw02.q3": (
        [is_g1_unit, is_g1_cauchy_schwarz],
        [
            is_g1_plane_cross,
            is_g1_ignores_direction,
            is_g1_first_component_ratio,
            is_g1_absolute_tolerance,
            is_g1_loose_tolerance,
            is_g1_returns_int,
            is_g1_zero_is_fine,
            returns_none,
            raises,
        ],
    ),
    "hw02.q4": (
        [
            4 * B1 * B3 + 3 * B2**2,
            "4*beta1*beta3 + 3*beta2**2",
            4 * BP1 * BP3 + 3 * BP2**2,  # symbols with assumptions
            "3*beta2^2 + 4*beta1*beta3",
            B1 * (4 * B3) + 3 * B2 * B2,
            sp.expand((2 * B1 + B3) ** 2 - 4 * B1**2 - B3**2 + 3 * B2**2),
        ],
        [
            4 * B1 * B2 + 3 * B2**2,  # seed 001 eq. (2.7) as printed
            4 * B1 * B3,
            3 * B2**2,
            6 * B1**2 * B2,  # the coefficient of q'''
            "4*beta1*beta3 + 3*beta2**2 + s",
            "abc",
            7.0,
            [4 * B1 * B3, 3 * B2**2],
        ],
    ),
    "hw02.q5": (
        [_Q5_HW02, list(_Q5_HW02), tuple(_Q5_HW02), sp.Matrix([sp.Rational(17, 4), sp.Rational(-3, 4)])],
        [
            0.5 * np.array([1.0, -3.0]) + 2 * np.array([2.0, 0.0]),  # β1 not squared
            0.25 * np.array([2.0, 0.0]) + 2 * np.array([1.0, -3.0]),  # mixed up
            np.array([4.25]),
            np.array([4.25, 0.75]),
        ],
    ),
    "hw02.q6": (["a", "A", "(a)", ["a"], "a.", ("A",)], ["b", "c", "d", "a, c", "e", "yes"]),
    "hw02.q7": (["A", "a", "(A)", ["A"], " a "], ["B", "C", "A, B", "D", "joint A"]),
    "hw03.q1": (
        # p3 = (2/3)(2, 3) + (1/3)(4, 3) = (8/3, 3)
        [np.array([8 / 3, 3.0]), [8 / 3, 3], (8 / 3, 3.0), sp.Matrix([sp.Rational(8, 3), 3])],
        [np.array([10 / 3, 3.0]), np.array([3.0, 3.0]), np.array([8 / 3]), D[2], np.array([3.0, 4.0])],
    ),
    "hw03.q2": (
        [g1_points, g1_points_vectorized],
        [g1_points_swapped, g1_points_midpoints, g1_points_plane_only, returns_none, raises],
    ),
    "hw03.q3": (
        [
            [g1_points(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])],
            tuple(g1_points(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])),
            np.array([g1_points(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])]),
            [g1_points(D, k).tolist() for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])],
        ],
        [
            [g1_points_midpoints(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])],
            [g1_points_swapped(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])],
            [g1_points(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9])],
            [g1_points(D, k)[:9] for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])],
        ],
    ),
    "hw03.q4": (["b", "B", ["b"], "(b)"], ["a", "c", "a, b", "b, c", "d"]),
    "hw03.q5": (
        [np.array([[2.0, 0.0], [2.0, 0.0]]), [[2, 0], [2, 0]], sp.Matrix([[2, 0], [2, 0]])],
        [
            np.array([[4.0, 0.0], [2.0, 0.0]]),  # local derivatives 3 (p3 - p2), 3 (p4 - p3)
            np.array([[1.0, 0.0], [4.0, 0.0]]),  # p3 with the ratio swapped
            np.array([2.0, 0.0]),
            np.array([[2.0, 0.0], [2.0, 1.0]]),
        ],
    ),
    "hw03.q6": (
        [
            3 * (P4 - P2) / (T2 - T0),
            "3*(p4 - p2)/(t2 - t0)",
            _P3_LEFT / (T1 - T0),  # not simplified
            3 * (P4 - (((T2 - T1) * P2 + (T1 - T0) * P4) / (T2 - T0))) / (T2 - T1),  # the right one
        ],
        [
            _P3_LEFT,  # local parameter
            3 * (P4 - P2) / (T1 - T0),
            3 * (sp.Symbol("p3") - P2) / (T1 - T0),
            3.0,
            "3*(p4-p2)/(t2-t0",
        ],
    ),
    "hw03.q7": (
        [knot_ratio, knot_ratio_list],
        [knot_ratio_upside_down, knot_ratio_differences, returns_none, raises],
    ),
    "hw04.q1": (
        # W1 = (3, 3) + 1.5 (2, 1) = (6, 4.5)
        [np.array([6.0, 4.5]), [6, 4.5], (6.0, 4.5), sp.Matrix([6, sp.Rational(9, 2)])],
        [np.array([0.0, 1.5]), np.array([3 + 2 / 1.5, 3 + 1 / 1.5]), np.array([4.0, 7.0]), np.array([5.0, 4.0])],
    ),
    "hw04.q2": (
        [g2_stitch, g2_stitch_from_derivatives],
        [
            g2_stitch_cubic_only,
            g2_stitch_no_beta2,
            g2_stitch_beta1_not_squared,
            g2_stitch_g1_only,
            returns_none,
            raises,
        ],
    ),
    "hw04.q3": (
        [_T, list(_T), tuple(_T), sp.Matrix([sp.Rational(96, 17), sp.Rational(147, 34)])],
        [
            np.array([3.0, 3.0]) + 1.5 * (10 / 17) * np.array([2.0, 1.0]),  # β1 not squared
            np.array([3.0, 3.0]) + 2.25 * np.array([2.0, 1.0]),  # γ forgotten
            np.array([4.0, 2.0]) + 2.25 * (10 / 17) * np.array([1.0, -1.0]),  # from V_d
        ],
    ),
    "hw04.q4": (
        [quad_spline, quad_spline_vectorized],
        [quad_spline_swapped, quad_spline_one_beta, returns_none, raises],
    ),
    "hw04.q5": (
        # J = (2 (2, 1) + (5, 4))/3 = (3, 2)
        [np.array([3.0, 2.0]), [3, 2], (3.0, 2.0), sp.Matrix([3, 2])],
        [np.array([4.0, 3.0]), np.array([3.5, 2.5]), np.array([3.0]), np.array([2.0, 1.0])],
    ),
    "hw04.q6": (["b", "B", "(b)", ["b"]], ["a", "c", "d", "b, c", "x"]),
    # hw05.q1: outer contour 13 joints = 6 corners (4 of the stem, 2 where the bowl meets it),
    # 6 implied/explicit G1, 1 G2 (the right extreme, symmetric); counter 8 joints = 4 implied G1
    # + 4 extremes sitting at the midpoint of symmetric off-curve neighbours (G2)
    "hw05.q1": (
        [np.array([6, 10, 5]), [6, 10, 5], (6.0, 10.0, 5.0)],
        [np.array([6, 15, 0]), np.array([6, 6, 1]), np.array([5, 10, 6]), np.array([0, 4, 4])],
    ),
    "hw05.q2": (
        [implied_is_g2, implied_is_g2_sine],
        [
            implied_is_g2_exact,
            implied_is_g2_absolute,
            implied_is_g2_same_direction,
            implied_is_g2_wrong_legs,
            returns_none,
            raises,
        ],
    ),
    # hw05.q3 in font units: v = B - A = (177, 97), |v|² = 40738; q''(1) = (61, -103),
    # r''(0) = (69, -97); v x q'' = -24148, v x r'' = -23862; in em multiply by 2048
    "hw05.q3": (
        [_KAPPA_B, list(_KAPPA_B), tuple(_KAPPA_B)],
        [_KAPPA_B / 2048, _KAPPA_B[::-1], -_KAPPA_B, np.array([_KAPPA_B[0], _KAPPA_B[0]])],
    ),
    "hw05.q4": (["b", "B", "(b)", ["b"]], ["a", "c", "d", "a, b"]),
    "hw05.q5": (
        [g2_run, g2_run_matrix],
        [g2_run_no_phantoms, g2_run_doubled_ends, g2_run_reversed, returns_none, raises],
    ),
    # hw05.q6: the counter as in q1 (4 G1, 4 G2); outer: 6 corners kept, bowl of 9 cubics (10 run
    # points) with 8 G2 inner joints
    "hw05.q6": (
        [np.array([6, 4, 12]), [6, 4, 12], (6.0, 4.0, 12.0)],
        [np.array([6, 0, 8]), np.array([6, 10, 5]), np.array([4, 4, 12])],
    ),
}

ALL_IDS = [q for hw in HOMEWORKS for q in questions(hw)]


def hidden_test(hw: str, q: str):
    """The hidden test ``q`` of ``hw``, on the default data if the homework has variants."""
    test = getattr(HIDDEN[hw], q)
    if getattr(HIDDEN[hw], "VARIANTS", False):
        return functools.partial(test, data=variants.data(hw, variants.DEFAULT))
    return test


def _grade(qid: str, value) -> tuple[float, str]:
    hw, q = qid.split(".")
    name = registry()[qid].answer_name
    return run_question(hidden_test(hw, q), LocalStudent({name: value}))


def test_every_question_has_a_table():
    missing = [q for q in ALL_IDS if q not in TABLE]
    assert not missing, (
        f"no row in TABLE (tests/test_answer_equivalence.py) for {missing}: add one per question, "
        '"hwNN.qK": ([>= 2 accepted forms of the right answer], [>= 3 typical wrong answers]), '
        "the right answer derived by hand (CONTRIBUTING.md, 'Homework: the rules the tests enforce')"
    )
    stale = sorted(set(TABLE) - set(ALL_IDS))
    assert not stale, f"TABLE has rows for questions no checks module registers: {stale}"
    for qid, (right, wrong) in TABLE.items():
        assert len(right) >= 2 and len(wrong) >= 3, (
            f"{qid}: TABLE needs >= 2 accepted forms and >= 3 typical wrong answers, "
            f"it has {len(right)} and {len(wrong)}"
        )


def _cases(kind: int):
    return [
        pytest.param(qid, k, value, id=f"{qid}-{k}")
        for qid in sorted(TABLE)
        for k, value in enumerate(TABLE[qid][kind])
    ]


@pytest.mark.parametrize(("qid", "k", "value"), _cases(0))
def test_accepted_form_passes_the_check_and_earns_full_points(qid, k, value):
    v = check(qid, value)
    assert v.passed, f"{qid} form {k}: {v}"
    fraction, note = _grade(qid, value)
    assert fraction == 1.0, f"{qid} form {k}: {fraction} ({note})"


@pytest.mark.parametrize(("qid", "k", "value"), _cases(1))
def test_typical_wrong_answer_fails_the_check_and_loses_points(qid, k, value):
    v = check(qid, value)
    assert not v.passed, f"{qid} wrong answer {k} passes the check: {v}"
    assert "could not read" not in v.message, v.message
    fraction, note = _grade(qid, value)
    assert fraction < 1.0, f"{qid} wrong answer {k} earns full points"
    assert note, f"{qid} wrong answer {k}: no note for the student"


# ------------------------------------------------------------------ format hints
@pytest.mark.parametrize(
    ("qid", "value"),
    [("hw01.q3", "e"), ("hw01.q6", "b, f"), ("hw02.q6", "yes"), ("hw03.q4", "d"), ("hw04.q6", "x"), ("hw05.q4", "e")],
)
def test_a_letter_that_is_no_option_gets_a_format_hint(qid, value):
    v = check(qid, value)
    assert "not one of the options" in v.message and "not this one" not in v.message
    fraction, note = _grade(qid, value)
    assert fraction == 0.0 and "not one of the options" in note


def test_the_check_and_the_grader_read_the_same_plain_data():
    """``answers.plain`` (check side) == the protocol's decoding (grader side), type and value."""
    import json

    from course_lib.homework import protocol as _probe
    from tools.grading.protocol import decode_value

    values = [
        2.5, np.float32(1.5), np.int64(3), np.array([2.5]), [1, 2.0], (1, (2, 3)), sp.Rational(1, 3),
        sp.Matrix([[1, 2], [3, 4]]), np.array([[1, 2]], dtype=np.int32), np.array([True]),
        {"a": [1.0]}, "b, d", complex(1, 2), np.array([1 + 2j]), float("nan"), sp.Symbol("x") + 1,
        np.array([sp.Rational(1, 2), 1], dtype=object), None, True,
    ]  # fmt: skip
    for value in values:
        ours = answers.plain(value)
        theirs = decode_value(json.loads(json.dumps(_probe.encode(value))))
        assert type(ours).__name__ == type(theirs).__name__, value
        if isinstance(ours, np.ndarray):
            assert ours.dtype == theirs.dtype and ours.shape == theirs.shape
            assert np.array_equal(ours, theirs, equal_nan=ours.dtype.kind == "f"), value
        elif isinstance(ours, float) and math.isnan(ours):
            assert math.isnan(theirs)
        else:
            assert ours == theirs, value


# ------------------------------------------------------------------ whole notebooks
@functools.cache
def _namespace(hw: str, version: str) -> dict:
    """The globals left by the code cells of the built notebook, executed in-process."""
    import matplotlib.pyplot as plt

    (source,) = [s for s in build.sources() if s.stem.startswith(hw)]
    nb = build.build(source, version)
    ns: dict = {"__name__": f"{hw}_{version}"}
    show = plt.show
    plt.show = lambda *a, **k: None
    try:
        for cell in nb.cells:
            if cell.cell_type == "code":
                exec(compile(cell.source, f"{hw}-{version}", "exec"), ns)
    finally:
        plt.show = show
        plt.close("all")
    return ns


@pytest.mark.parametrize("hw", HOMEWORKS)
def test_solution_notebook_scores_full_marks(hw):
    ns = _namespace(hw, "solution")
    module = HIDDEN[hw]
    for q in module.POINTS:
        fraction, note = run_question(hidden_test(hw, q), LocalStudent(ns))
        assert fraction == 1.0, f"{hw}.{q}: {fraction} ({note})"


@pytest.mark.parametrize("hw", HOMEWORKS)
def test_blank_exercise_scores_zero_with_not_answered_notes(hw):
    ns = _namespace(hw, "student")
    module = HIDDEN[hw]
    for q in module.POINTS:
        fraction, note = run_question(hidden_test(hw, q), LocalStudent(ns))
        assert fraction == 0.0, f"{hw}.{q}: {fraction}"
        assert note.startswith("not answered"), f"{hw}.{q}: {note}"


# ------------------------------------------------------------------ an exception costs its case only
def test_a_function_that_raises_on_some_inputs_loses_only_those_cases():
    def is_g1_no_zero_guard(q, r, tol=1e-9):  # right, but divides by a zero length
        nq, nr = math.hypot(*q), math.hypot(*r)
        return math.dist([float(x) / nq for x in q], [float(x) / nr for x in r]) <= tol

    v = check("hw02.q3", is_g1_no_zero_guard)
    assert not v.passed and "ZeroDivisionError" in v.message
    fraction, note = _grade("hw02.q3", is_g1_no_zero_guard)
    assert 0.5 < fraction < 1.0 and "your code raised ZeroDivisionError" in note


# ------------------------------------------------------------------ properties of the normalizers
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=60, deadline=None)
@given(
    letters=st.sets(st.sampled_from("abcde"), min_size=1),
    sep=st.sampled_from([",", ", ", " ", "", "; ", " and "]),
    upper=st.booleans(),
    parens=st.booleans(),
    as_list=st.booleans(),
)
def test_choice_reads_every_spelling_of_the_same_letters(letters, sep, upper, parens, as_list):
    items = sorted(letters, reverse=True)
    items = [f"({x})" if parens else x for x in items]
    items = [x.upper() if upper else x for x in items]
    value = items if as_list else sep.join(items)
    canonical = answers.choice(answers.plain(value), "abcde")
    assert canonical == ",".join(sorted(letters))


@settings(max_examples=60, deadline=None)
@given(st.floats(-1e6, 1e6), st.sampled_from([(), (1,), (1, 1)]), st.sampled_from(["array", "list", "scalar"]))
def test_number_accepts_any_size_one_container(x, shape, kind):
    value = np.full(shape, x) if kind == "array" else np.full(shape, x).tolist() if kind == "list" else x
    assert answers.number(answers.plain(value)) == x
    fraction, _ = run_question(lambda s: answers.number(s["a"]) == x or 0.0, LocalStudent({"a": value}))
    assert fraction == 1.0


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.floats(-1e3, 1e3), min_size=1, max_size=5),
    st.sampled_from(["array", "list", "tuple", "column", "sympy"]),
)
def test_array_accepts_every_container_of_the_right_shape(xs, kind):
    n = len(xs)
    value = {
        "array": lambda: np.array(xs),
        "list": lambda: list(xs),
        "tuple": lambda: tuple(xs),
        "column": lambda: np.array(xs)[:, None],
        "sympy": lambda: sp.Matrix([sp.Float(x, 17) for x in xs]),
    }[kind]()
    got = answers.array(answers.plain(value), (n,))
    assert answers.close(got, np.array(xs), tol=1e-12)


# ------------------------------------------------------------------ the mismatches issue 12 found
def _wrong_only_for_quadratics(mistake):
    def stitch(V, b1, b2):
        V = np.asarray(V, float)
        if len(V) - 1 != 2:
            return g2_stitch(V, b1, b2)
        return g2_stitch(V, b1, 0.0) if mistake == "no beta2" else g2_stitch_cubic_only(V, b1, b2)

    return stitch


@pytest.mark.parametrize(
    ("qid", "value", "accepted"),
    [
        ("hw02.q1", np.array([2.5]), True),  # was ✓ but 0 points
        ("hw02.q6", ["a"], True),  # was ✓ but 0 points
        ("hw02.q4", "4*beta1*beta3 + 3*beta2**2", True),  # was ✗ but full points
        ("hw02.q3", is_g1_plane_cross, False),  # was ✓ but lost points
        ("hw01.q5", np.array([1.0, 2 * 25 / 16 + 2 * 0.75]), False),  # q'(s): f(1) = 1 hid it
        ("hw04.q2", _wrong_only_for_quadratics("no beta2"), False),  # β2 = 0 hid it
        ("hw04.q2", _wrong_only_for_quadratics("/2"), False),
    ],
)
def test_the_mismatches_found_in_issue_12_are_gone(qid, value, accepted):
    assert check(qid, value).passed == accepted
    fraction, _ = _grade(qid, value)
    assert (fraction == 1.0) == accepted, fraction
