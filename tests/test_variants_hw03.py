"""Homework 3 with per-student variants (issue 19): every variant is well posed, and graded right.

* The default variant (empty code) is the data the notebook always had.
* Over 1,000 codes: the generated data is valid and well conditioned for every question (no
  degenerate leg of the control polygon, increasing knots, a joint off the midpoint in q1,
  exactly one uniform knot sequence of three distinct ones in q3, local ≠ global derivatives in
  q5), the hidden test's expected values are finite and far from the typical mistakes, and the
  feedback check marks them ✓.
* (The solution notebook graded on 50 variants, and on another student's data, is tested for
  every homework with variants in ``tests/test_variants_solutions.py``.)
* The check ✓ ⇔ full points equivalence holds on non-default variants, for accepted forms and
  for typical mistakes computed from each variant's data.
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from _homework_support import VariantHomework, default_data_afterwards, differ, far

from course_lib.homework import variants
from course_lib.homework.checks import check
from course_lib.homework.checks.hw03 import D_DEFAULT

HOME = VariantHomework("hw03")
HIDDEN = HOME.hidden
CODES = HOME.codes
DATA_QUESTIONS = ("q1", "q3", "q4", "q5")


_default_afterwards = default_data_afterwards("hw03")  # checks elsewhere see the default data


def _grade(q: str, namespace: dict, data: dict) -> tuple[float, str]:
    return HOME.grade(q, namespace, data)


# ------------------------------------------------------------------ the default data
def test_the_default_variant_is_the_historical_data():
    d = variants.data("hw03", "")
    assert (
        d["D"]["points"]
        == D_DEFAULT
        == [[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]]
    )
    assert d["q1"]["knots"] == [0, 1, 3]
    assert d["q3"]["knots"] == {"a": [0, 1, 2, 4], "b": [0, 3, 6, 9], "c": [0, 2, 3, 6]}
    assert d["q5"]["knots"] == [0, 2, 3] and d["q5"]["letter"] == "c"
    worked = HIDDEN.answers_for(d)  # the old constants, derived by hand
    assert np.allclose(worked["answer_q1"], [8 / 3, 3])  # (2/3)(2, 3) + (1/3)(4, 3)
    assert worked["answer_q4"] == "b"
    assert np.allclose(worked["answer_q5"], [[2, 0], [2, 0]])  # p3 = (10/3, 3)


def test_codes_are_validated_and_reproducible():
    with pytest.raises(ValueError, match="not a variant code"):
        variants.data("hw03", "ABC")
    code = CODES[0]
    assert variants.data("hw03", code.lower()) == variants.data("hw03", code)


# ------------------------------------------------------------------ 1,000 variants: well posed
_far = far


def _mistakes(d: dict) -> dict[str, list]:
    """Typical wrong answers of a variant, each derived from its data by hand."""
    D = np.array(d["D"]["points"])
    t0, t1, t2 = d["q1"]["knots"]
    p2, p4 = D[2], D[3]
    s0, s1, s2 = d["q5"]["knots"]
    p3 = ((s2 - s1) * p2 + (s1 - s0) * p4) / (s2 - s0)
    return {
        "q1": [  # the swapped ratio; the midpoint; the other end's weight
            ((t1 - t0) * p2 + (t2 - t1) * p4) / (t2 - t0),
            (p2 + p4) / 2,
            p2 + (t2 - t1) / (t2 - t0) * (p4 - p2),
        ],
        "q5": [  # in the local parameter (both sides, one side); from p3 at the midpoint
            [3 * (p3 - p2), 3 * (p4 - p3)],
            [3 * (p3 - p2), 3 * (p4 - p3) / (s2 - s1)],
            [3 * (p3 - p2) / (s1 - s0), 3 * (p4 - p3)],
            [3 * ((p2 + p4) / 2 - p2) / (s1 - s0), 3 * (p4 - (p2 + p4) / 2) / (s2 - s1)],
        ],
    }


def test_a_thousand_variants_are_well_posed_and_well_conditioned():
    datas = [variants.data("hw03", code) for code in CODES]
    for code, d in zip(CODES, datas, strict=True):
        where = f"variant {code}"
        D = np.array(d["D"]["points"])
        assert D.shape == (8, 2) and np.all(np.diff(D[:, 0]) >= 1), where  # no degenerate leg
        t0, t1, t2 = d["q1"]["knots"]
        assert t0 < t1 < t2 and abs((t1 - t0) - (t2 - t1)) >= 1, where  # joint off the midpoint
        knots = d["q3"]["knots"]
        assert sorted(knots) == list("abc") and len({tuple(k) for k in knots.values()}) == 3, where
        steps = {x: np.diff(k) for x, k in knots.items()}
        assert all(
            len(k) == 4 and np.all(s >= 1)
            for k, s in zip(knots.values(), steps.values(), strict=True)
        ), where
        uniform = [x for x, s in steps.items() if np.all(s == s[0])]
        assert len(uniform) == 1, where
        letter = d["q5"]["letter"]
        assert d["q5"]["knots"] == knots[letter][:3] and letter not in uniform, where
        s = steps[letter]
        assert s[0] != s[1] and s[0] != 1 and s[1] != 1, where  # local ≠ global, both sides
        worked = HIDDEN.answers_for(d)
        for name in ("answer_q1", "answer_q5"):
            assert np.all(np.isfinite(worked[name])), (where, name)
        assert worked["answer_q4"] == uniform[0], where
        # the joint points of q3 by hand: p_{3i} = (Δt_{i+1} p_{3i-1} + Δt_i p_{3i+1}) / (Δt_i + Δt_{i+1})
        for x, k in knots.items():
            P = np.array(worked["answer_q3"][x])
            a, b, c = np.diff(k)
            assert np.allclose(P[3], (b * D[2] + a * D[3]) / (a + b)), where
            assert np.allclose(P[6], (c * D[4] + b * D[5]) / (b + c)), where
        for q, wrong in _mistakes(d).items():
            for w in wrong:
                assert _far(w, worked[f"answer_{q}"]), (where, q, w)
    # the variants really vary
    assert (
        len({d["D"]["text"] for d in datas}) > 900 and len({d["q3"]["text"] for d in datas}) > 300
    )
    assert len({d["q1"]["text"] for d in datas}) > 300
    assert {HIDDEN.answers_for(d)["answer_q4"] for d in datas} == set("abc")
    assert {d["q5"]["letter"] for d in datas} == set("abc")


def test_the_check_accepts_the_worked_answers_of_a_thousand_variants():
    for code in CODES:
        d = variants.data("hw03", code)
        worked = HIDDEN.answers_for(d)
        worked["answer_q3"] = [np.array(worked["answer_q3"][x]) for x in "abc"]
        for q in DATA_QUESTIONS:
            v = check(f"hw03.{q}", worked[f"answer_{q}"])
            assert v.passed, (code, v)


# ------------------------------------------------------------------ check ✓ ⇔ full points on variants
@pytest.mark.parametrize("code", CODES[:40:4])
def test_check_and_grade_agree_on_other_variants(code):
    d = variants.data("hw03", code)
    worked = HIDDEN.answers_for(d)
    w1, w5, w4 = worked["answer_q1"], worked["answer_q5"], worked["answer_q4"]
    P = [np.array(worked["answer_q3"][x]) for x in "abc"]
    forms = {
        "q1": [np.array(w1), list(w1), tuple(w1)],
        "q3": [P, [p.tolist() for p in P], tuple(P)],
        "q4": [w4, w4.upper(), [w4], f"({w4})"],
        "q5": [np.array(w5), [list(r) for r in w5]],
    }
    wrong = _mistakes(d)
    wrong["q3"] = [
        P[::-1] if not np.allclose(P[0], P[2]) else [P[1], P[0], P[2]],
        [P[0], P[0], P[0]],
    ]
    wrong["q4"] = [x for x in "abc" if x != w4] + [",".join("abc")]
    for q in forms:
        name = f"answer_{q}"
        for value in forms[q]:
            assert check(f"hw03.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] == 1.0, (code, q, value)
        for value in wrong[q]:
            assert not check(f"hw03.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] < 1.0, (code, q, value)


def test_the_old_answers_are_wrong_on_most_variants():
    """The letters and numbers of the example data do not carry over (no shared answer key)."""
    old = HIDDEN.answers_for(variants.data("hw03", ""))
    worked = [HIDDEN.answers_for(variants.data("hw03", c)) for c in CODES[:200]]
    for name in ("answer_q1", "answer_q3", "answer_q4", "answer_q5"):
        same = sum(not differ(w[name], old[name]) for w in worked)
        assert same <= 200 * (0.4 if name == "answer_q4" else 0.1), (name, same)
