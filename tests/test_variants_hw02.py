"""Homework 2 with per-student variants (issue 19): every variant is well posed, and graded right.

* The default variant (empty code) is the data the notebook always had.
* Over 1,000 codes: the generated data is valid and well conditioned for every question
  (``β1 > 0`` away from 0 and ≠ 1, ``β2 ≠ 0``, ``q'`` and ``q''`` not parallel, ``β1² ≠ β2``,
  options a permutation, exactly one ``G1``-only joint), the Beta-constraints hold exactly, the
  hidden test's expected values are finite and far from the typical mistakes, and the feedback
  check marks them ✓.
* (The solution notebook graded on 50 variants, and on another student's data, is tested for
  every homework with variants in ``tests/test_variants_solutions.py``.)
* The check ✓ ⇔ full points equivalence holds on non-default variants, for accepted forms and
  for typical mistakes computed from each variant's data.
"""

from __future__ import annotations

import itertools

import matplotlib
import numpy as np
import pytest
import sympy as sp

matplotlib.use("Agg")

from _homework_support import VariantHomework, default_data_afterwards, far

from course_lib.homework import variants
from course_lib.homework.checks import check, questions, registry
from course_lib.homework.checks.hw02 import Q6_OPTIONS, Q7_SEGMENTS

C2 = "the two parametrizations meet with C² continuity there"


HOME = VariantHomework("hw02")
HIDDEN = HOME.hidden
CODES = HOME.codes
DATA_QUESTIONS = ("q1", "q2", "q5", "q6", "q7")


_default_afterwards = default_data_afterwards("hw02")  # checks elsewhere see the default data


def _grade(q: str, namespace: dict, data: dict) -> tuple[float, str]:
    return HOME.grade(q, namespace, data)


# ------------------------------------------------------------------ the default data
def test_the_default_variant_is_the_historical_data():
    d = variants.data("hw02", "")
    assert d["q1"]["q1"] == [2, -1] and d["q1"]["r1"] == [5, -2.5]
    assert d["q1"]["text"] == "q'(1) = (2, −1),  r'(0) = (5, −2.5)"
    assert (d["q2"]["q1"], d["q2"]["q2"], d["q2"]["r1"], d["q2"]["r2"]) == (
        [1, 2],
        [0, 2],
        [3, 6],
        [-4, 10],
    )
    assert (d["q5"]["q1"], d["q5"]["q2"], d["q5"]["beta1"], d["q5"]["beta2"]) == (
        [2, 0],
        [1, -3],
        0.5,
        2,
    )
    assert d["q6"]["options"] == dict(zip("abcd", Q6_OPTIONS, strict=True)) and Q6_OPTIONS[0] == C2
    assert d["q7"]["labels"] == "ABC"
    assert d["q7"]["segments"] == [[list(map(float, p)) for p in s] for s in Q7_SEGMENTS]
    worked = HIDDEN.answers_for(d)  # the old constants, derived by hand
    assert worked["answer_q1"] == 2.5  # (5, -2.5) = 2.5 (2, -1)
    assert worked["answer_q2"] == [3, -4]  # (-4, 10) - 9 (0, 2) = -4 (1, 2)
    assert worked["answer_q5"] == [4.25, -0.75]  # 0.25 (1, -3) + 2 (2, 0)
    assert worked["answer_q6"] == "a" and worked["answer_q7"] == "A"


def test_codes_are_validated_and_reproducible():
    with pytest.raises(ValueError, match="not a variant code"):
        variants.data("hw02", "ABC")
    code = CODES[0]
    assert variants.data("hw02", code.lower()) == variants.data("hw02", code)


# ------------------------------------------------------------------ 1,000 variants: well posed
def _det(a, b) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


_far = far


def _kinds(segments) -> list[str]:
    """The kind of each joint, from sampled derivatives (independent of the hidden closed form)."""
    segs = [np.asarray(s, float) for s in segments]
    out = []
    for P, Q in itertools.pairwise(segs):
        # cubic Bézier derivatives at the ends: c'(1) = 3 (P3 − P2), c''(1) = 6 (P3 − 2 P2 + P1), ...
        a1, a2 = 3 * (P[3] - P[2]), 6 * (P[3] - 2 * P[2] + P[1])
        b1, b2 = 3 * (Q[1] - Q[0]), 6 * (Q[2] - 2 * Q[1] + Q[0])
        g1 = np.allclose(a1 / np.linalg.norm(a1), b1 / np.linalg.norm(b1), atol=1e-12)
        ka, kb = _det(a1, a2) / np.linalg.norm(a1) ** 3, _det(b1, b2) / np.linalg.norm(b1) ** 3
        out.append("G2" if g1 and abs(ka - kb) < 1e-12 else "G1 only" if g1 else "not G1")
    return out


def _mistakes(d: dict) -> dict[str, list]:
    """Typical wrong answers of a variant, each derived from its data by hand."""
    q1, r1 = np.array(d["q1"]["q1"]), np.array(d["q1"]["r1"])
    b = float(np.linalg.norm(r1) / np.linalg.norm(q1))
    e = d["q2"]
    a1, a2, s2 = np.array(e["q1"]), np.array(e["q2"]), np.array(e["r2"])
    c1 = float(np.linalg.norm(e["r1"]) / np.linalg.norm(a1))
    c2 = float((s2 - c1**2 * a2) @ a1 / (a1 @ a1))
    # β1 not squared, β2 read off by projection or off either coordinate
    unsquared = [float((s2 - c1 * a2) @ a1 / (a1 @ a1)), *((s2 - c1 * a2) / a1).tolist()]
    f = d["q5"]
    f1, f2, e1, e2 = np.array(f["q1"]), np.array(f["q2"]), f["beta1"], f["beta2"]
    return {
        "q1": [1 / b, -b],  # upside down; a negative β1
        "q2": [
            [c1, -c2],
            *([c1, u] for u in unsquared),
            [c1, 0.0],
            [1 / c1, c2],
        ],  # sign; unsquared; no β2
        "q5": [
            e1 * f2 + e2 * f1,
            e1**2 * f1 + e2 * f2,
            e1**2 * f2,
            e2 * f1,
        ],  # unsquared; swapped; one term
    }


def test_a_thousand_variants_are_well_posed_and_well_conditioned():
    datas = [variants.data("hw02", code) for code in CODES]
    for code, d in zip(CODES, datas, strict=True):
        where = f"variant {code}"
        # q1: r'(0) = β1 q'(1) exactly, β1 > 0 away from 0 and from 1
        q1, r1 = np.array(d["q1"]["q1"]), np.array(d["q1"]["r1"])
        assert np.all(q1 != 0) and abs(_det(q1, r1)) == 0 and q1 @ r1 > 0, where
        b = (r1 @ q1) / (q1 @ q1)  # exact: small dyadic numbers
        assert b >= 0.5 and abs(b - 1) >= 0.25, where
        # q2: (7.1) and (7.2) hold exactly with β1 ≠ 1, β2 ≠ 0; q', q'' not parallel
        e = d["q2"]
        a1, a2, s1, s2 = (np.array(e[k]) for k in ("q1", "q2", "r1", "r2"))
        assert abs(_det(a1, a2)) >= 1 and a1 @ a2 != 0 and np.all(a1 * a2 != 0), where
        c1 = (s1 @ a1) / (a1 @ a1)  # exact: small dyadic numbers
        assert np.array_equal(s1, c1 * a1) and c1 >= 0.5 and abs(c1 - 1) >= 0.25, where
        c2 = (s2 - c1**2 * a2) @ a1 / (a1 @ a1)
        assert np.array_equal(s2, c1**2 * a2 + c2 * a1) and abs(c2) >= 0.5, where
        # q5: β1 ≠ 1, β2 ≠ 0, β1² ≠ β2, q', q'' not parallel
        f = d["q5"]
        f1, f2, e1, e2 = np.array(f["q1"]), np.array(f["q2"]), f["beta1"], f["beta2"]
        assert abs(_det(f1, f2)) >= 1 and e1 >= 0.5 and abs(e1 - 1) >= 0.25, where
        assert abs(e2) >= 0.5 and abs(e1**2 - e2) >= 0.25, where
        # q6: the four statements in some order; q7: the same curve, a permutation of the letters
        assert sorted(d["q6"]["options"].values()) == sorted(Q6_OPTIONS), where
        assert sorted(d["q7"]["labels"]) == list("ABC"), where
        assert _kinds(d["q7"]["segments"]) == ["G1 only", "G2", "not G1"], where
        # expected values: finite, right, far from the typical mistakes
        worked = HIDDEN.answers_for(d)
        for name in ("answer_q1", "answer_q2", "answer_q5"):
            assert np.all(np.isfinite(worked[name])), (where, name)
        assert np.isclose(worked["answer_q1"], b) and np.allclose(worked["answer_q2"], [c1, c2]), (
            where
        )
        assert np.allclose(worked["answer_q5"], e1**2 * f2 + e2 * f1), where
        assert d["q6"]["options"][worked["answer_q6"]] == C2, where
        assert worked["answer_q7"] == d["q7"]["labels"][0], where
        for q, wrong in _mistakes(d).items():
            for w in wrong:
                assert _far(w, worked[f"answer_{q}"]), (where, q, w)
    # the variants really vary
    for q in ("q1", "q2", "q5"):
        assert len({d[q]["text"] for d in datas}) > 300, q
    assert (
        len({d["q6"]["text"] for d in datas}) == 24 and len({d["q7"]["labels"] for d in datas}) == 6
    )
    assert {HIDDEN.answers_for(d)["answer_q6"] for d in datas} == set("abcd")
    assert {HIDDEN.answers_for(d)["answer_q7"] for d in datas} == set("ABC")


def test_the_check_accepts_the_worked_answers_of_a_thousand_variants():
    for code in CODES:
        d = variants.data("hw02", code)
        worked = HIDDEN.answers_for(d)
        for qid in questions("hw02"):
            name = registry()[qid].answer_name
            if qid.split(".")[1] not in DATA_QUESTIONS:
                continue
            v = check(qid, worked[name])
            assert v.passed, (code, v)


# ------------------------------------------------------------------ check ✓ ⇔ full points on variants
@pytest.mark.parametrize("code", CODES[:40:4])
def test_check_and_grade_agree_on_other_variants(code):
    d = variants.data("hw02", code)
    worked = HIDDEN.answers_for(d)
    w1, w2, w5 = worked["answer_q1"], worked["answer_q2"], worked["answer_q5"]
    forms = {
        "q1": [w1, np.array([w1]), sp.nsimplify(w1)],
        "q2": [np.array(w2), list(w2), tuple(w2)],
        "q5": [np.array(w5), list(w5), sp.Matrix(w5)],
        "q6": [worked["answer_q6"], worked["answer_q6"].upper(), [worked["answer_q6"]]],
        "q7": [worked["answer_q7"], worked["answer_q7"].lower(), f"({worked['answer_q7']})"],
    }
    wrong = _mistakes(d)
    wrong["q6"] = [x for x in "abcd" if x != worked["answer_q6"]]
    wrong["q7"] = [x for x in "ABC" if x != worked["answer_q7"]]
    for q in forms:
        name = f"answer_{q}"
        for value in forms[q]:
            assert check(f"hw02.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] == 1.0, (code, q, value)
        for value in wrong[q]:
            assert not check(f"hw02.{q}", value).passed, (code, q, value)
            assert _grade(q, {name: value}, d)[0] < 1.0, (code, q, value)


def test_the_old_answers_are_wrong_on_most_variants():
    """The letters and numbers of the example data do not carry over (no shared answer key)."""
    old = HIDDEN.answers_for(variants.data("hw02", ""))
    worked = [HIDDEN.answers_for(variants.data("hw02", c)) for c in CODES[:200]]
    for name in ("answer_q1", "answer_q2", "answer_q5", "answer_q6", "answer_q7"):
        same = sum(w[name] == old[name] for w in worked)
        assert same <= 200 * (0.4 if name in ("answer_q6", "answer_q7") else 0.1), (name, same)
