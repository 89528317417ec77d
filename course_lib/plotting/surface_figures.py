"""Two pictures of seed 001 §3: the oriented domain and its image (Fig. 6), and the
parameter lines of a patch under a change of parameters (Fig. 8).

Like every plotting module, these take a 3D Axes and return their artists; the points
come from :class:`~course_lib.constructions.surfaces.BezierPatch` (the math layer).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from course_lib.plotting.style import OKABE_ITO
from course_lib.plotting.surfaces3d import plot_patch, require_3d
from course_lib.validation import check_integer

__all__ = ["plot_domain_and_patch", "plot_parameter_lines"]


def plot_domain_and_patch(ax, patch, *, below: float = 2.0) -> dict:
    """Seed 001 Fig. 6: the patch over a flat copy of its oriented domain ``D``.

    The domain is drawn as a grey grid ``below`` units under the patch's lowest control
    point, spanning the patch's x-y extent, labelled ``D``, with an arrow for its top
    side at the front corner; the patch carries its unit normal at the centre, ``(u, v) = (1/2, 1/2)``.

    Returns
    -------
    dict with ``patch``, ``domain``, ``label``, ``domain_arrow``, ``normal``.
    """
    require_3d(ax)
    N = patch.control_net.reshape(-1, 3)
    (x0, y0, z0), (x1, y1, z1) = N.min(axis=0), N.max(axis=0)
    zd = z0 - below
    size = max(x1 - x0, y1 - y0, z1 - z0)
    X, Y = np.meshgrid(np.linspace(x0, x1, 7), np.linspace(y0, y1, 7))
    art = {"patch": plot_patch(ax, patch, net=False)}
    art["domain"] = ax.plot_wireframe(X, Y, np.full_like(X, zd), color="grey", lw=0.8)
    art["label"] = ax.text(x1 + 0.08 * size, y0 + 0.5 * (y1 - y0), zd, "D", fontsize=16)
    up = 0.3 * size
    # the top side of D, at the front corner where the patch does not hide it
    art["domain_arrow"] = ax.quiver(x1, y0, zd, 0, 0, min(up, 0.6 * below), color="k", lw=2)
    p, n = patch.evaluate(0.5, 0.5), patch.normal(0.5, 0.5)
    art["normal"] = ax.quiver(*p, *(n * up), color="k", lw=2)
    ax.set_zlim(zd - 0.05 * size, max(z1, p[2] + up) + 0.05 * size)
    return art


def plot_parameter_lines(
    ax,
    patch,
    change: Callable[[np.ndarray, np.ndarray], tuple] | None = None,
    *,
    lines: int = 9,
    color: str | None = None,
) -> object:
    """Seed 001 Fig. 8: the lines of constant parameter of ``patch`` (``change=None``) or of
    the reparametrized patch ``G(u(ũ, ṽ), v(ũ, ṽ))`` with ``change(ũ, ṽ) -> (u, v)``.

    Returns the wireframe artist.
    """
    require_3d(ax)
    n = check_integer(lines, "lines", minimum=2)
    s = np.linspace(0.0, 1.0, n)
    if change is None:
        X = patch.evaluate(s, s)
    else:
        S, T = np.meshgrid(s, s, indexing="ij")
        u, v = (np.asarray(w, dtype=float).ravel() for w in change(S, T))
        X = patch.evaluate(u, v, grid=False).reshape(n, n, 3)
    color = color or (OKABE_ITO["blue"] if change is not None else "grey")
    return ax.plot_wireframe(X[..., 0], X[..., 1], X[..., 2], color=color, lw=1.0)
