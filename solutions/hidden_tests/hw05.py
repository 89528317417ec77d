"""Hidden tests of homework 5: Are letters smooth? (run by tools/grade.py in the grader; never shipped).

Form: ``solutions/hidden_tests/README.md``.  Expected values come from first principles, never
from course_lib's mathematics or the solution notebook:

* the joint counts of the student's glyph: the glyph drawn by fontTools' own pen
  (``RecordingPen`` on the font's glyph set, quadratic runs split by fontTools'
  ``decomposeQuadraticSegment``) and every joint classified here with hand formulas (end
  derivatives of line and quadratic pieces);
* G2 at an implied point: exact rational arithmetic on the cross product
  ``(B - A) x (P2 - P0)`` of the data before it was rotated or scaled;
* the runs: B-spline to Bézier conversion written out by hand, on another glyph (DejaVu Sans
  'D', DejaVu Serif 'o') than the feedback check.

Per-student variants (issue 19): ``VARIANTS = True``, so the grader calls ``qN(student, data)``
with the student's own data (``course_lib.homework.variants.data("hw05", code)``: a b, d, p or q of one of
four DejaVu Sans fonts, an implied point of its bowl, q4's options in the student's order).
The data names the glyph (character, font file), the points of q3 and the order of q4's
reasons; every expected value is computed here from the font file and those points.  The
function questions q2 and q5 are the same for everyone.  Multiple choice is feedback only
(course policy: a student can find the letter by trying each in ``check()``): q4 is graded but
worth 0 points; so are q1, q3 and q6, which ``classify_joints`` answers in a line (the
README's list of questions open to a one-liner).  :func:`answers_for` gives the worked answers of a variant
(``tools/variant.py show``).
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

import numpy as np

from course_lib.homework import answers

HOMEWORK = "hw05"
#: q1, q3 and q6 are read off classify_joints, the tool this homework teaches: a library call
#: answers them, so they are practice like multiple choice, worth 0 points (issue 24).
POINTS = {"q1": 0, "q2": 3, "q3": 0, "q4": 0, "q5": 4, "q6": 0}

VARIANTS = True

#: The tolerances stated in the notebook (the defaults of classify_joints); the glyph, the
#: points of q3 and the order of q4's options are the student's data.
DATA = {"corner_deg": 2.0, "g2_rtol": 1e-8}

#: implied_is_g2 cases: base points (exact), then the transform the student's copy gets.
#: The base decides the answer: rotating and scaling keep (non-)parallel chords.
Q2_CASES = [
    # DejaVu Serif 'o', counter, lower right implied point: a G1 joint in font units
    ([(616, 70), (764, 70), (915, 304), (915, 532)], 0.0, 1.0, "a point in font units"),
    # DejaVu Serif 'o', top of the outer ring (616, 1092) as a midpoint joint: symmetric, G2
    ([(242.5, 939), (383, 1092), (849, 1092), (989.5, 939)], 0.0, 1.0, "a point in font units"),
    (
        [(242.5, 939), (383, 1092), (849, 1092), (989.5, 939)],
        math.pi / 4,
        1 / 2048,
        "a rotated glyph in em units",
    ),
    # DejaVu Serif 'D', G1, at a millionth of an em: only a relative test keeps it G1
    ([(692, 106), (983, 106), (1294, 438), (1294, 748)], 0.3, 1e-8, "a very small glyph"),
    # chord against the leg: parallel all the same
    ([(0, 0), (2, 1), (5, 1), (-4, 0)], 1.0, 1.0, "a chord pointing against the leg"),
    # leg tilted by a millionth: far above the 1e-9 tolerance
    (
        [(0, 0), (1, 1), (2, Fraction(1) + Fraction(1, 10**6)), (3, 0)],
        0.0,
        1.0,
        "a leg and a chord almost parallel",
    ),
]

#: g2_run cases: the bowls of other glyphs (font units) and short runs.
Q5_CASES = [
    # DejaVu Sans 'D', outer contour, from the top corner round the bowl to the bottom corner
    [
        (201, 1493),
        (616, 1493),
        (1050, 1493),
        (1456, 1132),
        (1456, 362),
        (1048, 0),
        (616, 0),
        (201, 0),
    ],
    # DejaVu Serif 'o' counter as an open run between two made-up corners
    [(616, 70), (764, 70), (915, 304), (915, 760), (764, 993), (616, 993)],
    [(2, 1), (5, 3), (7, -1)],
    [(-1, 4), (1, 1)],
]


def _cross(a, b):
    return a[0] * b[1] - b[0] * a[1]


@cache
def _pen_joints(char: str, file: str):
    """(contour index, angle in degrees, relative curvature jump) of every joint of a glyph,
    from fontTools' pen, by hand; and the contours as lists of pieces (2 points: a line,
    3: a quadratic)."""
    import matplotlib
    from fontTools.pens.basePen import decomposeQuadraticSegment
    from fontTools.pens.recordingPen import RecordingPen
    from fontTools.ttLib import TTFont

    font = TTFont(f"{matplotlib.get_data_path()}/fonts/ttf/{file}")
    pen = RecordingPen()
    font.getGlyphSet()[font.getBestCmap()[ord(char)]].draw(pen)
    contours, pieces, start = [], [], None
    for op, args in pen.value:
        if op == "moveTo":
            start = current = np.array(args[0], float)
            pieces = []
        elif op == "lineTo":
            pieces.append([current, np.array(args[0], float)])
            current = pieces[-1][-1]
        elif op == "qCurveTo":
            for off, on in decomposeQuadraticSegment(list(args)):
                pieces.append([current, np.array(off, float), np.array(on, float)])
                current = pieces[-1][-1]
        elif op in ("closePath", "endPath"):
            if np.any(current != start):
                pieces.append([current, start])
            contours.append(pieces)
    joints = []
    for c, pieces in enumerate(contours):
        for k, q in enumerate(pieces):
            r = pieces[(k + 1) % len(pieces)]
            # a line has x'' = 0; a quadratic: x'(1) = 2 (P2 - P1), x''= 2 (P0 - 2 P1 + P2)
            dq = (len(q) - 1) * (q[-1] - q[-2])
            dr = (len(r) - 1) * (r[1] - r[0])
            aq = 2 * (q[0] - 2 * q[1] + q[2]) if len(q) == 3 else np.zeros(2)
            ar = 2 * (r[0] - 2 * r[1] + r[2]) if len(r) == 3 else np.zeros(2)
            turn = math.degrees(math.atan2(abs(_cross(dq, dr)), float(dq @ dr)))
            kq = _cross(dq, aq) / np.linalg.norm(dq) ** 3
            kr = _cross(dr, ar) / np.linalg.norm(dr) ** 3
            scale = max(abs(kq), abs(kr), 1 / max(np.linalg.norm(dq), np.linalg.norm(dr)))
            joints.append((c, turn, abs(kr - kq) / scale))
    return contours, joints


def _count(joints):
    corners = sum(1 for _, turn, _ in joints if turn > DATA["corner_deg"])
    g2 = sum(
        1 for _, turn, jump in joints if turn <= DATA["corner_deg"] and jump <= DATA["g2_rtol"]
    )
    return np.array([corners, len(joints) - corners - g2, g2], float)


def _glyph_joints(data):
    g = data["glyph"]
    return _pen_joints(g["char"], g["file"])


def q1(student, data):
    got = answers.array(student["answer_q1"], (3,), "answer_q1", "three counts")
    _, joints = _glyph_joints(data)
    # 2 contours drawn by fontTools' pen; corners turn by 90° or ~150°, smooth points by 0°
    assert answers.close(got, _count(joints)), "the counts of your glyph's joints are wrong"


def _rotated(points, angle, scale):
    c, s = math.cos(angle), math.sin(angle)
    return [
        np.array([scale * (c * float(x) - s * float(y)), scale * (s * float(x) + c * float(y))])
        for x, y in points
    ]


def q2(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("implied_is_g2")

    def case(points, angle, scale, kind):
        def run():
            # exact: G2 iff (B - A) x (P2 - P0) == 0 in rationals (lecture 09, §2)
            P0, A, B, P2 = ([Fraction(v) for v in p] for p in points)
            expected = _cross((B[0] - A[0], B[1] - A[1]), (P2[0] - P0[0], P2[1] - P0[1])) == 0
            got = answers.boolean(func(*_rotated(points, angle, scale)), "implied_is_g2's result")
            assert got == expected, f"wrong for {kind}"

        return run

    return answers.partial_credit([case(*c) for c in Q2_CASES])


def _curvatures(data):
    P0, A, B, P2 = (np.array(p, float) / data["q3"]["em"] for p in data["q3"]["points"])
    M = (A + B) / 2
    # q(u) = (1-u)² P0 + 2u(1-u) A + u² M: q'(1) = 2 (M - A) = B - A, q''(1) = 2 (P0 - 2A + M);
    # r(u) = (1-u)² M + 2u(1-u) B + u² P2: r'(0) = 2 (B - M) = B - A, r''(0) = 2 (M - 2B + P2)
    v = B - A
    return (
        np.array([_cross(v, 2 * (P0 - 2 * A + M)), _cross(v, 2 * (M - 2 * B + P2))])
        / np.linalg.norm(v) ** 3
    )


def q3(student, data):
    got = answers.array(student["answer_q3"], (2,), "answer_q3", "[kappa_in, kappa_out]")
    assert answers.close(got, _curvatures(data)), "the curvatures at the implied point are wrong"


def _right_letter(data):
    # the reason that holds at every G2 point of these glyphs: the chord P0P2 parallel to the
    # leg AB (tests/test_variants_hw05.py proves it glyph by glyph); the others are false
    letter_of = dict(zip(data["q4"]["order"], "abcd", strict=True))  # reason -> its letter
    return letter_of["parallel"]


def q4(student, data):
    letters = answers.choice(student["answer_q4"], "abcd", "answer_q4", single=True)
    assert letters == _right_letter(data), "wrong choice"


def _by_hand(V):
    """Bézier polygons of the uniform cubic B-spline on 2V0 - V1, V0..Vn, 2Vn - Vn-1."""
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    out = []
    for i in range(len(E) - 3):
        a, b, c, d = E[i : i + 4]
        # the span of a, b, c, d: b0 = (a + 4b + c)/6, b1 = (2b + c)/3, b2 = (b + 2c)/3, b3 = (b + 4c + d)/6
        out.append([(a + 4 * b + c) / 6, (2 * b + c) / 3, (b + 2 * c) / 3, (b + 4 * c + d) / 6])
    return np.array(out)


def q5(student, data):
    answers.require_own_data(lambda: student["DATA"], data, HOMEWORK)  # no copied notebook
    func = student.function("g2_run")

    def case(points):
        def run():
            V = np.array([[float(x), float(y)] for x, y in points])
            n = len(V) - 1
            got = answers.array(
                func(V.copy()), (n, 4, 2), "g2_run's result", "n cubic Bézier polygons"
            )
            kind = {1: "a straight run", 2: "a run of a single quadratic"}.get(n, "a long run")
            assert answers.close(got, _by_hand(V)), f"wrong for {kind}"

        return run

    return answers.partial_credit([case(c) for c in Q5_CASES])


def _new_counts(data):
    contours, joints = _glyph_joints(data)
    counts = _count(joints)
    # the counter (the contour without corners) keeps its joints; the outer contour keeps its
    # corners (same points, same tangents: V1 - V0 and Vn - Vn-1) and its bowl becomes a C2
    # B-spline.  The bowl's k quadratic pieces (between its two corners) have k off-curve
    # points, and every on-curve point inside the bowl sits between two of them, so the run
    # polygon is corner, k off-curve points, corner: n = k + 1 cubics with k inner G2 joints
    # (the b of DejaVu Sans: 8 pieces, 9 cubics, 8 G2 joints)
    per_contour = [_count([j for j in joints if j[0] == c]) for c in range(len(contours))]
    (counter,) = [c for c, n in enumerate(per_contour) if n[0] == 0]
    (outer,) = [c for c in range(len(contours)) if c != counter]
    k = sum(1 for piece in contours[outer] if len(piece) == 3)
    assert len(contours) == 2 and per_contour[outer][0] == counts[0]
    return per_contour[counter] + np.array([counts[0], 0.0, float(k)])


def q6(student, data):
    got = answers.array(student["answer_q6"], (3,), "answer_q6", "three counts")
    assert answers.close(got, _new_counts(data)), "the counts of your glyph made G2 are wrong"


def answers_for(data):
    """The worked answers of a variant (for office hours: ``tools/variant.py show``)."""
    _, joints = _glyph_joints(data)
    return {
        "answer_q1": [int(x) for x in _count(joints)],
        "implied_is_g2": "|(B - A) x (P2 - P0)| <= 1e-9 |B - A| |P2 - P0| (the same for everyone)",
        "answer_q3": _curvatures(data).tolist(),
        "answer_q4": _right_letter(data),
        "g2_run": "uniform cubic B-spline on 2V0 - V1, V0..Vn, 2Vn - Vn-1 (the same for everyone)",
        "answer_q6": [int(x) for x in _new_counts(data)],
    }
