"""Hidden tests of homework 5: Are letters smooth? (run by tools/grade.py in the grader; never shipped).

Form: ``solutions/hidden_tests/README.md``.  Expected values come from first principles, never
from course_lib's mathematics or the solution notebook:

* the joint counts of the b: the glyph drawn by fontTools' own pen (``RecordingPen`` on the
  font's glyph set, quadratic runs split by fontTools' ``decomposeQuadraticSegment``) and every
  joint classified here with hand formulas (end derivatives of line and quadratic pieces);
* G2 at an implied point: exact rational arithmetic on the cross product
  ``(B - A) x (P2 - P0)`` of the data before it was rotated or scaled;
* the runs: B-spline to Bézier conversion written out by hand, on another glyph (DejaVu Sans
  'D', DejaVu Serif 'o') than the feedback check.
"""

from __future__ import annotations

import math
from fractions import Fraction
from functools import cache

import numpy as np

from course_lib import answers

HOMEWORK = "hw05"
POINTS = {"q1": 2, "q2": 3, "q3": 2, "q4": 1, "q5": 4, "q6": 1}

#: The question data as stated in the notebook.
DATA = {
    "glyph": ("b", "DejaVuSans.ttf"),
    "em": 2048.0,
    "q3": [(371, 950), (429, 1050), (606, 1147), (729, 1147)],
    "corner_deg": 2.0,
    "g2_rtol": 1e-8,
}

#: implied_is_g2 cases: base points (exact), then the transform the student's copy gets.
#: The base decides the answer: rotating and scaling keep (non-)parallel chords.
Q2_CASES = [
    # DejaVu Serif 'o', counter, lower right implied point: a G1 joint in font units
    ([(616, 70), (764, 70), (915, 304), (915, 532)], 0.0, 1.0),
    # DejaVu Serif 'o', top of the outer ring (616, 1092) as a midpoint joint: symmetric, G2
    ([(242.5, 939), (383, 1092), (849, 1092), (989.5, 939)], 0.0, 1.0),
    ([(242.5, 939), (383, 1092), (849, 1092), (989.5, 939)], math.pi / 4, 1 / 2048),
    # DejaVu Serif 'D', G1, at a millionth of an em: only a relative test keeps it G1
    ([(692, 106), (983, 106), (1294, 438), (1294, 748)], 0.3, 1e-8),
    # chord against the leg: parallel all the same
    ([(0, 0), (2, 1), (5, 1), (-4, 0)], 1.0, 1.0),
    # leg tilted by a millionth: far above the 1e-9 tolerance
    ([(0, 0), (1, 1), (2, Fraction(1) + Fraction(1, 10**6)), (3, 0)], 0.0, 1.0),
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
def _pen_joints():
    """(contour index, angle in degrees, relative curvature jump) of every joint of the b,
    from fontTools' pen, by hand."""
    import matplotlib
    from fontTools.pens.basePen import decomposeQuadraticSegment
    from fontTools.pens.recordingPen import RecordingPen
    from fontTools.ttLib import TTFont

    char, file = DATA["glyph"]
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


def q1(student):
    got = answers.array(student["answer_q1"], (3,), "answer_q1", "three counts")
    _, joints = _pen_joints()
    # 2 contours drawn by fontTools' pen; corners turn by 90° or 150°, smooth points by 0°
    assert answers.close(got, _count(joints)), "the counts of the b's joints are wrong"


def _rotated(points, angle, scale):
    c, s = math.cos(angle), math.sin(angle)
    return [
        np.array([scale * (c * float(x) - s * float(y)), scale * (s * float(x) + c * float(y))])
        for x, y in points
    ]


def q2(student):
    func = student.function("implied_is_g2")

    def case(points, angle, scale):
        def run():
            # exact: G2 iff (B - A) x (P2 - P0) == 0 in rationals (lecture 06, §2)
            P0, A, B, P2 = ([Fraction(v) for v in p] for p in points)
            expected = _cross((B[0] - A[0], B[1] - A[1]), (P2[0] - P0[0], P2[1] - P0[1])) == 0
            got = answers.boolean(func(*_rotated(points, angle, scale)), "implied_is_g2's result")
            assert got == expected, f"wrong for a {'G2' if expected else 'G1'} implied point"

        return run

    return answers.partial_credit([case(*c) for c in Q2_CASES])


def q3(student):
    got = answers.array(student["answer_q3"], (2,), "answer_q3", "[kappa_in, kappa_out]")
    P0, A, B, P2 = (np.array(p, float) / DATA["em"] for p in DATA["q3"])
    M = (A + B) / 2
    # q(u) = (1-u)² P0 + 2u(1-u) A + u² M: q'(1) = 2 (M - A) = B - A, q''(1) = 2 (P0 - 2A + M);
    # r(u) = (1-u)² M + 2u(1-u) B + u² P2: r'(0) = 2 (B - M) = B - A, r''(0) = 2 (M - 2B + P2)
    v = B - A
    expected = (
        np.array([_cross(v, 2 * (P0 - 2 * A + M)), _cross(v, 2 * (M - 2 * B + P2))])
        / np.linalg.norm(v) ** 3
    )
    assert answers.close(got, expected), "the curvatures at the implied point are wrong"


def q4(student):
    letters = answers.choice(student["answer_q4"], "abcd", "answer_q4", single=True)
    assert letters == "b", "wrong choice"


def _by_hand(V):
    """Bézier polygons of the uniform cubic B-spline on 2V0 - V1, V0..Vn, 2Vn - Vn-1."""
    E = np.vstack([2 * V[0] - V[1], V, 2 * V[-1] - V[-2]])
    out = []
    for i in range(len(E) - 3):
        a, b, c, d = E[i : i + 4]
        # the span of a, b, c, d: b0 = (a + 4b + c)/6, b1 = (2b + c)/3, b2 = (b + 2c)/3, b3 = (b + 4c + d)/6
        out.append([(a + 4 * b + c) / 6, (2 * b + c) / 3, (b + 2 * c) / 3, (b + 4 * c + d) / 6])
    return np.array(out)


def q5(student):
    func = student.function("g2_run")

    def case(points):
        def run():
            V = np.array([[float(x), float(y)] for x, y in points])
            n = len(V) - 1
            got = answers.array(
                func(V.copy()), (n, 4, 2), "g2_run's result", "n cubic Bézier polygons"
            )
            assert answers.close(got, _by_hand(V)), f"wrong for a run of {n + 1} points"

        return run

    return answers.partial_credit([case(c) for c in Q5_CASES])


def q6(student):
    got = answers.array(student["answer_q6"], (3,), "answer_q6", "three counts")
    contours, joints = _pen_joints()
    # the counter (contour 0) keeps its joints; the outer contour keeps its corners (same
    # points, same tangents: V1 - V0 and Vn - Vn-1) and its bowl becomes a C2 B-spline of
    # n = 9 cubic segments (10 run points: 13 stored points minus 3 extreme on-curve points),
    # whose 8 inner joints are G2
    counter = _count([j for j in joints if j[0] == 0])
    corners = _count(joints)[0]
    expected = counter + np.array([corners, 0.0, 8.0])
    assert len(contours) == 2 and answers.close(got, expected), "the counts of the new b are wrong"
