"""Feedback checks of homework 5: Are letters smooth? (lecture 06; seed 000 §10.1-10.2).

The question data -- the lower-case b of DejaVu Sans and the points stated in
``exercises/hw05_are_letters_smooth.ipynb`` -- is repeated here; the solution notebook,
executed by the test suite, passes every check.  The checks compare with values computed at
check time (the joint classification of :mod:`course_lib.outlines`, the quadratic end
derivatives of seed 000 eq. (8), the cubic Beta-spline of §10.2) or test the defining
properties, read answers with the grader's readers and never print an expected value.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from .. import answers
from ._core import as_vector, call_answer, close, cross2, fail, ok, register, register_choice

DATA = {
    "glyph": ("b", "DejaVuSans"),
    # q3: P0, A, B, P2 of the outer contour of the b, font units; the question asks in em
    "q3": np.array([[371.0, 950.0], [429.0, 1050.0], [606.0, 1147.0], [729.0, 1147.0]]),
    "em": 2048.0,
}


@cache
def _glyph():
    from ..outlines import classify_joints, glyph_outline

    char, font = DATA["glyph"]
    outline = glyph_outline(char, font)
    return outline, classify_joints(outline)


def _counts(kind: np.ndarray) -> np.ndarray:
    return np.array([np.count_nonzero(kind == k) for k in ("corner", "G1", "G2")], dtype=float)


def _read_counts(answer, name: str) -> np.ndarray:
    return as_vector(answer, (3,), name, "three counts [corners, G1 not G2, G2]")


@register("hw05.q1", "answer_q1", "the joints of DejaVu Sans 'b': corners, G1, G2")
def _q1(answer):
    got = _read_counts(answer, "answer_q1")
    outline, table = _glyph()
    right = _counts(table.kind)
    if close(got, right):
        return ok("correct: every joint of both contours, closing joints included.")
    per_contour = [_counts(table.kind[table.contour == c]) for c in range(len(outline.contours))]
    if any(close(got, c) for c in per_contour):
        return fail(
            "these are the counts of one contour only: the b has two (the bowl's counter too)."
        )
    if close(got, [right[0], right[1] + right[2], 0]):
        return fail(
            "not every smooth point is only G1: look at the relative curvature jump (rel_jump)."
        )
    if close(np.sort(got), np.sort(right)):
        return fail("the right numbers in the wrong order: [corners, G1 not G2, G2].")
    if got.sum() != len(table):
        return fail(
            "the three counts must add up to the number of joints of the glyph "
            "(every joint of both contours, the closing joints included)."
        )
    return fail("not the counts of classify_joints with its default tolerances (2°, 1e-8).")


# (P0, A, B, P2), G2?: the b in font units and in em, rotated (never exactly parallel in
# floats), a tiny copy (an absolute tolerance fails), an antiparallel chord (still parallel).
_ROT = np.array([[np.cos(0.5), -np.sin(0.5)], [np.sin(0.5), np.cos(0.5)]])
_B_G1 = np.array([[371.0, 950.0], [429.0, 1050.0], [606.0, 1147.0], [729.0, 1147.0]])
_B_G2 = np.array([[913.5, 877.5], [830.0, 993.0], [538.0, 993.0], [454.5, 877.5]])
_Q2_CASES = [
    (_B_G1, False),
    (_B_G2, True),
    (_B_G2 / 2048, True),
    (_B_G2 @ _ROT.T, True),
    (_B_G1 * 1e-7, False),
    (np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.0], [-1.0, 0.0]]), True),
]


@register("hw05.q2", "implied_is_g2", "implied_is_g2(P0, A, B, P2): G2 at an implied point?")
def _q2(func):
    for pts, right in _Q2_CASES:
        res = call_answer(func, *(p.copy() for p in pts), name="implied_is_g2")
        got = answers.boolean(
            answers.plain(res, "implied_is_g2's result"), "implied_is_g2's result"
        )
        if got == right:
            continue
        leg, chord = pts[2] - pts[1], pts[3] - pts[0]
        if right and np.dot(leg, chord) < 0:
            return fail(
                "wrong for a chord P0P2 that points against AB: parallel in the opposite direction "
                "still makes the cross product vanish, so the joint is G2."
            )
        if right and cross2(leg, chord) != 0:
            return fail(
                "wrong for a G2 joint whose cross product is a rounding error, not exactly 0: "
                "compare |(B − A) × (P2 − P0)| with 1e-9 |B − A| |P2 − P0|."
            )
        if not right and np.abs(pts).max() < 1e-3:
            return fail(
                "wrong for a tiny copy of a G1 joint: an absolute tolerance calls every small "
                "glyph G2; make the test relative to |B − A| |P2 − P0|."
            )
        return fail(
            "wrong: G2 exactly when the chord P2 − P0 is parallel to the off-curve leg B − A."
        )
    return ok(f"correct on {len(_Q2_CASES)} cases (font units, em, rotated, tiny, antiparallel).")


def _quad_end_curvatures(P0, A, B, P2) -> np.ndarray:
    """Signed curvature at M = (A + B)/2 at the end of P0, A, M and the start of M, B, P2."""
    M = (A + B) / 2

    def kappa(d1, d2):
        return cross2(d1, d2) / np.linalg.norm(d1) ** 3

    return np.array(
        [kappa(2 * (M - A), 2 * (P0 - 2 * A + M)), kappa(2 * (B - M), 2 * (M - 2 * B + P2))]
    )


@register(
    "hw05.q3", "answer_q3", "the signed curvatures on both sides of an implied point of the b"
)
def _q3(answer):
    got = as_vector(answer, (2,), "answer_q3", "two numbers [kappa_in, kappa_out]")
    right = _quad_end_curvatures(*(DATA["q3"] / DATA["em"]))
    if close(got, right):
        return ok("correct: the curvature jumps at the implied point, so it is G1 but not G2.")
    if close(got, right[::-1]):
        return fail("swapped: kappa_in belongs to the segment that ends at M, P0, A, M.")
    if close(got, right / DATA["em"]):
        return fail(
            "in font units: curvature is 1/length, so divide the coordinates by 2048 first."
        )
    if close(got, -right) or close(got, np.abs(right)):
        return fail(
            "the sign: the signed curvature is (x′ × x″)/|x′|³, negative where the contour turns clockwise."
        )
    if close(got[0], got[1]):
        return fail(
            "both sides are equal in your answer, but the curvature jumps at this implied point."
        )
    return fail(
        "not the signed curvatures: use the end derivatives of a quadratic Bézier curve, "
        "x′(1) = 2 (M − A), x″(1) = 2 (P0 − 2A + M), and x′(0) = 2 (B − M), x″(0) = 2 (M − 2B + P2)."
    )


register_choice(
    "hw05.q4",
    "answer_q4",
    "595ce0fb35d57a12",
    "why the G2 points of the b are G2",
    options="abcd",
    single=True,
)


def _bspline_polygons(V: np.ndarray) -> np.ndarray:
    from ..beta_splines import cubic_beta_spline

    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    return np.array(cubic_beta_spline(E, 1.0, 0.0).segments)


def _bowl() -> np.ndarray:
    outline, _ = _glyph()
    P, on = outline.points[1]
    between_off = on[1:12] & ~on[:11] & ~on[2:13]
    return P[:13][~np.concatenate([[False], between_off, [False]])]


def _run_problem(V: np.ndarray, W: np.ndarray) -> str | None:
    """What is wrong with the cubic Bézier polygons W for the run polygon V, or None."""
    if not (close(W[0, 0], V[0]) and close(W[-1, -1], V[-1])):
        return "the run must start at the corner V0 and end at the corner Vn (the corners stay)."
    t0, t1 = W[0, 1] - W[0, 0], W[-1, -1] - W[-1, -2]
    for t, leg in ((t0, V[1] - V[0]), (t1, V[-1] - V[-2])):
        if (
            abs(cross2(t, leg)) > 1e-9 * np.linalg.norm(t) * np.linalg.norm(leg)
            or np.dot(t, leg) <= 0
        ):
            return "the tangent at a corner changed: it must point along V1 − V0 at the start and Vn − Vn−1 at the end."
    for k in range(len(W) - 1):
        q, r = W[k], W[k + 1]
        q1, q2 = 3 * (q[3] - q[2]), 6 * (q[3] - 2 * q[2] + q[1])
        r1, r2 = 3 * (r[1] - r[0]), 6 * (r[2] - 2 * r[1] + r[0])
        if not (close(q[3], r[0]) and close(q1, r1) and close(q2, r2)):
            return (
                f"segments {k} and {k + 1} do not meet with C2 (position, velocity, acceleration)."
            )
    return None


_Q5_CASES = [
    np.array([[0.0, 0.0], [3.0, 1.0]]),  # n = 1: a straight run
    np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 0.0]]),  # n = 2: one quadratic between two corners
]


@register("hw05.q5", "g2_run", "g2_run(V): a G2 run between two corners (phantom end vertices)")
def _q5(func):
    for V in [_bowl(), *_Q5_CASES]:
        n = V.shape[0] - 1
        res = call_answer(func, V.copy(), name="g2_run")
        try:
            shape = np.shape(answers.plain(res, "g2_run's result"))
        except ValueError:  # ragged: as_vector below names the problem
            shape = ()
        if n > 2 and shape == (n - 2, 4, 2):
            return fail(f"n = {n}: n − 2 segments; the phantom vertices V−1 and Vn+1 are missing.")
        W = as_vector(
            res, (n, 4, 2), f"the result for n = {n}", "an array of n cubic Bézier polygons"
        )
        why = _run_problem(V, W)
        if why:
            return fail(f"n = {n}: {why}")
        if not close(W, _bspline_polygons(V)):
            return fail(
                f"n = {n}: corners, end tangents and C2 joints are right, but this is not the uniform cubic "
                "B-spline on V−1, V0, ..., Vn+1 (the cubic Beta-spline with β1 = 1, β2 = 0)."
            )
    return ok("correct: the bowl of the b, a straight run and a single quadratic run.")


@register("hw05.q6", "answer_q6", "the b with a G2 bowl: corners, G1, G2")
def _q6(answer):
    got = _read_counts(answer, "answer_q6")
    _, table = _glyph()
    inner = _counts(table.kind[table.contour == 0])
    n = len(_bowl()) - 1
    corners = np.count_nonzero(table.kind == "corner")
    right = inner + np.array([corners, 0, n - 1])
    if close(got, right):
        return ok("correct: the same corners, the counter unchanged, every joint of the bowl G2.")
    if close(got, _counts(table.kind)):
        return fail(
            "these are the counts of the original b: replace the bowl by g2_run(V_bowl) first."
        )
    if close(got, right - inner):
        return fail(
            "these are the counts of the outer contour only: the counter belongs to the glyph too."
        )
    if got[0] != corners:
        return fail(
            "the corners must stay the same: the run keeps the corner points and their tangents."
        )
    return fail("not the counts of the new glyph: classify its joints as in question 1.")
