"""Seed 000 Fig. 3 / seed 001 Fig. 3 as a static picture: one curve, two parametrizations.

Left: the curve ``Q`` with the points of equally spaced ``u`` (dots) and of equally spaced
``v`` mapped by ``f`` (squares), and the two velocities at one point: ``Q'(f(v))`` and
``(Q∘f)'(v) = f'(v) Q'(f(v))``.  They are parallel by the chain rule, so drawn from one
point one would hide the other: they start from the same point but are drawn side by side,
offset perpendicular to the curve by a few percent of its size.  Right: the graph of ``f``.
"""

from __future__ import annotations

import numpy as np

from course_lib.plotting.curves import plot_curve
from course_lib.plotting.style import OKABE_ITO
from course_lib.plotting.vectors import plot_vectors

__all__ = ["plot_reparametrization"]


def plot_reparametrization(axes, Q, f, v0: float, *, n: int = 9, scale: float = 0.25) -> dict:
    """Draw the curve panel on ``axes[0]`` and the graph of ``f`` on ``axes[1]``.

    Parameters
    ----------
    Q : plane parametrization (``evaluate(t, n)``), ``f`` : ChangeOfVariables onto Q's domain
    v0 : float
        The new parameter of the black point (in ``f.domain``).
    scale : float
        Drawn arrow = ``scale`` × velocity (say it in the caption).

    Returns
    -------
    dict of artists: ``curve``, ``dots``, ``squares``, ``velocity_Q``, ``velocity_Qf``,
    ``point``, ``graph``.
    """
    ax, fax = axes
    blue, red = OKABE_ITO["blue"], OKABE_ITO["vermillion"]
    (a, b), (c, d) = f.domain, Q.domain
    vs = np.linspace(a, b, n)
    us = np.linspace(c, d, n)
    art = {"curve": plot_curve(ax, Q, polygon=False, points=False, color="0.55")}
    P, S = Q.evaluate(us), Q.evaluate(f(vs))
    (art["dots"],) = ax.plot(*P.T, "o", ms=7, color=blue, label="Q(u), u equally spaced")
    (art["squares"],) = ax.plot(
        *S.T, "s", ms=7, mfc="none", mec=red, mew=2, label="Q(f(v)), v equally spaced"
    )
    u0 = float(f(v0))
    p, vel = Q.evaluate(u0), Q.evaluate(u0, 1)
    vel_f = float(f(v0, 1)) * vel  # chain rule
    size = float(np.ptp(Q.evaluate(np.linspace(c, d, 65)), axis=0).max())
    normal = np.array([-vel[1], vel[0]]) / np.linalg.norm(vel)
    off = 0.03 * size * normal
    art["velocity_Q"] = plot_vectors(
        ax, p + off, vel, scale=scale, color=blue, width=0.008, label=f"Q'(u), drawn × {scale:g}"
    )
    art["velocity_Qf"] = plot_vectors(
        ax,
        p - off,
        vel_f,
        scale=scale,
        color=red,
        width=0.008,
        label=f"(Q∘f)'(v), drawn × {scale:g}",
    )
    (art["point"],) = ax.plot(*p, "o", color="black", ms=8, zorder=8)
    tips = np.array([p + off + scale * vel, p - off + scale * vel_f])
    ax.update_datalim(tips)  # quivers do not autoscale: keep the arrow tips in view
    ax.autoscale_view()
    # Below the panel, one column: inside it, the legend would cover the curve or an axis
    # once the figure fits a laptop's notebook column (about 9 inches).
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.1), fontsize=9)
    ax.set_title("one curve, two parametrizations")
    grid = np.linspace(a, b, 101)
    (art["graph"],) = fax.plot(grid, f(grid), color=red, lw=2.4)
    fax.plot([a, b], [c, d], color="0.6", lw=1, ls=":")
    fax.plot(v0, u0, "o", color="black", ms=7)
    fax.set_xlabel("v")
    fax.set_ylabel("u = f(v)")
    fax.set_aspect("equal")
    fax.set_title("change of variables f")
    return art
