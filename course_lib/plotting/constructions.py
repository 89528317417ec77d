"""Construction diagrams: how the Bézier control points of a geometrically continuous curve arise.

* :func:`plot_g1_stitch` -- seed 000 Fig. 7: ``W_0 = V_d``, ``W_1`` on the ray from
  ``V_{d-1}`` through ``V_d``, ``|W_0 W_1| : |V_{d-1} V_d| = β1 : 1`` (eq. (9)-(10)).
* :func:`plot_farin_boehm` -- seed 000 Fig. 8: the auxiliary point ``T`` on the
  extension of ``V_{d-2} V_{d-1}``, and ``W_2`` on the ray from ``T`` through ``W_1``
  (eq. (12)).
* :func:`plot_beta_spline_construction` -- seed 000 Fig. 10 and 11: interior Bézier
  vertices on the legs of the Beta-spline control polygon, junction vertices
  dividing ``1 : β1``.
* :func:`plot_knot_joint_construction` -- seed 004 Fig. 7: Finn's joint point
  ``p_{3i}`` divides ``p_{3i-1} p_{3i+1}`` as the knot ``t_i`` divides
  ``[t_{i-1}, t_{i+1}]`` (barycentric equivalence), drawn with the knot line.

The diagrams *read* the geometry (control points, ``curve.info``); they compute
nothing but where to put labels.  All return a :class:`Diagram` whose ``update``
moves every artist to new points (for widgets).

Why this module is long: each construction diagram (stitching, Farin-Boehm, Beta-spline,
knot joint) is one function with its labels, and they share the diagram type and its styles.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from itertools import pairwise

import numpy as np

from course_lib.plotting.curves import plot_curve
from course_lib.plotting.style import OKABE_ITO, ROLE_COLORS, SIZES
from course_lib.validation import as_points

__all__ = [
    "Diagram",
    "plot_beta_spline_construction",
    "plot_farin_boehm",
    "plot_g1_stitch",
    "plot_knot_joint_construction",
    "plot_stitching",
]

_STYLES = {
    "q": dict(color=OKABE_ITO["blue"], lw=1.6, ls="-", marker="o"),
    "r": dict(color=OKABE_ITO["vermillion"], lw=1.6, ls="-", marker="o"),
    "V": dict(color=OKABE_ITO["black"], lw=1.6, ls="-", marker="o"),
    "aux": dict(color=OKABE_ITO["bluish_green"], lw=SIZES["construction"], ls="--", marker=None),
    "knot": dict(color=OKABE_ITO["reddish_purple"], lw=2.0, ls="-", marker="|"),
    "link": dict(color="#888888", lw=1.0, ls=":", marker=None),
}


@dataclass
class Diagram:
    """Named points, polylines through them, labels and ratio marks, drawn and updatable.

    Attributes
    ----------
    points : dict of name -> (2,) array
    lines : dict of key -> (tuple of point names, style name)
    artists : dict of key -> matplotlib artist
        ``"line:<key>"``, ``"label:<point>"``, ``"ratio:<i>"``, ``"point:<style>"``,
        and ``"curve"`` (a :class:`~course_lib.plotting.curves.CurveArtists`) if drawn.
    """

    points: dict
    lines: dict
    labels: dict
    ratios: list
    artists: dict = field(default_factory=dict)

    def _ratio_pos(self, a: str, b: str, side: float):
        pa, pb = self.points[a], self.points[b]
        mid = 0.5 * (pa + pb)
        d = pb - pa
        n = np.array([-d[1], d[0]])
        nn = np.linalg.norm(n)
        return mid + (side * 0.035 * self._size / nn) * n if nn > 0 else mid

    @property
    def _size(self) -> float:
        P = np.array(list(self.points.values()))
        return float(np.linalg.norm(P.max(axis=0) - P.min(axis=0))) or 1.0

    def update(self, points: Mapping[str, np.ndarray], curve=None) -> None:
        """Move the diagram to new points (same names), and the curve if one was drawn."""
        for k, v in points.items():
            self.points[k] = np.asarray(v, dtype=float)
        for key, (names, _) in self.lines.items():
            P = np.array([self.points[n] for n in names])
            self.artists[f"line:{key}"].set_data(P[:, 0], P[:, 1])
        for name in self.labels:
            self.artists[f"label:{name}"].xy = tuple(self.points[name])
        for i, (a, b, _text, side) in enumerate(self.ratios):
            self.artists[f"ratio:{i}"].set_position(tuple(self._ratio_pos(a, b, side)))
        if curve is not None and "curve" in self.artists:
            self.artists["curve"].update(curve)


def _draw(ax, diagram: Diagram, *, label_offsets: Mapping[str, tuple] | None = None) -> Diagram:
    offs = dict(label_offsets or {})
    for key, (names, style) in diagram.lines.items():
        st = _STYLES[style]
        P = np.array([diagram.points[n] for n in names])
        (ln,) = ax.plot(
            P[:, 0],
            P[:, 1],
            color=st["color"],
            lw=st["lw"],
            ls=st["ls"],
            marker=st["marker"],
            ms=SIZES["control_point"] if st["marker"] == "o" else 12,
            mfc="white" if st["marker"] == "o" else st["color"],
            mec=st["color"],
            mew=1.6,
            zorder=5 if style in ("q", "r", "V") else 4,
        )
        diagram.artists[f"line:{key}"] = ln
    for name, text in diagram.labels.items():
        diagram.artists[f"label:{name}"] = ax.annotate(
            text,
            tuple(diagram.points[name]),
            xytext=offs.get(name, (7, 7)),
            textcoords="offset points",
            fontsize=SIZES["label"],
            zorder=8,
            ha="left" if offs.get(name, (7, 7))[0] >= 0 else "right",
            va="bottom" if offs.get(name, (7, 7))[1] >= 0 else "top",
            bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.7),
        )
    for i, (a, b, text, side) in enumerate(diagram.ratios):
        diagram.artists[f"ratio:{i}"] = ax.text(
            *diagram._ratio_pos(a, b, side),
            text,
            fontsize=SIZES["label"] - 1,
            color=OKABE_ITO["bluish_green"],
            ha="center",
            va="center",
            zorder=8,
            bbox=dict(boxstyle="round,pad=0.15", fc="white", ec=OKABE_ITO["bluish_green"], lw=0.8),
        )
    ax.set_aspect("equal", adjustable="datalim")
    ax.margins(0.15)  # room for the labels next to the outermost points (e.g. T)
    ax.autoscale_view()
    return diagram


# ----------------------------------------------------------------- stitching
def _stitch_parts(V: np.ndarray, W: np.ndarray, labels: bool):
    """Points, the q/r polygons and the labels shared by the G1 and G2 stitching diagrams."""
    d = V.shape[0] - 1
    pts = {f"V{i}": V[i] for i in range(d + 1)}
    pts.update({f"W{j}": W[j] for j in range(W.shape[0])})
    lines = {
        "ray": ((f"V{d - 1}", f"V{d}", "W1"), "aux"),
        "q": (tuple(f"V{i}" for i in range(d + 1)), "q"),
        "r": (tuple(f"W{j}" for j in range(W.shape[0])), "r"),
    }
    lab = {}
    if labels:
        lab = {f"V{i}": f"$V_{{{i}}}$" for i in range(d)}
        lab[f"V{d}"] = f"$V_{{{d}}} = W_0$"
        lab.update({f"W{j}": f"$W_{{{j}}}$" for j in range(1, W.shape[0])})
    return d, pts, lines, lab


def plot_g1_stitch(
    ax,
    V,
    W,
    beta1: float | None = None,
    *,
    curve: bool = True,
    labels: bool = True,
) -> Diagram:
    """Seed 000 Fig. 7: G1 stitching, ``W_0 = V_d`` and ``W_1 = V_d + β1 (V_d - V_{d-1})``.

    Parameters
    ----------
    V, W : array_like of shape (d + 1, 2)
        Control polygons of ``q`` (ending at the joint) and ``r`` (starting there).
    beta1 : float, optional
        Shown in the ratio label (the picture itself shows the ratio as lengths).
    curve : bool
        Also draw the two Bézier curves.

    Returns
    -------
    Diagram
        Points ``V0..Vd``, ``W0..Wd``; the ray from ``V_{d-1}`` through ``W_1`` is
        the line ``"ray"``.
    """
    V = as_points(V, "V", min_points=2, dims=(2,))
    W = as_points(W, "W", min_points=2, dims=(2,))
    d, pts, lines, lab = _stitch_parts(V, W, labels)
    ratios = [
        (f"V{d - 1}", f"V{d}", "1", _away(V[d - 1], V[d], V[:-1].mean(axis=0))),
        (
            "W0",
            "W1",
            "β₁" if beta1 is None else f"β₁ = {beta1:.3g}",
            _away(W[0], W[1], W[1:].mean(axis=0)),
        ),
    ]
    diagram = Diagram(pts, lines, lab, ratios)
    if curve:
        from course_lib.curves.curve import PiecewiseBezier

        diagram.artists["curve"] = plot_curve(
            ax, PiecewiseBezier([V, W]), polygon=False, points=False
        )
    return _draw(ax, diagram, label_offsets={f"V{d}": (-10, -12)})


def plot_farin_boehm(
    ax,
    V,
    W,
    T,
    beta1: float | None = None,
    gamma: float | None = None,
    *,
    curve: bool = True,
    labels: bool = True,
    lengths: bool = False,
) -> Diagram:
    """Seed 000 Fig. 8: the Farin-Boehm construction of ``W_0, W_1, W_2`` (eq. (12)).

    ``T = V_{d-1} + β1² γ (V_{d-1} - V_{d-2})`` lies on the extension of the leg
    ``V_{d-2} V_{d-1}``; ``W_2 = W_1 + (W_1 - T)/γ`` on the extension of ``T W_1``.
    The ratio labels name the lengths: ``|V_{d-2}V_{d-1}| : |V_{d-1}T| = 1 : β1²γ``,
    ``|TW_1| : |W_1W_2| = γ : 1``, ``|V_{d-1}V_d| : |W_0W_1| = 1 : β1``.

    Parameters
    ----------
    V, W : array_like of shape (d + 1, 2)
    T : array_like of shape (2,)
        The auxiliary point (from the construction, e.g. ``curve.info["T"]``).
    beta1, gamma : float, optional
        Values shown in the ratio labels.
    lengths : bool
        Name the lengths instead of marking the unit of each ratio with "1": the leg
        ``V_{d-2} V_{d-1}`` is ``a``, ``V_{d-1} T`` is ``β1²γ a``, ``W_1 W_2`` is ``b`` and
        ``T W_1`` is ``γ b`` (two different units: the plain "1" twice is ambiguous).

    Returns
    -------
    Diagram
        Points ``V*``, ``W*`` and ``T``; lines ``"leg"`` (``V_{d-2} V_{d-1} T``),
        ``"ray"`` (``V_{d-1} V_d W_1``) and ``"fan"`` (``T W_1 W_2``).
    """
    V = as_points(V, "V", min_points=3, dims=(2,))
    W = as_points(W, "W", min_points=3, dims=(2,))
    T = as_points(np.atleast_2d(np.asarray(T, dtype=float)), "T", min_points=1, dims=(2,))[0]
    d, pts, parts, lab = _stitch_parts(V, W, labels)
    pts["T"] = T
    lines = {
        "leg": ((f"V{d - 2}", f"V{d - 1}", "T"), "aux"),
        "ray": parts["ray"],
        "fan": (("T", "W1", "W2"), "aux"),
        "q": parts["q"],
        "r": parts["r"],
    }
    if labels:
        lab["T"] = "$T$"
    g = "γ" if gamma is None else f"γ={gamma:.3g}"
    bg = "β₁²γ" if beta1 is None or gamma is None else f"β₁²γ={beta1**2 * gamma:.3g}"
    units = ("a", "b") if lengths else ("1", "1")
    if lengths:
        bg = "β₁²γ·a" if beta1 is None or gamma is None else f"β₁²γ·a = {beta1**2 * gamma:.3g} a"
        g = "γ·b" if gamma is None else f"γ·b = {gamma:.3g} b"
    ratios = [
        (f"V{d - 2}", f"V{d - 1}", units[0], _away(V[d - 2], V[d - 1], V[d])),
        (f"V{d - 1}", "T", bg, 1.5 * _away(V[d - 1], T, V[d])),  # clear of the leg to V_d
        ("T", "W1", g, 1.0),
        ("W1", "W2", units[1], _away(W[1], W[2], np.delete(W, [1, 2], axis=0).mean(axis=0))),
    ]
    diagram = Diagram(pts, lines, lab, ratios)
    if curve:
        from course_lib.curves.curve import PiecewiseBezier

        diagram.artists["curve"] = plot_curve(
            ax, PiecewiseBezier([V, W]), polygon=False, points=False
        )
    offsets = _away_from_lines(pts, lines, lab)  # each label off every line through its point
    # V_{d-1} up and left: the ratio label of the short segment V_{d-1} T sits to its right
    offsets.update({f"V{d - 1}": (-8, 6), f"V{d}": (-10, -12), "T": (8, 4)})
    return _draw(ax, diagram, label_offsets=offsets)


def _info_get(info: Mapping, *names: str):
    for n in names:
        if n in info:
            return info[n]
    return None


def _first(x):
    if x is None:
        return None
    a = np.atleast_1d(np.asarray(x, dtype=float))
    return float(a[0]) if a.size else None


def plot_stitching(ax, curve, *, labels: bool = True) -> Diagram:
    """The stitching diagram of a two-segment curve built by G1 or G2 stitching.

    Reads ``curve.segments`` (``V``, ``W``) and ``curve.info`` (``"beta1"``, ``"beta2"``,
    or ``"T"``, ``"gamma"``): Fig. 8 (Farin-Boehm, ``T`` from
    :func:`course_lib.constructions.stitching.farin_boehm`) for a G2 stitch, else Fig. 7 (G1).
    """
    if curve.n_segments != 2:
        raise ValueError(
            f"plot_stitching draws a two-segment stitched curve; this one has {curve.n_segments}"
        )
    V, W = curve.segments
    info = curve.info
    b1 = _first(_info_get(info, "beta1", "β1"))
    b2 = _first(_info_get(info, "beta2", "β2"))
    T = _info_get(info, "T")
    gamma = _first(_info_get(info, "gamma"))
    if T is None and b1 is not None and b2 is not None:
        from course_lib.constructions.stitching import farin_boehm

        fb = farin_boehm(V[-3:], b1, b2, V.shape[0] - 1)
        T, gamma = fb.T, fb.gamma
    if T is not None:
        return plot_farin_boehm(ax, V, W, T, b1, gamma, labels=labels)
    return plot_g1_stitch(ax, V, W, b1, labels=labels)


# -------------------------------------------------------------- Beta-splines
def plot_beta_spline_construction(
    ax,
    curve,
    V,
    *,
    labels: bool = True,
    bezier_polygons: bool = True,
    show: str = "all",
) -> Diagram:
    """Seed 000 Fig. 10 (quadratic) / Fig. 11 (cubic): a Beta-spline built on its control polygon.

    Draws the Beta-spline control polygon ``V`` (black), the curve, the junction
    Bézier vertices (diamonds; they divide ``V_{i-1} V_i`` as ``1 : β1`` for the
    quadratic, the dashed link ``W_{i-1,2} W_{i,1}`` as ``1 : β1`` for the cubic)
    and the interior Bézier vertices (squares; on the legs of ``V``).

    Parameters
    ----------
    curve : PiecewiseBezier
        The Beta-spline (quadratic or cubic segments).
    V : array_like of shape (m + 1, 2)
        Its control polygon.
    show : {"all", "interior"}
        ``"interior"`` draws only the polygon and the interior Bézier vertices (seed 000
        Fig. 11 (a)); ``"all"`` adds the curve, the links and the junction vertices (b).
        Vertex labels sit outside the polygon's corners, away from the curve.

    Returns
    -------
    Diagram
        Points ``V*`` and ``J*`` (junctions), ``I*_*`` (interior vertices); ``"curve"`` artists.
    """
    V = as_points(V, "V", min_points=2, dims=(2,))
    if show not in ("all", "interior"):
        raise ValueError(f"show must be 'all' or 'interior'; got {show!r}")
    degs = set(curve.degrees)
    if len(degs) != 1 or degs.pop() not in (2, 3):
        raise ValueError(
            f"plot_beta_spline_construction needs quadratic or cubic segments; got {curve.degrees}"
        )
    d = curve.degrees[0]
    segs = curve.segments
    pts = {f"V{i}": V[i] for i in range(V.shape[0])}
    lines = {"V": (tuple(f"V{i}" for i in range(V.shape[0])), "V")}
    for j, s in enumerate(segs):
        pts[f"J{j}"] = s[0]
        for r in range(1, d):
            pts[f"I{j}_{r}"] = s[r]
    pts[f"J{len(segs)}"] = segs[-1][-1]
    if d == 3 and show == "all":
        for j in range(1, len(segs)):
            lines[f"link{j}"] = ((f"I{j - 1}_2", f"J{j}", f"I{j}_1"), "aux")
    lab = {}
    if labels:
        lab = {f"V{i}": f"$V_{{{i}}}$" for i in range(V.shape[0])}
    diagram = Diagram(pts, lines, lab, [])
    if show == "all":
        diagram.artists["curve"] = plot_curve(
            ax, curve, polygon=bezier_polygons, points=False, joints=False
        )
    _draw(ax, diagram, label_offsets=_outward_offsets(V))
    J = np.array([pts[f"J{j}"] for j in range(len(segs) + 1)])
    if show == "interior":
        J = J[:0]
    (jm,) = ax.plot(
        J[:, 0],
        J[:, 1],
        ls="none",
        marker="D",
        ms=SIZES["joint"] * 0.85,
        mfc=ROLE_COLORS["joint"],
        mec="black",
        zorder=7,
        label="junction vertices",
    )
    diagram.artists["junctions"] = jm
    if d >= 2:
        inner = np.array([pts[k] for k in pts if k.startswith("I")])
        (im,) = ax.plot(
            inner[:, 0],
            inner[:, 1],
            ls="none",
            marker="s",
            ms=6.5,
            mfc=OKABE_ITO["bluish_green"],
            mec="black",
            zorder=7,
            label="interior Bézier vertices",
        )
        diagram.artists["interior"] = im
    return diagram


def _away(P: np.ndarray, Q: np.ndarray, R: np.ndarray) -> float:
    """Side (+1 left of P->Q, -1 right) for a label on PQ, away from the point R (where the
    curve is: inside its control polygon)."""
    d, r = Q - P, R - P
    return -1.0 if d[0] * r[1] - d[1] * r[0] > 0 else 1.0


def _away_from_lines(pts: Mapping, lines: Mapping, names, dist: float = 9.0) -> dict:
    """Label offsets (points) for ``names``: away from the mean of each point's neighbours on
    the diagram's lines, so that a label sits beside its point, not on a line through it."""
    near: dict = {}
    for chain, _style in lines.values():
        for a, b in pairwise(chain):
            near.setdefault(a, []).append(pts[b])
            near.setdefault(b, []).append(pts[a])
    out = {}
    for name in names:
        d = pts[name] - np.mean(near.get(name, [pts[name]]), axis=0)
        n = np.linalg.norm(d)
        d = d / n if n > 0 else np.array([0.7, 0.7])
        out[name] = (float(dist * d[0]), float(dist * d[1]))
    return out


def _outward_offsets(V: np.ndarray, dist: float = 9.0) -> dict:
    """Label offsets (points) pointing out of each polygon corner, where the curve is not."""
    out = {}
    for i in range(V.shape[0]):
        nb = [V[j] for j in (i - 1, i + 1) if 0 <= j < V.shape[0]]
        d = V[i] - np.mean(nb, axis=0)
        n = np.linalg.norm(d)
        d = d / n if n > 0 else np.array([0.7, 0.7])
        out[f"V{i}"] = (float(dist * d[0]), float(dist * d[1]))
    return out


# ----------------------------------------------------------- Finn's knots
def plot_knot_joint_construction(
    ax,
    curve,
    knots: Sequence[float] | None = None,
    *,
    joints: Sequence[int] | None = None,
    d_points=None,
    offset: float = 0.12,
    labels: bool = True,
) -> Diagram:
    """Seed 004 Fig. 7: each joint point divides its neighbours as its knot divides its neighbours.

    For joint ``i`` (Finn's ``p_{3i}``, between segments ``i-1`` and ``i``, 1-based)
    the points ``p_{3i-1}, p_{3i}, p_{3i+1}`` are drawn with a copy of the knot
    interval ``[t_{i-1}, t_{i+1}]`` laid parallel to ``p_{3i-1} p_{3i+1}`` (offset to
    the side by ``offset`` times the picture size) so that ``t_{i-1}, t_i, t_{i+1}``
    sit level with ``p_{3i-1}, p_{3i}, p_{3i+1}``: dotted links connect them.
    If the links are parallel, the barycentric coordinates agree.

    Parameters
    ----------
    curve : PiecewiseBezier of cubic segments
    knots : array_like, optional
        Default ``curve.knots``.
    joints : sequence of int, optional
        Finn's 1-based joint indices ``i`` (``1 .. L-1``); default all.
    d_points : array_like of shape (2L + 2, 2), optional
        Finn's control points ``d_{-1} .. d_{2L}``, drawn as the black polygon.
    offset : float
        Distance of the knot copy from ``p_{3i-1} p_{3i+1}``, as a fraction of the picture
        size; its sign chooses the side (negative: the other side), so the copy and its
        labels can be put where the curve is not.

    Returns
    -------
    Diagram
    """
    if set(curve.degrees) != {3}:
        raise ValueError(f"Finn's G1 splines have cubic segments; got degrees {curve.degrees}")
    k = np.asarray(curve.knots if knots is None else knots, dtype=float)
    if k.shape != (curve.n_segments + 1,):
        raise ValueError(f"knots must have {curve.n_segments + 1} values; got {k.size}")
    if not np.isfinite(offset):
        raise ValueError(
            f"offset must be a finite number (a fraction of the picture size); got {offset}"
        )
    L = curve.n_segments
    idx = list(range(1, L)) if joints is None else [int(i) for i in joints]
    for i in idx:
        if not 1 <= i <= L - 1:
            raise ValueError(f"joints must be in 1..{L - 1} (Finn's joint index); got {i}")
    segs = curve.segments
    P = np.vstack(segs)
    size = float(np.linalg.norm(P.max(axis=0) - P.min(axis=0))) or 1.0
    pts, lines, lab, ratios = {}, {}, {}, []
    if d_points is not None:
        D = as_points(d_points, "d_points", min_points=2, dims=(2,))
        for j in range(D.shape[0]):
            pts[f"d{j}"] = D[j]
        lines["d"] = (tuple(f"d{j}" for j in range(D.shape[0])), "V")
        if labels:
            lab.update({f"d{j}": f"$d_{{{j - 1}}}$" for j in range(D.shape[0])})
    for i in idx:
        a, p, b = segs[i - 1][2], segs[i - 1][3], segs[i][1]
        ab = b - a
        n = np.array([-ab[1], ab[0]])
        n = n / (np.linalg.norm(n) or 1.0)
        off = -offset * size * n
        lam = (k[i] - k[i - 1]) / (k[i + 1] - k[i - 1])
        names = (f"a{i}", f"p{i}", f"b{i}")
        pts.update(dict(zip(names, (a, p, b), strict=True)))
        tnames = (f"ta{i}", f"tp{i}", f"tb{i}")
        pts.update(dict(zip(tnames, (a + off, a + lam * ab + off, b + off), strict=True)))
        lines[f"seg{i}"] = (names, "aux")
        lines[f"knot{i}"] = (tnames, "knot")
        for m, (u, v) in enumerate(zip(names, tnames, strict=True)):
            lines[f"link{i}_{m}"] = ((u, v), "link")
        if labels:
            lab[f"a{i}"] = f"$p_{{{3 * i - 1}}}$"
            lab[f"p{i}"] = f"$p_{{{3 * i}}}$"
            lab[f"b{i}"] = f"$p_{{{3 * i + 1}}}$"
            lab[f"ta{i}"] = f"$t_{{{i - 1}}}={k[i - 1]:.3g}$"
            lab[f"tp{i}"] = f"$t_{{{i}}}={k[i]:.3g}$"
            lab[f"tb{i}"] = f"$t_{{{i + 1}}}={k[i + 1]:.3g}$"
    diagram = Diagram(pts, lines, lab, ratios)
    diagram.artists["curve"] = plot_curve(ax, curve, polygon=True, points=False)
    offs = {}
    for i in idx:  # knot labels on the far side of the knot copy, away from the curve
        ab = segs[i][1] - segs[i - 1][2]
        away = np.copysign(1.0, offset) * np.array([ab[1], -ab[0]]) / (np.linalg.norm(ab) or 1.0)
        for nm in (f"ta{i}", f"tp{i}", f"tb{i}"):
            offs[nm] = (float(14 * away[0]), float(14 * away[1]))
    return _draw(ax, diagram, label_offsets=offs)
