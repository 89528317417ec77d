"""The lectures' answers, derived here independently, are the ones their checks accept.

Multiple choice in a lecture is practice (CONTRIBUTING.md, "Lecture notebooks"): the notebook
stores no answer and no hash of one, and :func:`course_lib.homework.checks.lectures.quiz` checks the
letters.  This test works each right answer out from first principles (or the course's
definitions), checks that ``quiz`` accepts exactly it among all letter sets, and that no
lecture cell carries a hash-like string.  The code exercises (``check_number``,
``check_vector``) are answered by hand or by a route other than the one
``course_lib.homework.checks.lectures`` takes; each must accept that answer, reject typical wrong ones
and call a blank answer "not answered yet".
"""

from __future__ import annotations

import itertools
import json
import re
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[1]
LECTURES = sorted((ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"))
QUIZ = re.compile(r'\bquiz\(\s*"(lecture\d\d\.q\d)"')
HASHLIKE = re.compile(r'"[0-9a-f]{16}"')


def _code(path: Path) -> list[str]:
    return ["".join(c["source"]) for c in json.loads(path.read_text())["cells"]
            if c["cell_type"] == "code"]


def quiz_questions() -> set:
    return {qid for path in LECTURES for src in _code(path) for qid in QUIZ.findall(src)}


def _quartic_c1_not_c2():
    from course_lib.constructions.beta_splines import quartic_beta_spline
    from course_lib.geometry.continuity import curve_continuity

    P = np.array([[0, 0], [1, 2.4], [3, 3], [4, 0.6], [6, 0.2], [7, 2.6], [9, 3], [10, 0.4]])
    reps = curve_continuity(quartic_beta_spline(P, 1, 100, 0), max_order=3)
    assert all(r.c_order == 1 and r.g_order >= 3 for r in reps)
    return "b"  # C1 but not C2


def _knot_ratio():
    t0, t1, t2 = 0.0, 1.0, 3.0  # |p2 p3| : |p3 p4| = (t1 - t0) : (t2 - t1)  (Finn §19.6)
    assert (t1 - t0) / (t2 - t1) == 1 / 2
    return "b"  # 1 : 2


def _w1_for_beta1_3():
    V2, V3 = np.array([1.0, 2.0]), np.array([3.0, 2.0])  # r'(0) = 3 q'(1): W1 - V3 = 3 (V3 - V2)
    W1 = V3 + 3 * (V3 - V2)
    assert not np.allclose(W1, 3 * V3 - V2)
    return "a"


def _g2_not_c1():
    # r' = 2 q' (β1 = 2 ≠ 1: not C1), r'' = 2² q'' + 5 q' (β2 = 5): G2
    return "c"


def _corner_pair():
    # q(u) = (u³, -u³), r(t) = (t³, t³): every derivative of order 0..2 is 0 at the joint (C2,
    # velocity 0, so not regular); the pieces lie on the lines y = -x (x < 0) and y = x (x > 0):
    # a 90° corner. By hand, sampled: the chords to the joint are perpendicular.
    q_end, r_start = np.array([-0.5**3, 0.5**3]), np.array([0.5**3, 0.5**3])
    assert np.isclose(q_end @ r_start, 0)
    return "a, c"


def _same_tangent_other_curvature():
    # Theorem 1 (Barsky & DeRose 1988, §6): G2 <=> common unit tangent and curvature vector.
    # Curvatures 1 and 2 (same side): the curvature vectors differ, the tangents agree: G1 only;
    # no β2 helps, since the curvature vector does not depend on β2 (lecture 4, §1).
    K_q, K_r = np.array([0.0, 1.0]), np.array([0.0, 2.0])
    assert not np.allclose(K_q, K_r)
    return "b"


def _implied_point_c1():
    A, B = np.array([0.2, 0.4]), np.array([0.6, 0.4])
    M = (A + B) / 2  # q'(1) = 2 (M - A), r'(0) = 2 (B - M): equal vectors, C1 with β1 = 1
    assert np.allclose(2 * (M - A), 2 * (B - M))
    return "a"


ANSWERS = {  # qid: (option letters, right answer)
    "lecture01.q1": ("abcd", _corner_pair),
    "lecture02.q1": ("abcd", lambda: "b, d"),  # unit tangent and curvature are intrinsic
    "lecture02.q2": ("abc", lambda: "b"),  # Example 1: G1 but not C1
    "lecture03.q1": ("abcd", lambda: "b"),  # three shape parameters, only β1 > 0
    "lecture03.q2": ("abcd", _g2_not_c1),
    "lecture04.q1": ("abcd", _same_tangent_other_curvature),
    "lecture05.q1": ("abcd", lambda: "c"),  # κ = 0: radius 1/|κ| = ∞, a straight line
    "lecture06.q1": ("abcd", _knot_ratio),
    "lecture07.q1": ("abcd", _w1_for_beta1_3),
    "lecture09.q1": ("abcd", _quartic_c1_not_c2),
    "lecture11.q1": ("abcd", _implied_point_c1),
    "lecture11.q3": ("abcd", lambda: "b"),  # all joints G2; the outline moved (nb11, §4)
}


def _letter_sets(letters: str):
    for k in range(1, len(letters) + 1):
        yield from (", ".join(c) for c in itertools.combinations(letters, k))


@pytest.mark.parametrize("qid", sorted(ANSWERS))
def test_quiz_accepts_exactly_the_right_letters(qid):
    from course_lib.homework.checks.lectures import quiz

    letters, right = ANSWERS[qid]
    right = ", ".join(sorted(right().replace(",", " ").split()))
    for option in _letter_sets(letters):
        verdict = quiz(qid, option)
        assert verdict.passed == (option == right), (qid, option)
        assert verdict.answered
    assert quiz(qid, right.upper()).passed  # case does not matter
    blank = quiz(qid, ...)
    assert blank.status == "not answered"


def test_every_quiz_of_the_lectures_is_covered():
    # a later lecture adds its questions to ANSWERS (CONTRIBUTING.md, "Lecture notebooks")
    assert quiz_questions() == set(ANSWERS)


@pytest.mark.parametrize("path", LECTURES, ids=[p.stem for p in LECTURES])
def test_no_lecture_stores_an_answer_hash(path):
    found = [src for src in _code(path) if HASHLIKE.search(src) or "answer_hash" in src]
    assert not found, f"{path.name}: a hash of an answer in {found}"


def test_the_question_table_hands_out_no_answers():
    from course_lib.homework.checks.lectures import LECTURE_QUESTIONS

    assert set(LECTURE_QUESTIONS.values()) <= {"number", "vector", "choice"}
    assert not any(callable(v) for v in LECTURE_QUESTIONS.values())
    assert set(ANSWERS) | set(NUMBERS) | set(VECTORS) == set(LECTURE_QUESTIONS)


# ------------------------------------------------ code exercises: check_number, check_vector
# Every numeric or vector question of a lecture, answered here by hand or by a route other
# than the one course_lib.homework.checks.lectures takes, with typical wrong answers that must fail.
CHECKED = re.compile(r'\b(check_number|check_vector)\("(lecture\d\d\.q\d)"')


def checked_questions() -> dict:
    return {qid: kind for path in LECTURES for src in _code(path)
            for kind, qid in CHECKED.findall(src)}


def _unit_tangent_of_q_after_f():
    import sympy as sp

    v = sp.Symbol("v")
    f = (v + v**2) / 2  # onto [0, 1], f' = (1 + 2v)/2 > 0
    Q_f = sp.Matrix([3 * f, 4 * f**2])  # Q(u) = (3u, 4u²) composed directly, no course_lib
    vel = Q_f.diff(v).subs(v, sp.Rational(1, 2))
    T = vel / vel.norm()
    # by hand: u = f(1/2) = 3/8, Q'(3/8) = (3, 8·3/8) = (3, 3), f'(1/2) = 1: T = (1, 1)/√2
    assert sp.simplify(T - sp.Matrix([1, 1]) / sp.sqrt(2)) == sp.zeros(2, 1)
    return np.array(T, dtype=float).ravel()


def _third_derivative_by_composition():
    import sympy as sp

    ub, x = sp.symbols("ubar x")
    d1, d2, d3 = sp.Matrix([1, 0]), sp.Matrix([0, 1]), sp.Matrix([1, 1])
    q = d1 * (x - 1) + d2 * (x - 1) ** 2 / 2 + d3 * (x - 1) ** 3 / 6  # q', q'', q''' at 1
    u = 1 + 2 * (ub - 1) + (ub - 1) ** 2 / 2 + 3 * (ub - 1) ** 3 / 6  # β = (2, 1, 3)
    exact = q.subs(x, u).diff(ub, 3).subs(ub, 1)
    # by hand (Barsky & DeRose 1988, eq. 7.3): β1³ q''' + 3 β1 β2 q'' + β3 q' = 8(1,1) + 6(0,1) + 3(1,0)
    assert exact == sp.Matrix([11, 14])
    return np.array(exact, dtype=float).ravel()


def _curvature_jump_by_hand():
    P0, A, B, P2 = (np.array(p) for p in ([0.0, 0.0], [0.2, 0.4], [0.6, 0.4], [0.7, 0.1]))
    M = (A + B) / 2
    v = B - A  # both velocities at M (lecture 11, §2)
    qpp, rpp = 2 * (P0 - 2 * A + M), 2 * (M - 2 * B + P2)  # second derivatives of quadratics
    cross = lambda a, b: a[0] * b[1] - a[1] * b[0]  # noqa: E731
    kq, kr = cross(v, qpp) / 0.4**3, cross(v, rpp) / 0.4**3  # |v| = 0.4: -5 and -3.75
    assert np.isclose(kq, -5) and np.isclose(kr, -3.75)
    assert np.isclose(kr - kq, 2 * cross(v, P2 - P0) / 0.4**3)  # 2·0.04 / 0.064
    return 1.25


def _g2_joints_of_eight_by_continuity_report():
    from course_lib.constructions.outlines import glyph_outline
    from course_lib.geometry.continuity import curve_continuity, joint_continuity

    g2 = 0
    for contour in glyph_outline("8").contours:  # closed: the closing joint counts too
        c = contour.curve
        reports = list(curve_continuity(c, max_order=2))
        reports.append(joint_continuity(c.segment_curve(c.n_segments - 1), c.segment_curve(0),
                                        max_order=2))
        g2 += sum(r.g_order >= 2 for r in reports)
    assert g2 == 4
    return g2


def _corners_of_ampersand_by_tangent_angles():
    from course_lib.constructions.outlines import glyph_outline

    corners = 0
    for contour in glyph_outline("&").contours:  # closed: the closing joint counts too
        segs = contour.curve.segments
        for a, b in zip(segs, segs[1:] + segs[:1], strict=True):
            t_in, t_out = a[-1] - a[-2], b[1] - b[0]  # end legs: the tangent directions
            cos = t_in @ t_out / (np.linalg.norm(t_in) * np.linalg.norm(t_out))
            corners += np.degrees(np.arccos(np.clip(cos, -1, 1))) > 2  # default tolerance
    return corners


def _b_by_beta_constraints():
    # r' = (3, 0) = β1 q'(1) with q'(1) = (2, 0): β1 = 3/2; the second constraint
    # r'' = β1² q''(1) + β2 q'(1) = (9/4)(1, 3) + β2 (2, 0) = (0, b): β2 = -9/8, b = 27/4
    beta1 = 3.0 / 2.0
    beta2 = -(beta1**2) * 1.0 / 2.0
    b = beta1**2 * 3.0 + beta2 * 0.0
    assert np.isclose(beta1**2 * 1.0 + beta2 * 2.0, 0.0) and b == 6.75
    return b


NUMBERS = {  # qid: (right answer, typical wrong answers)
    # q'' = (0, 2) at u = 1, r'' = (0, 2a) at t = 0 (the velocities (1, 2) agree): a = 1;
    # wrong: a = 2 (r'' set to q''s 2 without the 2 from t²), 0
    "lecture01.q2": (1.0, [2.0, 0.0]),
    "lecture02.q3": (np.hypot(4, 2), [np.hypot(2, 1)]),  # q~'(v) = 2 q'(2v) = (4, 2)
    "lecture03.q3": (3.0, [0.0, 2.0]),  # (3, 4) = 2² (0, 1) + β2 (1, 0)
    # wrong: q''s 3 without β1², with β1 instead of β1², the curvature 3/4 itself
    "lecture04.q3": (_b_by_beta_constraints, [3.0, 4.5, 0.75]),
    "lecture05.q2": (0.5, [2.0, -0.5]),  # 1 / radius, counterclockwise: left turn
    # (x' y'' - y' x'') / (x'² + y'²)^(3/2) = (1 · 2 - 0) / 1; wrong: the radius, the sign
    "lecture05.q3": (2.0, [0.5, -2.0]),
    "lecture06.q2": (2.0, [0.5]),  # knot intervals 1 and 2: β1 = 2 / 1
    # p3 = (h2 p2 + h1 p4) / (h1 + h2) with h1 = 2, h2 = 1: (1 · 0 + 2 · 3) / 3; wrong: the
    # weights swapped, the midpoint
    "lecture06.q3": (2.0, [1.0, 1.5]),
    "lecture07.q2": (1.0, [0.5]),
    "lecture07.q3": (4.0, [5.0]),  # W1 = V3 + 0.5 (V3 - V2) = (3, 2) + 0.5 (2, 0)
    # W = (β V0 + V1) / (1 + β) = (3 (0, 0) + (4, 0)) / 4; wrong: the ratio swapped, the midpoint
    "lecture08.q1": (1.0, [3.0, 2.0]),
    # γ's denominator β2 + β1 (d - 1)(1 + β1) = β2 + 4 for d = 3, β1 = 1; wrong: the sign, and
    # the true pole of the spline (Barsky's δ = 0 at β2 = -12)
    "lecture08.q2": (-4.0, [4.0, -12.0]),
    "lecture09.q2": (-0.125, [0.125, -0.5]),  # -β2 / β1³ = -1 / 8
    # (n + 2) weights of degree n + 1 for n = 4; wrong: n = 3's 25, the 35 equations without
    # the normalization
    "lecture09.q3": (36, [25, 35]),
    "lecture10.q1": (10, [4, 6]),  # n (n + 3) for n = 2
    # u^(h,l), v^(h,l) with l >= 1: 2k of order k, sum over k = 1..3; wrong: all 18, order 3's 6
    "lecture10.q2": (12, [18, 6]),
    "lecture11.q2": (_corners_of_ampersand_by_tangent_angles, [0, 11, 13, 6]),
    "lecture11.q4": (_curvature_jump_by_hand, [0.625, 0.08, -1.25]),  # no 2, numerator, sign
    "lecture11.q5": (_g2_joints_of_eight_by_continuity_report, [30, 26, 3]),
}
VECTORS = {
    # q(u) = (u, u²): q'(1) = (1, 2), |q'(1)| = √5; wrong: not normalized, x and y swapped
    "lecture01.q3": (np.array([1.0, 2.0]) / np.sqrt(5), [[1, 2], [2 / np.sqrt(5), 1 / np.sqrt(5)]]),
    # K = (q'' - (q''·T) T) / |q'|² = ((1, 3) - (1, 0)) / 4 = (0, 3/4); wrong: not divided by
    # |q'|², the tangential part of q'' kept
    "lecture04.q2": (np.array([0.0, 0.75]), [[0, 3], [0.25, 0.75]]),
    # wrong: the velocity of Q∘f (not normalized); T of Q at u = v instead of u = f(v)
    "lecture02.q4": (_unit_tangent_of_q_after_f, [[3, 3], [0.6, 0.8]]),
    # wrong: without the 3 of 3 β1 β2 q''; with DeRose & Barsky's misprint β2 q' for β3 q'
    "lecture03.q4": (_third_derivative_by_composition, [[11, 10], [9, 14]]),
}


def _right(spec):
    value = spec[0]
    return value() if callable(value) else value


@pytest.mark.parametrize("qid", sorted(NUMBERS))
def test_numeric_exercise_accepts_the_right_answer_only(qid):
    from course_lib.homework.checks.lectures import check_number

    right, wrong = _right(NUMBERS[qid]), NUMBERS[qid][1]
    assert check_number(qid, right).passed
    for w in wrong:
        verdict = check_number(qid, w)
        assert not verdict.passed and verdict.answered, (qid, w)
        assert f"{right:g}" not in verdict.message
    blank = check_number(qid, ...)
    assert blank.status == "not answered" and "not answered yet" in blank.message


@pytest.mark.parametrize("qid", sorted(VECTORS))
def test_vector_exercise_accepts_the_right_answer_only(qid):
    from course_lib.homework.checks.lectures import check_vector

    right, wrong = _right(VECTORS[qid]), VECTORS[qid][1]
    for form in (right, list(right), tuple(right), right.reshape(2, 1)):
        assert check_vector(qid, form).passed, form
    for w in wrong:
        verdict = check_vector(qid, w)
        assert not verdict.passed and verdict.answered, (qid, w)
        assert not any(f"{c:g}" in verdict.message for c in right if c not in w)
        assert "component" in verdict.message or "length" in verdict.message
    blank = check_vector(qid, ...)
    assert blank.status == "not answered" and "not answered yet" in blank.message
    assert not check_vector(qid, [1.0, 2.0, 3.0]).passed  # a plane vector has two entries


def test_every_code_exercise_of_the_lectures_is_covered():
    found = checked_questions()
    assert {q for q, k in found.items() if k == "check_number"} == set(NUMBERS)
    assert {q for q, k in found.items() if k == "check_vector"} == set(VECTORS)
    per_lecture = {}
    for qid in found:
        per_lecture[qid[7:9]] = per_lecture.get(qid[7:9], 0) + 1
    assert all(per_lecture.get(f"{n:02d}", 0) >= 2 for n in range(1, 12)), per_lecture


_ANY_ANSWER = st.one_of(
    st.none(),
    st.booleans(),
    st.text(max_size=8),
    st.floats(allow_nan=True, allow_infinity=True),
    st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=4),
    st.lists(st.lists(st.integers(-5, 5), max_size=3), max_size=3),
    st.dictionaries(st.text(max_size=2), st.integers(), max_size=2),
)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(sorted(VECTORS)), _ANY_ANSWER)
def test_check_vector_never_raises_and_never_passes_garbage(qid, answer):
    from course_lib.homework.checks.lectures import check_vector

    verdict = check_vector(qid, answer)  # must not raise, whatever the answer
    assert isinstance(verdict.message, str) and verdict.message
    if verdict.passed:  # only the right vector (two finite numbers) may pass
        assert np.allclose(np.asarray(answer, dtype=float).ravel(), _right(VECTORS[qid]))


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(sorted(VECTORS)),
    st.floats(-20, 20, allow_nan=False),
    st.floats(-20, 20, allow_nan=False),
)
def test_check_vector_passes_exactly_the_expected_vector(qid, x, y):
    from course_lib.homework.checks.lectures import check_vector

    right = _right(VECTORS[qid])
    assert check_vector(qid, [x, y]).passed == bool(np.allclose([x, y], right, rtol=0, atol=1e-8))
