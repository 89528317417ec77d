"""The question data of homework 4 as a function of a random generator (issue 19).

``generate(None)`` is the data printed in the notebook since the first edition (the default
variant); ``generate(rng)`` a student's own variant (:mod:`course_lib.homework.variants`).  Every variant
is well posed by construction (tested over thousands of codes in ``tests/test_variants_hw04.py``):

* q1: ``V_{d-1} ≠ V_d`` integer points (the leg is not degenerate) and ``β1`` in
  :data:`BETA1` (away from 0 and ≠ 1: an inverted ``β1`` is another point);
* q3: a cubic ``V_0 .. V_3`` of integer points with strictly increasing ``x`` (no leg is
  degenerate) whose last three points are not collinear (a construction from the wrong base
  point is another point); ``β1`` in :data:`BETA1`, ``β2 ≠ 0`` a half-integer, with
  ``γ = 2 (1 + β1) / (β2 + 2 β1 (1 + β1))`` (seed 000 eq. 12.1, d = 3) in ``[1/4, 5/2]``
  (far from its pole, positive, so ``T`` is on the ray) and ``|γ − 1| ≥ 3/20`` (forgetting
  ``γ`` is another point; ``β2 ≠ 0`` makes forgetting ``β2`` or taking ``d`` for ``d − 1``
  another point too);
* q5: ``W_{i−1,2} ≠ W_{i,1}`` integer points and ``β1`` in :data:`BETA1` (a swapped ratio is
  another point);
* q6: the four statements of :data:`Q6_OPTIONS` in an order shuffled per student; the check
  finds the right letter in the student's order.  (q6 is feedback only, worth 0 points.)
* q2, q4 (functions) are the same for everyone.

All numbers are small fractions (halves, quarters), exact in binary floating point.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from course_lib.homework import variants

__all__ = ["BETA1", "Q6_OPTIONS", "Q6_RIGHT", "generate", "strata"]

#: β1 of q1, q3, q5: away from 0, ≠ 1
BETA1 = [Fraction(n, 4) for n in (2, 3, 5, 6, 8, 10, 12)]  # 1/2, 3/4, 5/4, 3/2, 2, 5/2, 3
#: β2 of q3: −4 .. 4 by halves, not 0
BETA2 = [Fraction(n, 2) for n in range(-8, 9) if n != 0]

#: q6: the statements, as printed (default order)
Q6_OPTIONS = [
    "a Catmull–Rom spline through the V_i",
    "the uniform cubic B-spline of the same control polygon",
    "a G² curve that is not C²",
    "the control polygon itself",
]
#: the true statement (β1 = 1, β2 = 0: γ = 1, the Bézier points of the uniform cubic B-spline;
#: tests/unit/test_checks.py::test_hw04_q6_unit_shape_parameters_give_the_uniform_cubic_b_spline)
Q6_RIGHT = Q6_OPTIONS[1]


def _num(x) -> str:
    """``2.5`` -> ``"2.5"``, ``-1`` -> ``"−1"`` (a unicode minus, as in the printed text)."""
    x = Fraction(x)
    return ("−" if x < 0 else "") + f"{float(abs(x)):g}"


def _pt(p) -> str:
    return "(" + ", ".join(_num(c) for c in p) + ")"


def gamma(beta1, beta2, d: int = 3) -> Fraction:
    """γ of the Farin–Boehm construction (seed 000 eq. 12.1), exactly."""
    b1, b2 = Fraction(beta1), Fraction(beta2)
    return (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))


def _params(rng: np.random.Generator | None) -> dict:
    if rng is None:
        return {
            "q1": ([1, 2], [3, 3], Fraction(3, 2)),
            "q3": ([[0, 0], [1, 2], [3, 3], [4, 2]], Fraction(3, 2), Fraction(1)),
            "q5": ([2, 1], [5, 4], Fraction(2)),
            "q6": list(range(4)),
        }  # fmt: skip

    def pick(seq):
        return seq[int(rng.integers(len(seq)))]

    def point():
        return [int(rng.integers(0, 6)), int(rng.integers(0, 6))]

    def two_points():
        while True:
            a, b = point(), point()
            if a != b:
                return a, b

    q1 = (*two_points(), pick(BETA1))
    while True:
        x = np.cumsum([int(rng.integers(0, 3)), *(pick([1, 2]) for _ in range(3))]).tolist()
        V = [[int(xi), int(rng.integers(0, 5))] for xi in x]
        (ax, ay), (bx, by) = (np.subtract(V[2], V[1]), np.subtract(V[3], V[2]))
        if ax * by - ay * bx != 0:  # V_1, V_2, V_3 not collinear
            break
    while True:
        b1, b2 = pick(BETA1), pick(BETA2)
        den = b2 + 2 * b1 * (1 + b1)
        if den > 0 and 10 * abs(b2) >= den:  # γ > 0 (T on the ray); β2 moves γ by ≥ 10 %
            g = gamma(b1, b2)
            if Fraction(1, 4) <= g <= Fraction(5, 2) and abs(g - 1) >= Fraction(3, 20):
                break
    q5 = (*two_points(), pick(BETA1))
    return {"q1": q1, "q3": (V, b1, b2), "q5": q5, "q6": rng.permutation(4).tolist()}


@variants.register("hw04")
def generate(rng: np.random.Generator | None) -> dict:
    """The data of homework 4: the default (``rng`` None) or a student's variant."""
    p = _params(rng)
    (a1, b1_, c1), (V, e1, e2), (a5, b5, c5) = p["q1"], p["q3"], p["q5"]
    q6 = {letter: Q6_OPTIONS[i] for letter, i in zip("abcd", p["q6"], strict=True)}
    return {
        "q1": {
            "V_dm1": [float(c) for c in a1], "V_d": [float(c) for c in b1_], "beta1": float(c1),
            "text": f"V_(d−1) = {_pt(a1)},  V_d = {_pt(b1_)},  β1 = {_num(c1)}",
        },
        "q3": {
            "V": [[float(c) for c in row] for row in V], "beta1": float(e1), "beta2": float(e2),
            "text": f"V_0, ..., V_3 = {', '.join(_pt(row) for row in V)};  β1 = {_num(e1)},  β2 = {_num(e2)}",
        },
        "q5": {
            "W_left": [float(c) for c in a5], "W_right": [float(c) for c in b5], "beta1": float(c5),
            "text": f"W_(i−1,2) = {_pt(a5)},  W_(i,1) = {_pt(b5)},  β1,i = {_num(c5)}",
        },
        "q6": {"options": q6, "text": "\n".join(f"({letter}) {label}" for letter, label in q6.items())},
    }  # fmt: skip


@variants.register_strata("hw04")
def strata(data: dict) -> dict[str, str]:
    """What kind of variant each question is (for the class summary's difficulty check)."""

    def side(b: float) -> str:
        return "β1 > 1" if b > 1 else "β1 < 1"

    right = "".join(x for x, label in data["q6"]["options"].items() if label == Q6_RIGHT)
    return {
        "q1": side(data["q1"]["beta1"]),
        "q3": "β2 > 0" if data["q3"]["beta2"] > 0 else "β2 < 0",
        "q5": side(data["q5"]["beta1"]),
        "q6": f"right option ({right})",
    }
