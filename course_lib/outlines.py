"""Real outlines as course curves: TrueType glyphs and SVG path data, and their joints.

Everything else in the course was drawn for the course.  This module reads outlines that
nobody here drew -- the letters of the fonts matplotlib ships, and SVG path data such as
matplotlib's toolbar icons -- into the course's one curve type, one
:class:`~course_lib.curve.PiecewiseBezier` per contour, and classifies every joint.

Reading
-------
* :func:`glyph_outline` -- a TrueType glyph (by character or by glyph name) from a font
  file, read with fontTools from the raw ``glyf`` points.  TrueType contours are
  quadratic: between two consecutive off-curve points lies an *implied* on-curve point,
  their midpoint, which is made explicit here.  Units are kept (font units) or
  normalised to the em (``em=True``, default).  One-point contours (anchors that draw
  nothing) are skipped and counted; zero-length segments (repeated points) are dropped.
* :func:`svg_outline` -- SVG path data (``d`` strings: ``M L H V C S Q T A Z``, absolute
  and relative), parsed by a strict scanner of the SVG 1.1 path grammar that names the
  offending token and its position, and read as a browser draws them: subpaths of one
  point and closing lines within rounding of the path's size are dropped (they draw
  nothing), no point is ever infinite.  Elliptical arcs ``A`` are converted to cubics whose
  distance from the true ellipse is at most ``arc_tolerance`` times its larger radius,
  or refused (``arcs="refuse"``).

Analysis
--------
:func:`classify_joints` computes, for every joint of an outline (the closing joint of a
closed contour included, as the last joint of that contour), the gap, the tangent
angle, the signed curvature on both sides and the curvature jump relative to the local
curvature, all vectorized.  Two verdicts:

* ``g_order`` (-1, 0, 1, 2): the strict G-order with the rule and tolerance of
  :func:`~course_lib.continuity.joint_continuity` (``rtol = 1e-8``; arc-length
  characterization, seed 000 §6: unit tangents agree to ``rtol``, curvature vectors to
  ``rtol`` times ``max(|K_q|, |K_r|, 1/l)``).  Tests check it against the continuity
  report joint by joint on samples of real glyphs.
* ``kind`` -- the type designer's view: ``"corner"`` where the tangent turns by more
  than ``corner_angle`` degrees; otherwise a smooth point, ``"G2"`` if the curvature
  jump relative to the local curvature is at most ``curvature_rtol``, else ``"G1"``.
  ``"singular"`` where a side has a vanishing derivative, ``"gap"`` where the pieces do
  not meet.

:func:`glyph_summary` and :func:`font_summary` count joints, corners, G1 and G2 smooth
points per glyph and per font.

Lesson: ``notebooks/11_are_letters_smooth.ipynb``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

import numpy as np

from . import own_work
from ._svg_path import svg_subpaths
from ._validation import as_points, check_finite_scalar
from .curve import PiecewiseBezier

__all__ = [
    "KINDS",
    "Contour",
    "FontSummary",
    "GlyphSummary",
    "JointTable",
    "Outline",
    "bundled_fonts",
    "classify_joints",
    "font_glyph_names",
    "font_summary",
    "glyph_outline",
    "glyph_summary",
    "svg_file_outlines",
    "svg_outline",
    "truetype_contour",
    "truetype_outline",
]

#: Joint kinds of :func:`classify_joints`, in this order.
KINDS = ("gap", "singular", "corner", "G1", "G2")

#: Tolerance of the strict G-order, the default of :func:`~course_lib.continuity.joint_continuity`.
RTOL = 1e-8


# ==================================================================== data types
@dataclass(frozen=True)
class Contour:
    """One contour of an outline.

    Attributes
    ----------
    curve : PiecewiseBezier
        The segments in drawing order.  A closed contour ends where it starts.
    closed : bool
        True for a closed contour: it has a *closing joint* (last segment to first),
        counted as its last joint.
    implied : ndarray of bool
        One entry per joint (``n_joints`` of the curve, plus the closing joint): True
        where the joint is an implied TrueType on-curve point (the midpoint of two
        off-curve points).  All False for SVG data.
    """

    curve: PiecewiseBezier
    closed: bool
    implied: np.ndarray

    @property
    def n_joints(self) -> int:
        """Joints including the closing joint of a closed contour."""
        return self.curve.n_segments - 1 + int(self.closed)


@dataclass(frozen=True)
class Outline:
    """An outline: a glyph or an SVG path, as a list of contours.

    Attributes
    ----------
    contours : tuple of Contour
    name : str
        Glyph name, or ``"svg path"``.
    source : str
        Font file or description of the data.
    scale : float
        Units per drawing unit: ``units_per_em`` if the glyph was normalised to the em,
        else 1.
    skipped : int
        One-point contours skipped while reading (TrueType anchors, SVG subpaths of one
        point: they draw nothing).
    points : tuple of (ndarray (n, 2), ndarray of bool (n,))
        For TrueType outlines: the raw points of each contour and their on-curve flags
        (the data :func:`truetype_outline` rebuilds the contours from); empty for SVG.
    """

    contours: tuple[Contour, ...]
    name: str
    source: str = ""
    scale: float = 1.0
    skipped: int = 0
    points: tuple = ()

    @property
    def n_joints(self) -> int:
        return sum(c.n_joints for c in self.contours)

    @property
    def n_segments(self) -> int:
        return sum(c.curve.n_segments for c in self.contours)


# ==================================================================== TrueType
_FONT_DIR_PARTS = ("fonts", "ttf")


def _font_dir() -> Path:
    """matplotlib's ``mpl-data/fonts/ttf``, found without importing matplotlib (a math
    module imports no plotting library)."""
    from importlib.util import find_spec

    spec = find_spec("matplotlib")
    if spec is None or not spec.submodule_search_locations:
        raise ValueError("matplotlib is not installed: its bundled fonts are not available")
    return Path(spec.submodule_search_locations[0], "mpl-data", *_FONT_DIR_PARTS)


def bundled_fonts() -> dict[str, Path]:
    """The TrueType fonts that matplotlib ships, by file stem (``"DejaVuSans"``, ...)."""
    return {p.stem: p for p in sorted(_font_dir().glob("*.ttf"))}


def _resolve_font(font: object) -> Path:
    if isinstance(font, Path) or (
        isinstance(font, str) and ("/" in font or font.endswith((".ttf", ".otf")))
    ):
        path = Path(font)
        if not path.is_file():
            raise ValueError(f"font file {str(path)!r} does not exist")
        return path
    if not isinstance(font, str):
        raise TypeError(f"font must be a font name or a file path, got {type(font).__name__}")
    fonts = bundled_fonts()
    key = font.replace(" ", "")
    if key not in fonts:
        raise ValueError(
            f"font {font!r} is not one of matplotlib's bundled fonts; choose one of "
            f"{', '.join(sorted(fonts))} or pass a file path"
        )
    return fonts[key]


@lru_cache(maxsize=16)
def _load_font(path: str):
    from fontTools.ttLib import TTFont  # lazily: fontTools is needed only to read fonts

    try:
        font = TTFont(path, lazy=True)
        glyf, cmap, upem = font["glyf"], font.getBestCmap() or {}, font["head"].unitsPerEm
        hmtx = font["hmtx"]
    except Exception as exc:  # fontTools raises many types for a file that is not a font
        raise ValueError(
            f"{path!r} is not a TrueType font with quadratic outlines (a 'glyf' table): "
            f"{type(exc).__name__}: {exc}"
        ) from None
    return font, glyf, cmap, float(upem), hmtx


def font_glyph_names(font: object = "DejaVuSans") -> list[str]:
    """All glyph names of a font, in the font's glyph order."""
    return list(_load_font(str(_resolve_font(font)))[0].getGlyphOrder())


def _truetype_contours(
    P: np.ndarray, on: np.ndarray, ends: np.ndarray
) -> list[tuple[list[np.ndarray], np.ndarray]]:
    """Segments of the closed TrueType contours of one glyph, implied points explicit.

    ``P`` (n, 2) and ``on`` (n,) hold all points, contour ``c`` ending at index
    ``ends[c]``.  Between two consecutive off-curve points the implied on-curve point
    (their midpoint) is inserted.  Each contour starts at its first on-curve point (or,
    if it has none, at the midpoint of its last and first points), as fontTools' pens
    draw it, and ends there again.  Returns, per contour, its segments (zero-length ones
    dropped) and whether each segment's end point is an implied on-curve point.
    Vectorized over all points of the glyph.
    """
    n, C = P.shape[0], ends.size
    starts = np.concatenate([[0], ends[:-1] + 1])
    cid = np.repeat(np.arange(C), ends - starts + 1)
    nxt = np.arange(1, n + 1)
    nxt[ends] = starts
    # Interleave: point i, then (if i and i+1 are both off-curve) the midpoint of i, i+1.
    pts = np.empty((2 * n, 2))
    pts[0::2], pts[1::2] = P, 0.5 * (P + P[nxt])
    flag = np.empty(2 * n, bool)
    flag[0::2], flag[1::2] = on, True
    implied = np.zeros(2 * n, bool)
    implied[1::2] = True
    keep = np.ones(2 * n, bool)
    keep[1::2] = ~on & ~on[nxt]
    pts, flag, implied, kc = pts[keep], flag[keep], implied[keep], np.repeat(cid, 2)[keep]
    m = np.bincount(kc, minlength=C)
    base = np.concatenate([[0], np.cumsum(m)[:-1]])
    # Local index of each contour's first explicit on-curve point (default: the last
    # point, the midpoint of the last and first off-curve points).
    first = m - 1
    explicit = np.flatnonzero(flag & ~implied)[::-1]
    first[kc[explicit]] = explicit - base[kc[explicit]]
    # Each contour rotated to its start, the start repeated at the end.
    lens = m + 1
    local = np.arange(lens.sum()) - np.repeat(np.cumsum(lens) - lens, lens)
    order = np.repeat(base, lens) + (local + np.repeat(first, lens)) % np.repeat(m, lens)
    ext, ext_on, ext_implied = pts[order], flag[order], implied[order]
    ext_c = np.repeat(np.arange(C), lens)
    k = np.flatnonzero(ext_on)
    a, b = k[:-1], k[1:]
    same = ext_c[a] == ext_c[b]
    a, b = a[same], b[same]
    moves = np.append(np.any(ext[1:] != ext[:-1], axis=1), False)
    nonzero = moves[a] | ((b - a == 2) & moves[a + 1])
    a, b = a[nonzero], b[nonzero]
    seg_c = ext_c[a]
    segs = [ext[i : j + 1] for i, j in zip(a.tolist(), b.tolist(), strict=True)]
    bounds = np.searchsorted(seg_c, np.arange(C + 1))
    ends_implied = ext_implied[b]
    return [
        (segs[bounds[c] : bounds[c + 1]], ends_implied[bounds[c] : bounds[c + 1]]) for c in range(C)
    ]


def truetype_contour(points: object, on_curve: object) -> Contour:
    """One closed TrueType contour from its points and on-curve flags.

    Between two consecutive off-curve points the implied on-curve point (their midpoint)
    is made explicit; zero-length segments (repeated points) are dropped.

    Parameters
    ----------
    points : array_like (n, 2)
    on_curve : array_like of bool (n,)

    Raises
    ------
    ValueError
        Fewer than 2 points, flags of the wrong length, or a contour whose points all
        coincide (it draws nothing).
    """
    P = as_points(points, "points", min_points=2, dims=(2,))
    on = np.asarray(on_curve, dtype=bool).ravel()
    if on.shape[0] != P.shape[0]:
        raise ValueError(
            f"on_curve must have one flag per point: {P.shape[0]} points, {on.shape[0]} flags"
        )
    ((segs, implied),) = _truetype_contours(P, on, np.array([P.shape[0] - 1]))
    if not segs:
        raise ValueError("the contour's points all coincide: it has no segment to draw")
    return Contour(PiecewiseBezier._fast(segs), True, implied)


def truetype_outline(
    points: object, *, name: str = "truetype", source: str = "", scale: float = 1.0
) -> Outline:
    """An :class:`Outline` from raw TrueType contours: a sequence of ``(points, on_curve)``.

    This is how a glyph is rebuilt after one of its points moved (the demo drags
    off-curve points); :func:`glyph_outline` reads the same data from a font.
    """
    pts = tuple(
        (as_points(p, f"points of contour {k}", min_points=2, dims=(2,)), np.asarray(o, bool))
        for k, (p, o) in enumerate(points)
    )
    contours = []
    for k, (p, o) in enumerate(pts):
        try:
            contours.append(truetype_contour(p, o))
        except ValueError as exc:
            raise ValueError(f"contour {k}: {exc}") from None
    return Outline(tuple(contours), name, source, scale, 0, pts)


def _glyph_name(font, cmap, char, glyph, fontname: str) -> str:
    if (char is None) == (glyph is None):
        raise TypeError("give exactly one of char (a character) and glyph (a glyph name)")
    if glyph is not None:
        if not isinstance(glyph, str):
            raise TypeError(f"glyph must be a glyph name (str), got {type(glyph).__name__}")
        if glyph not in font.getReverseGlyphMap():
            raise ValueError(f"font {fontname} has no glyph named {glyph!r}")
        return glyph
    if not isinstance(char, str) or len(char) != 1:
        raise ValueError(f"char must be a single character, got {char!r}")
    name = cmap.get(ord(char))
    if name is None:
        raise ValueError(
            f"font {fontname} has no glyph for the character {char!r} (U+{ord(char):04X})"
        )
    return name


def glyph_outline(
    char: str | None = None,
    font: object = "DejaVuSans",
    *,
    glyph: str | None = None,
    em: bool = True,
) -> Outline:
    """Read a TrueType glyph as closed quadratic contours (implied on-curve points explicit).

    Parameters
    ----------
    char : str, optional
        One character, looked up in the font's character map.
    font : str or path
        A bundled font by file stem (``"DejaVuSans"``, ``"DejaVu Serif"``,
        ``"STIXGeneral"``, ... see :func:`bundled_fonts`) or a ``.ttf`` file.
    glyph : str, optional
        A glyph name instead of ``char`` (``"at"``, ``"uni01BA"``).
    em : bool
        Divide coordinates by the font's units per em (default) or keep font units.

    Returns
    -------
    Outline
        One closed :class:`Contour` per TrueType contour; composite glyphs are
        decomposed (component transforms applied).

    Raises
    ------
    ValueError
        A character the font lacks, an unknown glyph name or font, a file that is not a
        TrueType font (naming the file).
    """
    path = str(_resolve_font(font))
    tt, glyf, cmap, upem, hmtx = _load_font(path)
    name = _glyph_name(tt, cmap, char, glyph, Path(path).stem)
    return _outline_from_glyf(glyf, hmtx, name, path, upem if em else 1.0)


def _outline_from_glyf(glyf, hmtx, name: str, path: str, scale: float) -> Outline:
    g = glyf[name]
    coords, end_pts, flags = g.getCoordinates(glyf)
    P = np.array(coords.array, dtype=float).reshape(-1, 2)
    # TrueType places the outline so that its left side bearing is hmtx's lsb (the
    # phantom point pp1 = xMin - lsb is the origin).  Like fontTools' glyph sets (the
    # reference of the tests), simple glyphs are shifted by lsb - xMin, composites not.
    if hasattr(g, "xMin") and P.size and not g.isComposite():
        P[:, 0] += hmtx[name][1] - g.xMin
    P /= scale
    on = (np.frombuffer(bytes(flags), dtype=np.uint8) & 1).astype(bool)
    ends = np.asarray(end_pts, dtype=int)
    contours, raw, skipped = [], [], 0
    if not ends.size:
        return Outline((), name, path, scale, 0, ())
    starts = np.concatenate([[0], ends[:-1] + 1])
    for s, e, (segs, implied) in zip(starts, ends, _truetype_contours(P, on, ends), strict=True):
        p, o = P[s : e + 1], on[s : e + 1]
        if not segs:
            skipped += 1
            continue
        contours.append(Contour(PiecewiseBezier._fast(segs), True, implied))
        raw.append((p, o))
    return Outline(tuple(contours), name, path, scale, skipped, tuple(raw))


# ==================================================================== SVG path data
def svg_outline(
    d: str,
    *,
    arcs: str = "convert",
    arc_tolerance: float = 1e-6,
    name: str = "svg path",
) -> Outline:
    """Read SVG path data (a ``d`` attribute) as one contour per subpath.

    Parameters
    ----------
    d : str
        Path data: ``M L H V C S Q T A Z`` and their relative (lower-case) forms, with
        implicit repetition, as in SVG 1.1 §8.3.
    arcs : {"convert", "refuse"}
        Approximate elliptical arcs by cubics (default) or refuse them.
    arc_tolerance : float
        Largest distance of an arc's cubics from the true ellipse, relative to the
        ellipse's larger radius (default 1e-6: a full circle takes 12 cubics).
    name : str
        Name of the outline.

    Returns
    -------
    Outline
        A subpath ending with ``Z``/``z`` is a closed contour (a closing line is added
        when its last point differs from its start).  What draws nothing is dropped, as
        a browser draws the path: zero-length segments; subpaths of one point (a moveto
        followed by a moveto or the end, such as Inkscape's trailing ``z m 0 0``, or
        ``m x y z``), counted in ``skipped``; closing lines shorter than ``1e-9`` times
        the path's size (rounding left by summing relative coordinates), the contour
        then ends exactly at its start.  A path that draws nothing has no contours.

    Raises
    ------
    ValueError
        Anything the SVG 1.1 path grammar forbids, naming the token and its position:
        an unknown command letter or stray token, missing numbers, a misplaced comma
        (``M,0``, ``0,,0``, a comma before a command or at the end), a non-ASCII digit,
        an arc flag other than 0/1, a path not starting with a moveto; a number or a
        point beyond the range of doubles (``1e999``), an arc that cannot be represented;
        an arc when ``arcs="refuse"``; empty path data.
    TypeError
        ``d`` is not a str.
    """
    if arcs not in ("convert", "refuse"):
        raise ValueError(f"arcs must be 'convert' or 'refuse'; got {arcs!r}")
    tol = check_finite_scalar(arc_tolerance, "arc_tolerance")
    if not 0 < tol < 0.1:
        raise ValueError(f"arc_tolerance must be in (0, 0.1); got {tol}")
    contours = []
    subpaths, skipped = svg_subpaths(d, arcs, tol)
    for segs, closed, _pos in subpaths:
        curve = PiecewiseBezier._fast(segs)
        contours.append(Contour(curve, closed, np.zeros(len(segs) - 1 + closed, bool)))
    return Outline(tuple(contours), name, "svg path data", skipped=skipped)


def svg_file_outlines(path: object, **kwargs) -> list[Outline]:
    """One :class:`Outline` per ``<path d="...">`` element of an SVG file.

    Transforms (``transform`` attributes) are not applied: the outlines are in the
    coordinates of the path data.  Keyword arguments go to :func:`svg_outline`.

    Raises
    ------
    ValueError
        A file that is not XML (naming the file), or bad path data (naming the element).
    """
    import xml.etree.ElementTree as ET

    p = Path(path)
    try:
        root = ET.parse(p).getroot()
    except (ET.ParseError, OSError) as exc:
        raise ValueError(f"{str(p)!r} is not a readable SVG file: {exc}") from None
    out = []
    for k, el in enumerate(e for e in root.iter() if e.tag.rsplit("}", 1)[-1] == "path"):
        d = el.get("d")
        if d is None or not d.strip():
            continue  # no path data: the element is not rendered (SVG 1.1 §8.3.1)
        ident = el.get("id") or f"path {k}"
        try:
            out.append(svg_outline(d, name=f"{p.name}: {ident}", **kwargs))
        except ValueError as exc:
            raise ValueError(f"{p.name}, {ident}: {exc}") from None
    return out


# ==================================================================== joint analysis
@dataclass(frozen=True)
class JointTable:
    """Every joint of an outline, one entry per joint (arrays of equal length).

    Attributes
    ----------
    contour, joint : ndarray of int
        Contour index and joint index within it (the closing joint of a closed contour
        is its last joint).
    point : ndarray (m, 2)
        End point of the incoming segment.
    gap : ndarray
        Distance between the incoming segment's end and the outgoing segment's start.
    angle : ndarray
        Angle in degrees between the incoming and outgoing tangent directions (the
        geometric tangents: first non-vanishing control-point difference at each end).
    kappa_in, kappa_out : ndarray
        Signed curvature at the end of the incoming / the start of the outgoing segment
        (NaN where that side is singular).
    rel_jump : ndarray
        ``|kappa_out - kappa_in| / max(|kappa_in|, |kappa_out|, 1/l)``: the curvature
        jump relative to the local curvature (``l``: the larger end speed, a length scale
        of the two pieces).
    regular : ndarray of bool
        Both sides have a non-vanishing first derivative.
    implied : ndarray of bool
        The joint is an implied TrueType on-curve point.
    g_order : ndarray of int
        Strict G-order -1..2 (tolerance ``rtol``, the continuity report's rule).
    kind : ndarray of str
        One of :data:`KINDS` (``corner_angle``, ``curvature_rtol`` tolerances).
    """

    contour: np.ndarray
    joint: np.ndarray
    point: np.ndarray
    gap: np.ndarray
    angle: np.ndarray
    kappa_in: np.ndarray
    kappa_out: np.ndarray
    rel_jump: np.ndarray
    regular: np.ndarray
    implied: np.ndarray
    g_order: np.ndarray
    kind: np.ndarray
    settings: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(self.contour.size)

    def counts(self) -> dict[str, int]:
        """Number of joints of each kind (keys :data:`KINDS`)."""
        return {k: int(np.count_nonzero(self.kind == k)) for k in KINDS}


def _end_data(segs: list[np.ndarray]):
    """Per segment: start/end points, first and second derivatives, geometric tangents.

    Vectorized over the segments of each degree (seed 000 eq. (8): the end derivatives of
    a Bézier curve are differences of its end control points).
    """
    S = len(segs)
    out = {k: np.zeros((S, 2)) for k in ("p0", "p1", "a1", "a2", "b1", "b2", "ta", "tb")}
    scale = np.zeros(S)
    degrees = np.fromiter((s.shape[0] - 1 for s in segs), int, S)
    for d in np.unique(degrees):
        idx = np.flatnonzero(degrees == d)
        P = np.stack([segs[i] for i in idx])  # (m, d+1, 2)
        out["p0"][idx], out["p1"][idx] = P[:, 0], P[:, -1]
        out["a1"][idx] = d * (P[:, 1] - P[:, 0])
        out["b1"][idx] = d * (P[:, -1] - P[:, -2])
        if d >= 2:
            out["a2"][idx] = d * (d - 1) * (P[:, 2] - 2 * P[:, 1] + P[:, 0])
            out["b2"][idx] = d * (d - 1) * (P[:, -1] - 2 * P[:, -2] + P[:, -3])
        scale[idx] = d * np.ptp(P, axis=1).max(axis=1)
        # Geometric tangent: the first non-zero difference from each end.
        ta = P[:, 1:] - P[:, :1]
        tb = P[:, -1:] - P[:, -2::-1]
        for name, D in (("ta", ta), ("tb", tb)):
            nz = np.linalg.norm(D, axis=2) > 0
            first = np.argmax(nz, axis=1)
            out[name][idx] = D[np.arange(idx.size), first]
    return out, scale


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def classify_joints(
    outline: Outline,
    *,
    corner_angle: float = 2.0,
    curvature_rtol: float = RTOL,
    rtol: float = RTOL,
) -> JointTable:
    """Classify every joint of an outline (vectorized).

    Parameters
    ----------
    outline : Outline
    corner_angle : float
        Tangent angle in degrees above which a joint is a corner (default 2°).  Font
        outlines live on an integer grid, so an explicit on-curve point a designer meant
        to be smooth turns by a little: in DejaVu Sans 'S' one turns by 1.0° (a
        quadratic meeting a line, directions (166, -31) and (122, -25) font units).
        Implied midpoints turn by 0 (up to rounding).
    curvature_rtol : float
        A smooth point is ``"G2"`` when its relative curvature jump is at most this.
    rtol : float
        Tolerance of the strict ``g_order`` (the continuity report's default).

    Returns
    -------
    JointTable

    Examples
    --------
    A right triangle from SVG path data: three corners.

    >>> table = classify_joints(svg_outline("M 0 0 L 2 0 L 2 2 Z"))
    >>> table.kind.tolist(), table.angle.tolist()
    (['corner', 'corner', 'corner'], [90.0, 135.0, 135.0])
    """
    own_work.require("course_lib.outlines.classify_joints")
    if not isinstance(outline, Outline):
        raise TypeError(f"outline must be an Outline, got {type(outline).__name__}")
    corner_angle = check_finite_scalar(corner_angle, "corner_angle")
    curvature_rtol = check_finite_scalar(curvature_rtol, "curvature_rtol")
    rtol = check_finite_scalar(rtol, "rtol")
    if not 0 <= corner_angle < 180:
        raise ValueError(f"corner_angle must be in [0, 180) degrees; got {corner_angle}")
    if curvature_rtol < 0 or rtol < 0:
        raise ValueError("curvature_rtol and rtol must be >= 0")
    segs: list[np.ndarray] = []
    q_idx, r_idx, cont, jnt, impl = [], [], [], [], []
    for ci, c in enumerate(outline.contours):
        S, base = c.curve.n_segments, len(segs)
        segs.extend(c.curve.segments)
        J = c.n_joints
        q = base + np.arange(J)
        q_idx.append(q)
        r_idx.append(base + (np.arange(J) + 1) % S)
        cont.append(np.full(J, ci))
        jnt.append(np.arange(J))
        impl.append(np.asarray(c.implied, bool))
    if not segs or not sum(len(x) for x in q_idx):
        e, i, b = np.zeros(0), np.zeros(0, int), np.zeros(0, bool)
        return JointTable(i, i, np.zeros((0, 2)), e, e, e, e, e, b, b, i, e.astype(str))
    data, scale = _end_data(segs)
    qi, ri = np.concatenate(q_idx), np.concatenate(r_idx)
    dq1, dq2, dr1, dr2 = data["b1"][qi], data["b2"][qi], data["a1"][ri], data["a2"][ri]
    vq, vr = np.linalg.norm(dq1, axis=1), np.linalg.norm(dr1, axis=1)
    regular = (vq > 1e-10 * scale[qi]) & (vr > 1e-10 * scale[ri])
    ell = np.maximum(vq, vr)
    gap = np.linalg.norm(data["p0"][ri] - data["p1"][qi], axis=1)
    tq, tr = data["tb"][qi], data["ta"][ri]
    nq, nr = np.linalg.norm(tq, axis=1), np.linalg.norm(tr, axis=1)
    with np.errstate(invalid="ignore", divide="ignore"):
        Tq, Tr = tq / nq[:, None], tr / nr[:, None]
        angle = np.degrees(np.arctan2(np.abs(_cross(Tq, Tr)), np.einsum("ij,ij->i", Tq, Tr)))
        kq = np.where(regular, _cross(dq1, dq2) / vq**3, np.nan)
        kr = np.where(regular, _cross(dr1, dr2) / vr**3, np.nan)
        denom = np.maximum.reduce([np.abs(kq), np.abs(kr), 1.0 / ell])
        rel = np.abs(kr - kq) / denom
    # Strict G-order, the continuity report's arc-length rule (seed 000 §6).
    g = np.where(gap > rtol * ell, -1, 0)
    g1 = (g == 0) & regular & (np.linalg.norm(Tq - Tr, axis=1) <= rtol)
    g = np.where(g1, 1, g)
    g = np.where(g1 & (rel <= rtol), 2, g)
    kind = np.full(qi.size, "G1", dtype="<U8")
    kind[rel <= curvature_rtol] = "G2"
    kind[angle > corner_angle] = "corner"
    kind[~regular] = "singular"
    kind[gap > rtol * np.maximum(ell, scale[qi])] = "gap"
    return JointTable(
        np.concatenate(cont),
        np.concatenate(jnt),
        data["p1"][qi],
        gap,
        angle,
        kq,
        kr,
        rel,
        regular,
        np.concatenate(impl),
        g.astype(int),
        kind,
        {"corner_angle": corner_angle, "curvature_rtol": curvature_rtol, "rtol": rtol},
    )


# ==================================================================== summaries
@dataclass(frozen=True)
class GlyphSummary:
    """Counts of one outline's joints: ``joints = corners + g1 + g2 + singular + gaps``."""

    name: str
    contours: int
    joints: int
    corners: int
    g1: int
    g2: int
    singular: int
    gaps: int

    @property
    def smooth(self) -> int:
        """Smooth points (G1 or G2)."""
        return self.g1 + self.g2


def glyph_summary(outline: Outline, **kwargs) -> GlyphSummary:
    """Count an outline's corners and G1 / G2 smooth points (keywords: :func:`classify_joints`)."""
    return _summary(outline, classify_joints(outline, **kwargs).counts())


def _summary(outline: Outline, c: dict) -> GlyphSummary:
    return GlyphSummary(
        outline.name,
        len(outline.contours),
        sum(c.values()),
        c["corner"],
        c["G1"],
        c["G2"],
        c["singular"],
        c["gap"],
    )


@dataclass(frozen=True)
class FontSummary:
    """Per-glyph summaries of a whole font, and their totals."""

    font: str
    glyphs: tuple[GlyphSummary, ...]

    def total(self, name: str) -> int:
        """Sum of one count (``"joints"``, ``"corners"``, ``"g1"``, ``"g2"``, ...) over glyphs."""
        return sum(getattr(g, name) for g in self.glyphs)

    @property
    def g2_share(self) -> float:
        """Share of the smooth points that are G2."""
        smooth = self.total("smooth")
        return self.total("g2") / smooth if smooth else float("nan")

    def __str__(self) -> str:
        keys = ("joints", "corners", "g1", "g2", "singular", "gaps")
        counts = ", ".join(f"{k} {self.total(k)}" for k in keys)
        return (
            f"{self.font}: {len(self.glyphs)} glyphs, {counts}; "
            f"G2 share of smooth points {self.g2_share:.1%}"
        )


def font_summary(
    font: object = "DejaVuSans", glyphs: list[str] | None = None, **kwargs
) -> FontSummary:
    """Classify every joint of every glyph of a font (or of the named ``glyphs``).

    Keyword arguments go to :func:`classify_joints`; glyphs without contours (space,
    ...) are counted with zero joints.
    """
    path = str(_resolve_font(font))
    tt, glyf, _cmap, upem, hmtx = _load_font(path)
    names = tt.getGlyphOrder() if glyphs is None else list(glyphs)
    known = tt.getReverseGlyphMap()
    missing = [n for n in names if n not in known]
    if missing:
        raise ValueError(f"font {Path(path).stem} has no glyph named {missing[0]!r}")
    outs = [_outline_from_glyf(glyf, hmtx, n, path, upem) for n in names]
    # One classification of all contours at once (vectorized), then counts per glyph.
    merged = Outline(tuple(c for o in outs for c in o.contours), "all glyphs", path)
    table = classify_joints(merged, **kwargs)
    glyph_of_contour = np.repeat(np.arange(len(outs)), [len(o.contours) for o in outs])
    code = np.zeros(len(table), int)
    for i, k in enumerate(KINDS):
        code[table.kind == k] = i
    counts = np.zeros((len(outs), len(KINDS)), int)
    np.add.at(counts, (glyph_of_contour[table.contour], code), 1)
    return FontSummary(
        Path(path).stem,
        tuple(
            _summary(o, dict(zip(KINDS, row, strict=True)))
            for o, row in zip(outs, counts.tolist(), strict=True)
        ),
    )
