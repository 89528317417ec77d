"""The lectures' multiple-choice answers, derived here independently, match the stored hashes.

A lecture stores only ``answer_hash(right, salt=qid)``; this test computes each right answer
from first principles (or the course's definitions) and checks the hash, so a wrong hash in a
lecture fails here instead of misleading students.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np
import pytest

from course_lib.checks import answer_hash

ROOT = Path(__file__).resolve().parents[1]
QUIZ = re.compile(r'quiz\("(lecture\d\d\.q\d)".*?"([0-9a-f]{16})"\)', re.S)


def stored_hashes() -> dict:
    out = {}
    for path in (ROOT / "notebooks").glob("[0-9][0-9]_*.ipynb"):
        for cell in json.loads(path.read_text())["cells"]:
            for qid, h in QUIZ.findall("".join(cell["source"])):
                out[qid] = h
    return out


def _quartic_c1_not_c2():
    from course_lib.continuity import curve_continuity
    from course_lib.higher_order import quartic_beta_spline

    P = np.array([[0, 0], [1, 2.4], [3, 3], [4, 0.6], [6, 0.2], [7, 2.6], [9, 3], [10, 0.4]])
    reps = curve_continuity(quartic_beta_spline(P, 1, 100, 0), max_order=3)
    assert all(r.c_order == 1 and r.g_order >= 3 for r in reps)
    return "b"  # C1 but not C2


def _knot_ratio():
    t0, t1, t2 = 0.0, 1.0, 3.0  # |p2 p3| : |p3 p4| = (t1 - t0) : (t2 - t1)  (seed 004 §19.6)
    assert (t1 - t0) / (t2 - t1) == 1 / 2
    return "b"  # 1 : 2


def _w1_for_beta1_3():
    V2, V3 = np.array([1.0, 2.0]), np.array([3.0, 2.0])  # r'(0) = 3 q'(1): W1 - V3 = 3 (V3 - V2)
    W1 = V3 + 3 * (V3 - V2)
    assert not np.allclose(W1, 3 * V3 - V2)
    return "a"


def _g2_not_c1():
    # r' = 2 q' (β1 = 2 ≠ 1: not C1), r'' = 2² q'' + 5 q' (β2 = 5): G2
    return "c"


ANSWERS = {
    "lecture01.q1": lambda: "b, d",  # unit tangent and curvature are intrinsic
    "lecture01.q2": lambda: "b",  # Example 1: G1 but not C1
    "lecture02.q1": lambda: "b",  # three shape parameters, only β1 > 0
    "lecture02.q2": _g2_not_c1,
    "lecture03.q1": _knot_ratio,
    "lecture03.q3": lambda: "c",  # κ = 0: radius 1/|κ| = ∞, a straight line
    "lecture04.q1": _w1_for_beta1_3,
    "lecture05.q1": _quartic_c1_not_c2,
}


@pytest.mark.parametrize("qid", sorted(ANSWERS))
def test_stored_hash_is_the_right_answer(qid):
    hashes = stored_hashes()
    assert qid in hashes, f"{qid} not found in the lectures"
    assert answer_hash(ANSWERS[qid](), salt=qid) == hashes[qid]


def test_every_quiz_of_lectures_01_to_05_is_covered():
    # a later lecture adds its questions to ANSWERS (CONTRIBUTING.md, "Lecture notebooks")
    early = {q for q in stored_hashes() if int(q[7:9]) <= 5}
    assert early == set(ANSWERS)
