"""The SVG reader on real files, against an independent parser (``svgelements``, test extra).

Real ``d`` attributes as they are written -- matplotlib's toolbar icons, JupyterLab's icons
(its ``.svg`` files and the icons inlined in its JavaScript bundles), every other ``.svg``
of the course's environment, and Debian's Adwaita and Tango icon themes (``adwaita-icon-theme``,
``tango-icon-theme``, installed by ``tools/ensure-test-data`` under ``make test``; the
tests that need them skip with a reason where they are absent, and fail in CI) -- are read by
:func:`course_lib.constructions.outlines.svg_outline` and by ``svgelements.Path``, and must agree:

* none is refused (they are valid SVG; Inkscape's trailing ``z m 0 0`` draws nothing);
* the same shapes: subpath by subpath, segment by segment, the same control points (arcs:
  the same points at the same angles, within the arc tolerance);
* no spurious corner: the joints that :func:`classify_joints` calls corners are exactly
  those where the reference's tangents turn by more than the corner angle.

Only what draws nothing may differ: zero-length segments, one-point subpaths, closing
lines within rounding of the path's size.
"""

from __future__ import annotations

import math
import os
import re
import sys
from functools import cache
from pathlib import Path

import numpy as np
import pytest

from course_lib.constructions.outlines import classify_joints, svg_outline

se = pytest.importorskip(
    "svgelements", reason="the independent SVG parser of the tests: pip install -e '.[test]'"
)

ROUNDING = 1e-9  # closing lines within this times the path's size are rounding (the rule)
ARC_TOL = 1e-6  # svg_outline's default arc_tolerance, relative to the larger radius
# An arc whose radius just fits its chord (F.6.6, Λ ≈ 1) has an ill-conditioned centre: a
# rounding of Λ by 1e-16 moves it by sqrt(2e-16) ≈ 1.4e-8 radii, in either parser.
ARC_CENTRE = 1e-7
CORNER = 2.0  # classify_joints' default corner angle, degrees
#: Debian icon themes (packages adwaita-icon-theme, tango-icon-theme)
THEMES = {"adwaita": Path("/usr/share/icons/Adwaita"), "tango": Path("/usr/share/icons/Tango")}
_JS_PATH = re.compile(r"""<path\b[^<>]*?\sd=(\\?["'])([^"'\\]*)\1""")


def _xml_paths(files) -> list[tuple[str, str]]:
    import xml.etree.ElementTree as ET

    out = []
    for f in sorted(files):
        try:
            root = ET.parse(f).getroot()
        except ET.ParseError:
            continue  # not XML (a template): not an SVG file to read
        for k, el in enumerate(e for e in root.iter() if e.tag.rsplit("}", 1)[-1] == "path"):
            d = el.get("d")
            if d and d.strip():
                out.append((f"{f}: path {k}", d))
    return out


@cache
def corpus(source: str) -> tuple[tuple[str, str], ...]:
    """``(where, d)`` of every real path of ``source``, duplicates removed."""
    env = Path(sys.prefix)
    if source == "matplotlib":
        import matplotlib

        files = Path(matplotlib.get_data_path(), "images").glob("*.svg")
        paths = _xml_paths(files)
    elif source == "jupyterlab":
        lab = env / "share" / "jupyter" / "lab"
        paths = _xml_paths(lab.rglob("*.svg"))
        for js in sorted(lab.rglob("*.js")):
            text = js.read_text(encoding="utf-8", errors="replace")
            paths += [(f"{js}: icon", m.group(2)) for m in _JS_PATH.finditer(text)
                      if re.match(r"\s*[Mm]", m.group(2))]
    elif source == "environment":
        lab = env / "share" / "jupyter" / "lab"
        files = [f for f in env.rglob("*.svg")
                 if lab not in f.parents and "mpl-data" not in f.parts]
        paths = _xml_paths(files)
    elif source in THEMES:
        paths = _xml_paths(THEMES[source].rglob("*.svg"))
    else:
        raise ValueError(source)
    seen, out = set(), []
    for where, d in paths:
        if d not in seen:
            seen.add(d)
            out.append((where, d))
    return tuple(out)


def _theme_or_skip(*names: str) -> None:
    for name in names:
        if not THEMES[name].is_dir():
            msg = (f"Debian's {name}-icon-theme is not installed ({THEMES[name]}): "
                   "`bash tools/ensure-test-data` (root, apt-get) installs it")
            if os.environ.get("CI"):
                pytest.fail(msg)
            pytest.skip(msg)


# ------------------------------------------------------------ the independent reading
def _xy(p) -> np.ndarray:
    return np.array([float(p.x), float(p.y)])


def reference(d: str) -> list[dict]:
    """svgelements' reading: per subpath, its drawn segments (``("bezier", ctrl)`` or
    ``("arc", seg)``) and whether it is closed."""
    subs: list[dict] = []
    for seg in se.Path(d):
        if isinstance(seg, se.Move):
            subs.append({"segs": [], "closed": False})
            continue
        if not subs or subs[-1]["closed"]:  # a command after Z: a new subpath
            subs.append({"segs": [], "closed": False})
        cur = subs[-1]
        if isinstance(seg, se.Close):
            cur["closed"] = True
            ctrl = np.array([_xy(seg.start), _xy(seg.end)])
            cur["segs"].append(("close", ctrl))
        elif isinstance(seg, se.Line):
            cur["segs"].append(("bezier", np.array([_xy(seg.start), _xy(seg.end)])))
        elif isinstance(seg, se.QuadraticBezier):
            cur["segs"].append(
                ("bezier", np.array([_xy(seg.start), _xy(seg.control), _xy(seg.end)])))
        elif isinstance(seg, se.CubicBezier):
            cur["segs"].append(("bezier", np.array(
                [_xy(seg.start), _xy(seg.control1), _xy(seg.control2), _xy(seg.end)])))
        elif isinstance(seg, se.Arc):
            cur["segs"].append(("arc", seg))
        else:  # pragma: no cover - svgelements has no other path segment
            raise TypeError(type(seg).__name__)
    return subs


def _size(subs) -> float:
    pts = [c for s in subs for kind, c in s["segs"] if kind != "arc"]
    pts += [np.array([_xy(c.start), _xy(c.end)]) for s in subs for kind, c in s["segs"]
            if kind == "arc"]
    if not pts:
        return 0.0
    P = np.vstack(pts)
    return max(float(np.hypot(*np.ptp(P, axis=0))), float(np.abs(P).max()))


def _tangents(kind, c, n_pieces=None):
    """Unit tangents at the start and the end of a reference segment (first/last distinct
    control point; an arc: its derivative in the ellipse parameter, by a tiny step)."""
    if kind == "arc":
        p0, p1 = _xy(c.point(0.0)), _xy(c.point(1e-7))
        q0, q1 = _xy(c.point(1 - 1e-7)), _xy(c.point(1.0))
        a, b = p1 - p0, q1 - q0
    else:
        d0 = [p - c[0] for p in c[1:] if np.any(p != c[0])]
        d1 = [c[-1] - p for p in c[-2::-1] if np.any(p != c[-1])]
        a, b = d0[0], d1[0]
    return a / np.linalg.norm(a), b / np.linalg.norm(b)


def _turn(u, v) -> float:
    return math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u @ v))


def compare(where: str, d: str) -> dict:
    """Assert that svg_outline and svgelements read the same shape; return counts."""
    out = svg_outline(d, name=where)
    subs = reference(d)
    eps = ROUNDING * _size(subs)
    drawn = []
    for s in subs:
        segs = [(k, c) for k, c in s["segs"]
                if (k == "arc" and np.any(_xy(c.start) != _xy(c.end)))
                or (k != "arc" and np.ptp(c, axis=0).any())]
        if segs and segs[-1][0] == "close" and len(segs) > 1 and \
                np.linalg.norm(segs[-1][1][1] - segs[-1][1][0]) <= eps:
            segs = segs[:-1]  # a closing line left by rounding draws nothing
        if segs:
            drawn.append((segs, s["closed"]))
    assert len(out.contours) == len(drawn), (
        f"{where}: {len(out.contours)} contours, the reference draws {len(drawn)} subpaths")
    joints = corners = 0
    table = classify_joints(out)
    for ci, (contour, (segs, closed)) in enumerate(zip(out.contours, drawn, strict=True)):
        assert contour.closed == closed, where
        ours = list(contour.curve.segments)
        i = 0
        tangents = []  # (start, end) unit tangents per piece of ours, from the reference
        for kind, c in segs:
            if kind == "arc":
                r = max(float(c.rx), float(c.ry))
                end = _xy(c.end)
                j = i
                while not np.allclose(ours[j][-1], end, rtol=0, atol=eps):
                    j += 1
                n = j + 1 - i
                for m in range(n):
                    p = ours[i + m]
                    assert np.allclose(p[0], _xy(c.point(m / n)), rtol=0, atol=ARC_CENTRE * r + eps), where
                    mid = 0.125 * (p[0] + 3 * p[1] + 3 * p[2] + p[3])
                    assert np.allclose(mid, _xy(c.point((m + 0.5) / n)), rtol=0,
                                       atol=(1.01 * ARC_TOL + ARC_CENTRE) * r + eps), where
                t0, t1 = _tangents(kind, c)
                tangents += [(t0, None)] + [(None, None)] * (n - 2) + [(None, t1)] \
                    if n > 1 else [(t0, t1)]
                i = j + 1
            else:
                assert np.allclose(ours[i], c, rtol=0, atol=eps), (
                    f"{where}: segment {i} of contour {ci}: {ours[i].tolist()} vs {c.tolist()}")
                tangents.append(_tangents(kind, c))
                i += 1
        assert i == len(ours), f"{where}: {len(ours) - i} segments more than the reference"
        # joints: ours kind 'corner' exactly where the reference turns by > CORNER degrees
        rows = np.flatnonzero(table.contour == ci)
        for r_, j in zip(rows, table.joint[rows], strict=True):
            a, b = tangents[j][1], tangents[(j + 1) % len(tangents)][0]
            kind = table.kind[r_]
            if a is None or b is None:  # inside an arc: smooth
                assert kind in ("G1", "G2"), f"{where}: joint {j} inside an arc is {kind}"
                continue
            if kind == "singular":
                continue
            turn = _turn(a, b)
            if abs(turn - CORNER) < 0.01:
                continue  # at the threshold itself
            assert (kind == "corner") == (turn > CORNER), (
                f"{where}: contour {ci} joint {j} is {kind!r}; the reference turns {turn:.6g}°")
            joints += 1
            corners += kind == "corner"
    return {"contours": len(drawn), "joints": joints, "corners": corners,
            "skipped": out.skipped}


SOURCES = ["matplotlib", "jupyterlab", "environment", *THEMES]


@pytest.mark.parametrize("source", SOURCES)
def test_real_svg_paths_read_as_the_independent_parser_draws_them(source):
    if source in THEMES:
        _theme_or_skip(source)
    paths = corpus(source)
    assert paths, f"no SVG path found for {source}"
    totals = {"contours": 0, "joints": 0, "corners": 0, "skipped": 0}
    for where, d in paths:
        for k, v in compare(where, d).items():
            totals[k] += v
    assert totals["contours"] >= len(paths)
    print(f"{source}: {len(paths)} paths, {totals}")


def test_at_least_a_thousand_real_paths():
    _theme_or_skip(*THEMES)
    n = sum(len(corpus(s)) for s in SOURCES)
    assert n >= 1000, n


def test_inkscape_trailing_moveto_and_rounding_closing_lines_draw_nothing():
    """The two habits of real files that made the reader refuse or add false corners."""
    # Inkscape: "z m 0 0" at the end -- valid, draws nothing.
    out = svg_outline("m 2 2 l 4 0 l 0 4 z m 0 0")
    assert len(out.contours) == 1 and out.skipped == 1
    # Relative coordinates that close in decimal but not in binary (0.1 + 0.2 != 0.3):
    d = "m 0 0 l 0.1 0 l 0.2 0 l 0 1 l -0.3 0 l 0 -1 z"
    (c,) = svg_outline(d).contours
    assert c.curve.n_segments == 5  # no closing line of length 5.6e-17
    assert np.array_equal(c.curve.segments[-1][-1], c.curve.segments[0][0])
    t = classify_joints(svg_outline(d))
    assert t.kind.tolist().count("corner") == 4  # the rectangle's corners, no cusp
