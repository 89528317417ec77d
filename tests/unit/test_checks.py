"""The homework feedback checks: right answers pass, every kind of wrong answer gets a friendly
message (never an exception, never the expected value), and the lecture helpers work.

The right answers below are derived by hand (derivations in comments), independently of both
the checks and the solution notebooks.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
import sympy as sp
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from course_lib.homework import checks
from course_lib.homework.checks import (
    Report,
    Verdict,
    _core,
    answer_hash,
    check,
    check_all,
    check_choice,
    check_value,
    questions,
    quiz,
)

B = sp.symbols("beta1:5")
T0, T1, T2, P2, P4 = sp.symbols("t0 t1 t2 p2 p4")


def _chain(q1, q2, f1, f2):
    return np.array([q1 * f1, q2 * f1**2 + q1 * f2])


def _g1_points(d, knots):
    t = np.asarray(knots, float)
    L = t.size - 1
    rows = [d[0], d[1], d[2]]
    for i in range(1, L):
        a, b = t[i] - t[i - 1], t[i + 1] - t[i]
        rows += [(b * rows[-1] + a * d[2 * i + 1]) / (a + b), d[2 * i + 1], d[2 * i + 2]]
    rows.append(d[2 * L + 1])
    return np.array(rows)


def _g2_stitch(V, b1, b2):
    V = np.asarray(V, float)
    d = len(V) - 1
    W1 = V[-1] + b1 * (V[-1] - V[-2])
    W2 = 2 * W1 - V[-1] + b1**2 * (V[-3] - 2 * V[-2] + V[-1]) + b2 * (V[-1] - V[-2]) / (d - 1)
    return np.array([V[-1], W1, W2])


def _quadratic_beta_spline(V, b):
    V = np.asarray(V, float)
    m = len(V) - 1
    j = [V[k] + (V[k + 1] - V[k]) / (1 + b[k]) for k in range(m)]
    return np.array([[j[i - 1], V[i], j[i]] for i in range(1, m)])


D = np.array([[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]], dtype=float)


def _g2_run(V):
    """Uniform cubic B-spline on 2V0 - V1, V0..Vn, 2Vn - Vn-1 in Bézier form, span by span."""
    V = np.asarray(V, float)
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    return np.array([[(a + 4 * b + c) / 6, (2 * b + c) / 3, (b + 2 * c) / 3, (b + 4 * c + d) / 6]
                     for a, b, c, d in zip(E, E[1:], E[2:], E[3:], strict=False)])


RIGHT = {
    "hw01.q1": np.array([3.0, 1.0]) / math.sqrt(10),  # c'(1) = (3, 1)
    "hw01.q2": _chain,
    "hw01.q3": "d",
    "hw01.q4": 2 / sp.Integer(5) ** sp.Rational(3, 2),  # det((1,2),(0,2)) / 5^(3/2)
    # ((s+s²)/2, (s+s²)²/4)'' at s = 3/4: x'' = f'' = 1, y'' = 2 f'² + 2 f f''
    # with f = 21/32, f' = 5/4: 25/8 + 21/16 = 71/16
    "hw01.q5": np.array([1.0, 71 / 16]),
    "hw01.q6": "b, d",
    "hw01.q7": (2 * math.sqrt(5) + math.asinh(2)) / 4,
    "hw02.q1": 2.5,  # (5, -2.5) = 2.5 (2, -1)
    "hw02.q2": np.array([3.0, -4.0]),  # (-4, 10) - 9 (0, 2) = -4 (1, 2)
    "hw02.q3": lambda q, r, tol=1e-9: bool(
        min(np.linalg.norm(q), np.linalg.norm(r)) > 0
        and np.linalg.norm(q / np.linalg.norm(q) - r / np.linalg.norm(r)) < tol
    ),
    "hw02.q4": 4 * B[0] * B[2] + 3 * B[1] ** 2,
    "hw02.q5": np.array([4.25, -0.75]),
    "hw02.q6": "a",
    "hw02.q7": "A",
    "hw03.q1": np.array([8 / 3, 3.0]),
    "hw03.q2": _g1_points,
    "hw03.q3": [_g1_points(D, k) for k in ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6])],
    "hw03.q4": "b",
    "hw03.q5": np.array([[2.0, 0.0], [2.0, 0.0]]),
    "hw03.q6": 3 * (P4 - P2) / (T2 - T0),
    "hw03.q7": lambda t: np.diff(t)[1:] / np.diff(t)[:-1],
    "hw04.q1": np.array([6.0, 4.5]),
    "hw04.q2": _g2_stitch,
    "hw04.q3": np.array([96 / 17, 147 / 34]),
    "hw04.q4": _quadratic_beta_spline,
    "hw04.q5": np.array([3.0, 2.0]),
    "hw04.q6": "b",
    # hw05: see tests/test_answer_equivalence.py for the derivations
    "hw05.q1": np.array([6, 10, 5]),
    "hw05.q2": lambda P0, A, B, P2: bool(
        abs(np.linalg.det(np.array([np.subtract(B, A), np.subtract(P2, P0)], dtype=float)))
        <= 1e-9 * np.linalg.norm(np.subtract(B, A)) * np.linalg.norm(np.subtract(P2, P0))
    ),
    "hw05.q3": np.array([-24148.0, -23862.0]) * 2048 / 40738**1.5,
    "hw05.q4": "b",
    "hw05.q5": _g2_run,
    "hw05.q6": np.array([6, 4, 12]),
}
ALL_IDS = sorted(RIGHT)


def _raises(*args, **kwargs):
    raise ZeroDivisionError("division by zero")


def _stub(*args, **kwargs):
    raise NotImplementedError("write the body")


def _returns_none(*args, **kwargs):
    return None


def _wrong_shape(*args, **kwargs):
    return np.zeros(7)


def _returns_nan(*args, **kwargs):
    return np.full(3, np.nan)


WRONG = {
    "Ellipsis": ...,
    "None": None,
    "string": "no idea",
    "complex": 3 + 4j,
    "bool": True,
    "nan": float("nan"),
    "inf": float("inf"),
    "nan array": np.array([np.nan, 1.0]),
    "wrong shape": np.zeros((3, 3, 3)),
    "dict": {"a": 1},
    "symbolic": sp.Symbol("x") + 1,
    "raises": _raises,
    "stub": _stub,
    "returns None": _returns_none,
    "returns wrong shape": _wrong_shape,
    "returns NaN": _returns_nan,
    "list of Ellipsis": [..., ..., ...],
    "sympy matrix": sp.Matrix([[1, 2], [3, 4]]),
    "list": [1.0, 2.0],
}


def test_every_homework_question_is_covered_here():
    registered = [q for hw in checks.HOMEWORKS for q in questions(hw)]
    missing = sorted(set(registered) - set(ALL_IDS))
    assert not missing, (
        f"no right answer in RIGHT (tests/unit/test_checks.py) for {missing}: add one per "
        "question, derived by hand (CONTRIBUTING.md, 'Homework: the rules the tests enforce')"
    )
    assert sorted(registered) == ALL_IDS, f"RIGHT has unregistered ids {sorted(set(ALL_IDS) - set(registered))}"
    sizes = {hw: len(questions(hw)) for hw in checks.HOMEWORKS}
    assert all(5 <= n <= 8 for n in sizes.values()), f"a homework has 5 to 8 questions: {sizes}"


@pytest.mark.parametrize("qid", ALL_IDS)
def test_right_answer_passes(qid):
    v = check(qid, RIGHT[qid])
    assert isinstance(v, Verdict)
    assert v.passed and v.status == "passed" and bool(v), str(v)


@pytest.mark.parametrize("qid", ALL_IDS)
def test_placeholder_is_not_answered(qid):
    v = check(qid, ...)
    assert not v.passed and v.status == "not answered", str(v)
    assert "not answered yet" in v.message
    if callable(RIGHT[qid]):
        v = check(qid, _stub)
        assert v.status == "not answered" and "NotImplementedError" in v.message


def _expected_numbers(value) -> set[str]:
    """Printed forms of the non-trivial numbers of a right answer (to search messages for)."""
    if callable(value) or isinstance(value, str):
        return set()
    if isinstance(value, list):
        return set().union(*(_expected_numbers(v) for v in value))
    if isinstance(value, sp.Expr) and value.free_symbols:
        return {str(value), str(sp.expand(value)), str(sp.simplify(value))}
    out = set()
    for x in np.asarray(value, dtype=float).ravel():
        if float(x).is_integer():
            continue  # small integers appear in shapes and indices of any message
        out |= {f"{x:.3g}", f"{x:.4g}", f"{x:.6g}", repr(float(x)), str(x)}
    return out


@pytest.mark.parametrize("qid", ALL_IDS)
@pytest.mark.parametrize("kind", list(WRONG))
def test_wrong_answers_get_a_friendly_verdict(qid, kind, monkeypatch):
    monkeypatch.setattr(_core, "FUNCTION_TIME_LIMIT", 0.5)
    v = check(qid, WRONG[kind])  # must not raise
    assert isinstance(v, Verdict) and not v.passed
    assert v.message and "Traceback" not in v.message
    assert "the check could not read your answer" not in v.message, v.message  # no check bugs
    if kind in ("Ellipsis", "list of Ellipsis", "stub", "returns None"):
        return
    for number in _expected_numbers(RIGHT[qid]):
        assert number not in v.message, f"{qid}: message reveals {number!r}: {v.message}"
        assert number not in v._repr_html_()


def test_function_that_raises_reports_type_and_message():
    v = check("hw04.q2", _raises)
    assert "ZeroDivisionError: division by zero" in v.message and v.status == "failed"


def test_endless_function_is_stopped(monkeypatch):
    monkeypatch.setattr(_core, "FUNCTION_TIME_LIMIT", 0.3)

    def loop(*args):
        while True:
            pass

    v = check("hw01.q2", loop)
    assert not v.passed and "did not return" in v.message


def test_recursion_is_reported():
    def rec(*args):
        return rec(*args)

    v = check("hw03.q7", rec)
    assert not v.passed and "RecursionError" in v.message


# Targeted wrong answers: the message names the course's concept, not the answer.
TARGETED = [
    ("hw01.q1", np.array([3.0, 1.0]), "length 1"),
    ("hw01.q1", -np.array([3.0, 1.0]) / math.sqrt(10), "backwards"),
    ("hw01.q1", np.array([1.0, 0.0]), "not parallel"),
    ("hw01.q2", lambda q1, q2, f1, f2: np.array([q1 * f1, q2 * f1**2]), "product rule"),
    ("hw01.q4", -2 / 5**1.5, "sign"),
    ("hw01.q4", 5**1.5 / 2, "radius of curvature"),
    ("hw01.q7", math.sqrt(2), "chord"),
    ("hw02.q1", -2.5, "> 0"),
    ("hw02.q1", 0.4, "upside down"),
    ("hw02.q2", np.array([3.0, 4.0]), "sign of β2"),
    ("hw02.q4", 4 * B[0] * B[1] + 3 * B[1] ** 2, "seed 001 eq. (2.7)"),
    ("hw02.q5", 0.5 * np.array([1.0, -3.0]) + 2 * np.array([2.0, 0.0]), "squared"),
    ("hw03.q1", np.array([10 / 3, 3.0]), "swapped"),
    ("hw03.q1", np.array([3.0, 4.0]), "on the segment"),
    ("hw03.q5", np.array([[4.0, 0.0], [2.0, 0.0]]), "local parameter"),
    ("hw03.q7", lambda t: np.diff(t)[:-1] / np.diff(t)[1:], "upside down"),
    ("hw04.q1", np.array([3.0, 3.0]) - 1.5 * np.array([2.0, 1.0]), "backwards -- is β1 positive"),
    ("hw04.q1", np.array([3.0, 3.0]) + np.array([2.0, 1.0]) / 1.5, "inverted"),
    ("hw04.q1", np.array([4.0, 7.0]), "off that line"),
    ("hw04.q5", np.array([4.0, 3.0]), "swapped"),
    ("hw05.q1", np.array([6, 15, 0]), "rel_jump"),
    ("hw05.q1", np.array([6, 6, 1]), "one contour only"),
    ("hw05.q1", np.array([5, 10, 6]), "wrong order"),
    ("hw05.q3", np.array([-24148.0, -23862.0]) / 40738**1.5, "font units"),
    ("hw05.q3", np.array([-23862.0, -24148.0]) * 2048 / 40738**1.5, "swapped"),
    ("hw05.q3", np.array([24148.0, 23862.0]) * 2048 / 40738**1.5, "sign"),
    ("hw05.q6", np.array([6, 0, 8]), "outer contour only"),
    ("hw05.q6", np.array([6, 10, 5]), "original glyph"),
]


@pytest.mark.parametrize(("qid", "answer", "phrase"), TARGETED)
def test_targeted_feedback(qid, answer, phrase):
    v = check(qid, answer)
    assert not v.passed and phrase in v.message, str(v)


def test_g2_stitch_degree_hint():
    def cubic_only(V, b1, b2):  # uses (d - 1) = 2 whatever the degree
        V = np.asarray(V, float)
        W1 = V[-1] + b1 * (V[-1] - V[-2])
        W2 = 2 * W1 - V[-1] + b1**2 * (V[-3] - 2 * V[-2] + V[-1]) + b2 * (V[-1] - V[-2]) / 2
        return np.array([V[-1], W1, W2])

    v = check("hw04.q2", cubic_only)
    assert not v.passed and "where does the degree d enter" in v.message


def test_unknown_question_and_bad_id():
    assert "unknown question" in check("hw09.q1", 1).message
    assert not check(42, 1).passed


def test_check_all_reports_missing_and_deleted_names():
    ns = {"answer_q1": RIGHT["hw01.q1"], "HOMEWORK": "hw01"}
    report = check_all(ns)
    assert isinstance(report, Report) and not report.all_passed
    assert report.n_passed == 1 and len(report.verdicts) == len(questions("hw01"))
    assert "is not defined" in str(report.verdicts[1])
    assert "1 of 7" in report._repr_html_()
    # its own CSS class: cl-report is the live report of the widgets (tests/browser)
    assert 'class="cl-check-report"' in report._repr_html_()
    assert "cl-report" not in report._repr_html_().replace("cl-check-report", "")
    full = {name: RIGHT[q] for q, name in ((q, checks.registry()[q].answer_name) for q in questions("hw01"))}
    assert check_all(full, "hw01").all_passed
    assert not check_all({}, None).all_passed


def test_choice_and_value_helpers_for_lectures():
    h = answer_hash("b", salt="lecture03.q1")
    assert h != answer_hash("b", salt="lecture03.q2") and len(h) == 16
    assert check_choice("lecture03.q1", " B ", h).passed
    assert not check_choice("lecture03.q1", "c", h).passed
    assert check_choice("lecture03.q1", ..., h).status == "not answered"
    h2 = answer_hash(["a", "c"], salt="l.q2")
    assert check_choice("l.q2", "c, a", h2).passed and check_choice("l.q2", "C A", h2).passed
    v = check_value("lecture02.q2", 0.1 + 0.2, expected=0.3)
    assert v.passed
    v = check_value("lecture02.q2", 0.5, expected=0.123456)
    assert not v.passed and "0.123" not in v.message
    assert check_value("l", [1, 2], expected=np.array([1.0, 2.0])).passed
    assert "shape" in check_value("l", [1, 2, 3], expected=np.array([1.0, 2.0])).message
    q = quiz("lecture01.q3", "Which is intrinsic?", ["speed", "unit tangent"], "b", answer_hash("b", salt="lecture01.q3"))
    assert q.passed and "(b) unit tangent" in q.message
    h3 = answer_hash("b", salt="lecture01.q3")
    for spelling in ("B", "(b)", ["b"], " b. "):
        assert quiz("lecture01.q3", "?", ["x", "y"], spelling, h3).passed, spelling
    hint = quiz("lecture01.q3", "?", ["x", "y"], "c", h3)
    assert not hint.passed and "not one of the options" in hint.message
    assert quiz("lecture01.q3", "?", ["x", "y"], ..., h3).status == "not answered"


def test_verdict_display():
    v = check("hw01.q3", "d")
    assert str(v).startswith("✓") and repr(v) == str(v)
    assert "cl-verdict-passed" in v._repr_html_()
    w = check("hw01.q3", "<script>")
    assert "<script>" not in w._repr_html_()


# ----------------------------------------------------------- the homework's claims, verified
@pytest.mark.parametrize(
    "qid", [q for q in ALL_IDS if isinstance(RIGHT[q], str)]
)
def test_choice_questions_accept_only_the_right_letters(qid):
    right = set(RIGHT[qid].replace(",", " ").lower().split())
    for letter in "abcde":
        v = check(qid, letter)
        assert v.passed == ({letter} == right), (qid, letter)


def _bezier_end(P, at_end):
    d = len(P) - 1
    if at_end:
        return d * (P[-1] - P[-2]), d * (d - 1) * (P[-1] - 2 * P[-2] + P[-3])
    return d * (P[1] - P[0]), d * (d - 1) * (P[2] - 2 * P[1] + P[0])


def _kappa(d1, d2):
    return (d1[0] * d2[1] - d1[1] * d2[0]) / np.linalg.norm(d1) ** 3


def test_hw02_q7_picture_has_one_joint_of_each_kind():
    """A: G1 with a curvature jump; B: G2 (halves of one cubic); C: a corner."""
    segs = [np.array(s, float) for s in (
        [[0, 0], [1, 1], [2, 1.5], [3, 1.5]],
        [[3, 1.5], [4, 1.5], [5, 0.75], [6, 0.25]],
        [[6, 0.25], [7, -0.25], [8, -0.5], [9, 0.5]],
        [[9, 0.5], [10, 0.5], [11, 1.5], [12, 1.0]],
    )]  # fmt: skip
    kinds = []
    for q, r in itertools.pairwise(segs):
        assert np.array_equal(q[-1], r[0])
        q1, q2 = _bezier_end(q, True)
        r1, r2 = _bezier_end(r, False)
        g1 = abs(q1[0] * r1[1] - q1[1] * r1[0]) < 1e-12 and q1 @ r1 > 0
        g2 = g1 and abs(_kappa(q1, q2) - _kappa(r1, r2)) < 1e-12
        kinds.append("G2" if g2 else "G1 only" if g1 else "not G1")
    assert kinds == ["G1 only", "G2", "not G1"]
    assert RIGHT["hw02.q7"] == "A"
    # the jump at A is large enough to see: curvature ratio 1.5
    k_left = _kappa(*_bezier_end(segs[0], True))
    k_right = _kappa(*_bezier_end(segs[1], False))
    assert k_right / k_left == pytest.approx(1.5)


def test_hw04_q3_farin_boehm_point_gives_g2_exactly():
    # exact rational arithmetic: T = (96/17, 147/34) and W2 = W1 + (W1 - T)/γ satisfies (7.2)
    R = sp.Rational
    V = [sp.Matrix([0, 0]), sp.Matrix([1, 2]), sp.Matrix([3, 3]), sp.Matrix([4, 2])]
    b1, b2, d = R(3, 2), sp.Integer(1), 3
    gamma = (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))
    T = sp.Matrix([R(96, 17), R(147, 34)])
    assert T == V[2] + b1**2 * gamma * (V[2] - V[1])
    W0, W1 = V[3], V[3] + b1 * (V[3] - V[2])
    W2 = W1 + (W1 - T) / gamma
    q1, q2 = d * (V[3] - V[2]), d * (d - 1) * (V[1] - 2 * V[2] + V[3])
    r2 = d * (d - 1) * (W0 - 2 * W1 + W2)
    assert sp.simplify(r2 - (b1**2 * q2 + b2 * q1)) == sp.zeros(2, 1)


def test_hw04_q6_unit_shape_parameters_give_the_uniform_cubic_b_spline():
    Vm, V0, Vp = sp.symbols("Vm V0 Vp")
    b1, b2 = 1, 0
    gamma = sp.Rational(2 * (1 + b1), b2 + 2 * b1 * (1 + b1))  # seed 000 §10.2 step (1a)
    den = 1 + gamma + b1**2 * gamma
    W_left_2 = (b1**2 * gamma * Vm + (1 + gamma) * V0) / den  # leg V_{i-1} V_i, step (1b)
    W_right_1 = ((1 + b1**2 * gamma) * V0 + gamma * Vp) / den  # leg V_i V_{i+1}
    J = (b1 * W_left_2 + W_right_1) / (1 + b1)  # step (2)
    assert sp.simplify(J - (Vm + 4 * V0 + Vp) / 6) == 0  # uniform cubic B-spline, Bézier form
    assert RIGHT["hw04.q6"] == "b"


_GRID = st.tuples(st.integers(-2048, 2048), st.integers(-2048, 2048))


@settings(max_examples=60, deadline=None)
@given(st.lists(_GRID, min_size=2, max_size=9, unique=True))
def test_hw05_q5_phantom_vertices_keep_the_corners_and_their_tangents(points):
    # what hw05 q5 teaches, on run polygons of font-unit points: the cubic Beta-spline with
    # β1 = 1, β2 = 0 on 2V0 - V1, V0..Vn, 2Vn - Vn-1 is the span-by-span Bézier form written
    # by hand, starts at V0 along V1 - V0 with zero curvature, ends likewise, and is C2
    from course_lib.constructions.beta_splines import cubic_beta_spline

    V = np.array(points, float)
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    W = np.array(cubic_beta_spline(E, 1.0, 0.0).segments)
    assert W.shape == (len(V) - 1, 4, 2)
    assert np.allclose(W, _g2_run(V), rtol=0, atol=1e-9)
    assert np.allclose(W[0, 0], V[0], rtol=0, atol=1e-9) and np.allclose(W[-1, -1], V[-1], rtol=0, atol=1e-9)
    assert np.allclose(3 * (W[0, 1] - W[0, 0]), V[1] - V[0], rtol=0, atol=1e-9)
    assert np.allclose(3 * (W[-1, -1] - W[-1, -2]), V[-1] - V[-2], rtol=0, atol=1e-9)
    assert np.allclose(W[0, 2] - 2 * W[0, 1] + W[0, 0], 0, atol=1e-9)
    assert np.allclose(W[:-1, 3], W[1:, 0], rtol=0, atol=1e-9)
    assert np.allclose(W[:-1, 3] - W[:-1, 2], W[1:, 1] - W[1:, 0], rtol=0, atol=1e-9)
    assert np.allclose(W[:-1, 3] - 2 * W[:-1, 2] + W[:-1, 1], W[1:, 2] - 2 * W[1:, 1] + W[1:, 0], rtol=0, atol=1e-9)


@settings(max_examples=80, deadline=None)
@given(st.lists(_GRID, min_size=4, max_size=4, unique=True), st.integers(-3, 3), st.booleans())
def test_hw05_q2_the_cross_product_test_agrees_with_classify_joints(points, s, parallel):
    # the criterion of hw05 q2 (lecture 09 §2) against the outline classifier on a real
    # TrueType contour P0 (on), A, B (off), P2 (on): its first joint is the implied M
    from course_lib.constructions.outlines import Outline, classify_joints, truetype_contour

    P0, A, B, P2 = (np.array(p, float) for p in points)
    if parallel:
        assume(s != 0)
        P2 = P0 + s * (B - A)  # exactly parallel chord, in either direction
    u, w = B - A, P2 - P0
    rel = abs(u[0] * w[1] - u[1] * w[0]) / (np.linalg.norm(u) * np.linalg.norm(w) or 1.0)
    assume(parallel or rel > 1e-6)
    assume(min(np.linalg.norm(A - P0), np.linalg.norm(P2 - B), np.linalg.norm(w)) > 0)
    contour = truetype_contour(np.array([P0, A, B, P2]), [True, False, False, True])
    table = classify_joints(Outline((contour,), "two quadratics"))
    k = int(np.flatnonzero(table.implied)[0])
    assert table.g_order[k] >= 1 and table.angle[k] < 1e-7
    assert (table.kind[k] == "G2") == parallel == RIGHT["hw05.q2"](P0, A, B, P2)


def test_hw03_q4_only_uniform_knots_put_every_joint_at_the_midpoint():
    for label, knots in zip("abc", ([0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6]), strict=True):
        P = _g1_points(D, knots)
        mid = all(np.allclose(P[3 * i], (P[3 * i - 1] + P[3 * i + 1]) / 2) for i in (1, 2))
        assert mid == (label == RIGHT["hw03.q4"])


# ---------------------------------------------------------------- lecture numeric checks
def test_lecture_numeric_checks_pass_right_and_fail_wrong_answers():
    """The mechanism; every lecture answer is derived in tests/test_lecture_answers.py."""
    from course_lib.homework.checks.lectures import check_number

    right = np.hypot(4, 2)  # lecture02.q3 by hand: q~'(v) = 2 q'(2v) = (4, 2)
    assert check_number("lecture02.q3", right).passed
    assert not check_number("lecture02.q3", right + 0.5).passed
    assert check_number("lecture02.q3", ...).status == "not answered"
    assert not check_number("lecture11.q9", 1.0).passed
    assert "10" not in check_number("lecture10.q1", 3).message
