"""The question data of homework 2 as a function of a random generator (issue 19).

``generate(None)`` is the data printed in the notebook since the first edition (the default
variant); ``generate(rng)`` a student's own variant (:mod:`course_lib.homework.variants`).  Every variant
is well posed by construction (tested over thousands of codes in ``tests/test_variants_hw02.py``):

* q1: ``q'(1)`` with two non-zero integer components and ``r'(0) = β1 q'(1)`` with ``β1`` a
  quarter in ``[1/2, 5]``, ``β1 ≠ 1`` (``β1 > 0`` away from 0; an upside-down ``β1`` is another
  number);
* q2: ``q'(1)``, ``q''(1)`` integer vectors without a zero component, neither parallel
  (``|det| ≥ 1``) nor orthogonal, ``r'(0) = β1 q'(1)``, ``r''(0) = β1² q''(1) + β2 q'(1)`` with
  ``β1 ≠ 1`` as in q1 and ``β2 ≠ 0`` (a half-integer, ``|β2| ≥ 1/2``): a missing ``β2`` term, a
  wrong sign or an unsquared ``β1`` changes the answer, whichever coordinate it is read from;
* q4: the same for everyone (its answer does not depend on data);
* q5: like q2, and ``|β1² − β2| ≥ 1/4`` (so swapping ``q'`` and ``q''`` is another vector);
* q6: the four statements in an order shuffled per student;
* q7: the same curve (one joint of each kind), the joints' letters shuffled per student.

All numbers are small fractions (halves, quarters), exact in binary floating point.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from course_lib.homework import variants

__all__ = ["Q6_OPTIONS", "Q7_SEGMENTS", "generate"]

#: q6: the statements, as printed (default order); the first is right (β1 = 1, β2 = 0: C²).
Q6_OPTIONS = [
    "the two parametrizations meet with C² continuity there",
    "they meet with G² continuity but never C¹",
    "the curvature jumps at the joint",
    "nothing can be said about parametric continuity",
]

#: q7: four cubic segments; joint 1 is G1 but not G2, joint 2 G2 (halves of one cubic),
#: joint 3 a corner (tests/unit/test_checks.py::test_hw02_q7_picture_has_one_joint_of_each_kind).
Q7_SEGMENTS = [
    [[0, 0], [1, 1], [2, 1.5], [3, 1.5]],
    [[3, 1.5], [4, 1.5], [5, 0.75], [6, 0.25]],
    [[6, 0.25], [7, -0.25], [8, -0.5], [9, 0.5]],
    [[9, 0.5], [10, 0.5], [11, 1.5], [12, 1.0]],
]

BETA1 = [Fraction(n, 4) for n in range(2, 21) if n != 4]  # 1/2 .. 5 by quarters, not 1
BETA2 = [Fraction(n, 2) for n in range(-8, 9) if n != 0]  # −4 .. 4 by halves, not 0


def _num(x) -> str:
    """``2.5`` -> ``"2.5"``, ``-1`` -> ``"−1"`` (a unicode minus, as in the printed text)."""
    x = Fraction(x)
    text = f"{float(abs(x)):g}"
    return ("−" if x < 0 else "") + text


def _vec(v) -> str:
    return "(" + ", ".join(_num(c) for c in v) + ")"


def _floats(v) -> list[float]:
    return [float(c) for c in v]


def _det(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _params(rng: np.random.Generator | None) -> dict:
    if rng is None:
        return {
            "q1": ([2, -1], Fraction(5, 2)),
            "q2": ([1, 2], [0, 2], Fraction(3), Fraction(-4)),
            "q5": ([2, 0], [1, -3], Fraction(1, 2), Fraction(2)),
            "q6": list(Q6_OPTIONS), "q7": "ABC",
        }  # fmt: skip

    def pick(seq):
        return seq[int(rng.integers(len(seq)))]

    def nonzero():
        return pick([-3, -2, -1, 1, 2, 3])

    def pair(strict: bool = False):
        """Two integer vectors, not parallel, the first not 0; ``strict``: no zero component and
        not orthogonal either (so every coordinate and the projection see each term)."""
        while True:
            if strict:
                a, b = [nonzero(), nonzero()], [nonzero(), nonzero()]
            else:
                a, b = ([int(rng.integers(-3, 4)) for _ in range(2)] for _ in range(2))
            if a != [0, 0] and abs(_det(a, b)) >= 1 and (not strict or a[0] * b[0] + a[1] * b[1] != 0):
                return a, b

    q1 = [nonzero(), nonzero()]
    q2a, q2b = pair(strict=True)
    while True:
        q5a, q5b = pair()
        b1, b2 = pick(BETA1), pick(BETA2)
        if abs(b1 * b1 - b2) >= Fraction(1, 4):
            break
    q7 = pick(["ABC", "ACB", "BAC", "BCA", "CAB", "CBA"])
    return {
        "q1": (q1, pick(BETA1)),
        "q2": (q2a, q2b, pick(BETA1), pick(BETA2)),
        "q5": (q5a, q5b, b1, b2),
        "q6": [Q6_OPTIONS[i] for i in rng.permutation(4)],
        "q7": q7,
    }


@variants.register("hw02")
def generate(rng: np.random.Generator | None) -> dict:
    """The data of homework 2: the default (``rng`` None) or a student's variant."""
    p = _params(rng)
    q1, b1 = p["q1"]
    r1 = [b1 * c for c in q1]
    a1, a2, c1, c2 = p["q2"]
    s1 = [c1 * c for c in a1]
    s2 = [c1 * c1 * y + c2 * x for x, y in zip(a1, a2, strict=True)]
    f1, f2, e1, e2 = p["q5"]
    q6 = {letter: label for letter, label in zip("abcd", p["q6"], strict=True)}
    return {
        "q1": {
            "q1": _floats(q1), "r1": _floats(r1),
            "text": f"q'(1) = {_vec(q1)},  r'(0) = {_vec(r1)}",
        },
        "q2": {
            "q1": _floats(a1), "q2": _floats(a2), "r1": _floats(s1), "r2": _floats(s2),
            "text": f"q'(1) = {_vec(a1)},  q''(1) = {_vec(a2)},  r'(0) = {_vec(s1)},  r''(0) = {_vec(s2)}",
        },
        "q5": {
            "q1": _floats(f1), "q2": _floats(f2), "beta1": float(e1), "beta2": float(e2),
            "text": f"q'(1) = {_vec(f1)},  q''(1) = {_vec(f2)},  β1 = {_num(e1)},  β2 = {_num(e2)}",
        },
        "q6": {"options": q6, "text": "\n".join(f"({letter}) {label}" for letter, label in q6.items())},
        "q7": {
            "segments": [[list(map(float, pt)) for pt in seg] for seg in Q7_SEGMENTS],
            "labels": p["q7"],
            "text": "the joints, along the curve: " + ", ".join(p["q7"]),
        },
    }  # fmt: skip
