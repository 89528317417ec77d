"""Homework 1 with per-student variants (issue 19): every variant is well posed, and graded right.

* The default variant (empty code) is the data the notebook always had.
* Over 1,000 codes: the generated data is valid and well conditioned for every question (regular
  curve, ``f' > 0``, no ``f(s) = s`` or ``f'(s) = 1`` blind spot, ``|κ|`` away from 0 and 1,
  exactly one right option of distinct ones, options a permutation), the hidden test's expected
  values are finite, and the feedback check marks them ✓.
* (The solution notebook graded on 50 variants, and on another student's data, is tested for
  every homework with variants in ``tests/test_variants_solutions.py``.)
* The check ✓ ⇔ full points equivalence holds on non-default variants, for accepted forms and
  for typical mistakes computed from each variant's data.
"""

from __future__ import annotations

import math

import matplotlib
import numpy as np
import pytest
import sympy as sp
from scipy.integrate import quad

matplotlib.use("Agg")

from _homework_support import VariantHomework, default_data_afterwards, far

from course_lib.homework import variants
from course_lib.homework.checks import check, questions, registry
from course_lib.homework.checks.hw01 import Q6_OPTIONS

HOME = VariantHomework("hw01")
HIDDEN = HOME.hidden
CODES = HOME.codes


_default_afterwards = default_data_afterwards("hw01")  # checks elsewhere see the default data


def _grade(q: str, namespace: dict, data: dict) -> tuple[float, str]:
    return HOME.grade(q, namespace, data)


# ------------------------------------------------------------------ the default data
def test_the_default_variant_is_the_historical_data():
    d = variants.data("hw01", "")
    assert d["q1"]["x"] == [0, 1, 1] and d["q1"]["y"] == [0, -2, 0, 1] and d["q1"]["t"] == 1
    assert d["q1"]["text"] == "c(t) = (t² + t, t³ − 2t),  at t = 1"
    assert d["q3"]["options"] == {
        "a": "f(s) = s²",
        "b": "f(s) = 1 − s",
        "c": "f(s) = 2s",
        "d": "f(s) = (s + s²)/2",
    }
    assert d["q4"] == {"k": 1.0, "u": 1.0, "text": "q(u) = (u, u²),  at u = 1"}
    assert d["q5"]["f"] == [0, 0.5, 0.5] and d["q5"]["s"] == 0.75 and d["q5"]["k"] == 1
    assert d["q6"]["options"] == dict(zip("abcde", Q6_OPTIONS, strict=True))
    assert Q6_OPTIONS[1] == "the unit tangent vector" and Q6_OPTIONS[3] == "the curvature vector"
    assert (d["q7"]["k"], d["q7"]["b"]) == (1, 1)
    worked = HIDDEN.answers_for(d)  # the old constants, derived by hand
    assert np.allclose(worked["answer_q1"], np.array([3, 1]) / math.sqrt(10))
    assert worked["answer_q3"] == "d" and worked["answer_q6"] == "b,d"
    assert math.isclose(worked["answer_q4"], 2 / 5**1.5)
    assert np.allclose(worked["answer_q5"], [1.0, 71 / 16])
    assert math.isclose(worked["answer_q7"], (2 * math.sqrt(5) + math.asinh(2)) / 4)


def test_codes_are_validated():
    with pytest.raises(ValueError, match="not a variant code"):
        variants.data("hw01", "ABC")
    with pytest.raises(TypeError, match="as a string"):
        variants.data("hw01", 12345)
    code = CODES[0]
    assert variants.data("hw01", code.lower()) == variants.data("hw01", code)  # case, reproducible


# ------------------------------------------------------------------ 1,000 variants: well posed
def _sampled_min_slope(coef) -> float:  # independent of the hidden test's closed form
    return float(
        np.polynomial.polynomial.polyval(
            np.linspace(0, 1, 2001), np.polynomial.polynomial.polyder(coef)
        ).min()
    )


_far = far


def _mistakes(d: dict) -> dict[str, list]:
    """Typical wrong answers of a variant, each derived from its data by hand."""
    k, u = d["q4"]["k"], d["q4"]["u"]
    kappa = 2 * k / (1 + 4 * k * k * u * u) ** 1.5
    speed = math.sqrt(1 + 4 * k * k * u * u)
    k5, s, (c0, c1, c2) = d["q5"]["k"], d["q5"]["s"], d["q5"]["f"]
    f, f1, f2 = c0 + c1 * s + c2 * s * s, c1 + 2 * c2 * s, 2 * c2
    qp, qpp = np.array([1, 2 * k5 * f]), np.array([0, 2 * k5])
    k7, b = d["q7"]["k"], d["q7"]["b"]
    return {
        "q4": [-kappa, 1 / kappa, kappa * speed],
        "q5": [
            qpp * f1**2,  # one term
            qpp * f1**2 + np.array([1, 2 * k5 * s]) * f2,  # q' at s, not at f(s)
            qpp * f1 + qp * f2,  # f' not squared
            qpp,
        ],
        "q7": [math.hypot(b, k7 * b * b), b],  # the chord; the length of [0, b]
    }


def test_a_thousand_variants_are_well_posed_and_well_conditioned():
    datas = [variants.data("hw01", code) for code in CODES]
    for code, d in zip(CODES, datas, strict=True):
        where = f"variant {code}"
        t, x, y = d["q1"]["t"], d["q1"]["x"], d["q1"]["y"]
        c1 = np.array([x[1] + 2 * x[2] * t, y[1] + 3 * y[3] * t * t])
        assert abs(c1[0]) >= 1 and abs(c1[1]) >= 1 and abs(abs(c1[0]) - abs(c1[1])) >= 0.5, where
        # q3: four distinct options, exactly one an orientation-preserving change of variables
        opts = d["q3"]["coefficients"]
        assert sorted(opts) == list("abcd") and len({tuple(c) for c in opts.values()}) == 4, where
        assert len(set(d["q3"]["options"].values())) == 4, where
        good = [
            x_
            for x_, c in opts.items()
            if c[0] == 0 and math.isclose(sum(c), 1) and _sampled_min_slope(c) > 0
        ]
        assert len(good) == 1 and opts[good[0]] != d["q5"]["f"], where  # q5 does not give q3 away
        for x_, c in opts.items():  # the wrong ones fail clearly, not by a hair
            if x_ != good[0]:
                assert abs(c[0]) >= 0.5 or abs(sum(c) - 1) >= 0.5 or _sampled_min_slope(c) <= 0, (
                    where
                )
        # q4, q5, q7: one parabola (u, k u²), k ≠ 0
        k, u = d["q4"]["k"], d["q4"]["u"]
        assert k == d["q5"]["k"] == d["q7"]["k"] and abs(k) >= 0.25 and abs(u) >= 0.25, where
        s, fc = d["q5"]["s"], d["q5"]["f"]
        assert _sampled_min_slope(fc) >= 0.25, where  # f' > 0 on [0, 1], well away from 0
        f = np.polynomial.polynomial.polyval(s, fc)
        f1 = np.polynomial.polynomial.polyval(s, np.polynomial.polynomial.polyder(fc))
        assert abs(f - s) >= 0.01 and abs(f1 - 1) >= 0.05 and 0.1 <= s <= 0.9, where  # blind spots
        assert d["q7"]["b"] >= 0.5, where
        # q6: the five quantities in some order
        assert sorted(d["q6"]["options"].values()) == sorted(Q6_OPTIONS), where
        # expected values: finite, well away from the typical mistakes
        worked = HIDDEN.answers_for(d)
        for name in ("answer_q1", "answer_q4", "answer_q5", "answer_q7"):
            assert np.all(np.isfinite(worked[name])), (where, name)
        assert 0.02 <= abs(worked["answer_q4"]) and abs(abs(worked["answer_q4"]) - 1) >= 0.1, where
        assert worked["answer_q3"] == good[0], where
        assert worked["answer_q6"] == ",".join(
            x_
            for x_, label in sorted(d["q6"]["options"].items())
            if label in ("the unit tangent vector", "the curvature vector")
        ), where
        for q, wrong in _mistakes(d).items():
            for w in wrong:
                assert _far(w, worked[f"answer_{q}"]), (where, q, w)
    # the variants really vary
    assert (
        len({d["q1"]["text"] for d in datas}) > 300 and len({d["q5"]["text"] for d in datas}) > 200
    )
    assert (
        len({d["q3"]["text"] for d in datas}) > 200 and len({d["q6"]["text"] for d in datas}) == 120
    )
    assert {HIDDEN.answers_for(d)["answer_q3"] for d in datas} == set("abcd")


def test_the_check_accepts_the_worked_answers_of_a_thousand_variants():
    for code in CODES:
        d = variants.data("hw01", code)
        worked = HIDDEN.answers_for(d)
        for qid in questions("hw01"):
            name = registry()[qid].answer_name
            if name == "chain_rule_derivatives":
                continue
            v = check(qid, worked[name])
            assert v.passed, (code, v)


def test_the_hidden_arc_length_agrees_with_quadrature():
    for code in CODES[:100]:
        d = variants.data("hw01", code)["q7"]
        numeric, _ = quad(lambda u, k=d["k"]: math.hypot(1, 2 * k * u), 0, d["b"])
        assert math.isclose(HIDDEN._arc_length(d), numeric, rel_tol=1e-10)


# ------------------------------------------------------------------ check ✓ ⇔ full points on variants
@pytest.mark.parametrize("code", CODES[:40:4])
def test_check_and_grade_agree_on_other_variants(code):
    d = variants.data("hw01", code)
    worked = HIDDEN.answers_for(d)
    forms = {
        "q1": [
            np.array(worked["answer_q1"]),
            list(worked["answer_q1"]),
            sp.Matrix(worked["answer_q1"]),
        ],
        "q3": [worked["answer_q3"], worked["answer_q3"].upper(), [worked["answer_q3"]]],
        "q4": [worked["answer_q4"], np.array([worked["answer_q4"]])],
        "q5": [np.array(worked["answer_q5"]), tuple(worked["answer_q5"])],
        "q6": [
            worked["answer_q6"],
            worked["answer_q6"].replace(",", ", ").upper(),
            worked["answer_q6"].split(","),
        ],
        "q7": [worked["answer_q7"], [worked["answer_q7"]]],
    }
    right3, right6 = worked["answer_q3"], worked["answer_q6"].split(",")
    wrong = dict(_mistakes(d))
    wrong["q1"] = [
        -np.array(worked["answer_q1"]),
        np.array(worked["answer_q1"])[::-1],
        np.array(worked["answer_q1"]) * 2,
    ]
    wrong["q3"] = [x for x in "abcd" if x != right3]
    wrong["q6"] = [
        right6[0],
        ",".join(sorted(set("abcde") - set(right6))),
        ",".join([*right6, min(set("abcde") - set(right6))]),
    ]
    for q in forms:
        name = f"answer_{q}"
        for value in forms[q]:
            assert check(f"hw01.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] == 1.0, (code, q, value)
        for value in wrong[q]:
            assert not check(f"hw01.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] < 1.0, (code, q, value)
