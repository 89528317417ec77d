"""Numeric "check your understanding" questions of the lecture notebooks.

A lecture must never contain the answer to its own question, not even as an expression
such as ``expected=(3 - 1) / (1 - 0)``.  The expected values are computed here, at check
time, from the question's data with ``course_lib`` -- never printed::

    from course_lib.checks.lectures import check_number
    check_number("lecture03.q2", my_beta1)

Multiple-choice questions use :func:`course_lib.checks.quiz` with a salted hash instead.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from ._core import Verdict, as_number, run_validate

__all__ = ["LECTURE_QUESTIONS", "check_number"]


def _speed_after_reparametrization() -> float:  # lecture 1, Q3: speed of q(2v) at the joint
    import sympy as sp

    from ..differential_geometry import speed
    from ..parametrization import ParametricCurve
    from ..reparametrization import ChangeOfVariables, Reparametrized

    u = sp.Symbol("u")
    q = ParametricCurve.from_sympy([2 * u, u], u, (0.0, 1.0))
    q_tilde = Reparametrized(q, ChangeOfVariables.affine((0.0, 0.5), (0.0, 1.0)))
    return float(speed(q_tilde, 0.5))


def _beta2_of_a_joint() -> float:  # lecture 2, Q3: the second Beta-constraint solved for β2
    from ..beta_constraints import solve_shape_parameters

    q_derivs = [np.array([1.0, 0.0]), np.array([0.0, 1.0])]
    r_derivs = [np.array([2.0, 0.0]), np.array([3.0, 4.0])]
    return float(solve_shape_parameters(q_derivs, r_derivs).betas[1])


def _kappa_circle_radius_2() -> float:  # lecture 3, Q4: signed curvature, radius 2, ccw
    import sympy as sp

    from ..differential_geometry import signed_curvature
    from ..parametrization import ParametricCurve

    t = sp.Symbol("t")
    circle = ParametricCurve.from_sympy([2 * sp.cos(t), 2 * sp.sin(t)], t, (0.0, 6.0))
    return float(signed_curvature(circle, 1.0))


def _beta1_for_knots() -> float:  # lecture 3, Q2: knots 0, 1, 3, local parameters
    from ..knot_splines import knot_ratio_beta1

    return float(knot_ratio_beta1(np.array([0.0, 1.0, 3.0]))[0])


def _gamma_uniform() -> float:  # lecture 4, Q2: γ of eq. (12.1), d = 3, β1 = 1, β2 = 0
    from ..stitching import farin_boehm_gamma

    return float(farin_boehm_gamma(1.0, 0.0, d=3))


def _w1_x_for_beta1_half() -> float:  # lecture 4, Q3: x of W_1, V_2 = (1, 2), V_3 = (3, 2)
    from ..stitching import g1_stitch

    q = np.array([[0.0, 0.0], [0.5, 1.0], [1.0, 2.0], [3.0, 2.0]])
    stitched = g1_stitch(q, beta1=0.5, W_rest=[[6.0, 1.0], [7.0, 0.0]])
    return float(stitched.segments[1][1][0])


def _beta2_in_course_convention() -> float:  # lecture 5, Q3: seed 001's (2, 1, 0) -> β2
    from ..seed_formulas import inverse_betas

    return float(inverse_betas((2.0, 1.0, 0.0))[1])


def _shape_functions_g2() -> float:  # lecture 5, Q2: seed 001 counts n(n + 3) for G^n
    from ..surfaces import count_shape_functions

    return float(count_shape_functions(2))


#: question id -> function computing the expected value from the question's data
LECTURE_QUESTIONS: dict[str, Callable[[], float]] = {
    "lecture01.q3": _speed_after_reparametrization,
    "lecture02.q3": _beta2_of_a_joint,
    "lecture03.q2": _beta1_for_knots,
    "lecture03.q4": _kappa_circle_radius_2,
    "lecture04.q2": _gamma_uniform,
    "lecture04.q3": _w1_x_for_beta1_half,
    "lecture05.q2": _shape_functions_g2,
    "lecture05.q3": _beta2_in_course_convention,
}


def check_number(question_id: str, answer: object, rtol: float = 1e-9) -> Verdict:
    """Check a numeric lecture answer; never raises, never prints the expected value."""
    if question_id not in LECTURE_QUESTIONS:
        known = ", ".join(LECTURE_QUESTIONS)
        return Verdict(str(question_id), False, f"unknown question id (known: {known}).")

    def validate(a):
        value = as_number(a, "your answer")
        if np.isclose(value, LECTURE_QUESTIONS[question_id](), rtol=rtol, atol=1e-12):
            return True, "correct."
        return False, "not the expected value -- check your computation."

    return run_validate(question_id, validate, answer)
