"""The font editor's view of an outline: contours, curvature combs, corners and smooth points.

:func:`plot_outline` draws every contour of a :class:`~course_lib.constructions.outlines.Outline`
(glyph or SVG path) with one common curvature comb scale, and marks each joint by its
kind from :func:`~course_lib.constructions.outlines.classify_joints`: corners, smooth points that are
only G1 (the comb jumps there), G2 smooth points, singular joints.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from course_lib.constructions.outlines import JointTable, Outline, classify_joints
from course_lib.plotting.curvature import CombArtists, comb_teeth, plot_curvature_comb
from course_lib.plotting.curves import CurveArtists, plot_curve
from course_lib.plotting.style import OKABE_ITO, SIZES

__all__ = ["MARK_STYLES", "OutlineArtists", "comb_scale_for", "plot_outline"]

#: Marker style per joint kind (the legend says what each means).
MARK_STYLES = {
    "corner": {"marker": "s", "color": OKABE_ITO["orange"], "label": "corner"},
    "G1": {"marker": "o", "color": OKABE_ITO["reddish_purple"], "label": "smooth, G1 not G2"},
    "G2": {"marker": "o", "color": OKABE_ITO["bluish_green"], "label": "smooth, G2"},
    "singular": {"marker": "X", "color": OKABE_ITO["black"], "label": "singular"},
    "gap": {"marker": "*", "color": OKABE_ITO["vermillion"], "label": "gap"},
}


def comb_scale_for(outline: Outline, teeth_per_segment: int = 12, quantile: float = 0.9) -> float:
    """A common comb scale: the ``quantile`` of |curvature| gets teeth 8 % of the outline's size.

    Glyph curvature spans orders of magnitude (tight joins, long flat stems), so the
    largest tooth would make most teeth invisible; a quantile keeps the comb readable
    and the same scale is used for every contour (teeth compare across contours).
    """
    K, P = [], []
    for c in outline.contours:
        feet, tips = comb_teeth(c.curve, teeth_per_segment, 1.0)
        K.append(np.linalg.norm(tips - feet, axis=-1).ravel())
        P.append(feet.reshape(-1, 2))
    if not K:
        return 1.0
    k = float(np.quantile(np.concatenate(K), quantile))
    P = np.vstack(P)
    size = float(np.max(np.ptp(P, axis=0))) or 1.0
    return 0.08 * size / k if k > 0 else 1.0


@dataclass
class OutlineArtists:
    """Artists of :func:`plot_outline`.

    Attributes
    ----------
    curves : list of CurveArtists
        One per contour.
    combs : list of CombArtists
        One per contour (empty when ``comb=False``).
    marks : dict of kind -> Line2D
        The joints of each kind (see :data:`MARK_STYLES`).
    table : JointTable
        The classification drawn.
    comb_scale : float
    """

    curves: list[CurveArtists]
    combs: list[CombArtists]
    marks: dict
    table: JointTable
    comb_scale: float
    classify: dict = field(default_factory=dict)

    @property
    def artists(self) -> list:
        out = [a for c in self.curves for a in c.artists]
        out += [a for c in self.combs for a in c.artists]
        return out + list(self.marks.values())

    def update(self, outline: Outline) -> JointTable:
        """Redraw for a changed outline with the same contours and segment counts."""
        for art, c in zip(self.curves, outline.contours, strict=True):
            art.update(c.curve)
            art.segments.set_color(OKABE_ITO["black"])  # update() alternates the colours
        for art, c in zip(self.combs, outline.contours, strict=False):
            art.update(c.curve)
        self.table = classify_joints(outline, **self.classify)
        for kind, line in self.marks.items():
            P = self.table.point[self.table.kind == kind]
            line.set_data(P[:, 0], P[:, 1])
            line.set_label(f"{MARK_STYLES[kind]['label']} ({len(P)})")
        return self.table


def plot_outline(
    ax,
    outline: Outline,
    *,
    comb: bool = True,
    comb_scale: float | None = None,
    teeth_per_segment: int = 12,
    marks: tuple[str, ...] = ("corner", "G1", "G2", "singular", "gap"),
    polygon: bool = False,
    legend: bool = True,
    **classify,
) -> OutlineArtists:
    """Draw an outline with its curvature comb and its joints marked by kind.

    Parameters
    ----------
    ax : matplotlib Axes
    outline : Outline
    comb : bool
        Draw the curvature comb (teeth outside the curve, one scale for all contours).
    comb_scale : float, optional
        Tooth length per unit of curvature (default :func:`comb_scale_for`).
    teeth_per_segment : int
    marks : tuple of str
        Kinds of joints to mark (see :data:`MARK_STYLES`).
    polygon : bool
        Also draw the Bézier control polygons and points (a TrueType glyph's off-curve
        points are the middle control points of its quadratics).
    legend : bool
    **classify
        Tolerances passed to :func:`~course_lib.constructions.outlines.classify_joints`.

    Returns
    -------
    OutlineArtists
    """
    if not isinstance(outline, Outline):
        raise TypeError(f"outline must be an Outline, got {type(outline).__name__}")
    unknown = set(marks) - set(MARK_STYLES)
    if unknown:
        raise ValueError(f"marks must be among {sorted(MARK_STYLES)}; got {sorted(unknown)}")
    table = classify_joints(outline, **classify)
    curves = [
        plot_curve(
            ax,
            c.curve,
            per_segment=24,
            polygon=polygon,
            points=polygon,
            joints=False,
            alternate=False,
            color=OKABE_ITO["black"],
            linewidth=SIZES["curve"] * 0.7,
            equal_aspect=True,
        )
        for c in outline.contours
    ]
    scale = comb_scale_for(outline, teeth_per_segment) if comb_scale is None else comb_scale
    combs = []
    if comb:
        for c in outline.contours:
            combs.append(
                plot_curvature_comb(
                    ax, c.curve, samples=teeth_per_segment * c.curve.n_segments, scale=scale
                )
            )
    mark_lines = {}
    for kind in marks:
        st = MARK_STYLES[kind]
        P = table.point[table.kind == kind]
        (line,) = ax.plot(
            P[:, 0],
            P[:, 1],
            ls="none",
            marker=st["marker"],
            ms=7 if kind != "G2" else 5,
            mfc=st["color"],
            mec="black",
            mew=0.6,
            zorder=6,
            label=f"{st['label']} ({len(P)})",
        )
        mark_lines[kind] = line
    ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    if legend and mark_lines:
        ax.legend(handles=list(mark_lines.values()), loc="upper left", bbox_to_anchor=(1.0, 1.0))
    return OutlineArtists(curves, combs, mark_lines, table, float(scale), dict(classify))
