"""Curvature pictures: the curvature comb (porcupine) and curvature against arc length.

A G1 joint that is not G2 shows as a jump of the curvature.  Both pictures draw
each segment on its own (its samples run up to its own one-sided limit at each
joint), so a jump is never bridged by a connecting line.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from course_lib.geometry import differential_geometry as dg
from course_lib.geometry.arc_length import segment_arc_lengths
from course_lib.geometry.sampling import (
    segment_derivatives,
    segment_grid,
    tangent_and_curvature,
)
from course_lib.plotting.style import ROLE_COLORS, SIZES, segment_color
from course_lib.validation import check_integer

__all__ = [
    "CombArtists",
    "CurvatureProfileArtists",
    "comb_teeth",
    "curvature_profile",
    "plot_curvature_comb",
    "plot_curvature_profile",
]


def _per_segment(curve, samples: int) -> int:
    samples = check_integer(samples, "samples", minimum=2)
    return max(2, round(samples / curve.n_segments))


def comb_teeth(curve, per_segment: int, scale: float, side: int = -1):
    """Feet and tips of the comb's teeth, each of shape ``(S, n, dim)``.

    A tooth stands at ``c(t)`` and ends at ``c(t) + side * scale * K(t)``, ``K`` the
    curvature vector (``kappa N`` in the plane): perpendicular to the curve, of length
    ``scale * |kappa|``; ``side = -1`` (default) points away from the centre of curvature.
    """
    feet, _T, K = _frame_samples(curve, per_segment)
    return feet, feet + (side * scale) * K


def _frame_samples(curve, per_segment: int):
    """Points, unit tangents ``T`` and curvature vectors ``K = dT/ds`` on the segment grid,
    each ``(S, n, dim)``, from one pass over the derivatives (cached Bernstein matrices,
    :func:`~course_lib.geometry.sampling.segment_derivatives`).

    Raises
    ------
    ValueError
        Where the parametrization is not regular.
    """
    P, d1, d2 = segment_derivatives(curve, per_segment, (0, 1, 2))
    T, K = tangent_and_curvature(curve, d1, d2, lambda: segment_grid(curve, per_segment))
    return P, T, K


@dataclass
class CombArtists:
    """Artists of :func:`plot_curvature_comb`.

    Attributes
    ----------
    teeth : Line2D
        All teeth in one line, ``foot, tip, NaN`` per tooth (one path: fast to
        update and draw); :meth:`tooth_array` gives them as ``(m, 2, dim)``.
    envelope : LineCollection
        The tips joined up, one line per segment (not bridged across a joint).
    scale : float
        Drawn tooth length per unit of curvature.
    per_segment : int
    side : int
        -1: teeth point away from the centre of curvature; +1: towards it.
    """

    teeth: object
    envelope: object
    scale: float
    per_segment: int
    side: int

    @property
    def artists(self) -> list:
        return [self.teeth, self.envelope]

    def tooth_array(self) -> np.ndarray:
        """The teeth as an array of shape ``(m, 2, 2)``: ``[foot, tip]`` per tooth."""
        x, y = self.teeth.get_data()
        xy = np.column_stack([x, y]).reshape(-1, 3, 2)
        return xy[:, :2]

    def update(self, curve) -> None:
        feet, tips = comb_teeth(curve, self.per_segment, self.scale, self.side)
        self.teeth.set_data(*_teeth_path(feet, tips))
        self.envelope.set_segments(list(tips))
        self.envelope.set_color([_envelope_color(i) for i in range(curve.n_segments)])


def _teeth_path(feet: np.ndarray, tips: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    m = feet.shape[0] * feet.shape[1]
    xy = np.full((m, 3, 2), np.nan)
    xy[:, 0] = feet.reshape(m, -1)[:, :2]
    xy[:, 1] = tips.reshape(m, -1)[:, :2]
    return xy[:, :, 0].ravel(), xy[:, :, 1].ravel()


def _envelope_color(i: int) -> str:
    return segment_color(i)


def _auto_scale(curve, K: np.ndarray) -> float:
    P = np.vstack(curve.segments)
    diag = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0))) or 1.0
    kmax = float(np.max(np.linalg.norm(K, axis=-1))) if K.size else 0.0
    return 0.2 * diag / kmax if kmax > 0 else 1.0


def plot_curvature_comb(
    ax,
    curve,
    *,
    samples: int = 400,
    scale: float | None = None,
    side: str = "outside",
    zorder: float = 1.5,
) -> CombArtists:
    """Draw the curvature comb: teeth normal to the curve, of length proportional to curvature.

    Parameters
    ----------
    curve : PiecewiseBezier (plane)
    samples : int
        Total number of teeth, spread evenly over the segments (in parameter).
    scale : float, optional
        Tooth length per unit of curvature (default: the longest tooth is 20 % of
        the control points' bounding-box diagonal).  Fixed afterwards: a widget
        shows the curvature change, not a rescaled comb.
    side : {"outside", "inside"}
        Teeth away from (default) or towards the centre of curvature.

    Returns
    -------
    CombArtists
    """
    from matplotlib.collections import LineCollection

    if side not in ("outside", "inside"):
        raise ValueError(f"side must be 'outside' or 'inside'; got {side!r}")
    if curve.dim != 2:
        raise ValueError(f"plot_curvature_comb draws plane curves; this curve has dim {curve.dim}")
    sgn = -1 if side == "outside" else 1
    n = _per_segment(curve, samples)
    if scale is None:
        scale = _auto_scale(curve, _frame_samples(curve, n)[2].reshape(-1, curve.dim))
    feet, tips = comb_teeth(curve, n, scale, sgn)
    (teeth,) = ax.plot(
        *_teeth_path(feet, tips),
        color=ROLE_COLORS["comb"],
        lw=SIZES["comb"],
        zorder=zorder,
        label="curvature comb",
        solid_capstyle="butt",
    )
    env = LineCollection(
        list(tips),
        colors=[_envelope_color(i) for i in range(curve.n_segments)],
        linewidths=SIZES["comb_envelope"],
        zorder=zorder,
    )
    ax.add_collection(env)
    ax.autoscale_view()
    return CombArtists(teeth, env, float(scale), n, sgn)


def curvature_profile(
    curve,
    per_segment: int = 80,
    *,
    signed: bool = True,
    x: str = "arc_length",
    arc_length_every: int = 1,
):
    """Samples for :func:`plot_curvature_profile`: ``(X, kappa)``, each of shape ``(S, n)``.

    ``X`` is the arc length from the start (``x="arc_length"``) or the global
    parameter (``x="parameter"``); ``kappa`` is the signed curvature (plane curves,
    ``signed=True``) or ``|kappa|``.  Row ``i`` is segment ``i``, its last entry the
    one-sided limit at the joint.

    ``arc_length_every = k > 1`` computes the arc length (the costly part) at every k-th
    sample and at both ends of every segment (fixed Gauss-Legendre sums with cached
    Bernstein matrices, :func:`~course_lib.geometry.arc_length.segment_arc_lengths`), and
    linearly in the parameter between them -- for live widgets; the joints stay exact.
    """
    if x not in ("arc_length", "parameter"):
        raise ValueError(f"x must be 'arc_length' or 'parameter'; got {x!r}")
    every = check_integer(arc_length_every, "arc_length_every", minimum=1)
    t = segment_grid(curve, per_segment)
    flat = t.ravel()
    _P, T, K = _frame_samples(curve, per_segment)
    if signed and curve.dim == 2:
        # K = kappa N with N = T turned +90 degrees (seed 004 §19.2), so kappa = T x K
        k = T[..., 0] * K[..., 1] - T[..., 1] * K[..., 0]
    else:
        k = np.linalg.norm(K, axis=-1)
    if x == "parameter":
        X = t.copy()
    elif every == 1:
        X = np.asarray(dg.cumulative_arc_length(curve, flat)).reshape(t.shape)
    else:
        n = t.shape[1]
        idx = np.unique(np.r_[0:n:every, n - 1])
        S = segment_arc_lengths(curve, n, idx)
        if S is None:
            S = np.asarray(dg.cumulative_arc_length(curve, t[:, idx].ravel()))
            S = S.reshape(-1, idx.size)
        u = np.linspace(0.0, 1.0, n)  # every row is affine in u: the same weights for all
        j = np.clip(np.searchsorted(idx, np.arange(n), side="right") - 1, 0, idx.size - 2)
        w = (u - u[idx[j]]) / (u[idx[j + 1]] - u[idx[j]])
        X = S[:, j] * (1.0 - w) + S[:, j + 1] * w
    return X, np.asarray(k).reshape(t.shape)


@dataclass
class CurvatureProfileArtists:
    """Artists of :func:`plot_curvature_profile`.

    Attributes
    ----------
    lines : LineCollection
        One line per segment: ``(X, kappa)`` (``get_segments()[i]``).
    ends : Line2D
        Dots at both ends of each segment: a jump shows as two dots one above the other.
    joint_lines : LineCollection
        Dotted vertical lines at the joints.
    """

    lines: object
    ends: object
    joint_lines: object
    per_segment: int
    signed: bool
    x: str
    arc_length_every: int = 1

    @property
    def artists(self) -> list:
        return [self.lines, self.ends, self.joint_lines]

    def update(self, curve, *, rescale: bool = True) -> None:
        X, k = curvature_profile(
            curve,
            self.per_segment,
            signed=self.signed,
            x=self.x,
            arc_length_every=self.arc_length_every,
        )
        self.lines.set_segments(list(np.stack([X, k], axis=-1)))
        self.lines.set_color([segment_color(i) for i in range(curve.n_segments)])
        ex = np.stack([X[:, 0], X[:, -1]], axis=1).ravel()
        ek = np.stack([k[:, 0], k[:, -1]], axis=1).ravel()
        self.ends.set_data(ex, ek)
        self.joint_lines.set_segments([[(xj, 0.0), (xj, 1.0)] for xj in X[1:, 0]])
        if rescale:
            ax = self.lines.axes
            lo, hi = float(np.min(k)), float(np.max(k))
            pad = 0.08 * (hi - lo) if hi > lo else max(abs(hi), 1.0) * 0.1
            ax.set_xlim(float(X[0, 0]), float(X[-1, -1]))
            ax.set_ylim(min(lo, 0.0) - pad, max(hi, 0.0) + pad)


def plot_curvature_profile(
    ax,
    curve,
    *,
    per_segment: int = 80,
    signed: bool = True,
    x: str = "arc_length",
    labels: bool = True,
    arc_length_every: int = 1,
) -> CurvatureProfileArtists:
    """Curvature against arc length (or parameter), each segment drawn on its own.

    At a joint where the curve is G1 but not G2 the two pieces end at different
    heights: the drawn jump ``kappa_right - kappa_left`` is the jump of the signed
    curvature (seed 000 §6: G2 means a continuous curvature vector).

    Returns
    -------
    CurvatureProfileArtists
    """
    from matplotlib.collections import LineCollection
    from matplotlib.transforms import blended_transform_factory

    per_segment = check_integer(per_segment, "per_segment", minimum=2)
    X, k = curvature_profile(
        curve, per_segment, signed=signed, x=x, arc_length_every=arc_length_every
    )
    S = curve.n_segments
    lines = LineCollection(
        list(np.stack([X, k], axis=-1)),
        colors=[segment_color(i) for i in range(S)],
        linewidths=SIZES["curve"] * 0.8,
        zorder=3,
    )
    ax.add_collection(lines)
    ex = np.stack([X[:, 0], X[:, -1]], axis=1).ravel()
    ek = np.stack([k[:, 0], k[:, -1]], axis=1).ravel()
    (ends,) = ax.plot(ex, ek, ls="none", marker="o", ms=5, color="black", zorder=4)
    trans = blended_transform_factory(ax.transData, ax.transAxes)
    jl = LineCollection(
        [[(xj, 0.0), (xj, 1.0)] for xj in X[1:, 0]],
        transform=trans,
        colors=ROLE_COLORS["joint"],
        linestyles=":",
        linewidths=1.5,
        zorder=1,
    )
    ax.add_collection(jl, autolim=False)
    ax.axhline(0.0, color="#8B8B8B", lw=0.8, zorder=0)
    if labels:
        ax.set_xlabel("arc length s" if x == "arc_length" else "parameter t")
        ax.set_ylabel("signed curvature κ" if (signed and curve.dim == 2) else "curvature |κ|")
    arts = CurvatureProfileArtists(lines, ends, jl, per_segment, signed, x, arc_length_every)
    arts.update(curve, rescale=True)
    return arts
