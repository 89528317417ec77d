"""The question data of homework 3 as a function of a random generator (issue 19).

``generate(None)`` is the data printed in the notebook since the first edition (the default
variant); ``generate(rng)`` a student's own variant (:mod:`course_lib.homework.variants`).  Every variant
is well posed by construction (tested over thousands of codes in ``tests/test_variants_hw03.py``):

* Finn's G1 control points ``d_-1 .. d_6`` (L = 3): integer points with strictly increasing
  ``x`` (steps 1 or 2, so no leg is degenerate) and ``y`` in ``0 .. 4``;
* q1: knots ``0, a, a + b`` with integer ``a ≠ b`` in ``1 .. 4`` (the joint is not the midpoint:
  a swapped ratio is another point);
* q3: three knot sequences ``0 < t1 < t2 < t3`` with integer intervals in ``1 .. 4``, exactly one
  uniform (q4's answer, its letter computed from the data) and two distinct non-uniform ones,
  in an order shuffled per student;
* q5: the first three knots of one non-uniform sequence of q3 whose first two intervals differ
  and are both ≠ 1 (so a derivative in the local parameter is another vector, on both sides);
* q2, q6, q7 (functions, a symbolic answer without data) are the same for everyone.
"""

from __future__ import annotations

import numpy as np

from course_lib.homework import variants

__all__ = ["generate"]

#: the default data: Finn's G1 control points d_-1 .. d_6 (row j holds d_{j-1})
D_DEFAULT = [[0, 0], [1, 2], [2, 3], [4, 3], [5, 1], [6, 0], [8, 1], [9, 3]]


def _num_list(values) -> str:
    return ", ".join(f"{float(v):g}" for v in values)


def _params(rng: np.random.Generator | None) -> dict:
    if rng is None:
        return {
            "D": D_DEFAULT, "q1": [0, 1, 3],
            "q3": [[0, 1, 2, 4], [0, 3, 6, 9], [0, 2, 3, 6]], "q5": "c",
        }  # fmt: skip

    def pick(seq):
        return seq[int(rng.integers(len(seq)))]

    x = np.cumsum([0, *(pick([1, 2]) for _ in range(7))]).tolist()
    D = [[int(xi), int(rng.integers(0, 5))] for xi in x]
    a = pick([1, 2, 3, 4])
    q1 = [0, a, a + pick([b for b in (1, 2, 3, 4) if b != a])]

    def knots(intervals):
        return np.cumsum([0, *intervals]).tolist()

    h = pick([1, 2, 3])
    uniform = knots([h, h, h])
    first = pick([2, 3, 4])  # the sequence of q5: its first two intervals differ, both ≠ 1
    for5 = knots([first, pick([v for v in (2, 3, 4) if v != first]), pick([1, 2, 3, 4])])
    while True:
        other = knots([pick([1, 2, 3, 4]) for _ in range(3)])
        if len(set(np.diff(other).tolist())) > 1 and other != for5:
            break
    seqs = [uniform, for5, other]
    order = rng.permutation(3)
    q3 = [seqs[i] for i in order]
    return {"D": D, "q1": q1, "q3": q3, "q5": "abc"[int(np.flatnonzero(order == 1)[0])]}


@variants.register("hw03")
def generate(rng: np.random.Generator | None) -> dict:
    """The data of homework 3: the default (``rng`` None) or a student's variant."""
    p = _params(rng)
    D = [[float(c) for c in row] for row in p["D"]]
    q1 = [float(t) for t in p["q1"]]
    q3 = {letter: [float(t) for t in k] for letter, k in zip("abc", p["q3"], strict=True)}
    q5 = q3[p["q5"]][:3]
    points = ", ".join(f"({x:g}, {y:g})" for x, y in D)
    return {
        "D": {"points": D, "text": f"d_-1, ..., d_6 = {points}"},
        "q1": {
            "knots": q1,
            "text": f"t0, t1, t2 = {_num_list(q1)};  p_2 = d_1 = ({D[2][0]:g}, {D[2][1]:g}),  "
            f"p_4 = d_2 = ({D[3][0]:g}, {D[3][1]:g})",
        },
        "q3": {"knots": q3, "text": "  ".join(f"({x}) {_num_list(k)}" for x, k in q3.items())},
        "q5": {"knots": q5, "letter": p["q5"], "text": f"knot sequence ({p['q5']}): {_num_list(q3[p['q5']])}"},
    }  # fmt: skip
