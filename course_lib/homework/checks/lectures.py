"""The "check your understanding" questions of the lecture notebooks: practice, not graded.

A lecture must never contain the answer to its own question, not even as an expression
such as ``expected=(3 - 1) / (1 - 0)``.  The expected values are computed here, at check
time, from the question's data with ``course_lib`` -- never printed::

    from course_lib.homework.checks.lectures import check_number, check_vector, quiz
    check_number("lecture06.q2", my_beta1)
    check_vector("lecture02.q4", my_tangent)      # a plane vector [x, y]
    quiz("lecture07.q1", my_answer)              # multiple choice: letters

Multiple-choice questions in a lecture are practice: the course grades homework only, and a
multiple-choice answer can always be found by trying the few letter sets there are.  So the
lectures store no hash that would pretend to hide it; :func:`quiz` checks the letters against
this module (computed from the question's data where that is cheap).  A student who reads
this module reads the answers -- the checks are feedback, not a lock.

:data:`LECTURE_QUESTIONS` lists the questions and their kind (``"number"``, ``"vector"``,
``"choice"``); it holds no answers and nothing in it can be called to get one.

Why this module is long: every lecture's practice questions live here, each a few lines with
its expected value computed at check time; one registry serves all lectures.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from course_lib.homework.checks._core import Verdict, as_choice, as_number, as_vector, run_validate

__all__ = ["LECTURE_QUESTIONS", "check_number", "check_vector", "quiz"]


def _a_for_c2() -> float:  # lecture 1, Q2: q = (u, u²), r = (1 + t, 1 + 2t + a t²): C2
    import sympy as sp

    u, t, a = sp.symbols("u t a")
    q, r = sp.Matrix([u, u**2]), sp.Matrix([1 + t, 1 + 2 * t + a * t**2])
    second = r.diff(t, 2).subs(t, 0) - q.diff(u, 2).subs(u, 1)
    return float(sp.solve(second[1], a)[0])


def _curvature_vector_of_q() -> np.ndarray:  # lecture 4, Q2: K of q at the joint
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve
    from course_lib.geometry.differential_geometry import arc_length_derivatives

    u = sp.Symbol("u")
    q1, q2 = np.array([2.0, 0.0]), np.array([1.0, 3.0])  # q'(1), q''(1)
    q = ParametricCurve.from_sympy(  # the quadratic with these derivatives at u = 1
        [q1[k] * (u - 1) + q2[k] * (u - 1) ** 2 / 2 for k in (0, 1)], u, (0.0, 1.0))
    return np.asarray(arc_length_derivatives(q, 1.0, 2)[1], dtype=float).ravel()


def _b_for_g2() -> float:  # lecture 4, Q3: r'' = (0, b) for a common curvature vector
    r1 = np.array([3.0, 0.0])  # r'(0)
    # r'' = (0, b) is perpendicular to r' = r1, so r's curvature vector is (0, b) / |r1|²
    return float(_curvature_vector_of_q()[1] * (r1 @ r1))


def _unit_tangent_at_joint() -> np.ndarray:  # lecture 1, Q3: T of q(u) = (u, u²) at u = 1
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve
    from course_lib.geometry.differential_geometry import unit_tangent

    u = sp.Symbol("u")
    q = ParametricCurve.from_sympy([u, u**2], u, (0.0, 1.0))
    return np.asarray(unit_tangent(q, 1.0), dtype=float).ravel()


def _speed_after_reparametrization() -> float:  # lecture 2, Q3: speed of q(2v) at the joint
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve
    from course_lib.geometry.differential_geometry import speed
    from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized

    u = sp.Symbol("u")
    q = ParametricCurve.from_sympy([2 * u, u], u, (0.0, 1.0))
    q_tilde = Reparametrized(q, ChangeOfVariables.affine((0.0, 0.5), (0.0, 1.0)))
    return float(speed(q_tilde, 0.5))


def _beta2_of_a_joint() -> float:  # lecture 3, Q3: the second Beta-constraint solved for β2
    from course_lib.geometry.beta_constraints import solve_shape_parameters

    q_derivs = [np.array([1.0, 0.0]), np.array([0.0, 1.0])]
    r_derivs = [np.array([2.0, 0.0]), np.array([3.0, 4.0])]
    return float(solve_shape_parameters(q_derivs, r_derivs).betas[1])


def _kappa_circle_radius_2() -> float:  # lecture 5, Q2: signed curvature, radius 2, ccw
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve
    from course_lib.geometry.differential_geometry import signed_curvature

    t = sp.Symbol("t")
    circle = ParametricCurve.from_sympy([2 * sp.cos(t), 2 * sp.sin(t)], t, (0.0, 6.0))
    return float(signed_curvature(circle, 1.0))


def _kappa_parabola_vertex() -> float:  # lecture 5, Q3: signed curvature of (t, t²) at t = 0
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve
    from course_lib.geometry.differential_geometry import signed_curvature

    t = sp.Symbol("t")
    parabola = ParametricCurve.from_sympy([t, t**2], t, (-1.0, 1.0))
    return float(signed_curvature(parabola, 0.0))


def _joint_x_for_knots_0_2_3() -> float:  # lecture 6, Q3: p3 between p2 = (0, 0), p4 = (3, 0)
    from course_lib.constructions.knot_splines import g1_knot_spline

    d = np.array([[-1.0, 1.0], [-0.5, 1.0], [0.0, 0.0], [3.0, 0.0], [3.5, 1.0], [4.0, 1.0]])
    return float(g1_knot_spline(d, np.array([0.0, 2.0, 3.0])).segments[1][0][0])


def _beta1_for_knots() -> float:  # lecture 6, Q2: knots 0, 1, 3, local parameters
    from course_lib.constructions.knot_splines import knot_ratio_beta1

    return float(knot_ratio_beta1(np.array([0.0, 1.0, 3.0]))[0])


def _gamma_uniform() -> float:  # lecture 7, Q2: γ of eq. (12.1), d = 3, β1 = 1, β2 = 0
    from course_lib.constructions.stitching import farin_boehm_gamma

    return float(farin_boehm_gamma(1.0, 0.0, d=3))


def _junction_x_quadratic() -> float:  # lecture 8, Q1: leg (0, 0) -> (4, 0), β_(1,0) = 3
    from course_lib.constructions.beta_splines import quadratic_beta_spline

    P = np.array([[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [0.0, 3.0]])
    return float(quadratic_beta_spline(P, beta1=[3.0, 1.0, 1.0]).segments[0][0][0])


def _gamma_pole_beta2() -> float:  # lecture 8, Q2: 1/γ is affine in β2; its zero for β1 = 1
    from course_lib.constructions.stitching import farin_boehm_gamma

    at0, at1 = 1.0 / farin_boehm_gamma(1.0, 0.0, d=3), 1.0 / farin_boehm_gamma(1.0, 1.0, d=3)
    return float(-at0 / (at1 - at0))


def _w1_x_for_beta1_half() -> float:  # lecture 7, Q3: x of W_1, V_2 = (1, 2), V_3 = (3, 2)
    from course_lib.constructions.stitching import g1_stitch

    q = np.array([[0.0, 0.0], [0.5, 1.0], [1.0, 2.0], [3.0, 2.0]])
    stitched = g1_stitch(q, beta1=0.5, W_rest=[[6.0, 1.0], [7.0, 0.0]])
    return float(stitched.segments[1][1][0])


def _beta2_in_course_convention() -> float:  # lecture 9, Q2: seed 001's (2, 1, 0) -> β2
    from course_lib.sources.seed_formulas import inverse_betas

    return float(inverse_betas((2.0, 1.0, 0.0))[1])


def _unknowns_g4() -> float:  # lecture 9, Q3: (n + 2)² coefficients of the G^4 weights
    from course_lib.sources.seed_formulas import blending_system

    return float(len(blending_system(4, [1, 0, 0, 0])[1]))


def _shape_functions_g2() -> float:  # lecture 10, Q1: seed 001 counts n(n + 3) for G^n
    from course_lib.constructions.surfaces import count_shape_functions

    return float(count_shape_functions(2))


def _free_shape_functions_g3() -> float:  # lecture 10, Q2: n(n + 3) less the 2n along the boundary
    from course_lib.constructions.surfaces import count_shape_functions

    return float(count_shape_functions(3) - 2 * 3)


def _unit_tangent_after_reparametrization() -> np.ndarray:  # lecture 2, Q4
    # Q(u) = (3u, 4u²) reparametrized by f(v) = (v + v²)/2: unit tangent of Q∘f at v = 1/2
    import sympy as sp

    from course_lib.curves.parametrization import ParametricCurve
    from course_lib.geometry.differential_geometry import unit_tangent
    from course_lib.geometry.reparametrization import ChangeOfVariables, Reparametrized

    u = sp.Symbol("u")
    Q = ParametricCurve.from_sympy([3 * u, 4 * u**2], u, (0.0, 1.0))
    f = ChangeOfVariables.polynomial([0.0, 0.5, 0.5], (0.0, 1.0), (0.0, 1.0))
    return np.asarray(unit_tangent(Reparametrized(Q, f), 0.5), dtype=float).ravel()


def _third_derivative_from_betas() -> np.ndarray:  # lecture 3, Q4: r'''(0) at a G3 joint
    from course_lib.geometry.beta_constraints import beta_constraints

    bc = beta_constraints(3)
    q_derivs = ([1.0, 0.0], [0.0, 1.0], [1.0, 1.0])  # q'(1), q''(1), q'''(1)
    third = bc.rhs[2].subs(dict(zip(bc.betas, (2.0, 1.0, 3.0), strict=True)))
    at_q = [{qk: d[c] for qk, d in zip(bc.q, q_derivs, strict=True)} for c in (0, 1)]
    return np.array([float(third.subs(at)) for at in at_q])


def _curvature_jump_at_implied_point() -> float:  # lecture 11, Q4: κ_r − κ_q at M, in 1/em
    from course_lib.curves.curve import PiecewiseBezier
    from course_lib.geometry.differential_geometry import signed_curvature

    P0, A, B, P2 = (np.array(p) for p in ([0.0, 0.0], [0.2, 0.4], [0.6, 0.4], [0.7, 0.1]))
    M = (A + B) / 2
    pair = PiecewiseBezier([[P0, A, M], [M, B, P2]])
    kappa_q = signed_curvature(pair.segment_curve(0), 1.0)
    kappa_r = signed_curvature(pair.segment_curve(1), 0.0)
    return float(np.squeeze(kappa_r - kappa_q))


def _g2_points_of_eight() -> float:  # lecture 11, Q5: G2 joints of DejaVu Sans' "8"
    from course_lib.constructions.outlines import glyph_outline, glyph_summary

    return float(glyph_summary(glyph_outline("8")).g2)


def _corners_of_ampersand() -> float:  # lecture 11, Q2: corners of DejaVu Sans' "&"
    from course_lib.constructions.outlines import glyph_outline, glyph_summary

    return float(glyph_summary(glyph_outline("&")).corners)


# ------------------------------------------------------------- multiple choice (practice)
def _corner_pair_choice() -> str:  # lecture 1, Q1: q = (u³, -u³), r = (t³, t³) at 0
    import sympy as sp

    u, t = sp.symbols("u t")
    q, r = sp.Matrix([u**3, -(u**3)]), sp.Matrix([t**3, t**3])
    at_joint = [(q.diff(u, k).subs(u, 0), r.diff(t, k).subs(t, 0)) for k in range(4)]
    c2 = all(a == b for a, b in at_joint[:3])
    moving = at_joint[1][0] != sp.zeros(2, 1)
    corner = sp.simplify(at_joint[3][0].dot(at_joint[3][1])) == 0  # directions (1,-1), (1,1)
    truths = {"a": c2, "b": moving, "c": corner, "d": moving}  # regular: velocity never 0
    return ", ".join(k for k, v in truths.items() if v)


def _w1_choice() -> str:  # lecture 7, Q1: W1 for β1 = 3, tried on a concrete cubic
    from course_lib.constructions.stitching import g1_stitch

    V = np.array([[0.0, 0.0], [1.0, 1.0], [1.0, 2.0], [3.0, 2.0]])
    W1 = g1_stitch(V, beta1=3.0, W_rest=[[9.0, 0.0], [10.0, 0.0]]).segments[1][1]
    options = {"a": V[3] + 3 * (V[3] - V[2]), "b": V[3] + (V[3] - V[2]) / 3, "c": 3 * V[3] - V[2]}
    return next(k for k, p in options.items() if np.allclose(p, W1))


def _knot_ratio_choice() -> str:  # lecture 6, Q1: |p2 p3| : |p3 p4| for knots 0, 1, 3
    from course_lib.constructions.knot_splines import knot_ratio_beta1

    beta1 = float(knot_ratio_beta1(np.array([0.0, 1.0, 3.0]))[0])  # |p3 p4| / |p2 p3|
    return {1.0: "a", 2.0: "b", 0.5: "c", 3.0: "d"}[beta1]


def _quartic_order_choice() -> str:  # lecture 9, Q1: β = (1, 100, 0) -- C1 but not C2
    from course_lib.constructions.beta_splines import quartic_beta_spline
    from course_lib.geometry.continuity import curve_continuity

    P = np.array([[0, 0], [1, 2.4], [3, 3], [4, 0.6], [6, 0.2], [7, 2.6], [9, 3], [10, 0.4]])
    reports = curve_continuity(quartic_beta_spline(P, 1.0, 100.0, 0.0), max_order=3)
    c, g = min(r.c_order for r in reports), min(r.g_order for r in reports)
    if c >= 3:
        return "a"
    if c >= 1:
        return "b"
    return "c" if g >= 3 else "d"


@dataclass(frozen=True)
class _Choice:
    """A practice multiple-choice question: its prompt, its options (a, b, c, ...) and a
    function returning the right letters."""

    prompt: str
    options: tuple[str, ...]
    right: Callable[[], str]

    @property
    def letters(self) -> str:
        return "abcdefgh"[: len(self.options)]


_CHOICES: dict[str, _Choice] = {
    "lecture01.q1": _Choice(
        "q(u) = (u³, -u³) on [-1, 0] and r(t) = (t³, t³) on [0, 1]: which are true?",
        ("they meet with C2 continuity", "the velocity at the joint is not zero",
         "the curve they draw has a corner", "both parametrizations are regular"),
        _corner_pair_choice,
    ),
    "lecture02.q1": _Choice(
        "Which are intrinsic (equal for equivalent parametrizations)?",
        ("the velocity vector", "the unit tangent", "the speed", "the curvature"),
        lambda: "b, d",  # unit tangent and curvature
    ),
    "lecture02.q2": _Choice(
        "q(u) = (2u, u) on [0, 1] and r(t) = (4t + 2, 2t + 1) on [0, 1/2] meet with",
        ("C1 continuity", "G1 but not C1 continuity", "neither C1 nor G1 continuity"),
        lambda: "b",  # Example 1 of Barsky & DeRose 1988
    ),
    "lecture03.q1": _Choice(
        "At a G3 joint: how many shape parameters, which positive?",
        ("2; both", "3; only β1", "3; all three", "4; only β1"),
        lambda: "b",
    ),
    "lecture03.q2": _Choice(
        "r'(0) = 2 q'(1), r''(0) = 4 q''(1) + 5 q'(1): the joint is",
        ("C2", "G1 but not G2", "G2 but not C1", "not even G1"),
        lambda: "c",  # β1 = 2, β2 = 5
    ),
    "lecture06.q1": _Choice(
        "Ratio |p2p3| : |p3p4| for knots 0, 1, 3?",
        ("1 : 1", "1 : 2", "2 : 1", "1 : 3"),
        _knot_ratio_choice,
    ),
    "lecture04.q1": _Choice(
        "Same unit tangent at J, curvature 1 before and 2 after: the joint is",
        ("G2", "G1 but not G2", "not even G1", "G2 for a suitable β2"),
        lambda: "b",  # Theorem 1: G2 needs a common curvature vector; β2 cannot change κ
    ),
    "lecture05.q1": _Choice(
        "The osculating circle at an inflection is",
        ("a point", "a circle of radius 0", "a straight line (radius ∞)", "undefined because T is"),
        lambda: "c",  # κ = 0: radius 1/|κ| = ∞
    ),
    "lecture07.q1": _Choice(
        "W1 for β1 = 3?",
        ("V3 + 3 (V3 - V2)", "V3 + (V3 - V2)/3", "3 V3 - V2", "anywhere on the line V2V3"),
        _w1_choice,
    ),
    "lecture09.q1": _Choice(
        "β1 = 1, β2 = 100, β3 = 0 gives",
        ("C3", "C1 but not C2", "G3 but not even C1", "neither C1 nor G3"),
        _quartic_order_choice,
    ),
    "lecture11.q1": _Choice(
        "At an implied on-curve point the two segments are",
        ("C1 with β1 = 1", "G1 but never C1", "always G2",
         "G2 exactly when the chord P0 P2 is perpendicular to AB"),
        lambda: "a",  # velocity B - A on both sides
    ),
    "lecture11.q3": _Choice(
        "After the change",
        ("the font's on-curve points still lie on the outline",
         "every joint is G2, but the outline moved by about 0.01 em",
         "the comb still steps at the four extremes", "the contour is only C1"),
        lambda: "b",
    ),
}


#: question id -> function computing the expected value from the question's data
_NUMBERS: dict[str, Callable[[], float]] = {
    "lecture01.q2": _a_for_c2,
    "lecture02.q3": _speed_after_reparametrization,
    "lecture03.q3": _beta2_of_a_joint,
    "lecture04.q3": _b_for_g2,
    "lecture05.q2": _kappa_circle_radius_2,
    "lecture05.q3": _kappa_parabola_vertex,
    "lecture06.q2": _beta1_for_knots,
    "lecture06.q3": _joint_x_for_knots_0_2_3,
    "lecture07.q2": _gamma_uniform,
    "lecture07.q3": _w1_x_for_beta1_half,
    "lecture08.q1": _junction_x_quadratic,
    "lecture08.q2": _gamma_pole_beta2,
    "lecture09.q2": _beta2_in_course_convention,
    "lecture09.q3": _unknowns_g4,
    "lecture10.q1": _shape_functions_g2,
    "lecture10.q2": _free_shape_functions_g3,
    "lecture11.q2": _corners_of_ampersand,
    "lecture11.q4": _curvature_jump_at_implied_point,
    "lecture11.q5": _g2_points_of_eight,
}

#: question id -> function computing the expected plane vector from the question's data
_VECTORS: dict[str, Callable[[], np.ndarray]] = {
    "lecture01.q3": _unit_tangent_at_joint,
    "lecture02.q4": _unit_tangent_after_reparametrization,
    "lecture03.q4": _third_derivative_from_betas,
    "lecture04.q2": _curvature_vector_of_q,
}

_KINDS = {"number": _NUMBERS, "vector": _VECTORS, "choice": _CHOICES}

#: question id -> its kind, "number", "vector" or "choice" (no answers here)
LECTURE_QUESTIONS: Mapping[str, str] = {
    qid: kind for kind, table in _KINDS.items() for qid in sorted(table)
}


_CHECKER = {"number": "check_number", "vector": "check_vector", "choice": "quiz"}


def _unknown(question_id: object, kind: str) -> Verdict:
    """The verdict for an id that the check of ``kind`` does not know."""
    other = LECTURE_QUESTIONS.get(question_id) if isinstance(question_id, str) else None
    if other is not None:
        return Verdict(question_id, False, f"this question is checked with {_CHECKER[other]}.")
    known = ", ".join(sorted(_KINDS[kind]))
    return Verdict(str(question_id), False, f"unknown question id (known: {known}).")


def check_number(question_id: str, answer: object, rtol: float = 1e-9) -> Verdict:
    """Check a numeric lecture answer; never raises, never prints the expected value."""
    if question_id not in _NUMBERS:
        return _unknown(question_id, "number")

    def validate(a):
        value = as_number(a, "your answer")
        if np.isclose(value, _NUMBERS[question_id](), rtol=rtol, atol=1e-12):
            return True, "correct."
        return False, "not the expected value -- check your computation."

    return run_validate(question_id, validate, answer)


def _what_is_wrong(value: np.ndarray, expected: np.ndarray, tol: float) -> str:
    """Name the wrong part of a vector answer without giving the expected vector away."""
    n_v, n_e = float(np.linalg.norm(value)), float(np.linalg.norm(expected))
    if n_v > 0 and n_e > 0:
        cos = float(value @ expected) / (n_v * n_e)
        if cos > 1 - 1e-12:
            return (
                f"it points the right way, but its length ({n_v:.6g}) is not the "
                "expected one -- a factor missing, or one too many?"
            )
        if cos < -1 + 1e-12:
            return "it is parallel to the expected vector but points the opposite way."
    names = "xyz"
    wrong = [names[k] for k in range(value.size) if abs(value[k] - expected[k]) > tol]
    right = [names[k] for k in range(value.size) if names[k] not in wrong]
    if right:
        return (
            f"its {' and '.join(right)}-component is right, its {' and '.join(wrong)}-component "
            "is not -- check your computation."
        )
    return "neither component is the expected value -- check your computation."


def check_vector(question_id: str, answer: object, rtol: float = 1e-9) -> Verdict:
    """Check a plane-vector lecture answer (list, tuple, numpy array or sympy Matrix).

    Never raises and never prints the expected vector.  A wrong answer is told which
    component is wrong, or that only its length, or only its orientation, is.
    """
    if question_id not in _VECTORS:
        return _unknown(question_id, "vector")

    def validate(a):
        value = as_vector(a, (2,), "your answer", "a plane vector [x, y]")
        expected = _VECTORS[question_id]()
        tol = rtol * max(1.0, float(np.linalg.norm(expected)))
        if np.all(np.abs(value - expected) <= tol):
            return True, "correct."
        return False, "not the expected vector: " + _what_is_wrong(value, expected, tol)

    return run_validate(question_id, validate, answer)


def quiz(question_id: str, answer: object) -> Verdict:
    """Show a practice multiple-choice question with its options and the verdict on ``answer``.

    Answers are read like homework choices: case, spaces and order do not matter (``"B, d"``
    is ``["d", "b"]``).  Never raises; says only "right" or "not this one".
    """
    if question_id not in _CHOICES:
        return _unknown(question_id, "choice")
    q = _CHOICES[question_id]
    lines = "; ".join(f"({k}) {v}" for k, v in zip(q.letters, q.options, strict=True))

    def validate(a):
        mine = as_choice(a, q.letters, "your answer")
        if mine == as_choice(q.right(), q.letters, "the right answer"):
            return True, "right."
        return False, "not this one -- think again (re-read the statement)."

    v = run_validate(question_id, validate, answer)
    return Verdict(v.question, v.passed, f"{q.prompt} {lines} -- {v.message}", v.status)
