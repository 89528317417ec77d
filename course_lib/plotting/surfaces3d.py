"""Bézier patches in 3D and the unit normals along a shared boundary (seed 001 §3).

Two patches meet with G1 (tangent-plane continuity) when their unit normals agree
along the common boundary: :func:`plot_patch_pair` draws both patches, the boundary,
and the normals of each patch there, drawn from both sides, so agreement shows as
arrows lying on top of each other and a crease as arrows that split.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from course_lib.plotting.style import OKABE_ITO, ROLE_COLORS
from course_lib.validation import check_integer

__all__ = ["PatchArtists", "PatchPairArtists", "plot_patch", "plot_patch_pair"]


def require_3d(ax) -> None:
    if getattr(ax, "name", "") != "3d":
        raise ValueError(
            "surface pictures need a 3D Axes: new_figure(projection='3d') or "
            "fig.add_subplot(projection='3d')"
        )


@dataclass
class PatchArtists:
    """Artists of :func:`plot_patch`: the surface and (optionally) its control net."""

    surface: object
    net: list = field(default_factory=list)


def plot_patch(
    ax,
    patch,
    *,
    color: str | None = None,
    resolution: int = 17,
    net: bool = True,
    alpha: float = 0.55,
    label: str | None = None,
) -> PatchArtists:
    """Draw a :class:`~course_lib.constructions.surfaces.BezierPatch` as a shaded surface with its control net.

    Parameters
    ----------
    ax : 3D Axes
    patch : BezierPatch
    resolution : int
        Samples per parameter direction.
    """
    require_3d(ax)
    n = check_integer(resolution, "resolution", minimum=2)
    color = color or OKABE_ITO["blue"]
    s = np.linspace(0.0, 1.0, n)
    X = patch.evaluate(s, s)  # (n, n, 3)
    surf = ax.plot_surface(
        X[..., 0],
        X[..., 1],
        X[..., 2],
        color=color,
        alpha=alpha,
        linewidth=0.3,
        edgecolor="white",
        shade=True,
        label=label,
    )
    lines = []
    if net:
        N = patch.control_net
        for row in N:
            lines += ax.plot(
                row[:, 0], row[:, 1], row[:, 2], color=color, lw=0.9, ls="--", marker="o", ms=3
            )
        for col in N.transpose(1, 0, 2):
            lines += ax.plot(col[:, 0], col[:, 1], col[:, 2], color=color, lw=0.9, ls="--")
    return PatchArtists(surf, lines)


@dataclass
class PatchPairArtists:
    """Artists of :func:`plot_patch_pair`."""

    F: PatchArtists
    G: PatchArtists
    boundary: object
    normals_F: object | None
    normals_G: object | None
    v: np.ndarray
    length: float
    #: on an interactive canvas: coarse surfaces while the mouse rotates (see ``_motion``)
    motion: object | None = None


def plot_patch_pair(
    ax,
    F,
    G,
    *,
    normals: bool = True,
    n_normals: int = 7,
    length: float | None = None,
    resolution: int = 17,
    net: bool = True,
    zoom: float = 1.0,
) -> PatchPairArtists:
    """Two patches sharing the boundary ``F(1, v) = G(0, v)``, with unit normals along it.

    The normals of ``F`` at ``u = 1`` (blue, solid) and of ``G`` at ``u = 0``
    (vermillion, dashed) are drawn at ``n_normals`` values of ``v``; for a G1 pair
    they coincide.  Normals come from :meth:`BezierPatch.normal` (the math layer).

    Parameters
    ----------
    length : float, optional
        Drawn length of the unit normals (default 35 % of the patches' size).
    zoom : float
        Scale of the 3D box inside its Axes (matplotlib's ``set_box_aspect(zoom=...)``);
        above 1 it trims the empty margin a 3D Axes keeps around its box, so a pair of
        panels stays readable in a figure narrow enough for a laptop (about 8.5 inches,
        850 px, for two panels side by side).

    Returns
    -------
    PatchPairArtists

    Raises
    ------
    ValueError
        If ``ax`` is not 3D, or a patch is not regular on the boundary.
    """
    require_3d(ax)
    k = check_integer(n_normals, "n_normals", minimum=1)
    if not (isinstance(zoom, (int, float)) and 0.25 <= zoom <= 4):
        raise ValueError(f"zoom must be a number between 0.25 and 4, got {zoom!r}")
    a = plot_patch(ax, F, color=OKABE_ITO["blue"], resolution=resolution, net=net)
    b = plot_patch(ax, G, color=OKABE_ITO["vermillion"], resolution=resolution, net=net)
    s = np.linspace(0.0, 1.0, 41)
    B = F.evaluate(1.0, s)
    (bd,) = ax.plot(
        B[:, 0], B[:, 1], B[:, 2], color=ROLE_COLORS["joint"], lw=3.0, label="shared boundary"
    )
    v = np.linspace(0.0, 1.0, k)
    nF = nG = None
    if length is None:
        P = np.vstack([F.control_net.reshape(-1, 3), G.control_net.reshape(-1, 3)])
        length = 0.35 * float(np.max(np.ptp(P, axis=0)))
    if normals:
        p = F.evaluate(1.0, v)
        dF = F.normal(1.0, v) * length
        dG = G.normal(0.0, v) * length
        nF = ax.quiver(
            p[:, 0],
            p[:, 1],
            p[:, 2],
            dF[:, 0],
            dF[:, 1],
            dF[:, 2],
            color=OKABE_ITO["blue"],
            linewidth=3.0,
            arrow_length_ratio=0.15,
            label="normal of F at u = 1",
        )
        q = G.evaluate(0.0, v)
        nG = ax.quiver(
            q[:, 0],
            q[:, 1],
            q[:, 2],
            dG[:, 0],
            dG[:, 1],
            dG[:, 2],
            color=OKABE_ITO["vermillion"],
            linewidth=1.4,
            linestyles="--",
            arrow_length_ratio=0.15,
            label="normal of G at u = 0",
        )
    # quivers do not autoscale: make room for the arrow tips so no normal is clipped
    pts = [F.control_net.reshape(-1, 3), G.control_net.reshape(-1, 3)]
    if normals:
        pts += [p + dF, q + dG]
    _fit_limits(ax, np.vstack(pts))
    ax.set_box_aspect((1, 1, 1), zoom=float(zoom))
    from matplotlib.ticker import MaxNLocator

    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):  # few ticks: the numbers are not the point
        axis.set_major_locator(MaxNLocator(4))
    motion = None
    from course_lib.plotting._motion import LightWhileRotating, is_interactive_canvas

    if is_interactive_canvas(ax.get_figure(root=True).canvas):
        # turning the picture with the mouse: coarse surfaces and a frozen layout until release
        coarse = max(2, min(resolution, 7))
        light = [
            plot_patch(ax, P, color=col, resolution=coarse, net=False).surface
            for P, col in ((F, OKABE_ITO["blue"]), (G, OKABE_ITO["vermillion"]))
        ]
        motion = LightWhileRotating(ax, [a.surface, b.surface], light)
    return PatchPairArtists(a, b, bd, nF, nG, v, float(length), motion)


def _fit_limits(ax, P: np.ndarray, margin: float = 0.05) -> None:
    """Set the 3D axes limits to contain the points ``P`` (n, 3) with a margin."""
    lo, hi = P.min(axis=0), P.max(axis=0)
    pad = margin * np.maximum(hi - lo, 1e-9)
    ax.set_xlim(lo[0] - pad[0], hi[0] + pad[0])
    ax.set_ylim(lo[1] - pad[1], hi[1] + pad[1])
    ax.set_zlim(lo[2] - pad[2], hi[2] + pad[2])
