"""A strict reader of SVG path data (SVG 1.1 §8.3), for :func:`course_lib.constructions.outlines.svg_outline`.

Why not a package: matplotlib has no path-data parser, and the parsers on PyPI that were
tried (``svg.path`` 7.1, ``svgelements`` 1.9.6, ``svgpathtools`` 1.8.0) silently drop what
they do not understand (``M 0 0 X 1 1`` reads as a lone moveto).  This scanner names the
offending token and its position instead.  (``svgelements`` is the independent reference
of the tests, on real files, where the data is valid.)

Reading follows the grammar of SVG 1.1 §8.3.9 and draws what a browser draws:

* numbers are ASCII only (``[+-]? digits [. digits] [e[+-] digits]``) and must be finite
  as doubles (``1e999`` or a 400-digit number is refused, naming its position);
* a comma may only *separate* two numbers (``comma-wsp``): ``M,0``, ``0,,0``, a comma
  before a command letter or at the end are refused; white space is space, tab, CR, LF
  (and form feed, as SVG 2 and browsers allow);
* a subpath that draws nothing -- a moveto followed by another moveto or by the end
  (Inkscape's trailing ``z m 0 0``), ``m x y z`` -- is dropped and counted;
* a closing line shorter than the rounding of the path (``1e-9`` times the path's size,
  the larger of its bounding box's diagonal and its largest coordinate) is dropped and
  the contour closed exactly: relative coordinates summed in floating point leave such
  lines where the decimal data closes exactly, and each would be a false corner;
* no point is ever infinite or NaN: a point that overflows raises ``ValueError``, and so
  does a coordinate beyond ``±1e300`` (``LIMIT``), whose derivatives would overflow.

Elliptical arcs are converted to cubics with the center parametrization of the SVG
implementation notes (F.6.5-F.6.6, out-of-range radii scaled up), computed relative to the
arc's start point so that radii from 1e-300 to 1e300 give finite, accurate control points,
and with a stated error bound (Goldapp 1991).

Returns plain control-point arrays; :mod:`course_lib.constructions.outlines` turns them into contours.
"""

from __future__ import annotations

import math
import re

import numpy as np

__all__ = ["LIMIT", "ROUNDING", "svg_subpaths"]

#: Closing lines shorter than this times the path's size are rounding, not drawing.
ROUNDING = 1e-9
#: Largest coordinate accepted: derivatives (degree times differences of control points)
#: and the analysis of joints must stay finite.
LIMIT = 1e300

_NUMBER = re.compile(r"[+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?", re.ASCII)
_WSP = " \t\r\n\f"
_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}
_LETTERS = frozenset("MLHVCSQTAZmlhvcsqtaz")
_NUMBER_START = frozenset("0123456789+-.")


def _token(d: str, i: int) -> str:
    """The token starting at ``d[i]`` (up to white space, a comma or a command letter),
    shortened for messages."""
    j = i + 1
    while j < len(d) and d[j] not in _WSP and d[j] != "," and d[j] not in _LETTERS:
        j += 1
    tok = d[i:j]
    return tok if len(tok) <= 24 else f"{tok[:20]}... ({len(tok)} characters)"


class _Scanner:
    """Reads numbers, arc flags, separators and command letters, tracking the position."""

    def __init__(self, d: str) -> None:
        self.d, self.i = d, 0

    def wsp(self) -> None:
        while self.i < len(self.d) and self.d[self.i] in _WSP:
            self.i += 1

    def comma_wsp(self) -> int | None:
        """Skip ``comma-wsp?``; return the position of the comma, if there was one."""
        self.wsp()
        if self.i < len(self.d) and self.d[self.i] == ",":
            at = self.i
            self.i += 1
            self.wsp()
            return at
        return None

    def at_number(self) -> bool:
        return self.i < len(self.d) and self.d[self.i] in _NUMBER_START

    def number(self, cmd: str, pos: int, flag: bool = False) -> float:
        d, i = self.d, self.i
        if i >= len(d):
            raise ValueError(
                f"command {cmd!r} at position {pos} needs {_ARGS[cmd.upper()]} numbers per "
                "segment; the path data ends before they are all given"
            )
        if d[i] == ",":
            raise ValueError(
                f"misplaced comma ',' at position {i} (command {cmd!r} at position {pos}): "
                "a comma may only separate two numbers (SVG 1.1 comma-wsp)"
            )
        if flag:
            if d[i] not in "01":
                raise ValueError(
                    f"arc flag {d[i]!r} at position {i} (command {cmd!r} at position {pos}) "
                    "must be 0 or 1"
                )
            self.i += 1
            return float(d[i])
        m = _NUMBER.match(d, i)
        if m is None:
            raise ValueError(
                f"expected a number at position {i} for command {cmd!r} at position "
                f"{pos}, found {_token(d, i)!r}"
            )
        value = float(m.group())
        if not math.isfinite(value):
            raise ValueError(
                f"number {_token(d, i)!r} at position {i} (command {cmd!r} at position "
                f"{pos}) is out of range: it overflows a double (largest about 1.8e308)"
            )
        self.i = m.end()
        return value


def _tokens(d: str):
    """Yield ``(command, position, args)`` for every segment command of ``d``."""
    if not isinstance(d, str):
        raise TypeError(f"path data must be a str, got {type(d).__name__}")
    s = _Scanner(d)
    s.wsp()
    if s.i >= len(d):
        raise ValueError("path data is empty: no command at position 0")
    cmd = None
    while True:
        s.wsp()
        if s.i >= len(d):
            return
        c = d[s.i]
        if c in _LETTERS:
            cmd, pos = c, s.i
            s.i += 1
            s.wsp()  # only white space between a command letter and its numbers
        elif s.at_number() and cmd is not None and cmd.upper() != "Z":
            pos = s.i  # an implicit repetition of the last command
            cmd = {"M": "L", "m": "l"}.get(cmd, cmd)
        elif c == ",":
            raise ValueError(
                f"misplaced comma ',' at position {s.i}: a comma may only separate two "
                "numbers (SVG 1.1 comma-wsp), not follow a command letter or "
                "'Z' or stand before a command letter"
            )
        else:
            what = "a command letter" if cmd is not None else "a moveto command 'M' or 'm'"
            raise ValueError(
                f"unexpected token {_token(d, s.i)!r} at position {s.i} in path data: "
                f"expected {what} (SVG path commands are {' '.join(_ARGS)} and their "
                "lower-case forms)"
            )
        n = _ARGS[cmd.upper()]
        flags = (3, 4) if cmd.upper() == "A" else ()
        args = []
        for k in range(n):
            if k:
                s.comma_wsp()
            args.append(s.number(cmd, pos, flag=k in flags))
        if n:
            comma = s.comma_wsp()
            if comma is not None and not s.at_number():
                where = "at the end" if s.i >= len(d) else f"before {_token(d, s.i)!r}"
                raise ValueError(
                    f"misplaced comma ',' at position {comma} {where}: a comma may only "
                    "separate two numbers (SVG 1.1 comma-wsp)"
                )
        yield cmd, pos, args


def _arc_segments(p0, rx, ry, phi_deg, large, sweep, p1, tol, where: str) -> list[np.ndarray]:
    """Cubic pieces of an SVG elliptical arc (SVG 1.1 implementation notes F.6.5-F.6.6).

    Each piece spans at most the angle ``h`` whose standard cubic (inner control points at
    ``k = 4/3 tan(h/4)`` along the tangents) stays within ``tol`` of the unit circle:
    the radial error of that cubic is at most ``4/27 sin^6(h/4) / cos^2(h/4)`` (Goldapp
    1991); mapped to the ellipse it is at most that times ``max(rx, ry)``.

    The computation is scale-free (lengths divided by a power of two of the half chord)
    and puts every point relative to ``p0`` (``p0 + M (u(θ) - u(θ1))`` with the
    difference of cosines and sines as products), never through the centre, so that a
    radius of 1e200 (a centre 1e200 away) or 1e-300 (scaled up by F.6.6) gives finite,
    accurate points.  What cannot be represented raises ``ValueError`` naming ``where``.
    """
    if np.array_equal(p0, p1):
        return []  # F.6.2: an arc whose end points coincide is omitted
    rx, ry = abs(rx), abs(ry)
    if rx == 0 or ry == 0:
        return [np.array([p0, p1])]  # F.6.2: a zero radius gives a straight line
    phi = math.radians(phi_deg % 360.0)
    c, s = math.cos(phi), math.sin(phi)
    R = np.array([[c, -s], [s, c]])
    hx, hy = R.T @ ((p0 - p1) / 2.0)  # F.6.5.1: (x1', y1')
    if not (math.isfinite(hx) and math.isfinite(hy)):
        raise ValueError(f"{where}: the arc's end points are too far apart for doubles")
    fit = _fitted_radii(hx, hy, rx, ry, large, where)
    if fit is None:
        return [np.array([p0, p1])]
    scale, a, b, a_r, b_r, L, f = fit
    sign = -1.0 if large == sweep else 1.0  # F.6.5.2
    # Unit-circle coordinates of the start point and of end - start (exact: -2 (a, b)).
    ux, uy = a - sign * f * b / L, b + sign * f * a / L
    dx, dy = -2.0 * a, -2.0 * b
    dtheta = math.atan2(ux * dy - uy * dx, 1.0 + ux * dx + uy * dy)  # F.6.5.6, no cancellation
    if sweep and dtheta <= 0:
        dtheta += 2 * math.pi
    elif not sweep and dtheta >= 0:
        dtheta -= 2 * math.pi
    n = 1
    while _arc_error(abs(dtheta) / n) > tol:
        n += 1
    theta1 = math.atan2(uy, ux)
    delta = dtheta * np.arange(n + 1) / n
    half = np.sin(delta / 2)
    mid = theta1 + delta / 2
    du = np.column_stack([-2.0 * np.sin(mid) * half, 2.0 * np.cos(mid) * half])  # u(θ)-u(θ1)
    t = theta1 + delta
    v = np.column_stack([-np.sin(t), np.cos(t)])  # tangents of the unit circle
    k = 4.0 / 3.0 * math.tan(dtheta / n / 4.0)
    M = R @ np.diag([a_r * scale, b_r * scale])
    with np.errstate(over="ignore", invalid="ignore"):
        P = du @ M.T + p0
        V = k * (v @ M.T)
        pieces = np.stack([P[:-1], P[:-1] + V[:-1], P[1:] - V[1:], P[1:]], axis=1)
    pieces[0, 0], pieces[-1, -1] = p0, p1  # exact end points, as the path states them
    if not np.isfinite(pieces).all():
        raise ValueError(f"{where}: the arc leaves the range of doubles")
    return list(pieces)


def _fitted_radii(hx: float, hy: float, rx: float, ry: float, large, where: str):
    """The arc's ellipse in unit-chord coordinates (F.6.5.1-F.6.6.3), scale-free.

    ``(hx, hy)`` is F.6.5.1's ``(x1', y1')``; ``rx, ry > 0``.  Returns ``(scale, a, b, a_r,
    b_r, L, f)``: the power of two the lengths were divided by, the start point on the unit
    circle before the centre shift (``a, b``), the radii as scaled up by F.6.6 if too small
    (``a_r, b_r``), ``L = sqrt(Λ)`` and F.6.5.2's root ``f``; or ``None`` when the arc is its
    chord to double precision (radii ~1e300 times the chord, short arc).
    """
    q = ry / rx  # the ellipse's aspect, kept by the F.6.6 scaling
    if q == 0 or not math.isfinite(q):
        raise ValueError(
            f"{where}: radii {rx:g} and {ry:g} differ by more than the range of doubles"
        )
    scale = 2.0 ** math.frexp(max(abs(hx), abs(hy)))[1]  # exact: a power of two
    x1, y1, a_r, b_r = hx / scale, hy / scale, rx / scale, ry / scale
    if not (math.isfinite(a_r) and math.isfinite(b_r)):
        L = 0.0  # radii beyond the chord's scale by more than the range of doubles
    elif a_r == 0 or b_r == 0:
        L = math.inf  # radii below the chord's scale by more than the range of doubles
    else:
        a, b = x1 / a_r, y1 / b_r
        L = math.hypot(a, b)  # sqrt(Λ) of F.6.6.2
    if L == 0.0:
        # Radii ~1e300 times the chord: the short arc is its chord to double precision;
        # the long arc would reach beyond the doubles.
        if large:
            raise ValueError(
                f"{where}: radii {rx:g}, {ry:g} are too large for the large arc between "
                "these end points (it would leave the range of doubles)"
            )
        return None
    if L >= 1.0:  # F.6.6.3: radii too small, scaled up so that the ellipse just fits
        if math.isfinite(L):
            a_r, b_r = a_r * L, b_r * L
        else:  # radii ~1e-300 of the chord: scale from the aspect instead
            a_r = math.hypot(x1, y1 / q)
            b_r = a_r * q
            if not (math.isfinite(a_r) and b_r > 0):
                raise ValueError(
                    f"{where}: radii {rx:g} and {ry:g} scaled up to reach the end points "
                    "leave the range of doubles"
                )
        a, b = x1 / a_r, y1 / b_r
        L, f = math.hypot(a, b), 0.0
    else:
        f = math.sqrt((1.0 - L) * (1.0 + L))
    return scale, a, b, a_r, b_r, L, f


def _arc_error(h: float) -> float:
    """Radial error bound of the standard cubic for a unit circular arc of angle ``h``."""
    return 4.0 / 27.0 * math.sin(h / 4) ** 6 / math.cos(h / 4) ** 2


def _read(d: str, arcs: str, tol: float):
    """The subpaths of ``d`` as read: ``[segments, closed, position, start]`` each, and
    the number of subpaths that draw nothing (dropped)."""
    cur = np.zeros(2)
    start = np.zeros(2)
    subpaths: list[list] = []
    segs: list[np.ndarray] = []
    closed, closing, sub_pos = False, False, None
    prev_ctrl, prev_kind = None, ""
    started = False
    skipped = 0

    def end_subpath() -> None:
        nonlocal skipped
        if segs:
            subpaths.append([segs, closed, sub_pos, start.copy(), closing])
        elif sub_pos is not None:
            skipped += 1  # a moveto alone, or "m x y z": draws nothing

    for cmd, pos, a in _tokens(d):
        up, rel = cmd.upper(), cmd.islower()
        base = cur if rel else np.zeros(2)
        if not started and up != "M":
            raise ValueError(
                f"path data must begin with a moveto 'M' or 'm'; found {cmd!r} at position {pos}"
            )
        started = True
        where = f"command {cmd!r} at position {pos}"
        if up == "M":
            end_subpath()
            cur = _finite(base + a[:2], where)
            start, segs, closed, closing, sub_pos = cur.copy(), [], False, False, pos
            prev_kind = ""
            continue
        if closed:  # a command after Z starts a new subpath at the same start point
            end_subpath()
            segs, closed, closing, sub_pos = [], False, False, pos
        if up == "Z":
            if segs and np.any(cur != start):
                segs.append(np.array([cur, start]))
                closing = True  # a closing line was drawn
            closed = True
            cur, prev_kind = start.copy(), ""
            continue
        new = _drawn(cmd, pos, a, cur, prev_ctrl, prev_kind, arcs, tol)
        for seg in new:
            _finite(seg, where)
        prev_kind = {"C": "C", "S": "C", "Q": "Q", "T": "Q"}.get(up, "")
        if new:
            prev_ctrl = new[-1][-2].copy()
            cur = new[-1][-1].copy()
        segs.extend(s for s in new if np.ptp(s, axis=0).any())
    end_subpath()
    return subpaths, skipped


def _drawn(
    cmd: str, pos: int, a: list, cur: np.ndarray, prev_ctrl, prev_kind: str, arcs: str, tol: float
) -> list[np.ndarray]:
    """The segments one drawing command (L H V C S Q T A, either case) adds after ``cur``.

    ``prev_ctrl`` and ``prev_kind`` (``"C"``, ``"Q"`` or ``""``) are the previous command's
    last inner control point and kind, reflected by S and T.
    """
    up, rel = cmd.upper(), cmd.islower()
    base = cur if rel else np.zeros(2)
    if up == "L":
        return [np.array([cur, base + a[:2]])]
    if up == "H":
        return [np.array([cur, [a[0] + (cur[0] if rel else 0.0), cur[1]]])]
    if up == "V":
        return [np.array([cur, [cur[0], a[0] + (cur[1] if rel else 0.0)]])]
    if up == "C":
        return [np.array([cur, base + a[0:2], base + a[2:4], base + a[4:6]])]
    if up == "S":
        c1 = 2 * cur - prev_ctrl if prev_kind == "C" else cur
        return [np.array([cur, c1, base + a[0:2], base + a[2:4]])]
    if up == "Q":
        return [np.array([cur, base + a[0:2], base + a[2:4]])]
    if up == "T":
        c1 = 2 * cur - prev_ctrl if prev_kind == "Q" else cur
        return [np.array([cur, c1, base + a[0:2]])]
    # "A"
    if arcs == "refuse":
        raise ValueError(
            f"elliptical arc {cmd!r} at position {pos}: arcs are refused "
            "(arcs='refuse'); pass arcs='convert' to approximate them by cubics"
        )
    where = f"command {cmd!r} at position {pos}"
    end = _finite(base + a[5:7], where)
    return _arc_segments(cur, a[0], a[1], a[2], a[3], a[4], end, tol, where)


def _finite(p: np.ndarray, where: str) -> np.ndarray:
    if not np.isfinite(p).all():
        raise ValueError(
            f"{where} gives a point beyond the range of doubles (coordinates add up to "
            "more than about 1.8e308)"
        )
    return p


def svg_subpaths(d: str, arcs: str, tol: float):
    """Read ``d``: a list of ``(segments, closed, position)`` per subpath that draws
    something, and the number of subpaths dropped because they draw nothing.

    A closed subpath whose closing line is shorter than ``ROUNDING`` times the path's
    size loses that line and ends exactly at its start (a segment that thereby shrinks
    to a point is dropped too).
    """
    with np.errstate(over="ignore", invalid="ignore"):  # every point is checked: _finite
        subpaths, skipped = _read(d, arcs, tol)
    if not subpaths:
        return [], skipped
    for segs, _closed, pos, *_ in subpaths:
        big = max(float(np.abs(s).max()) for s in segs)
        if big > LIMIT:
            raise ValueError(
                f"the subpath at position {pos} reaches the coordinate {big:.3g}: beyond "
                f"±{LIMIT:g} its derivatives and joints cannot be computed in doubles"
            )
    pts = np.vstack([np.vstack(segs) for segs, *_ in subpaths])
    size = max(float(np.hypot(*np.ptp(pts, axis=0))), float(np.abs(pts).max()))
    eps = ROUNDING * size
    out = []
    for segs, closed, pos, start, closing in subpaths:
        if closing and len(segs) > 1:
            last = segs[-1]
            if math.hypot(*(last[1] - last[0])) <= eps:
                segs = segs[:-1]  # a closing line left by rounding
                end = segs[-1].copy()
                end[-1] = start
                segs[-1] = end
                if not np.ptp(end, axis=0).any():
                    segs = segs[:-1]
        if not segs:
            skipped += 1
            continue
        out.append((segs, closed, pos))
    return out, skipped
