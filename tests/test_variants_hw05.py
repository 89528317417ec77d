"""Homework 5 with per-student variants (issue 19): every variant is well posed, and graded right.

There are only 16 glyphs (b, d, p, q of four DejaVu Sans fonts) and a few implied points per
glyph, so instead of sampling random data this proves every glyph and every q3 point a variant
can draw well posed, exhaustively:

* each glyph (read independently with fontTools' raw ``glyf`` points and its pen, the hidden
  tests' reading, against course_lib's): two contours, a counter without corners and an outer
  contour of one bowl between two corners and straight lines round the stem; every joint clearly
  a corner, clearly G2 or clearly G1 (far from the tolerances 2° and 1e-8), so the counts of q1
  and q6 have one answer, the same from the pen and from ``classify_joints``; q4's reason
  "parallel" true at every G2 point and the three others false; the stored indices of the bowl
  and the stem (q6's data) right; the bowl made G2 keeps the corners and is G2 far below the
  tolerance;
* each q3 point: curvatures finite, negative, |κ| > 1 em⁻¹, the sides differing by > 1e-3
  relative, and the typical mistakes (font units, swapped, sign, unsigned, equal sides) far from
  the answer; course_lib's ``classify_joints`` gives the same two curvatures at that joint;
* over 1,000 codes: valid data, every glyph, every q3 point and every right letter used, the
  default's point never drawn again, the check ✓ on the worked answers;
* check ✓ ⇔ full points on variants of every glyph, for accepted forms and typical mistakes;
  the example's answers lose points on every other variant.
* (The solution notebook graded on 50 variants, and on another student's data, is tested with
  the other homeworks with variants in ``tests/test_variants_solutions.py``; through the real
  grader in ``tests/test_grading_variants.py``.)
"""

from __future__ import annotations

import matplotlib
import numpy as np
import pytest

matplotlib.use("Agg")

from _homework_support import VariantHomework, default_data_afterwards, far

from course_lib import PiecewiseBezier
from course_lib.constructions.beta_splines import cubic_beta_spline
from course_lib.constructions.outlines import Contour, Outline, classify_joints, glyph_outline
from course_lib.homework import variants
from course_lib.homework.checks import check
from course_lib.homework.checks import hw05 as gen

HOME = VariantHomework("hw05")
HIDDEN = HOME.hidden
CODES = HOME.codes
DATA_QUESTIONS = ("q1", "q3", "q4", "q6")
DEFAULT_Q3 = [[371.0, 950.0], [429.0, 1050.0], [606.0, 1147.0], [729.0, 1147.0]]


_default_afterwards = default_data_afterwards("hw05")  # checks elsewhere see the default data


def _data_for(glyph, q3: int, order=None) -> dict:
    """The data of a variant with this glyph, q3 point and option order (made by the generator)."""
    p = {"glyph": glyph, "q3": q3, "order": list(order or gen.REASONS)}
    original = gen._params
    gen._params = lambda rng: p
    try:
        return variants.data("hw05", CODES[0])  # any code: _params is replaced
    finally:
        gen._params = original


_far = far


def _cross(u, w) -> float:
    return float(u[0] * w[1] - u[1] * w[0])


# ------------------------------------------------------------------ the default data
def test_the_default_variant_is_the_historical_data():
    d = variants.data("hw05", "")
    assert (d["glyph"]["char"], d["glyph"]["font"], d["glyph"]["file"]) == (
        "b",
        "DejaVuSans",
        "DejaVuSans.ttf",
    )
    assert d["q3"]["points"] == DEFAULT_Q3 and d["q3"]["em"] == 2048.0
    assert d["q4"]["order"] == ["explicit", "parallel", "angle", "zero"]
    assert d["q4"]["options"]["b"].startswith("at each of them the chord P0P2")
    assert d["q6"]["outer"] == 1 and d["q6"]["counter"] == 0
    assert d["q6"]["bowl"] == list(range(13)) and d["q6"]["stem"] == [12, 13, 14, 15, 16, 0]
    worked = HIDDEN.answers_for(d)  # the old constants (tests/test_answer_equivalence.py), by hand
    assert worked["answer_q1"] == [6, 10, 5]
    # v = B - A = (177, 97), |v|² = 40738; v x q''(1) = -24148, v x r''(0) = -23862 (font units)
    assert np.allclose(worked["answer_q3"], np.array([-24148.0, -23862.0]) * 2048 / 40738**1.5)
    assert worked["answer_q4"] == "b"
    assert worked["answer_q6"] == [6, 4, 12]
    assert HIDDEN.POINTS["q4"] == 0  # multiple choice is feedback only


def test_codes_are_validated_and_reproducible():
    with pytest.raises(ValueError, match="not a variant code"):
        variants.data("hw05", "ABC")
    code = CODES[0]
    assert variants.data("hw05", code.lower()) == variants.data("hw05", code)


# ------------------------------------------------------------------ every glyph, exhaustively
def _raw_points(char: str, font: str):
    """Stored points and on-curve flags of each contour, straight from fontTools' glyf table."""
    from fontTools.ttLib import TTFont

    tt = TTFont(f"{matplotlib.get_data_path()}/fonts/ttf/{font}.ttf")
    glyf = tt["glyf"]
    coords, ends, flags = glyf[tt.getBestCmap()[ord(char)]].getCoordinates(glyf)
    P = np.array(coords.array, float).reshape(-1, 2)
    on = (np.frombuffer(bytes(flags), np.uint8) & 1).astype(bool)
    starts = [0, *(e + 1 for e in ends[:-1])]
    return [(P[s : e + 1], on[s : e + 1]) for s, e in zip(starts, ends, strict=True)]


def _g2_glyph(glyph, d):
    """The solution of q6: the bowl replaced by the B-spline run, the stem and counter kept."""
    P, on = glyph.points[d["q6"]["outer"]]
    bowl, stem = d["q6"]["bowl"], d["q6"]["stem"]
    Pb, ob = P[bowl], on[bowl]
    V = Pb[np.concatenate([[True], ~(ob[1:-1] & ~ob[:-2] & ~ob[2:]), [True]])]
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    runs = list(cubic_beta_spline(E, 1.0, 0.0).segments)
    lines = [P[[stem[k], stem[k + 1]]] for k in range(len(stem) - 1)]
    outer = PiecewiseBezier(runs + lines)
    counter = glyph.contours[d["q6"]["counter"]]
    return Outline((counter, Contour(outer, True, np.zeros(outer.n_segments, bool))), "g2"), len(
        V
    ) - 1


@pytest.mark.parametrize("glyph", gen.GLYPHS, ids=[f"{c}-{f}" for c, f in gen.GLYPHS])
def test_every_glyph_is_well_posed(glyph):
    char, font = glyph
    facts = gen.glyph_facts(char, font)
    d = _data_for(glyph, facts["q3"][0])
    raw = _raw_points(char, font)
    contours, joints = HIDDEN._pen_joints(char, f"{font}.ttf")  # fontTools' pen, by hand
    assert len(raw) == len(contours) == 2
    # every joint far from the tolerances: a corner turns by > 60°, a smooth point by < 1e-6°;
    # a smooth point's relative curvature jump is 0 (G2) or > 1e-4 (G1), far from 1e-8
    for _, turn, jump in joints:
        assert turn > 60 or turn < 1e-6, (glyph, turn)
        assert turn > 60 or jump < 1e-12 or jump > 1e-4, (glyph, jump)
    # the pen and course_lib agree on q1
    outline = glyph_outline(char, font)
    table = classify_joints(outline)
    ours = [int(np.count_nonzero(table.kind == k)) for k in ("corner", "G1", "G2")]
    assert HIDDEN.answers_for(d)["answer_q1"] == ours and len(table) == len(joints), glyph
    # the counter has no corner; the outer contour's stored points: the bowl from corner to
    # corner (off-curve points in it, every inner on-curve point between two off-curve ones),
    # then the stem of on-curve points only back to the first corner, each point once
    P, on = raw[d["q6"]["outer"]]
    assert np.array_equal(P, outline.points[d["q6"]["outer"]][0] * 2048)  # data = the font's points
    assert not np.any(table.kind[table.contour == d["q6"]["counter"]] == "corner")
    bowl, stem = d["q6"]["bowl"], d["q6"]["stem"]
    n = len(P)
    assert bowl[-1] == stem[0] and stem[-1] == bowl[0]
    cycle = bowl + stem[1:-1]  # round the contour once, in drawing order
    assert len(cycle) == n and all((cycle[k + 1] - cycle[k]) % n == 1 for k in range(n - 1))
    assert on[stem].all() and not on[bowl].all()
    inner = bowl[1:-1]
    assert all(not on[i] or (not on[(i - 1) % n] and not on[(i + 1) % n]) for i in inner), glyph
    corners = table.point[table.kind == "corner"] * 2048
    ends = {tuple(P[bowl[0]]), tuple(P[bowl[-1]])}
    assert ends <= {tuple(c) for c in corners} and len(corners) == len(stem) == 6
    # q4: "parallel" holds at every G2 point, the other reasons are false
    g2 = table.kind == "G2"
    assert g2.any(), glyph
    for c, M in zip(table.contour[g2], table.point[g2] * 2048, strict=True):
        Q, onq = raw[c]
        m = len(Q)
        (i,) = np.flatnonzero(np.all(Q == M, axis=1))  # an explicit stored on-curve point
        A, B = Q[(i - 1) % m], Q[(i + 1) % m]
        assert onq[i] and not onq[(i - 1) % m] and not onq[(i + 1) % m]
        assert np.array_equal((A + B) / 2, M)  # the midpoint of its off-curve neighbours
        P0 = Q[(i - 2) % m] if onq[(i - 2) % m] else (Q[(i - 2) % m] + A) / 2
        P2 = Q[(i + 2) % m] if onq[(i + 2) % m] else (Q[(i + 2) % m] + B) / 2
        assert _cross(B - A, P2 - P0) == 0  # the chord parallel to the leg, exactly
        level = (A[1] == B[1] and P0[1] == P2[1]) or (A[0] == B[0] and P0[0] == P2[0])
        assert level, (glyph, M)  # both horizontal or both vertical, as option "parallel" says
    smooth = table.kind != "corner"
    assert np.any((table.kind == "G1") & ~table.implied)  # (a) false: explicit G1 points
    assert np.all(table.angle[smooth] < 2)  # (c) false: G1 points turn by < 2° too
    assert np.all(np.abs(table.kappa_in[g2]) > 1)  # (d) false: |κ| > 1 em⁻¹ at the G2 points
    # q6: the bowl made G2 keeps the corners (points, angles) and is G2 far below 1e-8
    new, n_run = _g2_glyph(outline, d)
    t = classify_joints(new)
    assert np.allclose(
        np.sort(t.angle[t.kind == "corner"]), np.sort(table.angle[table.kind == "corner"])
    )
    assert np.allclose(
        np.sort(t.point[t.kind == "corner"], axis=0),
        np.sort(table.point[table.kind == "corner"], axis=0),
    )
    assert np.all(t.rel_jump[t.kind == "G2"] < 1e-12) and np.all(t.angle[t.kind != "corner"] < 1e-6)
    counts = [int(np.count_nonzero(t.kind == k)) for k in ("corner", "G1", "G2")]
    assert HIDDEN.answers_for(d)["answer_q6"] == counts, glyph
    assert (
        counts[2] - int(np.count_nonzero(table.kind[table.contour == d["q6"]["counter"]] == "G2"))
        == n_run - 1
    )


def _q3_cases():
    return [
        pytest.param(g, i, id=f"{g[0]}-{g[1]}-{i}")
        for g in gen.GLYPHS
        for i in gen.glyph_facts(*g)["q3"]
    ]


def _mistakes_q3(d: dict, right) -> list:
    """Typical wrong answers of q3, from the data by hand."""
    right = np.asarray(right)
    return [
        right / d["q3"]["em"],
        right[::-1],
        -right,
        np.abs(right),
        np.array([right[0], right[0]]),
    ]


@pytest.mark.parametrize(("glyph", "index"), _q3_cases())
def test_every_q3_point_is_well_posed(glyph, index):
    d = _data_for(glyph, index)
    char, font = glyph
    P, on = _raw_points(char, font)[d["q6"]["outer"]]
    n = len(P)
    # the data are the glyph's stored points P0 (on), A, B (off), P2 (on), consecutive
    k = [(index - 1) % n, index, (index + 1) % n, (index + 2) % n]
    assert np.array_equal(np.array(d["q3"]["points"]), P[k]) and on[k].tolist() == [
        True,
        False,
        False,
        True,
    ]
    right = np.array(HIDDEN.answers_for(d)["answer_q3"])
    assert np.all(np.isfinite(right)) and np.all(right < -1.0)
    assert abs(right[0] - right[1]) > 1e-3 * np.abs(right).max()
    for wrong in _mistakes_q3(d, right):
        assert _far(wrong, right), (glyph, index, wrong)
    # course_lib's classification gives the same curvatures at that implied joint (in em)
    table = classify_joints(glyph_outline(char, font))
    M = (P[index] + P[(index + 1) % n]) / 2 / d["q3"]["em"]
    (j,) = np.flatnonzero(np.all(table.point == M, axis=1))
    assert table.implied[j] and np.allclose(
        [table.kappa_in[j], table.kappa_out[j]], right, rtol=1e-12
    )
    # the check and the grade agree on the answer and on each mistake
    assert check("hw05.q3", right).passed and HOME.grade("q3", {"answer_q3": right}, d)[0] == 1.0
    for wrong in _mistakes_q3(d, right):
        assert not check("hw05.q3", wrong).passed, (glyph, index, wrong)
        assert HOME.grade("q3", {"answer_q3": wrong}, d)[0] < 1.0


# ------------------------------------------------------------------ 1,000 codes: valid data
def test_a_thousand_codes_map_to_valid_data_and_use_every_glyph():
    default_points = variants.data("hw05", "")["q3"]["points"]
    used_glyphs, used_points, letters, datas = set(), set(), set(), []
    for code in CODES:
        d = variants.data("hw05", code)  # the checks read the variant chosen last
        datas.append(d)
        glyph = (d["glyph"]["char"], d["glyph"]["font"])
        assert glyph in gen.GLYPHS, code
        facts = gen.glyph_facts(*glyph)
        assert d["q3"]["index"] in facts["q3"] and d["q3"]["points"] != default_points, code
        assert sorted(d["q4"]["order"]) == sorted(gen.REASONS), code
        assert d["q4"]["options"] == {
            x: gen.REASONS[k] for x, k in zip("abcd", d["q4"]["order"], strict=True)
        }
        assert (d["q6"]["bowl"], d["q6"]["stem"], d["q6"]["outer"]) == (
            facts["bowl"],
            facts["stem"],
            facts["outer"],
        )
        worked = HIDDEN.answers_for(d)
        assert d["q4"]["options"][worked["answer_q4"]] == gen.REASONS["parallel"], code
        for q in DATA_QUESTIONS:
            v = check(f"hw05.{q}", worked[f"answer_{q}"])
            assert v.passed, (code, q, v)
        used_glyphs.add(glyph)
        used_points.add((glyph, d["q3"]["index"]))
        letters.add(worked["answer_q4"])
    assert used_glyphs == set(gen.GLYPHS)
    # every candidate but the example's point (in the b and in the p: their bowls are the same)
    candidates = {
        (g, i)
        for g in gen.GLYPHS
        for i in gen.glyph_facts(*g)["q3"]
        if _data_for(g, i)["q3"]["points"] != default_points
    }
    assert used_points == candidates and len(candidates) == 57  # of 59 (q3 cases above)
    assert letters == set("abcd")
    # the answers vary: every q1 count profile of the four fonts, many q3 answers
    worked = [HIDDEN.answers_for(d) for d in datas[:300]]
    assert len({tuple(w["answer_q1"]) for w in worked}) == 5
    assert len({tuple(np.round(w["answer_q3"], 9)) for w in worked}) >= 30
    assert {tuple(w["answer_q6"]) for w in worked} == {(6, 4, 12), (6, 6, 10), (6, 7, 9)}


# ------------------------------------------------------------------ check ✓ ⇔ full points on variants
def _codes_per_glyph(k: int = 2) -> list[str]:
    out, seen = [], {}
    for code in CODES:
        g = variants.generators()["hw05"](variants.rng_for("hw05", code))["glyph"]
        key = (g["char"], g["font"])
        if seen.get(key, 0) < k:
            seen[key] = seen.get(key, 0) + 1
            out.append(code)
    return out


@pytest.mark.parametrize("code", _codes_per_glyph())
def test_check_and_grade_agree_on_other_variants(code):
    d = variants.data("hw05", code)
    worked = HIDDEN.answers_for(d)
    w1, w3, w4, w6 = (worked[f"answer_{q}"] for q in DATA_QUESTIONS)
    forms = {
        "q1": [np.array(w1), list(w1), tuple(w1)],
        "q3": [np.array(w3), list(w3), tuple(w3)],
        "q4": [w4, w4.upper(), [w4], f"({w4})"],
        "q6": [np.array(w6), list(w6), tuple(w6)],
    }
    c, g1, g2 = w1
    wrong = {
        "q1": [[c, g1 + g2, 0], [g2, g1, c], [c - 1, g1, g2 + 1]],
        "q3": _mistakes_q3(d, w3),
        "q4": [x for x in "abcd" if x != w4],
        "q6": [w1, [w6[0] - 2, w6[1], w6[2]], [w6[0], w6[1] + 1, w6[2] - 1]],
    }
    for q in forms:
        name = f"answer_{q}"
        for value in forms[q]:
            assert check(f"hw05.{q}", value).passed, (code, q, value)
            assert HOME.grade(q, {name: value}, d)[0] == 1.0, (code, q, value)
        for value in wrong[q]:
            assert _far(value, forms[q][0]) if q != "q4" else True
            assert not check(f"hw05.{q}", value).passed, (code, q, value)
            assert HOME.grade(q, {name: value}, d)[0] < 1.0, (code, q, value)


def test_the_examples_answers_lose_points_on_every_other_variant():
    """The example's numbers do not carry over: q3 never, q1 not with another font."""
    old = HIDDEN.answers_for(variants.data("hw05", ""))
    for code in CODES[:200]:
        d = variants.data("hw05", code)
        ns = {f"answer_{q}": old[f"answer_{q}"] for q in DATA_QUESTIONS}
        lost = {q for q in ("q1", "q3", "q6") if HOME.grade(q, ns, d)[0] < 1.0}
        assert "q3" in lost, code
        if d["glyph"]["font"] != "DejaVuSans":
            assert "q1" in lost, code
        if d["glyph"]["font"] in ("DejaVuSans-Bold", "DejaVuSansMono"):
            assert "q6" in lost, code
