"""The SVG path-data grammar (SVG 1.1 §8.3.9) as the reader enforces it.

Properties (hypothesis): separators never change the reading; what the grammar forbids
(a misplaced comma, a non-ASCII digit) is refused at its position; no input makes the
reader raise anything but ``ValueError`` or return a non-finite point.  A table of
malformed strings, each with the position and token its error must name.  Arcs whose
radii are far from the chord's size (1e-300 to 1e200) stay finite and right.
Real files: tests/unit/test_svg_real.py.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from course_lib.constructions.outlines import classify_joints, svg_outline

ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}


def _points(out) -> np.ndarray:
    segs = [s for c in out.contours for s in c.curve.segments]
    return np.vstack(segs) if segs else np.zeros((0, 2))


def _same(a, b) -> bool:
    if len(a.contours) != len(b.contours) or a.skipped != b.skipped:
        return False
    for c, e in zip(a.contours, b.contours, strict=True):
        if c.closed != e.closed or c.curve.n_segments != e.curve.n_segments:
            return False
        if not all(np.array_equal(s, t) for s, t in zip(c.curve.segments, e.curve.segments,
                                                       strict=True)):
            return False
    return True


# ------------------------------------------------------------------ generated paths
numbers = st.one_of(
    st.integers(-999, 999).map(float),
    st.integers(-99999, 99999).map(lambda k: k / 100),
)


@st.composite
def commands(draw):
    """A valid path as ``[(letter, [numbers...]), ...]``, starting with a moveto."""
    out = [(draw(st.sampled_from("Mm")), [draw(numbers), draw(numbers)])]
    for _ in range(draw(st.integers(0, 8))):
        letter = draw(st.sampled_from("MLHVCSQTAZmlhvcsqtaz"))
        n = ARGS[letter.upper()]
        args = [draw(numbers) for _ in range(n)]
        if letter.upper() == "A":
            args[0], args[1] = abs(args[0]), abs(args[1])
            args[3], args[4] = float(draw(st.booleans())), float(draw(st.booleans()))
        out.append((letter, args))
    return out


def _num(x: float) -> str:
    return repr(int(x)) if x == int(x) else repr(x)


def canonical(cmds) -> str:
    return " ".join(f"{c} {' '.join(_num(a) for a in args)}".strip() for c, args in cmds)


@st.composite
def written(draw, cmds):
    """The same path with separators as real writers use them: optional white space after
    a letter, comma-wsp or nothing (before a sign) between numbers, compact arc flags,
    implicit repetition of a command."""
    wsp = st.sampled_from(["", " ", "\n", "\t", "  ", "\r\n"])
    sep = st.sampled_from([" ", ",", ", ", " ,", "\n", " , \t"])
    parts = []
    prev = None
    for letter, args in cmds:
        follows = {"M": "L", "m": "l"}.get(prev, prev)  # a moveto repeats as a lineto
        implicit = prev is not None and args and letter == follows and draw(st.booleans())
        if implicit:
            parts.append(draw(sep))
        else:
            parts.append(draw(wsp) + letter + draw(wsp))
        for k, a in enumerate(args):
            s = _num(a)
            if k:
                flag = letter.upper() == "A" and k in (4, 5)
                compact = (s.startswith("-") or flag) and draw(st.booleans())
                parts.append("" if compact else draw(sep))
            parts.append(s)
        prev = letter
    return "".join(parts) + draw(wsp)


def _read(d):
    try:
        return svg_outline(d)
    except ValueError as exc:
        return f"ValueError: {exc}"


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_separators_never_change_the_reading(data):
    cmds = data.draw(commands())
    a = _read(canonical(cmds))
    d = data.draw(written(cmds))
    b = _read(d)
    if isinstance(a, str) or isinstance(b, str):
        assert isinstance(a, str) and isinstance(b, str), (d, a, b)
        return
    assert _same(a, b), d


@settings(max_examples=200, deadline=None)
@given(st.data())
def test_a_misplaced_comma_is_refused_at_its_position(data):
    cmds = data.draw(commands())
    d = canonical(cmds)
    # places where comma-wsp is not allowed: after a letter, before a letter, at the end,
    # next to another comma
    letters = [m.start() for m in re.finditer(r"[A-Za-z]", d)]
    where = data.draw(st.sampled_from(["after", "before", "end", "double"]))
    if where == "after":
        i = data.draw(st.sampled_from(letters)) + 1
        bad = d[:i] + "," + d[i:]
    elif where == "before":
        starts = [i for i in letters if i > 0]
        assume(starts)
        i = data.draw(st.sampled_from(starts))
        bad = d[:i] + "," + d[i:]
    elif where == "end":
        i = len(d)
        bad = d + ","
    else:
        gaps = [m.start() for m in re.finditer(r"(?<=[0-9.]) (?=[-0-9.])", d)]
        assume(gaps)
        g = data.draw(st.sampled_from(gaps))
        bad = d[:g] + ",," + d[g + 1:]
        i = g + 1  # the second comma is the misplaced one
    with pytest.raises(ValueError, match=rf"misplaced comma ',' at position {i}\b"):
        svg_outline(bad)


NON_ASCII_DIGITS = "٠١٢٣٤٥٦٧٨٩۰۱۲۳۴۵۶۷۸۹०१२३४५६७८९０１２３４５６７８９"


@settings(max_examples=150, deadline=None)
@given(st.data())
def test_a_non_ascii_digit_is_refused_at_its_position(data):
    d = canonical(data.draw(commands()))
    digits = [m.start() for m in re.finditer(r"[0-9]", d)]
    i = data.draw(st.sampled_from(digits))
    bad = d[:i] + data.draw(st.sampled_from(NON_ASCII_DIGITS)) + d[i + 1:]
    with pytest.raises(ValueError, match=r"position (\d+)") as info:
        svg_outline(bad)
    pos = int(re.search(r"at position (\d+)", str(info.value)).group(1))
    # the error names the digit itself or the number it cut short (e.g. "1٢" reads "1",
    # then stops at "٢")
    assert pos <= i and not any(c in NON_ASCII_DIGITS for c in bad[:pos]), (bad, info.value)


extreme = st.one_of(
    numbers,
    st.floats(allow_nan=False, allow_infinity=False),
    st.sampled_from([1e308, -1e308, 1.7e308, 1e-300, 5e-324, 1e160, 1e200, 0.0]),
)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.sampled_from("LlCcQqAaHhVvSsTt"), st.lists(extreme, min_size=7,
                                                                         max_size=7)),
                min_size=1, max_size=4),
       st.tuples(extreme, extreme), st.booleans())
def test_never_a_non_finite_point_and_only_value_errors(cmds, start, close):
    parts = [f"M {start[0]!r} {start[1]!r}"]
    for letter, args in cmds:
        n = ARGS[letter.upper()]
        a = list(args[:n])
        if letter.upper() == "A":
            a[3], a[4] = float(a[3] > 0), float(a[4] > 0)
        parts.append(f"{letter} {' '.join(repr(x) for x in a)}")
    d = " ".join(parts) + (" z" if close else "")
    try:
        out = svg_outline(d)
    except ValueError as exc:
        assert re.search(r"position \d+", str(exc)), exc
        return
    assert np.isfinite(_points(out)).all(), d
    # and the analysis accepts it (its curvatures |v|^3 overflow beyond ~1e100: inf, no error)
    with np.errstate(over="ignore", invalid="ignore"):
        classify_joints(out)


@settings(max_examples=300, deadline=None)
@given(st.text(alphabet="MmLlZzAaCcHh0123456789.,-+eE \n٣", max_size=30))
def test_any_text_reads_or_raises_value_error(d):
    try:
        out = svg_outline(d)
    except ValueError as exc:
        assert re.search(r"position \d+", str(exc)), exc
        return
    assert np.isfinite(_points(out)).all()


# ------------------------------------------------------------------ malformed table
LONG = "9" * 400
MALFORMED = [
    # (path data, position, token or phrase the error names)
    ("M,0 0", 1, "misplaced comma ','"),
    ("M 0,,0 L1 1", 4, "misplaced comma ','"),
    ("M0 0 L1 1,", 9, "at the end"),
    ("M0 0 L1 1 ,", 10, "at the end"),
    ("M0 0,L1 1", 4, "before 'L1'"),
    ("M0 0 L1 1 z,M2 2 L3 3", 11, "misplaced comma ','"),
    ("M0 0 L1 1 z, 2 2", 11, "misplaced comma ','"),
    ("M0 0 a1 1 0 0,,1 1 1", 14, "misplaced comma ','"),
    ("M ٣ ٤ L1 1", 2, "'٣'"),
    ("M0 0 L １ 1", 7, "'１'"),
    ("M0 0 L1 1 L२ 0", 11, "'२'"),
    ("M0 0 L 1 1\u00a0L 2 2", 10, "'\\xa0'"),
    ("M0 0 L1e999 0", 6, "'1e999'"),
    ("M0 0 L-1e400 0", 6, "'-1e400'"),
    ("M0 0 L 2 1E+309", 9, "'1E+309'"),
    (f"M0 0 L{LONG} 0", 6, "(400 characters)"),
    (f"M0 0 L0 -{LONG}.5", 8, "(403 characters)"),
    ("M1e308 0 l1e308 0", 9, "beyond the range of doubles"),
    ("M-1.7e308 0 h 1.7e308 h 1.7e308 h 1.7e308", 32, "beyond the range of doubles"),
    ("M0 0 L 1 1 M 2e300 0 L 0 0", 11, "reaches the coordinate 2e+300"),
    ("M0 0 A1e-320 1 0 0 1 1 1", 5, "differ by more than the range"),
    ("M0 0 A1e308 1e308 0 1 1 1e-300 0", 5, "too large for the large arc"),
    ("M0 0 L1 1 Z 2 2", 12, "unexpected token '2'"),
    ("M0 0 L1-", 7, "found '-'"),
    ("M0 0 L1 1 L", 10, "needs 2 numbers"),
    ("M0 0 C1 1 2 2 3 3 4 4", 18, "needs 6 numbers"),
    ("M0 0 L 1 1e", 10, "unexpected token 'e'"),
    ("m0 0 l1 1 ſ 2 2", 10, "unexpected token 'ſ'"),
    ("M 0 0 X 1 1", 6, "unexpected token 'X'"),
    ("M0 0 A 1 1 0 2 0 3 3", 13, "arc flag '2'"),
    ("M0 0 A 1 1 0 1,- 0 3 3", 15, "arc flag '-'"),
]


@pytest.mark.parametrize(("d", "pos", "token"), MALFORMED)
def test_malformed_path_data_is_refused_naming_position_and_token(d, pos, token):
    with pytest.raises(ValueError, match=rf"position {pos}\b") as info:
        svg_outline(d)
    assert token in str(info.value), info.value


def test_draws_nothing_is_dropped_not_refused():
    """One-point subpaths draw nothing in a browser: dropped and counted, not refused."""
    for d, skipped in [("M 1 1", 1), ("M 1 1 Z", 1), ("m 1 1 z", 1), ("M 1 1 M 2 2", 2),
                       ("M0 0 L0 0 Z", 1), ("M 1 1 Z Z z", 3)]:
        out = svg_outline(d)
        assert out.contours == () and out.skipped == skipped, d
        assert len(classify_joints(out)) == 0
    out = svg_outline("M 1 1 M 2 2 L 3 3 z m 0 0 m 5 5 z")
    assert len(out.contours) == 1 and out.skipped == 3
    assert np.array_equal(out.contours[0].curve.segments[0], [[2, 2], [3, 3]])


def test_closing_lines_within_rounding_are_dropped_longer_ones_kept():
    # 1e-12 of a path of size ~1: rounding; the contour ends exactly at its start
    (c,) = svg_outline("M0 0 L1 0 L1 1 L1e-12 0 Z").contours
    assert c.curve.n_segments == 3 and np.array_equal(c.curve.segments[-1][-1], [0, 0])
    # 1e-6 is drawn (a browser draws it too): kept as a closing line
    (c,) = svg_outline("M0 0 L1 0 L1 1 L1e-6 0 Z").contours
    assert c.curve.n_segments == 4
    # the rule is relative to the path's size: 1e-12 in a path of size 1e-6 is kept
    (c,) = svg_outline("M0 0 L1e-6 0 L1e-6 1e-6 L1e-12 0 Z").contours
    assert c.curve.n_segments == 4
    # a subpath that shrinks to nothing once its rounding line is gone is dropped
    out = svg_outline("M0 0 L 1 0 L 1 1 z M 0 0 L 1e-13 0 z")
    assert len(out.contours) == 1 and out.skipped == 1


# ------------------------------------------------------------------ extreme arcs
@pytest.mark.parametrize("r", [1e160, 1e180, 1e200, 1e300, 1.7e308])
def test_huge_radius_small_arc_is_its_chord(r):
    (c,) = svg_outline(f"M0 0 A{r!r} {r!r} 0 0 1 1 0").contours
    P = np.vstack(c.curve.segments)
    assert np.isfinite(P).all()
    assert np.array_equal(P[0], [0, 0]) and np.array_equal(P[-1], [1, 0])
    assert np.abs(P[:, 1]).max() <= 1e-15  # the sagitta, 1/(8r), is far below rounding
    assert np.all(np.diff(P[:, 0]) >= 0)


@pytest.mark.parametrize("r", [1e160, 1e180, 1e200])
def test_huge_radius_large_arc_goes_round_the_huge_circle(r):
    (c,) = svg_outline(f"M0 0 A{r!r} {r!r} 0 1 1 1 0").contours
    centre = np.array([0.5, -math.sqrt(r * r - 0.25)]) if r < 1e154 else np.array([0.5, -r])
    for i in range(c.curve.n_segments):
        p = c.curve.evaluate_segment(i, np.linspace(0, 1, 9))
        assert np.isfinite(p).all()
        assert np.allclose(np.hypot(*(p - centre).T) / r, 1.0, rtol=0, atol=2e-6)


@pytest.mark.parametrize("r", [1e-300, 5e-324, 1e-150])
def test_tiny_radius_is_scaled_up_to_a_half_circle(r):
    """F.6.6: radii too small are scaled until the ellipse just reaches both ends."""
    (c,) = svg_outline(f"M0 0 A{r!r} {r!r} 0 0 1 4 0").contours
    for i in range(c.curve.n_segments):
        p = c.curve.evaluate_segment(i, np.linspace(0, 1, 9))
        assert np.allclose(np.hypot(p[:, 0] - 2, p[:, 1]), 2.0, rtol=0, atol=2e-6)
    # an ellipse of aspect 2 keeps its aspect when scaled
    (c,) = svg_outline(f"M0 0 A{r!r} {2 * r!r} 0 0 1 4 0").contours
    p = np.vstack([c.curve.evaluate_segment(i, np.linspace(0, 1, 9))
                   for i in range(c.curve.n_segments)])
    assert np.allclose(((p[:, 0] - 2) / 2) ** 2 + (p[:, 1] / 4) ** 2, 1.0, atol=4e-6)


@settings(max_examples=100, deadline=None)
@given(st.floats(0.01, 100), st.floats(0.01, 100), st.floats(-360, 360), st.booleans(),
       st.booleans(), st.floats(-10, 10), st.floats(-10, 10), st.integers(-900, 900))
def test_arcs_scale_exactly_by_powers_of_two(rx, ry, phi, large, sweep, x, y, k):
    """The arc computation is scale-free: the whole path times 2**k reads as 2**k times it."""
    assume(abs(x) + abs(y) > 1e-3)
    f = 2.0**k
    d = f"M0 0 A{rx!r} {ry!r} {phi!r} {int(large)} {int(sweep)} {x!r} {y!r}"
    ds = f"M0 0 A{rx * f!r} {ry * f!r} {phi!r} {int(large)} {int(sweep)} {x * f!r} {y * f!r}"
    a, b = _points(svg_outline(d)), _points(svg_outline(ds))
    assert np.allclose(b / f, a, rtol=1e-12, atol=1e-12 * max(rx, ry, 1.0))
