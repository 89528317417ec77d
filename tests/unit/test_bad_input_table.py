"""One table of bad inputs across course_lib (issue 14): every row must raise the named
error with a message naming the parameter -- never a ComplexWarning that drops the
imaginary part, a raw numpy message, or an IndexError."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

from course_lib.constructions.beta_splines import (
    beta_spline,
    cubic_beta_spline,
    design_beta_spline,
    quadratic_beta_spline,
)
from course_lib.constructions.catmull_rom import catmull_rom
from course_lib.constructions.stitching import farin_boehm, g1_stitch, g2_stitch
from course_lib.curves import bezier
from course_lib.curves.curve import PiecewiseBezier
from course_lib.geometry.beta_constraints import beta_coefficients
from course_lib.geometry.differential_geometry import (
    arc_length,
    curve_from_curvature,
    parameter_at_arc_length,
)
from course_lib.geometry.reparametrization import ChangeOfVariables, faa_di_bruno

V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [4.0, 0.0], [6.0, 1.0], [7.0, 3.0]])
C = PiecewiseBezier([V[:4], V[3:]])
Z = 1 + 0j

TABLE = [
    # complex numbers anywhere -> TypeError naming the parameter
    ("points", lambda: cubic_beta_spline(V + 0j), TypeError, "V"),
    ("segment", lambda: PiecewiseBezier([V[:4] + 1j]), TypeError, r"segments\[0\]"),
    ("u", lambda: bezier.evaluate(V[:4], 0.5 + 0j), TypeError, "u"),
    ("t", lambda: C.evaluate(np.array([0.5 + 1j])), TypeError, "t"),
    ("beta1", lambda: cubic_beta_spline(V, Z), TypeError, "beta1"),
    ("beta2 list", lambda: cubic_beta_spline(V, 1.0, [0.0, Z]), TypeError, "beta2"),
    ("beta1 stitch", lambda: g1_stitch(V[:4], Z, V[:2]), TypeError, "beta1"),
    ("beta2 FB", lambda: farin_boehm(V[:3], 1.0, Z, 3), TypeError, "beta2"),
    ("betas", lambda: beta_spline(V, (Z, 0.0), 2), TypeError, "betas"),
    ("betas coeff", lambda: beta_coefficients([Z, 0]), TypeError, "betas"),
    ("knots", lambda: PiecewiseBezier([V[:4], V[3:]], knots=[0, Z, 2]), TypeError, "knots"),
    ("matrix", lambda: C.transformed(np.eye(2) * Z), TypeError, "matrix"),
    ("offset", lambda: C.transformed(np.eye(2), [Z, 0]), TypeError, "offset"),
    ("catmull beta1", lambda: catmull_rom(V, [Z] * 5), TypeError, "beta1"),
    ("from_betas", lambda: ChangeOfVariables.from_betas([Z]), TypeError, "betas"),
    (
        "start_point",
        lambda: curve_from_curvature(1.0, 1.0, start_point=[Z, 0]),
        TypeError,
        "start_point",
    ),
    # numeric strings: refused bare and inside lists alike
    ("str list beta1", lambda: cubic_beta_spline(V, ["1"] * 6), TypeError, "beta1"),
    ("str beta1", lambda: cubic_beta_spline(V, "1.0"), TypeError, "beta1"),
    ("str quad", lambda: quadratic_beta_spline(V, ["1"] * 5), TypeError, "beta1"),
    ("str stitch", lambda: g2_stitch(V[:4], "1", 0.0, V[:1]), TypeError, "beta1"),
    ("str points", lambda: cubic_beta_spline(V.astype(str)), TypeError, "V"),
    ("str t", lambda: C.evaluate(["0.5"]), TypeError, "t"),
    ("str t bare", lambda: C.evaluate("0.5"), TypeError, "t"),
    (
        "str knots",
        lambda: PiecewiseBezier([V[:4], V[3:]], knots=["0", "1", "2"]),
        TypeError,
        "knots",
    ),
    ("str matrix", lambda: C.transformed("abc"), TypeError, "matrix"),
    ("str catmull", lambda: catmull_rom(V, beta1=["a", "b"]), TypeError, "beta1"),
    ("str interior", lambda: design_beta_spline(V, "W"), TypeError, "interior"),
    # ragged nested lists
    ("ragged matrix", lambda: C.transformed([[1, 0], [0]]), TypeError, "matrix"),
    (
        "ragged W_rest",
        lambda: g2_stitch(V[:5], 1.0, 0.0, W_rest=[[1, 2], [3]]),
        TypeError,
        "W_rest",
    ),
    ("ragged points", lambda: cubic_beta_spline([[0, 0], [1], [2, 2], [3, 3]]), TypeError, "V"),
    ("ragged beta1", lambda: catmull_rom(V, beta1=[[1, 2], [3]]), TypeError, "beta1"),
    # None where an array is needed
    ("faa None", lambda: faa_di_bruno(None, [1.0]), TypeError, "outer_derivs"),
    ("faa inner None", lambda: faa_di_bruno([[1.0, 0.0]], None), TypeError, "inner_derivs"),
    ("arc None", lambda: arc_length(None), TypeError, "curve"),
    ("t scalar", lambda: C.evaluate(0.5 + 0j), TypeError, "t"),
    ("t1", lambda: arc_length(C, 0.0, 0.5 + 0j), TypeError, "t1"),
    ("s", lambda: parameter_at_arc_length(C, 1 + 0j), TypeError, "s"),
]


@pytest.mark.parametrize(("what", "call", "exc", "name"), TABLE, ids=[r[0] for r in TABLE])
def test_bad_input_is_refused_by_name(what, call, exc, name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a ComplexWarning would mean the imaginary part was dropped
        with pytest.raises(exc, match=name):
            call()
