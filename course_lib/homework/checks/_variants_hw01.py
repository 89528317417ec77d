"""The question data of homework 1 as a function of a random generator (issue 19).

``generate(None)`` is the data printed in the notebook since the first edition (the default
variant); ``generate(rng)`` a student's own variant (:mod:`course_lib.homework.variants`).  Every variant
is well posed by construction (tested over thousands of codes in ``tests/test_variants_hw01.py``):

* q1: ``c(t) = (x(t), y(t))``, integer coefficients, a point ``t0`` where ``c'`` has two
  non-zero components of different sizes (``‖c'‖ ≥ √2``: regular; a swapped or backwards
  tangent is a different vector);
* q3: four changes of variables of ``[0, 1]``, one of each kind -- not regular (``f' = 0`` at
  an end), orientation-reversing, not onto ``[0, 1]``, and the right one (of q5's family, but
  another ``w`` than q5's, except in the default data) -- in an order shuffled per student;
* q4, q5, q7: the parabola ``q(u) = (u, k u²)``, ``k ≠ 0``; q4 at ``u0 ≠ 0`` with ``|κ|`` away
  from 1 (curvature ≠ radius); q5 with ``f(s) = (1 − w) s + w s²``, ``0 < |w| < 1`` (so
  ``f(0) = 0, f(1) = 1, f' ≥ 1 − |w| > 0``) at ``s`` with ``f(s) ≠ s`` and ``f'(s) ≠ 1`` (the
  blind spots of the old data); q7 over ``[0, b]``;
* q6: the five quantities of the question in an order shuffled per student.

All numbers are small fractions (quarters, fifths), shown as such in ``text``.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np

from course_lib.homework import variants

__all__ = ["generate", "poly_text"]

#: q3: the wrong options, one kind each; coefficients of f(s) in ascending powers of s.
NOT_REGULAR = [([0, 0, 1], "s²"), ([0, 0, 0, 1], "s³"), ([0, 0, 3, -2], "3s² − 2s³"), ([0, 2, -1], "2s − s²")]
REVERSING = [([1, -1], "1 − s"), ([1, 0, -1], "1 − s²"), ([1, -2, 1], "(1 − s)²")]
NOT_ONTO = [([0, 2], "2s"), ([0, Fraction(1, 2)], "s/2"), ([0, 1, 1], "s + s²")]

#: q6: the options, as printed (default order).
Q6_OPTIONS = [
    "the first derivative vector",
    "the unit tangent vector",
    "the speed ‖q'‖",
    "the curvature vector",
    "the second derivative vector",
]

QUARTERS = [Fraction(n, 4) for n in range(1, 9)]  # 1/4 .. 2
W_VALUES = [Fraction(n, 4) for n in (-3, -2, -1, 1, 2, 3)]
S_VALUES = [Fraction(1, 4), Fraction(3, 4), Fraction(1, 5), Fraction(2, 5), Fraction(3, 5), Fraction(4, 5)]


def _num(x: Fraction) -> str:
    sign, x = ("−" if x < 0 else ""), abs(x)
    return sign + (str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}")


def poly_text(coef, var: str = "t") -> str:
    """``[0, -2, 0, 1]`` -> ``"t³ − 2t"`` (highest power first; fractions as ``3/4``)."""
    sup = {1: "", 2: "²", 3: "³", 4: "⁴"}
    terms = []
    for power in range(len(coef) - 1, -1, -1):
        c = Fraction(coef[power]).limit_denominator(1000)
        if c == 0:
            continue
        mag = abs(c)
        body = var + sup[power] if power else ""
        if not body:
            text = _num(mag)
        elif mag == 1:
            text = body
        elif mag.denominator == 1:
            text = f"{mag.numerator}{body}"
        else:
            text = f"({_num(mag)}){body}"
        terms.append(("−" if c < 0 else "+", text))
    if not terms:
        return "0"
    first_sign, first = terms[0]
    out = ("−" if first_sign == "−" else "") + first
    for sign, text in terms[1:]:
        out += f" {sign} {text}"
    return out


def _f_text(w: Fraction) -> str:
    """f(s) = (1 − w) s + w s² written over a common denominator: w = 1/2 -> (s + s²)/2."""
    q = w.denominator
    a, b = (1 - w) * q, w * q  # integers
    # the linear term first: the notebook has always said (s + s²)/2
    lin = "s" if a == 1 else f"{int(a)}s"
    sq = "s²" if abs(b) == 1 else f"{abs(int(b))}s²"
    inner = f"{lin} {'+' if b > 0 else '−'} {sq}"
    return f"({inner})/{q}" if q != 1 else inner


def _floats(coef) -> list[float]:
    return [float(c) for c in coef]


def _q1_ok(x, y, t) -> bool:
    dx = 2 * x[2] * t + x[1]
    dy = 3 * y[3] * t * t + y[1]
    return abs(dx) >= 1 and abs(dy) >= 1 and abs(abs(dx) - abs(dy)) >= Fraction(1, 2)


def _kappa(k, u) -> float:
    return 2 * float(k) / (1 + 4 * float(k * k * u * u)) ** 1.5


def _q4_ok(k, u) -> bool:
    kap = abs(_kappa(k, u))
    return 0.02 <= kap and abs(kap - 1) >= 0.1


def _params(rng: np.random.Generator | None) -> dict:
    if rng is None:
        return {
            "x": [0, 1, 1], "y": [0, -2, 0, 1], "t": Fraction(1),
            "q3": [NOT_REGULAR[0], REVERSING[0], NOT_ONTO[0], None], "k": Fraction(1), "u": Fraction(1),
            "w": Fraction(1, 2), "w3": Fraction(1, 2), "s": Fraction(3, 4), "b": Fraction(1), "q6": list(Q6_OPTIONS),
        }  # fmt: skip

    def pick(seq):
        return seq[int(rng.integers(len(seq)))]

    while True:
        x = [0, int(rng.integers(-3, 4)), pick([-2, -1, 1, 2])]
        y = [0, int(rng.integers(-3, 4)), 0, pick([-1, 1])]
        t = pick([Fraction(n, 2) for n in (-4, -3, -2, -1, 1, 2, 3, 4)])
        if _q1_ok(x, y, t):
            break
    while True:
        k = pick(QUARTERS) * pick([-1, 1])
        u = pick(QUARTERS) * pick([-1, 1])
        if _q4_ok(k, u):
            break
    q3 = [pick(NOT_REGULAR), pick(REVERSING), pick(NOT_ONTO), None]
    q3 = [q3[i] for i in rng.permutation(4)]
    w = pick(W_VALUES)
    w3 = pick([v for v in W_VALUES if v != w])  # q5's f is not q3's answer (no give-away)
    q6 = [Q6_OPTIONS[i] for i in rng.permutation(5)]
    return {
        "x": x, "y": y, "t": t, "q3": q3, "k": k, "u": u, "w": w, "w3": w3, "s": pick(S_VALUES),
        "b": pick(QUARTERS[1:]), "q6": q6,
    }  # fmt: skip


@variants.register("hw01")
def generate(rng: np.random.Generator | None) -> dict:
    """The data of homework 1: the default (``rng`` None) or a student's variant."""
    p = _params(rng)
    k, w = p["k"], p["w"]
    f_coef = [0, 1 - w, w]
    parabola = f"q(u) = (u, {poly_text([0, 0, k], 'u')})"
    letters = "abcd"
    options, coefficients = {}, {}
    for letter, option in zip(letters, p["q3"], strict=True):
        w3 = p["w3"]
        coef, text = ([0, 1 - w3, w3], _f_text(w3)) if option is None else option
        options[letter] = f"f(s) = {text}"
        coefficients[letter] = _floats(coef)
    q6 = {letter: label for letter, label in zip("abcde", p["q6"], strict=True)}
    return {
        "q1": {
            "x": _floats(p["x"]), "y": _floats(p["y"]), "t": float(p["t"]),
            "text": f"c(t) = ({poly_text(p['x'])}, {poly_text(p['y'])}),  at t = {_num(p['t'])}",
        },
        "q3": {
            "options": options, "coefficients": coefficients,
            "text": "\n".join(f"({letter}) {options[letter]}" for letter in letters),
        },
        "q4": {"k": float(k), "u": float(p["u"]), "text": f"{parabola},  at u = {_num(p['u'])}"},
        "q5": {
            "k": float(k), "f": _floats(f_coef), "s": float(p["s"]),
            "text": f"{parabola},  f(s) = {_f_text(w)},  at s = {_num(p['s'])}",
        },
        "q6": {"options": q6, "text": "\n".join(f"({letter}) {label}" for letter, label in q6.items())},
        "q7": {"k": float(k), "b": float(p["b"]), "text": f"{parabola},  0 ≤ u ≤ {_num(p['b'])}"},
    }  # fmt: skip


@variants.register_strata("hw01")
def strata(data: dict) -> dict[str, str]:
    """What kind of variant each question is (for the class summary's difficulty check)."""

    def right_q3() -> str:
        for letter, coef in data["q3"]["coefficients"].items():
            f = np.polynomial.Polynomial(coef)
            s = np.linspace(0.0, 1.0, 101)
            if abs(f(0.0)) < 1e-12 and abs(f(1.0) - 1.0) < 1e-12 and np.all(f.deriv()(s) > 0):
                return f"right option ({letter})"
        return "?"

    intrinsic = ("the unit tangent vector", "the curvature vector")
    q6 = ", ".join(k for k, v in data["q6"]["options"].items() if v in intrinsic)
    k = "k > 0" if data["q4"]["k"] > 0 else "k < 0"
    w = "w > 0" if data["q5"]["f"][2] > 0 else "w < 0"
    return {
        "q1": "t > 0" if data["q1"]["t"] > 0 else "t < 0",
        "q3": right_q3(),
        "q4": k,
        "q5": f"{k}, {w}",
        "q6": f"right options ({q6})",
        "q7": k,
    }
