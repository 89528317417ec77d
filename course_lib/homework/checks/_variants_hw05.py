"""The question data of homework 5 as a function of a random generator (issue 19).

``generate(None)`` is the data of the notebook since its first edition (the default variant:
the lower-case b of DejaVu Sans); ``generate(rng)`` a student's own variant
(:mod:`course_lib.homework.variants`).  Every variant is well posed by construction; each glyph and each
point a variant can draw is proved well posed exhaustively in ``tests/test_variants_hw05.py``:

* the glyph: one of :data:`GLYPHS`, the letters b, d, p, q of DejaVu Sans, DejaVu Sans Bold,
  DejaVu Sans Mono and DejaVu Sans Mono Bold (bundled with matplotlib).  Each has two
  contours, a counter without corners and an outer contour made of a bowl of quadratic
  segments that runs between two corners where it meets the stem, and straight lines round
  the stem; every joint is clearly a corner (turn > 60°), clearly G2 (relative curvature jump
  0) or clearly G1 (jump > 1e-5, far above the tolerance 1e-8), so q1 and q6 have one answer;
  every G2 point is a stored on-curve point at the midpoint of its two off-curve neighbours
  with the chord P0P2 parallel to the leg AB, and the glyph has G2 points, explicit G1 points
  and curvature ≠ 0 at its G2 points (so q4's right reason is the same option for every
  glyph, and the three others are wrong);
* q1, q6: the joint counts of the glyph, and of the glyph with its bowl made G2 (the stored
  point indices of the bowl and of the stem are data: ``q6["bowl"]``, ``q6["stem"]``);
* q3: an implied point of the outer contour between two stored on-curve neighbours, with
  signed curvatures (in em) of the same sign < 0 and |κ| > 1 on both sides, differing by more
  than 1e-3 relative (so a swapped, unsigned or font-unit answer is another number).  A
  non-default variant never draws the default's point (the example's answer is nobody's);
* q4: the four reasons in an order shuffled per student; the right letter is the position of
  the reason ``"parallel"`` (:func:`right_letter`);
* q2 and q5 (functions) are the same for everyone.
"""

from __future__ import annotations

from functools import cache

import numpy as np

from course_lib.homework import variants

__all__ = ["FONT_NAMES", "GLYPHS", "REASONS", "generate", "glyph_facts", "right_letter"]

#: the fonts (file stems of matplotlib's bundled fonts) and their names in the text
FONT_NAMES = {
    "DejaVuSans": "DejaVu Sans",
    "DejaVuSans-Bold": "DejaVu Sans Bold",
    "DejaVuSansMono": "DejaVu Sans Mono",
    "DejaVuSansMono-Bold": "DejaVu Sans Mono Bold",
}
#: the glyphs a variant draws from: (character, font)
GLYPHS = tuple((char, font) for font in FONT_NAMES for char in "bdpq")
DEFAULT_GLYPH = ("b", "DejaVuSans")
#: index of the default q3 point: the stored off-curve point A of the outer contour of the b
DEFAULT_Q3 = 1

#: q4's reasons, in the order of the default data (a), (b), (c), (d); "parallel" is right
REASONS = {
    "explicit": "they are explicit on-curve points, and TrueType makes every explicit smooth point G2",
    "parallel": (
        "at each of them the chord P0P2 of the two neighbouring quadratics is parallel to the "
        "off-curve leg AB (the point is the midpoint of A and B, at an extreme of the bowl or "
        "the counter where AB and P0P2 are both horizontal or both vertical)"
    ),
    "angle": "the tangent turns there by less than 2°, and that makes a smooth point G2",
    "zero": "the curvature is zero on both sides, as where a straight line continues a straight line",
}


def _cross(u, w) -> float:
    return float(u[0] * w[1] - u[1] * w[0])


def _implied_curvatures(P0, A, B, P2) -> np.ndarray:
    """Signed curvature at M = (A + B)/2 at the end of P0, A, M and the start of M, B, P2."""
    M = (A + B) / 2
    v = B - A  # = 2 (M - A) = 2 (B - M)
    return (
        np.array([_cross(v, 2 * (P0 - 2 * A + M)), _cross(v, 2 * (M - 2 * B + P2))])
        / np.linalg.norm(v) ** 3
    )


@cache
def glyph_facts(char: str, font: str) -> dict:
    """Everything the questions need about one glyph (font units), from course_lib's outlines."""
    from course_lib.constructions.outlines import classify_joints, glyph_outline

    outline = glyph_outline(char, font, em=False)
    em = float(glyph_outline(char, font).scale)  # units per em
    table = classify_joints(outline)
    corner_contours = sorted(set(table.contour[table.kind == "corner"].tolist()))
    if len(outline.contours) != 2 or len(corner_contours) != 1:
        raise ValueError(
            f"{char!r} of {font}: not a bowl and a stem (two contours, corners on one)"
        )
    outer = corner_contours[0]
    counter = 1 - outer
    P, on = outline.points[outer]
    n = len(P)
    # the stored indices of the corners, in drawing order
    corner_points = table.point[(table.contour == outer) & (table.kind == "corner")]
    corners = [i for i in range(n) if on[i] and np.any(np.all(corner_points == P[i], axis=1))]
    # the bowl: the one cyclic run of stored points between two consecutive corners with
    # off-curve points in it; the stem: the rest, on-curve points only (straight lines)
    runs = [
        [(c + k) % n for k in range((d - c) % n + 1)]
        for c, d in zip(corners, corners[1:] + corners[:1], strict=True)
    ]
    bowls = [r for r in runs if not on[r].all()]
    if len(bowls) != 1:
        raise ValueError(f"{char!r} of {font}: not one bowl between two corners")
    bowl = bowls[0]
    start = runs.index(bowl)
    stem = [bowl[-1]]
    for r in runs[start + 1 :] + runs[:start]:
        stem += r[1:]
    # q3's candidates: implied points of the outer contour (between the stored off-curve
    # points i, i + 1) whose neighbours i - 1 and i + 2 are stored on-curve points
    q3 = []
    for i in range(n):
        j, before, after = (i + 1) % n, (i - 1) % n, (i + 2) % n
        if on[i] or on[j] or not (on[before] and on[after]):
            continue
        pts = P[[before, i, j, after]]
        kappa = _implied_curvatures(*(pts / em))
        jump = abs(kappa[0] - kappa[1]) / np.abs(kappa).max()
        if np.all(kappa < -1.0) and jump > 1e-3:
            q3.append(i)
    return {
        "outer": outer,
        "counter": counter,
        "points": P,
        "on": on,
        "bowl": bowl,
        "stem": stem,
        "q3": q3,
        "em": em,
    }


def right_letter(data: dict) -> str:
    """q4's right letter: the position of the reason "parallel" in the student's order."""
    return "abcd"[data["q4"]["order"].index("parallel")]


def _point_text(p) -> str:
    return f"({p[0]:g}, {p[1]:g})"


def _indices_text(idx) -> str:
    return " → ".join(str(i) for i in idx)


def _params(rng: np.random.Generator | None) -> dict:
    if rng is None:
        return {"glyph": DEFAULT_GLYPH, "q3": DEFAULT_Q3, "order": list(REASONS)}
    glyph = GLYPHS[int(rng.integers(len(GLYPHS)))]
    facts = glyph_facts(*glyph)
    default = glyph_facts(*DEFAULT_GLYPH)
    default_pts = default["points"][[DEFAULT_Q3 - 1, DEFAULT_Q3, DEFAULT_Q3 + 1, DEFAULT_Q3 + 2]]
    n = len(facts["points"])
    candidates = [
        i
        for i in facts["q3"]
        if not np.array_equal(
            facts["points"][[(i - 1) % n, i, (i + 1) % n, (i + 2) % n]], default_pts
        )
    ]
    q3 = candidates[int(rng.integers(len(candidates)))]
    order = [list(REASONS)[k] for k in rng.permutation(len(REASONS))]
    return {"glyph": glyph, "q3": q3, "order": order}


@variants.register("hw05")
def generate(rng: np.random.Generator | None) -> dict:
    """The data of homework 5: the default (``rng`` None) or a student's variant."""
    p = _params(rng)
    char, font = p["glyph"]
    facts = glyph_facts(char, font)
    P, n, i = facts["points"], len(facts["points"]), p["q3"]
    pts = [[float(x), float(y)] for x, y in P[[(i - 1) % n, i, (i + 1) % n, (i + 2) % n]]]
    name = f"the lower-case {char} of {FONT_NAMES[font]}"
    options = {letter: REASONS[key] for letter, key in zip("abcd", p["order"], strict=True)}
    bowl, stem = [int(k) for k in facts["bowl"]], [int(k) for k in facts["stem"]]
    labels = ("P0", "A", "B", "P2")
    return {
        "glyph": {
            "char": char, "font": font, "file": f"{font}.ttf", "em": facts["em"],
            "text": f"{name} (glyph_outline({char!r}, {font!r}); font file {font}.ttf)",
        },
        "q3": {
            "points": pts, "em": facts["em"], "contour": facts["outer"], "index": i,
            "text": ", ".join(f"{k} = {_point_text(q)}" for k, q in zip(labels, pts, strict=True))
            + f": stored points {', '.join(str(k % n) for k in range(i - 1, i + 3))} of contour "
            f"{facts['outer']}, font units (1 em = {facts['em']:g})",
        },
        "q4": {
            "order": list(p["order"]), "options": options,
            "text": "\n".join(f"({letter}) {text}" for letter, text in options.items()),
        },
        "q6": {
            "outer": facts["outer"], "counter": facts["counter"], "bowl": bowl, "stem": stem,
            "text": f"outer contour: contour {facts['outer']}; bowl: stored points "
            f"{_indices_text(bowl)}; stem: {_indices_text(stem)}; counter: contour {facts['counter']}",
        },
    }  # fmt: skip


@variants.register_strata("hw05")
def strata(data: dict) -> dict[str, str]:
    """What kind of variant each question is (for the class summary's difficulty check)."""
    font = FONT_NAMES[data["glyph"]["font"]]  # the counts and curvatures vary with the font
    return {"q1": font, "q3": font, "q4": f"right option ({right_letter(data)})", "q6": font}
