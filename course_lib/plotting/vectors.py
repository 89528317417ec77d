"""Arrows: any vectors, velocities, and the unit tangent, unit normal and curvature vector
at chosen parameters; the osculating circle.

Arrows are drawn in data units with ``quiver(..., angles="xy", scale_units="xy",
scale=1)``, so an arrow of length ``L`` in the picture is a vector of length ``L``
times the stated scale.  The scales are fixed when the artists are created, so a
widget that moves the point keeps comparable arrows.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from course_lib.curves.parametrization import as_parametrization, check_in_domain
from course_lib.geometry import differential_geometry as dg
from course_lib.geometry.sampling import point_derivatives, tangent_and_curvature
from course_lib.plotting.style import ROLE_COLORS, SIZES
from course_lib.validation import as_parameter_array, as_points, check_integer, check_positive

__all__ = [
    "FrameArtists",
    "OsculatingCircleArtists",
    "VectorArtists",
    "default_length",
    "plot_frame",
    "plot_osculating_circle",
    "plot_vectors",
    "plot_velocity",
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
        # points, T = dc/ds and K = d2c/ds2 (seed 000 §6) from one pass over c, c', c''
        p, d1, d2 = point_derivatives(curve, t, (0, 1, 2))
        T, K = tangent_and_curvature(curve, d1, d2, t)
        self.point.set_data(p[:, 0], p[:, 1])
        if self.tangent is not None:
            self.tangent.set_offsets(p)
            self.tangent.set_UVC(T[:, 0] * self.length, T[:, 1] * self.length)
        if self.normal is not None:
            self.normal.set_offsets(p)
            self.normal.set_UVC(-T[:, 1] * self.length, T[:, 0] * self.length)  # N = T turned +90°
        if self.curvature is not None:
            self.curvature.set_offsets(p)
            self.curvature.set_UVC(K[:, 0] * self.curvature_scale, K[:, 1] * self.curvature_scale)


def _quiver(ax, p, v, color, label, zorder, width=0.006):
    return ax.quiver(
        p[:, 0],
        p[:, 1],
        v[:, 0],
        v[:, 1],
        angles="xy",
        scale_units="xy",
        scale=1.0,
        color=color,
        width=width,
        headwidth=4.0,
        headlength=5.0,
        headaxislength=4.5,
        zorder=zorder,
        label=label,
    )


def _bases_and_vectors(bases, vectors) -> tuple[np.ndarray, np.ndarray]:
    """``(m, 2)`` arrays; a single base (or vector) is shared by all arrows."""
    P = as_points(np.atleast_2d(np.asarray(bases, dtype=float)), "bases", min_points=1, dims=(2,))
    V = as_points(
        np.atleast_2d(np.asarray(vectors, dtype=float)), "vectors", min_points=1, dims=(2,)
    )
    if P.shape[0] != V.shape[0]:
        if P.shape[0] == 1:
            P = np.repeat(P, V.shape[0], axis=0)
        elif V.shape[0] == 1:
            V = np.repeat(V, P.shape[0], axis=0)
        else:
            raise ValueError(
                f"bases and vectors must have the same number of rows (or one of them a "
                f"single row); got {P.shape[0]} bases and {V.shape[0]} vectors"
            )
    return P, V


@dataclass
class VectorArtists:
    """Artists of :func:`plot_vectors` and :func:`plot_velocity`.

    Attributes
    ----------
    quiver : Quiver
        The arrows; arrow ``i`` goes from ``bases[i]`` to ``bases[i] + scale * vectors[i]``.
    scale : float
        Drawn length / vector length (fixed when the artists are created).
    """

    quiver: object
    scale: float

    @property
    def artists(self) -> list:
        return [self.quiver]

    @property
    def n_arrows(self) -> int:
        return int(self.quiver.N)

    def update(self, bases, vectors) -> None:
        """Move the arrows (same number of arrows, same ``scale``).

        Raises
        ------
        ValueError
            If the number of arrows changes (a Quiver has a fixed number of arrows).
        """
        P, V = _bases_and_vectors(bases, vectors)
        if P.shape[0] != self.n_arrows:
            raise ValueError(
                f"update needs {self.n_arrows} arrows (as when drawn); got {P.shape[0]}"
            )
        self.quiver.set_offsets(P)
        self.quiver.set_UVC(V[:, 0] * self.scale, V[:, 1] * self.scale)


def plot_vectors(
    ax,
    bases,
    vectors,
    *,
    scale: float = 1.0,
    color: str | None = None,
    label: str | None = None,
    width: float = 0.006,
    zorder: float = 5,
) -> VectorArtists:
    """Draw the arrows ``bases[i] -> bases[i] + scale * vectors[i]`` in data units.

    The arrows are true to the data (``quiver(..., angles="xy", scale_units="xy",
    scale=1)``): a vector ``(2, 1)`` drawn with ``scale=0.5`` ends exactly one unit to
    the right of and half a unit above its base, whatever the Axes' aspect.

    Parameters
    ----------
    bases, vectors : array_like of shape (m, 2) or (2,)
        Where the arrows start, and the vectors; a single row is shared by all arrows.
    scale : float
        Factor (> 0) from vector to drawn arrow; say it in the label, e.g.
        ``"q'(1), drawn × ½"``.
    color : str, optional
        Default: the course's tangent colour.
    label : str, optional
        Legend entry.
    width : float
        Shaft width as a fraction of the Axes width.

    Returns
    -------
    VectorArtists

    Raises
    ------
    ValueError
        If the shapes do not match, a value is not finite, or ``scale <= 0``.
    """
    scale = check_positive(scale, "scale")
    P, V = _bases_and_vectors(bases, vectors)
    q = _quiver(
        ax, P, V * scale, ROLE_COLORS["tangent"] if color is None else color, label, zorder, width
    )
    return VectorArtists(q, scale)


def plot_velocity(
    ax,
    curve,
    t: float | np.ndarray,
    *,
    scale: float = 1.0,
    n: int = 1,
    color: str | None = None,
    label: str | None = None,
    width: float = 0.006,
    zorder: float = 5,
) -> VectorArtists:
    """Draw the velocity vectors ``c'(t)`` (``n = 1``; ``n``-th derivatives for ``n > 1``)
    of a plane parametrization at the points ``c(t)``, scaled by ``scale``.

    The velocity is a property of the parametrization, not of the curve (seed 000 §4):
    equivalent parametrizations give parallel arrows of different lengths.

    Parameters
    ----------
    curve : parametrization (protocol of CONTRIBUTING.md), plane
        At an interior joint of a PiecewiseBezier the segment that starts there is used;
        pass ``curve.segment_curve(i)`` for the other side.
    t : float or array_like
        Parameters in the domain.
    scale : float
        Drawn arrow = ``scale * c^(n)(t)`` (> 0).

    Returns
    -------
    VectorArtists

    Raises
    ------
    TypeError
        If ``curve`` does not follow the parametrization protocol.
    ValueError
        If ``t`` leaves the domain, ``n < 1``, ``scale <= 0`` or the curve is not plane.
    """
    curve = as_parametrization(curve)
    if curve.dim != 2:
        raise ValueError(
            f"plot_velocity draws plane curves (dim 2); this curve has dim {curve.dim}"
        )
    n = check_integer(n, "n", minimum=1)
    tt, _ = as_parameter_array(t, "t")
    tt = check_in_domain(tt, tuple(curve.domain))
    return plot_vectors(
        ax,
        curve.evaluate(tt),
        curve.evaluate(tt, n),
        scale=scale,
        color=color,
        label=label,
        width=width,
        zorder=zorder,
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
        # thin and on top: the curvature vector (parallel to N) must not hide it
        qn = _quiver(
            ax,
            p,
            v,
            ROLE_COLORS["normal"],
            "unit normal N" if labels else None,
            zorder + 0.5,
            width=0.004 if curvature else 0.006,
        )
    if curvature:
        v = dg.curvature_vector(curve, tt) * curvature_scale
        qk = _quiver(
            ax,
            p,
            v,
            ROLE_COLORS["curvature"],
            "curvature vector dT/ds" if labels else None,
            zorder - 0.5 if normal else zorder,
            width=0.011 if normal else 0.006,
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
