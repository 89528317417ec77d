"""Curves with their control polygons, joints marked, neighbouring segments in alternating colours.

Every function takes an Axes first and returns its artists, so that a widget can
update them in place (``artists.update(new_curve)`` calls ``set_data`` /
``set_segments``; the caller redraws with ``canvas.draw_idle()``).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from course_lib.geometry.sampling import segment_samples
from course_lib.plotting.style import ROLE_COLORS, SIZES, segment_color
from course_lib.validation import as_points

__all__ = [
    "CurveArtists",
    "PointsArtists",
    "plot_control_polygon",
    "plot_curve",
    "polygon_path",
]


def polygon_path(curve) -> np.ndarray:
    """The control polygons of all segments as one ``(m, dim)`` path, NaN rows between segments."""
    segs = curve.segments
    rows = []
    for s in segs:
        rows.append(s)
        rows.append(np.full((1, s.shape[1]), np.nan))
    return np.vstack(rows[:-1])


def _require_plane(curve, what: str) -> None:
    if curve.dim != 2:
        raise ValueError(
            f"{what} draws plane curves (dim 2); this curve has dim {curve.dim} "
            "(use course_lib.plotting.surfaces3d for space pictures)"
        )


@dataclass
class CurveArtists:
    """Artists of :func:`plot_curve`.

    Attributes
    ----------
    segments : LineCollection
        One line per Bézier segment (``get_segments()[i]`` is segment ``i``), colours alternating.
    polygon : Line2D or None
        The Bézier control polygons (segments separated by NaN rows).
    points : Line2D or None
        The Bézier control points.
    joints : Line2D or None
        The joints ``q_i(1)``, ``i = 0..S-2``.
    per_segment : int
        Samples per segment.
    """

    segments: object
    polygon: object | None
    points: object | None
    joints: object | None
    per_segment: int
    extra: dict = field(default_factory=dict)

    @property
    def artists(self) -> list:
        """All non-None artists (for ``set_visible``, ``remove``, blitting)."""
        return [a for a in (self.segments, self.polygon, self.points, self.joints) if a is not None]

    def update(self, curve) -> None:
        """Put the data of ``curve`` (same number of segments or not) into the artists."""
        _, pts = segment_samples(curve, self.per_segment)
        self.segments.set_segments(list(pts))
        self.segments.set_color([segment_color(i) for i in range(curve.n_segments)])
        if self.polygon is not None:
            path = polygon_path(curve)
            self.polygon.set_data(path[:, 0], path[:, 1])
        if self.points is not None:
            cp = np.vstack(curve.segments)
            self.points.set_data(cp[:, 0], cp[:, 1])
        if self.joints is not None:
            jp = curve.joint_points
            self.joints.set_data(jp[:, 0], jp[:, 1])


def plot_curve(
    ax,
    curve,
    *,
    per_segment: int = 64,
    polygon: bool = True,
    points: bool = True,
    joints: bool = True,
    alternate: bool = True,
    color: str | None = None,
    linewidth: float | None = None,
    label: str | None = None,
    equal_aspect: bool = True,
    zorder: float = 3,
) -> CurveArtists:
    """Draw a plane :class:`~course_lib.curves.curve.PiecewiseBezier` with its Bézier control polygons.

    Parameters
    ----------
    ax : matplotlib Axes
    curve : PiecewiseBezier
        A plane curve (``dim == 2``).
    per_segment : int
        Samples per segment (each segment is drawn on its own: a gap stays visible).
    polygon, points, joints : bool
        Draw the Bézier control polygons, their vertices, the joints.
    alternate : bool
        Alternate the colours of neighbouring segments (default); False draws all
        segments in ``color``.
    color, linewidth, label
        Style of the curve (``label`` goes to the legend).
    equal_aspect : bool
        Set an equal aspect ratio (default): a circle must look like a circle.

    Returns
    -------
    CurveArtists
    """
    from matplotlib.collections import LineCollection

    _require_plane(curve, "plot_curve")
    _, pts = segment_samples(curve, per_segment)
    S = curve.n_segments
    if alternate and color is None:
        colors = [segment_color(i) for i in range(S)]
    else:
        colors = [color or ROLE_COLORS["segment_even"]] * S
    lc = LineCollection(
        list(pts),
        colors=colors,
        linewidths=linewidth or SIZES["curve"],
        capstyle="round",
        joinstyle="round",
        zorder=zorder,
        label=label,
    )
    ax.add_collection(lc)
    poly_artist = pts_artist = joint_artist = None
    if polygon:
        path = polygon_path(curve)
        (poly_artist,) = ax.plot(
            path[:, 0],
            path[:, 1],
            color=ROLE_COLORS["polygon"],
            lw=SIZES["polygon"],
            ls="--",
            zorder=zorder - 1,
            label="Bézier control polygon" if label else None,
        )
    if points:
        cp = np.vstack(curve.segments)
        (pts_artist,) = ax.plot(
            cp[:, 0],
            cp[:, 1],
            ls="none",
            marker="o",
            ms=SIZES["control_point"] * 0.75,
            mfc="white",
            mec=ROLE_COLORS["control_point"],
            mew=1.3,
            zorder=zorder + 1,
        )
    if joints:
        jp = curve.joint_points
        (joint_artist,) = ax.plot(
            jp[:, 0],
            jp[:, 1],
            ls="none",
            marker="D",
            ms=SIZES["joint"] * 0.8,
            mfc=ROLE_COLORS["joint"],
            mec="black",
            mew=1.0,
            zorder=zorder + 2,
            label="joints" if label else None,
        )
    if equal_aspect:
        ax.set_aspect("equal", adjustable="datalim")
    ax.autoscale_view()
    return CurveArtists(lc, poly_artist, pts_artist, joint_artist, per_segment)


@dataclass
class PointsArtists:
    """Artists of :func:`plot_control_polygon`: the polygon line, its vertices, their labels."""

    line: object
    markers: object
    labels: list

    def update(self, points: np.ndarray) -> None:
        P = np.asarray(points, dtype=float)
        self.line.set_data(P[:, 0], P[:, 1])
        self.markers.set_data(P[:, 0], P[:, 1])
        for txt, p in zip(self.labels, P, strict=False):
            txt.set_position(p)


def plot_control_polygon(
    ax,
    points,
    *,
    labels: str | list[str] | None = None,
    color: str | None = None,
    linestyle: str = "-",
    marker: str = "o",
    markersize: float | None = None,
    label: str | None = None,
    closed: bool = False,
    zorder: float = 4,
) -> PointsArtists:
    """Draw a control polygon (e.g. the Beta-spline polygon ``V_0 .. V_m``) with its vertices.

    Parameters
    ----------
    points : array_like of shape (n, 2)
    labels : str or list of str, optional
        A format string with ``{i}`` (e.g. ``"$V_{{{i}}}$"``) or one label per vertex.
    closed : bool
        Join the last vertex back to the first.

    Returns
    -------
    PointsArtists
    """
    P = as_points(points, "points", min_points=1, dims=(2,))
    color = color or ROLE_COLORS["control_point"]
    path = np.vstack([P, P[:1]]) if closed else P
    (line,) = ax.plot(
        path[:, 0],
        path[:, 1],
        color=color,
        lw=SIZES["polygon"] * 1.2,
        ls=linestyle,
        zorder=zorder,
        label=label,
    )
    (markers,) = ax.plot(
        P[:, 0],
        P[:, 1],
        ls="none",
        marker=marker,
        ms=markersize or SIZES["control_point"],
        mfc=color,
        mec="white",
        mew=1.0,
        zorder=zorder + 0.5,
    )
    texts = []
    if labels is not None:
        names = [labels.format(i=i) for i in range(len(P))] if isinstance(labels, str) else labels
        for name, p in zip(names, P, strict=False):
            texts.append(
                ax.annotate(
                    name,
                    p,
                    xytext=(6, 6),
                    textcoords="offset points",
                    fontsize=SIZES["label"],
                    color=color,
                    zorder=zorder + 1,
                )
            )
    ax.set_aspect("equal", adjustable="datalim")
    return PointsArtists(line, markers, texts)
