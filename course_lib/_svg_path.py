"""A strict reader of SVG path data (SVG 1.1 §8.3), for :func:`course_lib.outlines.svg_outline`.

Why not a package: matplotlib has no path-data parser, and the parsers on PyPI that were
tried (``svg.path`` 7.1, ``svgelements`` 1.9.6, ``svgpathtools`` 1.8.0) silently drop what
they do not understand (``M 0 0 X 1 1`` reads as a lone moveto).  This scanner names the
offending token and its position instead.  Elliptical arcs are converted to cubics with
the center parametrization of the SVG implementation notes (F.6.5-F.6.6) and a stated
error bound (Goldapp 1991).

Returns plain control-point arrays; :mod:`course_lib.outlines` turns them into contours.
"""

from __future__ import annotations

import math
import re

import numpy as np

__all__ = ["svg_subpaths"]

_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
_SEPARATORS = " \t\r\n\f,"
_ARGS = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}


class _Scanner:
    """Reads numbers, arc flags and command letters from path data, tracking the position."""

    def __init__(self, d: str) -> None:
        self.d, self.i = d, 0

    def skip(self) -> None:
        while self.i < len(self.d) and self.d[self.i] in _SEPARATORS:
            self.i += 1

    def at_number(self) -> bool:
        self.skip()
        return self.i < len(self.d) and (self.d[self.i] in "+-." or self.d[self.i].isdigit())

    def number(self, cmd: str, pos: int, flag: bool = False) -> float:
        self.skip()
        if self.i >= len(self.d):
            raise ValueError(
                f"command {cmd!r} at position {pos} needs {_ARGS[cmd.upper()]} numbers per "
                "segment; the path data ends before they are all given"
            )
        if flag:
            c = self.d[self.i]
            if c not in "01":
                raise ValueError(
                    f"arc flag {c!r} at position {self.i} (command {cmd!r} at position {pos}) "
                    "must be 0 or 1"
                )
            self.i += 1
            return float(c)
        m = _NUMBER.match(self.d, self.i)
        if m is None:
            tok = self.d[self.i : self.i + 8].split()[0] if self.d[self.i :].strip() else ""
            raise ValueError(
                f"expected a number at position {self.i} for command {cmd!r} at position "
                f"{pos}, found {tok!r}"
            )
        self.i = m.end()
        return float(m.group())


def _tokens(d: str):
    """Yield ``(command, position, args)`` for every segment command of ``d``."""
    if not isinstance(d, str):
        raise TypeError(f"path data must be a str, got {type(d).__name__}")
    s = _Scanner(d)
    s.skip()
    if s.i >= len(d):
        raise ValueError("path data is empty: no command at position 0")
    cmd = None
    while True:
        s.skip()
        if s.i >= len(d):
            return
        c = d[s.i]
        if c.upper() in _ARGS:
            cmd, pos = c, s.i
            s.i += 1
        elif s.at_number() and cmd is not None and cmd.upper() != "Z":
            pos = s.i  # an implicit repetition of the last command
            cmd = {"M": "L", "m": "l"}.get(cmd, cmd)
        else:
            tok = d[s.i :].split()[0][:12] if d[s.i :].strip() else d[s.i]
            what = "a command letter" if cmd is not None else "a moveto command 'M' or 'm'"
            raise ValueError(
                f"unexpected token {tok!r} at position {s.i} in path data: expected {what} "
                f"(SVG path commands are {' '.join(_ARGS)} and their lower-case forms)"
            )
        n = _ARGS[cmd.upper()]
        flags = (3, 4) if cmd.upper() == "A" else ()
        args = [s.number(cmd, pos, flag=k in flags) for k in range(n)]
        yield cmd, pos, args


def _arc_segments(p0, rx, ry, phi_deg, large, sweep, p1, tol) -> list[np.ndarray]:
    """Cubic pieces of an SVG elliptical arc (SVG 1.1 implementation notes F.6.5-F.6.6).

    Each piece spans at most the angle ``h`` whose standard cubic (inner control points at
    ``k = 4/3 tan(h/4)`` along the tangents) stays within ``tol`` of the unit circle:
    the radial error of that cubic is at most ``4/27 sin^6(h/4) / cos^2(h/4)`` (Goldapp
    1991); mapped to the ellipse it is at most that times ``max(rx, ry)``.
    """
    if np.allclose(p0, p1, rtol=0, atol=0):
        return []
    rx, ry = abs(rx), abs(ry)
    if rx == 0 or ry == 0:
        return [np.array([p0, p1])]
    phi = math.radians(phi_deg % 360.0)
    c, s = math.cos(phi), math.sin(phi)
    R = np.array([[c, -s], [s, c]])
    x1, y1 = R.T @ ((p0 - p1) / 2.0)
    lam = (x1 / rx) ** 2 + (y1 / ry) ** 2
    if lam > 1:
        rx, ry = rx * math.sqrt(lam), ry * math.sqrt(lam)
    num = max(rx**2 * ry**2 - rx**2 * y1**2 - ry**2 * x1**2, 0.0)
    coef = math.sqrt(num / (rx**2 * y1**2 + ry**2 * x1**2))
    if large == sweep:
        coef = -coef
    cx1, cy1 = coef * rx * y1 / ry, -coef * ry * x1 / rx
    center = R @ np.array([cx1, cy1]) + (p0 + p1) / 2.0
    theta1 = math.atan2((y1 - cy1) / ry, (x1 - cx1) / rx)
    theta2 = math.atan2((-y1 - cy1) / ry, (-x1 - cx1) / rx)
    dtheta = theta2 - theta1
    if sweep and dtheta < 0:
        dtheta += 2 * math.pi
    elif not sweep and dtheta > 0:
        dtheta -= 2 * math.pi
    n = 1
    while _arc_error(abs(dtheta) / n) > tol:
        n += 1
    t = theta1 + dtheta * np.arange(n + 1) / n
    k = 4.0 / 3.0 * math.tan(dtheta / n / 4.0)
    u = np.column_stack([np.cos(t), np.sin(t)])
    v = np.column_stack([-np.sin(t), np.cos(t)])
    unit = np.stack([u[:-1], u[:-1] + k * v[:-1], u[1:] - k * v[1:], u[1:]], axis=1)
    M = R @ np.diag([rx, ry])
    pieces = unit @ M.T + center
    pieces[0, 0], pieces[-1, -1] = p0, p1  # exact end points, as the path states them
    return list(pieces)


def _arc_error(h: float) -> float:
    """Radial error bound of the standard cubic for a unit circular arc of angle ``h``."""
    return 4.0 / 27.0 * math.sin(h / 4) ** 6 / math.cos(h / 4) ** 2


def svg_subpaths(d: str, arcs: str, tol: float):
    """Yield ``(segments, closed, position)`` per subpath of ``d``."""
    cur = np.zeros(2)
    start = np.zeros(2)
    segs: list[np.ndarray] = []
    closed, sub_pos = False, None
    prev_ctrl, prev_kind = None, ""
    started = False
    for cmd, pos, a in _tokens(d):
        up, rel = cmd.upper(), cmd.islower()
        base = cur if rel else np.zeros(2)
        if not started and up != "M":
            raise ValueError(
                f"path data must begin with a moveto 'M' or 'm'; found {cmd!r} at position {pos}"
            )
        started = True
        if up == "M":
            if segs:
                yield segs, closed, sub_pos
            elif sub_pos is not None:  # the previous moveto drew nothing
                raise ValueError(
                    f"the subpath at position {sub_pos} has only one point: a contour "
                    "needs at least one segment"
                )
            cur = base + a[:2]
            start, segs, closed, sub_pos = cur.copy(), [], False, pos
            prev_kind = ""
            continue
        if closed:  # a command after Z starts a new subpath at the same start point
            yield segs, closed, sub_pos
            segs, closed, sub_pos = [], False, pos
        if up == "Z":
            if not segs:
                raise ValueError(
                    f"the subpath at position {sub_pos} has only one point: a contour needs "
                    f"at least one segment (closepath at position {pos})"
                )
            if np.any(cur != start):
                segs.append(np.array([cur, start]))
            cur, closed, prev_kind = start.copy(), True, ""
            continue
        new: list[np.ndarray]
        if up == "L":
            new = [np.array([cur, base + a[:2]])]
        elif up == "H":
            new = [np.array([cur, [a[0] + (cur[0] if rel else 0.0), cur[1]]])]
        elif up == "V":
            new = [np.array([cur, [cur[0], a[0] + (cur[1] if rel else 0.0)]])]
        elif up == "C":
            new = [np.array([cur, base + a[0:2], base + a[2:4], base + a[4:6]])]
        elif up == "S":
            c1 = 2 * cur - prev_ctrl if prev_kind == "C" else cur
            new = [np.array([cur, c1, base + a[0:2], base + a[2:4]])]
        elif up == "Q":
            new = [np.array([cur, base + a[0:2], base + a[2:4]])]
        elif up == "T":
            c1 = 2 * cur - prev_ctrl if prev_kind == "Q" else cur
            new = [np.array([cur, c1, base + a[0:2]])]
        else:  # "A"
            if arcs == "refuse":
                raise ValueError(
                    f"elliptical arc {cmd!r} at position {pos}: arcs are refused "
                    "(arcs='refuse'); pass arcs='convert' to approximate them by cubics"
                )
            new = _arc_segments(cur, a[0], a[1], a[2], a[3], a[4], base + a[5:7], tol)
        prev_kind = {"C": "C", "S": "C", "Q": "Q", "T": "Q"}.get(up, "")
        if new:
            prev_ctrl = new[-1][-2].copy()
            cur = new[-1][-1].copy()
        segs.extend(s for s in new if np.ptp(s, axis=0).any())
    if segs:
        yield segs, closed, sub_pos
    elif started:
        raise ValueError(
            f"the subpath at position {sub_pos} has only one point: a contour needs at "
            "least one segment"
        )
