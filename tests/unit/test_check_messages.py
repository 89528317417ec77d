"""Check messages that used to mislead (issue 23): each says what is really wrong."""

from __future__ import annotations

import numpy as np
import sympy as sp

from course_lib.homework import variants
from course_lib.homework.checks import check


def _joint(d, knots):
    t0, t1, t2 = knots
    return d[2] + (t1 - t0) / (t2 - t0) * (d[3] - d[2])


def test_a_rounded_joint_point_is_told_about_precision_not_place():
    data = variants.data("hw03")
    d, knots = np.array(data["D"]["points"], float), data["q1"]["knots"]
    exact = _joint(d, knots)
    assert check("hw03.q1", exact).passed
    rounded = exact + 2e-5 * (d[3] - d[2])  # on the segment, off by rounding
    verdict = check("hw03.q1", rounded)
    assert not verdict.passed
    assert "precision" in verdict.message and "wrong place" not in verdict.message
    far = exact + 0.2 * (d[3] - d[2])
    assert "wrong place" in check("hw03.q1", far).message


def test_equal_but_wrong_derivatives_do_not_blame_a_correct_joint_point():
    verdict = check("hw03.q5", np.array([[1.0, 2.0], [1.0, 2.0]]))
    assert not verdict.passed
    assert "p_3" not in verdict.message and "agree" in verdict.message


def test_a_function_that_raises_is_told_which_case():
    def g1_bezier_control_points(d, knots):
        raise ZeroDivisionError("boom")

    verdict = check("hw03.q2", g1_bezier_control_points)
    assert not verdict.passed
    assert "with knots" in verdict.message and "ZeroDivisionError" in verdict.message


def test_an_equation_is_named_as_such():
    b1, b2 = sp.symbols("beta1 beta2")
    message = check("hw02.q4", sp.Eq(b1, b2)).message
    assert "equation" in message and "a Equality" not in message


def test_check_all_warns_when_variant_is_empty():
    from course_lib.homework.checks import check_all

    empty = check_all({"VARIANT": ""}, "hw01")
    assert any("VARIANT is empty" in n for n in empty.notes)
    assert "VARIANT is empty" in str(empty) and "VARIANT is empty" in empty._repr_html_()
    own = check_all({"VARIANT": "KQW7MZP3XS"}, "hw01")
    assert own.notes == ()
