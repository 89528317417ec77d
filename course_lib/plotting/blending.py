"""Blending (basis) functions of a construction, drawn over their support.

A construction that is affine in its control points (Catmull-Rom, Beta-splines, Finn's
knot splines: every construction of the course, for fixed shape parameters or knots)
writes each point of the curve as ``sum_j b_j(t) V_j``.  The blending function
``b_k`` is read off by building the curve from the points ``V_j = (j, delta_jk)``: its
second coordinate is ``sum_j b_j(t) delta_jk = b_k(t)``.  No formula for ``b_k`` is
needed, so the picture shows exactly what the construction does (and the test
``tests/unit/test_plotting.py`` checks partition of unity and local support).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from course_lib.geometry.sampling import segment_samples
from course_lib.plotting.style import OKABE_ITO, SIZES
from course_lib.validation import check_integer

__all__ = ["BlendingArtists", "blending_functions", "plot_blending_functions"]


def blending_functions(
    construct: Callable[[np.ndarray], object], n_points: int, per_segment: int = 64
) -> tuple[np.ndarray, np.ndarray]:
    """Sample the blending functions ``b_0 .. b_{n-1}`` of ``construct``.

    Parameters
    ----------
    construct : callable ``points (n, 2) -> PiecewiseBezier``
        The construction with its shape parameters fixed, e.g.
        ``lambda P: cubic_beta_spline(P, beta1=2, beta2=0)``.
    n_points : int
        Number of control points it takes.

    Returns
    -------
    t : ndarray of shape (S, per_segment)
        Global parameters, one row per segment (one-sided at joints).
    b : ndarray of shape (n_points, S, per_segment)
        ``b[k]`` samples ``b_k(t)``.
    """
    n = check_integer(n_points, "n_points", minimum=1)
    rows = []
    t = None
    for k in range(n):
        P = np.zeros((n, 2))
        P[:, 0] = np.arange(n, dtype=float)
        P[k, 1] = 1.0
        curve = construct(P)
        tk, pts = segment_samples(curve, per_segment)
        if t is None:
            t = tk
        rows.append(pts[..., 1])
    return t, np.stack(rows)


@dataclass
class BlendingArtists:
    """Artists of :func:`plot_blending_functions`: one LineCollection per blending function."""

    lines: list
    support: object | None
    joint_lines: object


_CYCLE = [
    OKABE_ITO[k]
    for k in (
        "blue",
        "vermillion",
        "bluish_green",
        "orange",
        "reddish_purple",
        "sky_blue",
        "black",
        "yellow",
    )
]


def plot_blending_functions(
    ax,
    construct: Callable[[np.ndarray], object],
    n_points: int,
    *,
    per_segment: int = 64,
    highlight: int | None = None,
    labels: bool = True,
) -> BlendingArtists:
    """Draw every blending function ``b_k(t)`` of a construction against the global parameter.

    Each function is drawn segment by segment (a LineCollection), so a jump in a
    derivative is never smoothed over; dotted lines mark the joints.  With
    ``highlight=k`` the support of ``b_k`` (where it is not zero) is shaded and the
    other functions are drawn thin.

    Returns
    -------
    BlendingArtists
    """
    from matplotlib.collections import LineCollection
    from matplotlib.transforms import blended_transform_factory

    t, b = blending_functions(construct, n_points, per_segment)
    n = b.shape[0]
    if highlight is not None:
        highlight = check_integer(highlight, "highlight", minimum=0)
        if highlight >= n:
            raise ValueError(f"highlight must be < n_points = {n}; got {highlight}")
    lines = []
    for k in range(n):
        strong = highlight is None or k == highlight
        lc = LineCollection(
            list(np.stack([t, b[k]], axis=-1)),
            colors=_CYCLE[k % len(_CYCLE)],
            linewidths=SIZES["curve"] * (0.8 if strong else 0.35),
            alpha=1.0 if strong else 0.6,
            label=f"$b_{{{k}}}$" if labels else None,
            zorder=3,
        )
        ax.add_collection(lc)
        lines.append(lc)
    support = None
    if highlight is not None:
        scale = max(float(np.max(np.abs(b))), 1.0)
        nz = np.any(np.abs(b[highlight]) > 1e-12 * scale, axis=1)  # segments where b_k != 0
        if np.any(nz):
            lo = float(t[np.argmax(nz), 0])
            hi = float(t[len(nz) - 1 - np.argmax(nz[::-1]), -1])
            support = ax.axvspan(
                lo,
                hi,
                color=_CYCLE[highlight % len(_CYCLE)],
                alpha=0.12,
                zorder=0,
                label=f"support of $b_{{{highlight}}}$",
            )
    trans = blended_transform_factory(ax.transData, ax.transAxes)
    jl = LineCollection(
        [[(x, 0.0), (x, 1.0)] for x in t[1:, 0]],
        transform=trans,
        colors="#8B8B8B",
        linestyles=":",
        linewidths=1.0,
        zorder=1,
    )
    ax.add_collection(jl, autolim=False)
    ax.axhline(0.0, color="#8B8B8B", lw=0.8, zorder=0)
    ax.set_xlim(float(t[0, 0]), float(t[-1, -1]))
    lo, hi = float(np.min(b)), float(np.max(b))
    ax.set_ylim(min(lo, 0.0) - 0.05, max(hi, 1.0) + 0.05)
    if labels:
        ax.set_xlabel("parameter t")
        ax.set_ylabel("blending function")
    return BlendingArtists(lines, support, jl)
