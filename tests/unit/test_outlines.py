"""Tests of course_lib.constructions.outlines: glyphs and SVG path data read into PiecewiseBezier contours.

Independent references: fontTools' own pens (its decomposition of TrueType quadratic
runs and of composite glyphs, its exact bounding boxes), matplotlib's SVG path writer,
the course's continuity report (joint by joint), and hand-built paths whose joints were
worked out by hand.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from course_lib import PiecewiseBezier
from course_lib.constructions.outlines import (
    KINDS,
    Outline,
    bundled_fonts,
    classify_joints,
    font_glyph_names,
    font_summary,
    glyph_outline,
    glyph_summary,
    svg_file_outlines,
    svg_outline,
    truetype_contour,
    truetype_outline,
)
from course_lib.geometry.continuity import curve_continuity, joint_continuity

FONTS = ("DejaVuSans", "DejaVuSerif", "DejaVuSansMono", "STIXGeneral", "cmr10")
EM_TOL = 1e-12


def _sample_names(font: str, every: int) -> list[str]:
    names = font_glyph_names(font)
    return names[::every]


# Every 25th glyph of five fonts (about 660 glyphs), plus the lecture's letters.
SAMPLE = [(f, n) for f in FONTS for n in _sample_names(f, 25)]
LETTERS = [("DejaVuSans", n) for n in ("S", "O", "g", "at", "a", "u")]


# ------------------------------------------------------------------ fontTools references
def _pen_segments(font: str, name: str) -> list[list[np.ndarray]]:
    """Contours as lists of control polygons, drawn by fontTools' BasePen (its own
    decomposition of qCurveTo runs with implied on-curve points, and of components)."""
    from fontTools.pens.basePen import BasePen

    class Collect(BasePen):
        def __init__(self, glyphset):
            super().__init__(glyphset)
            self.contours, self.cur, self.start = [], None, None

        def _moveTo(self, p):
            self.contours.append([])
            self.cur = self.start = np.asarray(p, float)

        def _add(self, *pts):
            seg = np.vstack([self.cur, *[np.asarray(q, float) for q in pts]])
            if np.ptp(seg, axis=0).any():  # a zero-length segment draws nothing
                self.contours[-1].append(seg)
            self.cur = seg[-1]

        def _lineTo(self, p):
            self._add(p)

        def _qCurveToOne(self, p1, p2):
            self._add(p1, p2)

        def _curveToOne(self, p1, p2, p3):
            self._add(p1, p2, p3)

        def _closePath(self):
            if np.any(self.cur != self.start):
                self._add(self.start)

    from course_lib.constructions.outlines.fonts import load_font, resolve_font

    tt = load_font(str(resolve_font(font)))[0]
    gs = tt.getGlyphSet()
    pen = Collect(gs)
    gs[name].draw(pen)
    return [c for c in pen.contours if c]


@pytest.mark.parametrize(("font", "name"), SAMPLE)
def test_control_points_agree_with_fonttools_pens(font, name):
    ref = _pen_segments(font, name)
    got = glyph_outline(font=font, glyph=name)
    upem = _upem(font)
    assert len(got.contours) == len(ref)
    for c, r in zip(got.contours, ref, strict=True):
        assert c.closed
        assert c.curve.n_segments == len(r)
        for s, t in zip(c.curve.segments, r, strict=True):
            assert s.shape == t.shape
            assert np.max(np.abs(s - t / upem)) <= EM_TOL


@pytest.mark.parametrize(("font", "name"), SAMPLE[1::4] + LETTERS)
def test_on_and_off_curve_points_agree_with_fonttools_recording_pen(font, name):
    """fontTools' RecordingPen keeps TrueType's own form (qCurveTo with several off-curve
    points and implicit midpoints): its off-curve points are our quadratics' middle
    control points, and its on-curve points our non-implied joints, in order."""
    from fontTools.pens.recordingPen import DecomposingRecordingPen

    from course_lib.constructions.outlines.fonts import load_font, resolve_font

    gs = load_font(str(resolve_font(font)))[0].getGlyphSet()
    pen = DecomposingRecordingPen(gs)
    gs[name].draw(pen)
    off, on, contours = [], [], []
    for op, args in pen.value:
        if op == "moveTo":
            off, on = [], [args[0]]
        elif op == "lineTo":
            on.append(args[0])
        elif op == "qCurveTo":
            off += args[:-1]
            on += [] if args[-1] is None else [args[-1]]
        elif op in ("closePath", "endPath"):
            if off or len(on) > 1:
                contours.append((np.array(off, float), np.array(on, float)))
            off, on = [], []
    got = glyph_outline(font=font, glyph=name, em=False)
    if any((p == np.roll(p, 1, axis=0)).all(axis=1).any() for p, _ in got.points):
        pytest.skip("repeated points: zero-length segments were dropped")
    assert len(got.contours) == len(contours)
    for c, (off_, on_) in zip(got.contours, contours, strict=True):
        segs = c.curve.segments
        ends = [s[-1] for s, i in zip(segs, c.implied, strict=True) if not i]
        start = [] if c.implied[-1] else [segs[0][0]]  # all off-curve: no on-curve point
        mine_on = np.array([*start, *ends]).reshape(-1, 2)
        mine_off = np.array([s[1] for s in segs if s.shape[0] == 3]).reshape(-1, 2)
        assert np.array_equal(mine_off, off_.reshape(-1, 2))
        assert np.array_equal(_open(mine_on), _open(on_.reshape(-1, 2)))


def _open(P: np.ndarray) -> np.ndarray:
    """Drop a final point equal to the first (a closed list of on-curve points)."""
    return P[:-1] if len(P) > 1 and np.array_equal(P[0], P[-1]) else P


def _upem(font: str) -> float:
    from course_lib.constructions.outlines.fonts import load_font, resolve_font

    return load_font(str(resolve_font(font)))[3]


def _exact_bounds(outline: Outline) -> np.ndarray:
    """Tight bounds from the segments' end points and the roots of their derivatives
    (quadratics: one root per coordinate; fonts here have no cubics)."""
    pts = []
    for c in outline.contours:
        for s in c.curve.segments:
            pts += [s[0], s[-1]]
            if s.shape[0] == 3:
                den = s[0] - 2 * s[1] + s[2]
                with np.errstate(divide="ignore", invalid="ignore"):
                    u = np.where(den != 0, (s[0] - s[1]) / den, -1.0)
                for k in range(2):
                    if 0 < u[k] < 1:
                        w = u[k]
                        pts.append((1 - w) ** 2 * s[0] + 2 * w * (1 - w) * s[1] + w**2 * s[2])
    P = np.array(pts)
    return np.concatenate([P.min(axis=0), P.max(axis=0)])


@pytest.mark.parametrize(("font", "name"), SAMPLE[::3] + LETTERS)
def test_bounding_boxes_agree_with_fonttools_bounds_pen(font, name):
    from fontTools.pens.boundsPen import BoundsPen

    from course_lib.constructions.outlines.fonts import load_font, resolve_font

    tt = load_font(str(resolve_font(font)))[0]
    gs = tt.getGlyphSet()
    pen = BoundsPen(gs)
    gs[name].draw(pen)
    got = glyph_outline(font=font, glyph=name)
    if pen.bounds is None:
        assert got.n_segments == 0
        return
    ref = np.array(pen.bounds) / _upem(font)
    mine = _exact_bounds(got)
    if got.skipped:  # BoundsPen also counts the skipped one-point contours (anchors)
        assert np.all(mine[:2] >= ref[:2] - EM_TOL) and np.all(mine[2:] <= ref[2:] + EM_TOL)
    else:
        assert np.max(np.abs(mine - ref)) <= EM_TOL


@pytest.mark.parametrize("char", list("SOg@"))
def test_by_character_equals_by_glyph_name_and_units(char):
    by_char = glyph_outline(char)
    name = by_char.name
    by_name = glyph_outline(glyph=name)
    units = glyph_outline(char, em=False)
    assert units.scale == 1.0 and by_char.scale == 2048.0  # DejaVu Sans: 2048 units per em
    for a, b, c in zip(by_char.contours, by_name.contours, units.contours, strict=True):
        for s, t, u in zip(a.curve.segments, b.curve.segments, c.curve.segments, strict=True):
            assert np.array_equal(s, t)
            assert np.allclose(s * 2048.0, u, rtol=0, atol=1e-9)


# ------------------------------------------------------------------ continuity properties
@settings(max_examples=150, deadline=None)
@given(st.sampled_from(FONTS), st.integers(min_value=0, max_value=10**6))
def test_every_contour_closes_and_every_implied_point_is_g1(font, k):
    names = font_glyph_names(font)
    out = glyph_outline(font=font, glyph=names[k % len(names)])
    t = classify_joints(out)
    for c in out.contours:
        segs = c.curve.segments
        # G0 everywhere, the closing joint included: each segment starts where the last ended.
        ends = np.array([s[-1] for s in segs])
        starts = np.array([s[0] for s in segs[1:] + segs[:1]])
        assert np.max(np.abs(ends - starts)) <= EM_TOL
    assert np.all(t.gap <= EM_TOL)
    # At an implied on-curve point both tangents point along off_2 - off_1: G1 to 1e-9 rad.
    assert np.all(np.radians(t.angle[t.implied & t.regular]) <= 1e-9)
    assert np.all(t.g_order[t.implied & t.regular] >= 1)


def _report_orders(outline: Outline) -> list[tuple[int, int, int]]:
    """(contour, joint, G-order) from the continuity report, closing joints included."""
    return [(ci, j, r.g_order) for ci, j, r in _reports(outline)]


def _reports(outline: Outline) -> list[tuple[int, int, object]]:
    """(contour, joint, JointReport) of every joint, closing joints included."""
    rows = []
    for ci, c in enumerate(outline.contours):
        cur = c.curve
        reports = curve_continuity(cur, max_order=2) if cur.n_segments > 1 else []
        if c.closed:
            last = cur.segment_curve(cur.n_segments - 1)
            reports.append(joint_continuity(last, cur.segment_curve(0), max_order=2))
        rows += [(ci, j, r) for j, r in enumerate(reports)]
        assert all(r.characterizations_agree for r in reports)
    return rows


@pytest.mark.parametrize(
    ("font", "name"), [*SAMPLE[::11], ("DejaVuSans", "O"), ("DejaVuSans", "S")]
)
def test_vectorized_g_order_agrees_with_continuity_report(font, name):
    out = glyph_outline(font=font, glyph=name)
    t = classify_joints(out)
    if not t.regular.all():
        pytest.skip("a singular joint: the continuity report refuses non-regular pieces")
    # Both call the joint kernel, but by different paths: the table assembles every
    # contour's joints (closing joints by index) from control points in font units; the
    # report evaluates each pair of pieces, rescales the joint, and its g_order is the
    # Beta-constraints' verdict (seed 000 §5), not the kernel's arc-length one (§6).
    reports = _reports(out)
    assert len(reports) == len(t)
    assert [(ci, j) for ci, j, _ in reports] == list(
        zip(t.contour.tolist(), t.joint.tolist(), strict=True)
    )
    assert [r.g_order for _, _, r in reports] == t.g_order.tolist()
    np.testing.assert_allclose([r.gap for _, _, r in reports], t.gap, rtol=0, atol=1e-9)
    np.testing.assert_allclose([r.tangent_angle for _, _, r in reports], t.angle, atol=1e-7)
    # At a G1 joint the curvature vectors share a normal: |K_r - K_q| = |kappa_r - kappa_q|.
    g1 = t.g_order >= 1
    jump = np.array([r.curvature_jump for _, _, r in reports])
    np.testing.assert_allclose(
        jump[g1], np.abs(t.kappa_out - t.kappa_in)[g1], rtol=1e-7, atol=1e-12
    )
    # The designer's kinds agree with the report where the tangent is exactly continuous.
    exact = t.g_order >= 1
    assert np.array_equal(t.kind[exact] == "G2", t.g_order[exact] == 2)


def test_glyphs_with_singular_joints_are_flagged_not_reported():
    # uni01BA has two equal consecutive points (an off-curve point on an on-curve point):
    # that end of a quadratic has a zero derivative.
    t = classify_joints(glyph_outline(glyph="uni01BA"))
    assert (t.kind == "singular").sum() >= 1
    assert np.all(np.isnan(t.kappa_in[~t.regular]) | np.isnan(t.kappa_out[~t.regular]))


# ------------------------------------------------------------------ SVG path data
# q: (0,0) (1,0) (2,1) (3,1):  q'(1) = 3((3,1)-(2,1)) = (3,0),  q''(1) = 6((3,1)-2(2,1)+(1,0)) = (0,-6).
# r with beta1 = 2, beta2 = 1 (000 eq. 7): r'(0) = 2 q'(1) = (6,0) -> R1 = (3,1) + (2,0) = (5,1);
# r''(0) = 4 q''(1) + q'(1) = (3,-24) = 6 (R2 - 2 R1 + R0) -> R2 = (0.5,-4) + (10,2) - (3,1) = (7.5,-3).
# Joint (3,1): G2, not C1.  Joint (9,-3): tangent (1.5,0) then (0,-3): a 90° corner.
# Closing line (9,-6) -> (0,0): turn from (0,-1) to (-9,6)/|.|: 180 - atan2(9, 6) = 123.69°;
# then at (0,0) from (-9,6) to (1,0): 180 - atan2(6, 9) = 146.31°.
HAND = "M0 0 C1 0 2 1 3 1 C5 1 7.5 -3 9 -3 L 9 -6 Z"
HAND_REL = "m0 0 c1 0 2 1 3 1 c2 0 4.5 -4 6 -4 v-3 z"


def test_hand_built_svg_g2_joint_and_corners():
    out = svg_outline(HAND)
    (c,) = out.contours
    assert c.closed and c.curve.n_segments == 4
    t = classify_joints(out)
    assert t.kind.tolist() == ["G2", "corner", "corner", "corner"]
    assert t.g_order.tolist() == [2, 0, 0, 0]
    expected = [
        0.0,
        90.0,
        180 - math.degrees(math.atan2(9, 6)),
        180 - math.degrees(math.atan2(6, 9)),
    ]
    assert np.allclose(t.angle, expected, atol=1e-12)
    rep = joint_continuity(c.curve.segment_curve(0), c.curve.segment_curve(1))
    assert rep.g_order >= 2 and rep.c_order == 0
    assert np.allclose(rep.betas[:2], [2.0, 1.0])


def test_relative_and_shorthand_commands_read_like_absolute_ones():
    a, b = svg_outline(HAND), svg_outline(HAND_REL)
    for s, t in zip(a.contours[0].curve.segments, b.contours[0].curve.segments, strict=True):
        assert np.allclose(s, t, rtol=0, atol=1e-15)


def test_quadratic_shorthand_t_is_c1_like_a_truetype_implied_point():
    # T reflects the control point (1,2) about (2,0): (3,-2); the joint is C1, so G1.
    (c,) = svg_outline("M0 0 Q1 2 2 0 T4 0").contours
    assert np.array_equal(c.curve.segments[1], [[2, 0], [3, -2], [4, 0]])
    (rep,) = curve_continuity(c.curve, max_order=2)
    assert rep.c_order >= 1 and rep.g_order >= 1
    # Not G2: q''(1) = 2((2,0) - 2(1,2) + (0,0)) = (0,-8) and r''(0) = (0,8) with the same
    # q'(1) = r'(0) = (2,-4): the signed curvature flips from -16/|q'|^3 to +16/|q'|^3.
    t = classify_joints(svg_outline("M0 0 Q1 2 2 0 T4 0"))
    assert t.kind.tolist() == ["G1"]
    assert np.allclose([t.kappa_in[0], t.kappa_out[0]], np.array([-16, 16]) / 20**1.5)


def test_cubic_shorthand_s_reflects_the_last_control_point():
    # S reflects (2,1) about (3,1): the new first control point is (4,1), a C1 joint.
    (c,) = svg_outline("M0 0 C1 0 2 1 3 1 S 7.5 -3 9 -3").contours
    assert np.array_equal(c.curve.segments[1][1], [4, 1])
    assert curve_continuity(c.curve, max_order=2)[0].c_order >= 1


def test_h_v_and_implicit_lineto():
    (c,) = svg_outline("M 1 1 2 1 h 1 V 3 l -1 0 H 1 z").contours
    P = np.array([s[0] for s in c.curve.segments] + [c.curve.segments[-1][-1]])
    assert np.array_equal(P, [[1, 1], [2, 1], [3, 1], [3, 3], [2, 3], [1, 3], [1, 1]])


def test_leading_whitespace_and_compact_numbers():
    (c,) = svg_outline("  \n M0,0L1-1.5.5 1e1z").contours
    assert np.array_equal(c.curve.segments[1], [[1, -1.5], [0.5, 10]])
    (c,) = svg_outline("M0 0 a1 1 0 1010 0").contours  # compact arc flags: 1, 0, then 10 0
    assert np.array_equal(c.curve.segments[-1][-1], [10, 0])


def test_several_subpaths_and_command_after_close():
    out = svg_outline("M0 0 L1 0 L1 1 Z L 0 1 M 5 5 L 6 6")
    assert [c.closed for c in out.contours] == [True, False, False]
    # After Z the current point is the subpath's start (0,0).
    assert np.array_equal(out.contours[1].curve.segments[0], [[0, 0], [0, 1]])


@settings(max_examples=60, deadline=None)
@given(
    st.lists(
        st.tuples(
            st.sampled_from([2, 3, 4]), st.lists(st.integers(-500, 500), min_size=6, max_size=6)
        ),
        min_size=1,
        max_size=8,
    ),
    st.booleans(),
)
def test_matplotlib_svg_writer_round_trip(pieces, close):
    """Paths written by matplotlib's own SVG backend code are read back exactly."""
    from matplotlib import _path
    from matplotlib.path import Path as MPath

    verts, codes, segs = [(0.0, 0.0)], [MPath.MOVETO], []
    cur = np.zeros(2)
    for code, xy in pieces:
        n = {2: 1, 3: 2, 4: 3}[code]
        pts = np.array(xy[: 2 * n], float).reshape(n, 2) / 8.0
        verts += [tuple(p) for p in pts]
        codes += [code] * n
        seg = np.vstack([cur, pts])
        if np.ptp(seg, axis=0).any():
            segs.append(seg)
        cur = pts[-1]
    if close:
        verts.append((0.0, 0.0))
        codes.append(MPath.CLOSEPOLY)
        if np.any(cur != 0):
            segs.append(np.array([cur, [0.0, 0.0]]))
    if not segs:
        return
    path = MPath(verts, codes)
    d = _path.convert_to_string(
        path, None, None, False, None, 17, [b"M", b"L", b"Q", b"C", b"z"], False
    )
    (c,) = svg_outline(d.decode("ascii")).contours
    assert c.closed == close
    assert len(c.curve.segments) == len(segs)
    for s, t in zip(c.curve.segments, segs, strict=True):
        assert np.array_equal(s, t)


def test_matplotlib_toolbar_icons_read_and_closed_contours_close():
    from pathlib import Path

    import matplotlib

    files = sorted(Path(matplotlib.get_data_path(), "images").glob("*.svg"))
    assert len(files) >= 10
    n = 0
    for f in files:
        for out in svg_file_outlines(f):
            t = classify_joints(out)
            assert set(t.kind) <= set(KINDS) - {"gap"}
            n += out.n_joints
    assert n > 100


# ------------------------------------------------------------------ arcs
def _radial_error(c, center, rx, ry, phi=0.0) -> float:
    u = np.linspace(0, 1, 201)
    R = np.array([[math.cos(phi), math.sin(phi)], [-math.sin(phi), math.cos(phi)]])
    err = 0.0
    for i in range(c.curve.n_segments):
        p = (c.curve.evaluate_segment(i, u) - center) @ R.T / [rx, ry]
        err = max(err, float(np.max(np.abs(np.hypot(p[:, 0], p[:, 1]) - 1))))
    return err


@pytest.mark.parametrize("tol", [1e-3, 1e-6, 1e-9])
def test_arc_is_within_tolerance_of_the_ellipse(tol):
    # Semicircle from (0,0) to (10,0), radius 5, sweep 1 (angle increasing): the centre is
    # (5,0) and the arc passes (5,-5) (SVG's y axis points down; here just coordinates).
    (c,) = svg_outline("M0 0 A5 5 0 0 1 10 0", arc_tolerance=tol).contours
    assert _radial_error(c, np.array([5.0, 0.0]), 5, 5) <= tol * 1.0001
    mid = np.vstack(
        [c.curve.evaluate_segment(i, np.linspace(0, 1, 401)) for i in range(c.curve.n_segments)]
    )
    assert np.min(np.linalg.norm(mid - [5, -5], axis=1)) <= 5 * tol + 1e-3 * 5 * math.pi / 400
    assert np.array_equal(c.curve.segments[-1][-1], [10.0, 0.0])


def test_rotated_ellipse_arc_and_its_pieces_meet_g2():
    # Ellipse rx=4, ry=2 rotated by 30°, centred at the origin: its points at angles
    # 0 and 180° of the ellipse parameter are ±(4 cos30°, 4 sin30°).
    a = np.array([4 * math.cos(math.pi / 6), 4 * math.sin(math.pi / 6)])
    d = f"M{a[0]} {a[1]} A4 2 30 1 1 {-a[0]} {-a[1]} A4 2 30 1 1 {a[0]} {a[1]} Z"
    out = svg_outline(d, arc_tolerance=1e-8)
    (c,) = out.contours
    assert _radial_error(c, np.zeros(2), 4, 2, math.pi / 6) <= 1e-8
    t = classify_joints(out)
    # Affine images of the circle's symmetric pieces: every joint, the closing one too, is G2.
    assert set(t.kind) == {"G2"}


def test_arcs_refused_with_position():
    with pytest.raises(ValueError, match=r"arc 'a' at position 10: arcs are refused"):
        svg_outline("M0 0 L1 1 a 1 1 0 0 1 2 0", arcs="refuse")


def test_degenerate_arcs_follow_the_svg_rules():
    (c,) = svg_outline("M0 0 A0 3 0 0 1 4 0").contours  # zero radius: a straight line
    assert np.array_equal(c.curve.segments[0], [[0, 0], [4, 0]])
    # A radius too small is scaled up (SVG F.6.6): a half ellipse through both ends.
    (c,) = svg_outline("M0 0 A1 1 0 0 1 4 0").contours
    assert _radial_error(c, np.array([2.0, 0.0]), 2, 2) <= 1e-6


# ------------------------------------------------------------------ bad input
BAD_PATHS = [
    ("", r"empty.*position 0"),
    ("   ", r"empty.*position 0"),
    ("L 1 1", r"begin with a moveto.*'L' at position 0"),
    ("M 0 0 X 1 1", r"unexpected token 'X' at position 6"),
    ("M0 0 L 1", r"command 'L' at position 5 needs 2 numbers"),
    ("M0,0 L1,1 2", r"command 'L' at position 10 needs 2 numbers"),
    ("M0 0 L 1 1e", r"unexpected token 'e' at position 10"),
    ("M0 0 C 1 1 2 2 x 3", r"expected a number at position 15 for command 'C' at position 5"),
    ("M0 0 A 1 1 0 2 0 3 3", r"arc flag '2' at position 13"),
]
# More malformed strings (commas, digits, overflow, arcs): tests/unit/test_svg_path.py.


@pytest.mark.parametrize(("d", "message"), BAD_PATHS)
def test_malformed_path_data_names_token_and_position(d, message):
    with pytest.raises(ValueError, match=message):
        svg_outline(d)


def test_bad_arguments():
    with pytest.raises(TypeError, match="path data must be a str"):
        svg_outline(None)
    with pytest.raises(ValueError, match="arcs must be"):
        svg_outline("M0 0 L1 1", arcs="approximate")
    with pytest.raises(ValueError, match="arc_tolerance"):
        svg_outline("M0 0 L1 1", arc_tolerance=0)
    with pytest.raises(TypeError, match="outline must be an Outline"):
        classify_joints(PiecewiseBezier([[[0, 0], [1, 1]]]))
    with pytest.raises(ValueError, match="corner_angle"):
        classify_joints(svg_outline("M0 0 L1 1"), corner_angle=-1)


def test_bad_font_input(tmp_path):
    with pytest.raises(ValueError, match=r"no glyph for the character '\\u2fff' \(U\+2FFF\)"):
        glyph_outline("\u2fff")
    with pytest.raises(ValueError, match="no glyph named 'no-such-glyph'"):
        glyph_outline(glyph="no-such-glyph")
    with pytest.raises(ValueError, match="DejaVuSans has no glyph named 'nope'"):
        font_summary(glyphs=["a", "nope"])
    with pytest.raises(ValueError, match="single character"):
        glyph_outline("ab")
    with pytest.raises(TypeError, match="exactly one of char"):
        glyph_outline("a", glyph="a")
    with pytest.raises(ValueError, match=r"not one of matplotlib's bundled fonts.*DejaVuSans"):
        glyph_outline("a", font="Comic Sans")
    fake = tmp_path / "fake.ttf"
    fake.write_text("this is not a font")
    with pytest.raises(ValueError, match=r"fake\.ttf' is not a TrueType font"):
        glyph_outline("a", font=fake)
    with pytest.raises(ValueError, match="does not exist"):
        glyph_outline("a", font=tmp_path / "missing.ttf")
    svg = tmp_path / "bad.svg"
    svg.write_text("<svg><path d='M 0 0 Q 1'/></svg>")
    with pytest.raises(ValueError, match=r"bad\.svg, path 0: command 'Q' at position 6"):
        svg_file_outlines(svg)
    svg.write_text("not xml")
    with pytest.raises(ValueError, match=r"bad\.svg' is not a readable SVG file"):
        svg_file_outlines(svg)


# ------------------------------------------------------------------ summaries
def test_anchor_contours_are_skipped_and_counted():
    # DejaVu Sans 'u' carries a one-point contour (an anchor that draws nothing).
    out = glyph_outline("u")
    assert out.skipped == 1
    assert all(c.curve.n_segments >= 1 for c in out.contours)


def test_summaries_add_up():
    names = ["O", "S", "g", "at", "space", "u"]
    fs = font_summary("DejaVuSans", glyphs=names)
    for g in fs.glyphs:
        assert g.joints == g.corners + g.g1 + g.g2 + g.singular + g.gaps
        assert g.joints == glyph_outline(glyph=g.name).n_joints
    space = fs.glyphs[names.index("space")]
    assert space.joints == 0 and space.contours == 0
    # 'O' in DejaVu Sans has no corner: every point of its two contours is smooth.
    o = fs.glyphs[0]
    assert o.corners == 0 and o.smooth == o.joints == 16
    assert 0 < fs.g2_share < 1
    assert "DejaVuSans: 6 glyphs" in str(fs)
    assert glyph_summary(glyph_outline("O")) == o


def test_bundled_fonts_are_found():
    fonts = bundled_fonts()
    assert {"DejaVuSans", "DejaVuSerif", "STIXGeneral"} <= set(fonts)
    assert glyph_outline("a", font="DejaVu Serif").source.endswith("DejaVuSerif.ttf")


def test_benchmark_item_runs_on_tiny_sizes(monkeypatch):
    from pathlib import Path

    bench = Path(__file__).resolve().parents[2] / "benchmarks"
    monkeypatch.syspath_prepend(str(bench))
    import bench_common
    import bench_outlines

    (row,) = bench_outlines.run(bench_common.TINY)
    assert row.item == "7" and row.ours > 0 and row.reference > 0
    assert row.extra["glyphs"] == 40 and row.extra["joints"] > 0


def test_truetype_outline_rebuilds_a_glyph_from_its_points():
    g = glyph_outline("S")
    again = truetype_outline(g.points)
    for a, b in zip(g.contours, again.contours, strict=True):
        for s, t in zip(a.curve.segments, b.curve.segments, strict=True):
            assert np.array_equal(s, t)
    # Two off-curve points only: the contour is two quadratics through the two implied
    # midpoints (0.5, 0) and (0.5, 0): it starts at the midpoint of the last and first.
    c = truetype_contour([[0.0, 1.0], [1.0, -1.0]], [False, False])
    assert c.implied.tolist() == [True, True]
    assert np.array_equal(c.curve.segments[0], [[0.5, 0.0], [0.0, 1.0], [0.5, 0.0]])


@pytest.mark.parametrize(
    ("points", "flags", "message"),
    [
        ([[0.0, 0.0]], [True], "at least 2 points"),
        ([[0.0, 0.0], [1.0, 1.0]], [True], "one flag per point"),
        ([[1.0, 1.0], [1.0, 1.0]], [True, False], "all coincide"),
        ([[0.0, np.nan], [1.0, 1.0]], [True, True], "finite"),
    ],
)
def test_truetype_contour_bad_input(points, flags, message):
    with pytest.raises(ValueError, match=message):
        truetype_contour(points, flags)


# ------------------------------------------------------------------ plotting and the demo
def _mouse(canvas, kind, xy_px, button=1):
    from matplotlib.backend_bases import MouseEvent

    ev = MouseEvent(kind, canvas, float(xy_px[0]), float(xy_px[1]), button=button)
    canvas.callbacks.process(kind, ev)


def test_plot_outline_marks_every_joint_by_kind_and_updates_in_place():
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    from course_lib.plotting import plot_outline

    out = glyph_outline("g")
    fig = Figure()
    ax = fig.add_subplot()
    art = plot_outline(ax, out)
    t = classify_joints(out)
    for kind, line in art.marks.items():
        x, y = line.get_data()
        assert np.array_equal(np.column_stack([x, y]), t.point[t.kind == kind])
    assert sum(len(line.get_xdata()) for line in art.marks.values()) == len(t)
    assert len(art.curves) == len(art.combs) == len(out.contours)
    # Teeth of one comb scale for every contour: tooth length = scale * |curvature|.
    teeth = art.combs[0].tooth_array()
    assert np.all(np.linalg.norm(teeth[:, 1] - teeth[:, 0], axis=1) >= 0)
    assert art.comb_scale == art.combs[1].scale
    with pytest.raises(ValueError, match="marks must be among"):
        plot_outline(ax, out, marks=("bumps",))


def test_glyph_demo_drag_changes_comb_and_report():
    from course_lib.widgets import glyph_demo

    demo = glyph_demo("O", static=False)
    st = demo.state
    assert st.counts()["corner"] == 0 and "cl-joint-report" in demo.report.value
    before = demo.view.artists.combs[0].tooth_array().copy()
    P = st.offcurve_points()
    st.drag(0, P[0, 0] + 0.05, P[0, 1] + 0.05)
    after = demo.view.artists.combs[0].tooth_array()
    assert not np.allclose(before, after)
    assert "joints next to the moved point" in demo.report.value
    assert np.allclose(st.offcurve_points()[0], P[0] + 0.05)
    assert len({tuple(c) for c in demo.view.artists.curves[0].segments.get_colors()}) == 1
    # Dragging with the mouse through the canvas moves the same point.
    canvas = demo.figure.canvas
    demo.figure.canvas.draw()
    ax = demo.view.ax
    start = ax.transData.transform(st.offcurve_points()[1])
    _mouse(canvas, "button_press_event", start)
    _mouse(canvas, "motion_notify_event", start + np.array([0.0, 20.0]))
    _mouse(canvas, "button_release_event", start + np.array([0.0, 20.0]))
    assert st.offcurve_points()[1, 1] > P[1, 1]
    # Another character and font: new artists; a missing character shows a warning.
    demo.controls["char"].value = "g"
    assert st.outline.name == "g" and st.counts()["corner"] > 0
    demo.controls["font"].value = "DejaVuSerif"
    assert st.font == "DejaVuSerif"
    demo.controls["char"].value = "\u2fff"
    assert "no glyph for the character" in demo.warning.value and st.outline.name == "g"


def test_glyph_demo_static_figure():
    from course_lib.widgets import glyph_demo

    demo = glyph_demo("@", static=True)
    assert demo.widget is None and "image/png" in demo._repr_mimebundle_()
    with pytest.raises(ValueError, match="no glyph for the character"):
        glyph_demo("\u2fff", static=True)
