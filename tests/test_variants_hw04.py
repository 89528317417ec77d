"""Homework 4 with per-student variants (issue 19): every variant is well posed, and graded right.

* The default variant (empty code) is the data the notebook always had.
* Over 1,000 codes: the generated data is valid and well conditioned for every question (a
  non-degenerate leg and β1 ∉ {0, 1} in q1; a cubic with no degenerate leg, its last three
  points not collinear, β2 ≠ 0 and γ positive, far from its pole and from 1 in q3; distinct
  points and β1 ≠ 1 in q5; the four statements of q6 in some order, one of them true), the
  hidden test's expected values are finite, satisfy the defining properties and are far from
  the typical mistakes, and the feedback check marks them ✓.
* (The solution notebook graded on 50 variants, and on another student's data, is tested for
  every homework with variants in ``tests/test_variants_solutions.py``.)
* The check ✓ ⇔ full points equivalence holds on non-default variants, for accepted forms and
  for typical mistakes computed from each variant's data.
* q6 is feedback only (0 points); its hidden test still tells right from wrong.
"""

from __future__ import annotations

from fractions import Fraction

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from _homework_support import VariantHomework, default_data_afterwards, differ, far

from course_lib.homework import variants
from course_lib.homework.checks import check

HOME = VariantHomework("hw04")
HIDDEN = HOME.hidden
CODES = HOME.codes
DATA_QUESTIONS = ("q1", "q3", "q5", "q6")
#: the statements of q6 as the notebook printed them before variants; (b) is true
OLD_Q6 = {
    "a": "a Catmull–Rom spline through the V_i",
    "b": "the uniform cubic B-spline of the same control polygon",
    "c": "a G² curve that is not C²",
    "d": "the control polygon itself",
}


_default_afterwards = default_data_afterwards("hw04")  # checks elsewhere see the default data


def _grade(q: str, namespace: dict, data: dict) -> tuple[float, str]:
    return HOME.grade(q, namespace, data)


def _arr(v) -> np.ndarray:
    return np.asarray(v, dtype=float)


# ------------------------------------------------------------------ the default data
def test_the_default_variant_is_the_historical_data():
    d = variants.data("hw04", "")
    assert d["q1"]["V_dm1"] == [1, 2] and d["q1"]["V_d"] == [3, 3] and d["q1"]["beta1"] == 1.5
    assert d["q3"]["V"] == [[0, 0], [1, 2], [3, 3], [4, 2]]
    assert d["q3"]["beta1"] == 1.5 and d["q3"]["beta2"] == 1
    assert d["q5"]["W_left"] == [2, 1] and d["q5"]["W_right"] == [5, 4] and d["q5"]["beta1"] == 2
    assert d["q6"]["options"] == OLD_Q6
    worked = HIDDEN.answers_for(d)  # the old constants, derived by hand
    assert np.allclose(worked["answer_q1"], [6, 4.5])  # (3, 3) + 1.5 (2, 1)
    # γ = 2 (5/2) / (1 + (3/2) 2 (5/2)) = 10/17, β1² γ = 45/34: T = (3, 3) + (45/34) (2, 1)
    assert np.allclose(worked["answer_q3"], [96 / 17, 147 / 34])
    assert np.allclose(worked["answer_q5"], [3, 2])  # (2 (2, 1) + (5, 4)) / 3
    assert worked["answer_q6"] == "b"
    assert HIDDEN.POINTS["q6"] == 0  # multiple choice is feedback only
    assert variants.strata("hw04", "") == {
        "q1": "β1 > 1", "q3": "β2 > 0", "q5": "β1 > 1", "q6": "right option (b)",
    }  # fmt: skip


def test_codes_are_validated_and_reproducible():
    with pytest.raises(ValueError, match="not a variant code"):
        variants.data("hw04", "ABC")
    code = CODES[0]
    assert variants.data("hw04", code.lower()) == variants.data("hw04", code)


# ------------------------------------------------------------------ 1,000 variants: well posed
def _far(a, b, rel=5e-3) -> bool:
    """At least 0.5 % of the answer's size apart (the checks and the grader tolerate 1e-9)."""
    return far(a, b, rel)


def _gamma(b1, b2, d=3):
    """γ of seed 000 eq. (12.1)."""
    return (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))


def _mistakes(d: dict) -> dict[str, list]:
    """Typical wrong answers of a variant, each derived from its data by hand."""
    q = d["q1"]
    Vm, Vd, b = _arr(q["V_dm1"]), _arr(q["V_d"]), q["beta1"]
    q1 = [  # β1 inverted; backwards; from the wrong end of the leg; C1 (β1 = 1)
        Vd + (Vd - Vm) / b,
        Vd - b * (Vd - Vm),
        Vm + b * (Vd - Vm),
        Vd + (Vd - Vm),
    ]
    q = d["q3"]
    V, b1, b2 = _arr(q["V"]), q["beta1"], q["beta2"]
    g = _gamma(b1, b2)
    q3 = [  # β1 not squared; γ forgotten; from V_d; from V_{d-2}; backwards; d for d - 1; β2 forgotten
        V[2] + b1 * g * (V[2] - V[1]),
        V[2] + b1**2 * (V[2] - V[1]),
        V[3] + b1**2 * g * (V[3] - V[2]),
        V[1] + b1**2 * g * (V[2] - V[1]),
        V[2] - b1**2 * g * (V[2] - V[1]),
        V[2] + b1**2 * _gamma(b1, b2, d=4) * (V[2] - V[1]),
        V[2] + b1**2 * _gamma(b1, 0.0) * (V[2] - V[1]),
    ]
    q = d["q5"]
    A, B, b = _arr(q["W_left"]), _arr(q["W_right"]), q["beta1"]
    q5 = [(A + b * B) / (1 + b), (A + B) / 2, A + (B - A) / b]  # swapped; midpoint; 1/β1 of it
    return {"q1": q1, "q3": q3, "q5": q5}


def _g2_holds(V, b1, b2, T) -> bool:
    """W2 = W1 + (W1 − T)/γ satisfies (7.2) with the Bézier end derivatives (8.2), (8.3) of a cubic."""
    g = _gamma(b1, b2)
    W0, W1 = V[3], V[3] + b1 * (V[3] - V[2])
    W2 = W1 + (W1 - T) / g
    q1, q2 = 3 * (V[3] - V[2]), 6 * (V[1] - 2 * V[2] + V[3])
    return bool(np.allclose(6 * (W0 - 2 * W1 + W2), b1**2 * q2 + b2 * q1))


def test_a_thousand_variants_are_well_posed_and_well_conditioned():
    datas = [variants.data("hw04", code) for code in CODES]
    allowed_b1 = {0.5, 0.75, 1.25, 1.5, 2.0, 2.5, 3.0}
    for code, d in zip(CODES, datas, strict=True):
        where = f"variant {code}"
        q = d["q1"]
        Vm, Vd = _arr(q["V_dm1"]), _arr(q["V_d"])
        assert Vm.shape == Vd.shape == (2,) and np.all(Vm == np.round(Vm)) and np.all(Vd == np.round(Vd)), where
        assert np.linalg.norm(Vd - Vm) >= 1 and q["beta1"] in allowed_b1, where
        q = d["q3"]
        V, b1, b2 = _arr(q["V"]), q["beta1"], q["beta2"]
        assert V.shape == (4, 2) and np.all(V == np.round(V)) and np.all(np.diff(V[:, 0]) >= 1), where
        (ax, ay), (bx, by) = V[2] - V[1], V[3] - V[2]
        assert abs(ax * by - ay * bx) >= 1, where  # V_1, V_2, V_3 not collinear
        assert b1 in allowed_b1 and b2 != 0 and 2 * b2 == round(2 * b2), where
        g = _gamma(b1, b2)
        assert 0.25 <= g <= 2.5 and abs(g - 1) >= 0.15, where  # far from the pole, from 0 and from 1
        assert b2 + 2 * b1 * (1 + b1) >= 0.8 * (1 + b1), where  # the denominator of γ
        q = d["q5"]
        A, B = _arr(q["W_left"]), _arr(q["W_right"])
        assert np.linalg.norm(B - A) >= 1 and q["beta1"] in allowed_b1, where
        options = d["q6"]["options"]
        assert sorted(options) == list("abcd") and sorted(options.values()) == sorted(OLD_Q6.values()), where
        worked = HIDDEN.answers_for(d)
        for name in ("answer_q1", "answer_q3", "answer_q5"):
            assert np.all(np.isfinite(worked[name])), (where, name)
        # the worked answers have the defining properties
        W1 = _arr(worked["answer_q1"])
        assert np.allclose(W1 - Vd, d["q1"]["beta1"] * (Vd - Vm)), where  # r'(0) = β1 q'(1), (7.1)
        assert _g2_holds(V, b1, b2, _arr(worked["answer_q3"])), where
        J, b = _arr(worked["answer_q5"]), d["q5"]["beta1"]
        assert np.allclose(B - J, b * (J - A)), where  # G1 at the junction, ratio 1 : β1
        assert "B-spline" in options[worked["answer_q6"]], where
        for q, wrong in _mistakes(d).items():
            for w in wrong:
                assert _far(w, worked[f"answer_{q}"]), (where, q, w)
    # the variants really vary
    for q in ("q1", "q3", "q5"):
        assert len({d[q]["text"] for d in datas}) > 800, q
    assert {HIDDEN.answers_for(d)["answer_q6"] for d in datas} == set("abcd")
    labels = [variants.strata("hw04", code) for code in CODES[:200]]
    assert {s["q3"] for s in labels} == {"β2 > 0", "β2 < 0"}
    assert {s["q1"] for s in labels} == {s["q5"] for s in labels} == {"β1 > 1", "β1 < 1"}
    assert {s["q6"] for s in labels} == {f"right option ({x})" for x in "abcd"}


def test_the_check_accepts_the_worked_answers_of_a_thousand_variants():
    for code in CODES:
        d = variants.data("hw04", code)
        worked = HIDDEN.answers_for(d)
        for q in DATA_QUESTIONS:
            v = check(f"hw04.{q}", worked[f"answer_{q}"])
            assert v.passed, (code, v)


# ------------------------------------------------------------------ check ✓ ⇔ full points on variants
@pytest.mark.parametrize("code", CODES[:40:4])
def test_check_and_grade_agree_on_other_variants(code):
    d = variants.data("hw04", code)
    worked = HIDDEN.answers_for(d)
    forms = {}
    for q in ("q1", "q3", "q5"):
        w = worked[f"answer_{q}"]
        forms[q] = [np.array(w), list(w), tuple(w)]
    w6 = worked["answer_q6"]
    forms["q6"] = [w6, w6.upper(), [w6], f"({w6})"]
    wrong = _mistakes(d)
    wrong["q6"] = [x for x in "abcd" if x != w6]
    for q in forms:
        name = f"answer_{q}"
        for value in forms[q]:
            assert check(f"hw04.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] == 1.0, (code, q, value)
        for value in wrong[q]:
            assert not check(f"hw04.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] < 1.0, (code, q, value)
    # the feedback names the mistake on the student's own data
    inverted, backwards = wrong["q1"][:2]
    assert "inverted" in check("hw04.q1", inverted).message
    assert "backwards" in check("hw04.q1", backwards).message
    assert "swapped" in check("hw04.q5", wrong["q5"][0]).message
    assert "wrong distance" in check("hw04.q1", wrong["q1"][3]).message
    assert "G2 constraint" in check("hw04.q3", wrong["q3"][0]).message  # on the ray, wrong distance


def test_the_old_answers_are_wrong_on_most_variants():
    """The letters and numbers of the example data do not carry over (no shared answer key)."""
    old = HIDDEN.answers_for(variants.data("hw04", ""))
    worked = [HIDDEN.answers_for(variants.data("hw04", c)) for c in CODES[:200]]
    for name in ("answer_q1", "answer_q3", "answer_q5", "answer_q6"):
        same = sum(not differ(w[name], old[name]) for w in worked)
        assert same <= 200 * (0.4 if name == "answer_q6" else 0.05), (name, same)


def test_gamma_of_the_generator_is_exact():
    """The generator's exact γ agrees with eq. (12.1) in floating point (halves and quarters)."""
    from course_lib.homework.checks import hw04 as gen

    for code in CODES[:100]:
        q = variants.data("hw04", code)["q3"]
        exact = gen.gamma(Fraction(q["beta1"]), Fraction(q["beta2"]))
        assert float(exact) == pytest.approx(_gamma(q["beta1"], q["beta2"]), rel=1e-15)


# ------------------------------------------------------------------ any seed, not only the codes
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=200, deadline=None)
@given(st.integers(0, 2**63 - 1))
def test_every_seed_gives_well_posed_data(seed):
    from course_lib.homework.checks import hw04 as gen

    d = gen.generate(np.random.default_rng(seed))
    assert d["q1"]["V_dm1"] != d["q1"]["V_d"] and d["q5"]["W_left"] != d["q5"]["W_right"]
    assert {d["q1"]["beta1"], d["q3"]["beta1"], d["q5"]["beta1"]} <= {0.5, 0.75, 1.25, 1.5, 2.0, 2.5, 3.0}
    V, b1, b2 = _arr(d["q3"]["V"]), d["q3"]["beta1"], d["q3"]["beta2"]
    assert np.all(np.diff(V[:, 0]) >= 1) and b2 != 0
    (ax, ay), (bx, by) = V[2] - V[1], V[3] - V[2]
    assert ax * by - ay * bx != 0
    g = _gamma(b1, b2)
    assert 0.25 <= g <= 2.5 and abs(g - 1) >= 0.15 and abs(g * b1 - 1) >= 0.1  # β2 moves γ by ≥ 10 %
    assert sum("B-spline" in label for label in d["q6"]["options"].values()) == 1
