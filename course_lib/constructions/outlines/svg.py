"""SVG path data as outlines: one contour per subpath, read as a browser draws it (the
scanner is :mod:`course_lib.constructions.outlines.svg_path`)."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from course_lib.constructions.outlines.contours import Contour, Outline
from course_lib.constructions.outlines.svg_path import svg_subpaths
from course_lib.curves.curve import PiecewiseBezier
from course_lib.validation import check_finite_scalar

__all__ = ["svg_file_outlines", "svg_outline"]


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
        curve = PiecewiseBezier.from_trusted_segments(segs)
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


