"""TrueType glyphs as outlines: read with fontTools from the raw ``glyf`` points, implied
on-curve points made explicit (the midpoint of two off-curve points), one-point contours
skipped and counted."""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

import numpy as np

from course_lib.constructions.outlines.contours import Contour, Outline
from course_lib.curves.curve import PiecewiseBezier
from course_lib.validation import as_points

__all__ = [
    "bundled_fonts",
    "font_glyph_names",
    "glyph_outline",
    "load_font",
    "outline_from_glyf",
    "resolve_font",
    "truetype_contour",
    "truetype_outline",
]

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


def resolve_font(font: object) -> Path:
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
def load_font(path: str):
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
    return list(load_font(str(resolve_font(font)))[0].getGlyphOrder())


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
    return Contour(PiecewiseBezier.from_trusted_segments(segs), True, implied)


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
    path = str(resolve_font(font))
    tt, glyf, cmap, upem, hmtx = load_font(path)
    name = _glyph_name(tt, cmap, char, glyph, Path(path).stem)
    return outline_from_glyf(glyf, hmtx, name, path, upem if em else 1.0)


def outline_from_glyf(glyf, hmtx, name: str, path: str, scale: float) -> Outline:
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
        contours.append(Contour(PiecewiseBezier.from_trusted_segments(segs), True, implied))
        raw.append((p, o))
    return Outline(tuple(contours), name, path, scale, skipped, tuple(raw))


