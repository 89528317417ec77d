"""The types of real outlines: a :class:`Contour` is one closed or open ``PiecewiseBezier``,
an :class:`Outline` a glyph or an SVG path as a tuple of contours."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from course_lib.curves.curve import PiecewiseBezier

__all__ = ["Contour", "Outline"]


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


