"""Unit tangent, unit normal and curvature vector at chosen parameters; the osculating circle.

Arrows are drawn in data units with ``quiver(..., angles="xy", scale_units="xy",
scale=1)``, so an arrow of length ``L`` in the picture is a vector of length ``L``
times the stated scale.  The scales are fixed when the artists are created, so a
widget that moves the point keeps comparable arrows.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import differential_geometry as dg
from .style import ROLE_COLORS, SIZES

__all__ = [
    "FrameArtists",
    "OsculatingCircleArtists",
    "default_length",
    "plot_frame",
    "plot_osculating_circle",
]


def default_length(curve) -> float:
    """A length for arrows: 15 % of the diagonal of the control points' bounding box."""
    P = np.vstack(curve.segments)
    diag = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0)))
    return 0.15 * (diag if diag > 0 else 1.0)


@dataclass
class FrameArtists:
    """Artists of :func:`plot_frame`.

    Attributes
    ----------
    point : Line2D
        The curve points ``c(t)``.
    tangent, normal, curvature : Quiver or None
        Arrows ``length * T``, ``length * N`` and ``curvature_scale * K``.
    length : float
        Drawn length of the unit vectors.
    curvature_scale : float
        The curvature vector ``K`` (units 1/length) is drawn as ``curvature_scale * K``.
    """

    point: object
    tangent: object | None
    normal: object | None
    curvature: object | None
    length: float
    curvature_scale: float

    @property
    def artists(self) -> list:
        return [a for a in (self.point, self.tangent, self.normal, self.curvature) if a is not None]

    def update(self, curve, t) -> None:
        """Move the frame to the parameters ``t`` of ``curve``."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        p = curve.evaluate(t)
        self.point.set_data(p[:, 0], p[:, 1])
        # T = dc/ds and K = d2c/ds2 in one call (seed 000 §6)
        T, K = dg.arc_length_derivatives(curve, t, 2)
        if self.tangent is not None:
            self.tangent.set_offsets(p)
            self.tangent.set_UVC(T[:, 0] * self.length, T[:, 1] * self.length)
        if self.normal is not None:
            self.normal.set_offsets(p)
            self.normal.set_UVC(-T[:, 1] * self.length, T[:, 0] * self.length)  # N = T turned +90°
        if self.curvature is not None:
            self.curvature.set_offsets(p)
            self.curvature.set_UVC(K[:, 0] * self.curvature_scale, K[:, 1] * self.curvature_scale)


def _quiver(ax, p, v, color, label, zorder):
    return ax.quiver(
        p[:, 0],
        p[:, 1],
        v[:, 0],
        v[:, 1],
        angles="xy",
        scale_units="xy",
        scale=1.0,
        color=color,
        width=0.006,
        headwidth=4.0,
        headlength=5.0,
        headaxislength=4.5,
        zorder=zorder,
        label=label,
    )


def plot_frame(
    ax,
    curve,
    t: float | np.ndarray,
    *,
    tangent: bool = True,
    normal: bool = False,
    curvature: bool = True,
    length: float | None = None,
    curvature_scale: float | None = None,
    labels: bool = True,
    zorder: float = 6,
) -> FrameArtists:
    """Draw the unit tangent ``T``, unit normal ``N`` and curvature vector ``K = dT/ds`` at ``t``.

    Seed 004 §19.2: ``T = c'/|c'|``, ``dT/ds = kappa N``.  ``K`` points to the centre
    of the osculating circle; its drawn length is ``curvature_scale * |kappa|``.

    Parameters
    ----------
    curve : parametrization (protocol of CONTRIBUTING.md), plane
    t : float or array_like
        Parameters (global) where the vectors are drawn.
    length : float, optional
        Drawn length of ``T`` and ``N`` (default :func:`default_length` for a
        PiecewiseBezier, else 1).
    curvature_scale : float, optional
        Factor for ``K`` (default ``length**2``: then ``K`` and ``T`` have equal drawn
        length where the radius of curvature equals ``length``).

    Returns
    -------
    FrameArtists

    Raises
    ------
    ValueError
        Where the parametrization is not regular (from the math layer).
    """
    tt = np.atleast_1d(np.asarray(t, dtype=float))
    if length is None:
        length = default_length(curve) if hasattr(curve, "segments") else 1.0
    if curvature_scale is None:
        curvature_scale = length**2
    p = curve.evaluate(tt)
    (pt,) = ax.plot(
        p[:, 0],
        p[:, 1],
        ls="none",
        marker="o",
        ms=SIZES["moving_point"],
        color=ROLE_COLORS["moving_point"],
        zorder=zorder + 1,
    )
    qt = qn = qk = None
    if tangent:
        v = dg.unit_tangent(curve, tt) * length
        qt = _quiver(ax, p, v, ROLE_COLORS["tangent"], "unit tangent T" if labels else None, zorder)
    if normal:
        v = dg.unit_normal(curve, tt) * length
        qn = _quiver(ax, p, v, ROLE_COLORS["normal"], "unit normal N" if labels else None, zorder)
    if curvature:
        v = dg.curvature_vector(curve, tt) * curvature_scale
        qk = _quiver(
            ax,
            p,
            v,
            ROLE_COLORS["curvature"],
            "curvature vector dT/ds" if labels else None,
            zorder,
        )
    return FrameArtists(pt, qt, qn, qk, float(length), float(curvature_scale))


@dataclass
class OsculatingCircleArtists:
    """Artists of :func:`plot_osculating_circle`: the circle, its centre, the radius drawn."""

    circle: object
    centre: object
    radius_line: object

    @property
    def artists(self) -> list:
        return [self.circle, self.centre, self.radius_line]

    def update(self, curve, t: float) -> bool:
        """Move to ``t``; hide (and return False) where the curvature vanishes."""
        p = curve.evaluate(float(t))
        try:
            centre, radius = dg.osculating_circle(curve, float(t))
        except ValueError:
            for a in self.artists:
                a.set_visible(False)
            return False
        self.circle.set_center(centre)
        self.circle.set_radius(radius)
        self.centre.set_data([centre[0]], [centre[1]])
        self.radius_line.set_data([p[0], centre[0]], [p[1], centre[1]])
        for a in self.artists:
            a.set_visible(True)
        return True


def plot_osculating_circle(ax, curve, t: float, *, zorder: float = 2) -> OsculatingCircleArtists:
    """Draw the osculating circle at ``t`` (radius ``1/|kappa|``, seed 004 §19.2).

    Where the curvature vanishes the circle degenerates into the tangent line; the
    artists are then created hidden (``get_visible() is False``) and nothing raises.
    """
    from matplotlib.patches import Circle

    circ = Circle(
        (0.0, 0.0),
        1.0,
        fill=False,
        ec=ROLE_COLORS["circle"],
        lw=SIZES["construction"] * 1.3,
        ls="-",
        zorder=zorder,
        label="osculating circle",
    )
    ax.add_artist(circ)  # not add_patch: a huge circle must not rescale the view
    (c,) = ax.plot(
        [0.0],
        [0.0],
        ls="none",
        marker="+",
        ms=12,
        mew=2,
        color=ROLE_COLORS["circle"],
        zorder=zorder,
        scalex=False,
        scaley=False,
    )
    (r,) = ax.plot(
        [0.0, 0.0],
        [0.0, 0.0],
        color=ROLE_COLORS["circle"],
        lw=1.0,
        ls=":",
        zorder=zorder,
        scalex=False,
        scaley=False,
    )
    arts = OsculatingCircleArtists(circ, c, r)
    arts.update(curve, t)
    return arts
