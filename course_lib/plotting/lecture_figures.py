"""The lectures' static figures, one function per figure, so that a figure cell is one line.

Each function takes curves and points the lecture has already computed (no mathematics is
done here), draws them in the course style and returns the figure.  The notebook cell that
calls it is named in the docstring; the caption is the lecture's prose around that cell.

Why this module is long: every lecture figure is a one-line call the lectures import from
here; each function is short.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from course_lib.plotting.constructions import (
    plot_beta_spline_construction,
    plot_farin_boehm,
    plot_stitching,
)
from course_lib.plotting.curvature import plot_curvature_comb, plot_curvature_profile
from course_lib.plotting.curves import plot_control_polygon, plot_curve
from course_lib.plotting.style import OKABE_ITO, ROLE_COLORS, new_figure
from course_lib.plotting.vectors import (
    plot_frame,
    plot_osculating_circle,
    plot_vectors,
    plot_velocity,
)

__all__ = [
    "bezier_figure",
    "catmull_rom_figure",
    "closeness_figure",
    "combs_figure",
    "cubic_beta_spline_figure",
    "curvature_profiles_figure",
    "deformation_figure",
    "degree_raising_figure",
    "domain_and_patch_figure",
    "example1_figure",
    "farin_boehm_figure",
    "frame_figure",
    "g1_joint_figure",
    "g1_stitching_figure",
    "glyph_points_figure",
    "glyphs_figure",
    "joint_figure",
    "knot_joint_figure",
    "models_figure",
    "names_figure",
    "outlines_figure",
    "parameter_lines_figure",
    "patch_pairs_figure",
    "quadratic_beta_spline_figure",
    "quartic_conventions_figure",
    "rebuilt_figure",
    "reparametrization_figure",
    "splines_figure",
]


def _bezier(points):
    from course_lib.curves.curve import PiecewiseBezier  # a container for drawing, no computation

    return PiecewiseBezier([np.asarray(points, dtype=float)])


# ------------------------------------------------------------------------ lecture 05
def bezier_figure(V):
    """Lecture 07, ``nb07-005`` (Barsky & DeRose 1988, Fig. 4): a cubic and its polygon."""
    fig, ax = new_figure(figsize=(6.5, 4.4))
    plot_curve(ax, _bezier(V), points=False)
    plot_control_polygon(ax, V, labels="$V_{i}$", linestyle="none")
    ax.set_adjustable("box")
    ax.set_ylim(-0.3, 3.1)
    ax.set_title("a cubic Bézier curve and its control polygon")
    return fig


def degree_raising_figure(V, W):
    """Lecture 07, ``nb07-013`` (Fig. 5): the cubic polygon ``V`` (grey), the quartic ``W``."""
    fig, ax = new_figure(figsize=(6.5, 4.4))
    plot_curve(ax, _bezier(W), points=False)
    plot_control_polygon(ax, V, labels=["", "$V_1$", "$V_2$", ""], color=ROLE_COLORS["polygon"])
    plot_control_polygon(ax, W, labels="$W_{i}$")
    ax.set_adjustable("box")
    ax.set_ylim(-0.3, 3.1)
    ax.set_title("degree raising: V (cubic), W (quartic)")
    return fig


def g1_stitching_figure(q_poly, stitched, beta1: float):
    """Lecture 07, ``nb07-019`` (Figs. 6 and 7): the situation, then the G1 construction."""
    fig, (a1, a2) = new_figure(2, 1, figsize=(8.8, 5.6))
    plot_curve(a1, stitched, points=False)
    plot_control_polygon(a1, q_poly, labels="$V_{i}$", linestyle="none")
    W_labels = ["", "$W_1$", "$W_2$", "$W_3$"]
    plot_control_polygon(a1, stitched.segments[1], labels=W_labels, linestyle="none")
    a1.set_title("two Bézier curves, W₀ = V₃", pad=14)
    plot_stitching(a2, stitched)
    a2.set_title(f"G1 stitching, β₁ = {beta1:g}", pad=14)
    for ax in (a1, a2):
        ax.margins(y=0.18)
    return fig


def farin_boehm_figure(q_poly, stitched, fb, beta1: float):
    """Lecture 07, ``nb07-028`` (Fig. 8): the Farin–Boehm construction with its lengths."""
    fig, ax = new_figure(figsize=(8.6, 4.4))
    plot_farin_boehm(ax, q_poly, stitched.segments[1], fb.T, beta1, fb.gamma, lengths=True)
    ax.set_aspect("equal", adjustable="box")
    ax.set(xlim=(-0.7, 9.8), ylim=(-1.6, 3.2))  # room for the labels of V_0, W_3 and the title
    ax.set_title("Farin–Boehm: G2 stitching, β₁ = 1, β₂ = 1")
    return fig


def catmull_rom_figure(P, curves: Mapping[float, object]):
    """Lecture 07, ``nb07-044`` (Fig. 9): one panel per β1, and all of them overlaid."""
    colors = ("black", OKABE_ITO["bluish_green"], OKABE_ITO["reddish_purple"])
    fig, axs = new_figure(2, 2, figsize=(8.8, 4.6))
    for ax, (beta, cr), color in zip(axs.flat, curves.items(), colors, strict=False):
        plot_curve(ax, cr, polygon=False, points=False)
        plot_control_polygon(ax, P, linestyle=":")
        ax.set_title(f"β₁ = {beta:g}")
        plot_curve(
            axs[1, 1],
            cr,
            polygon=False,
            points=False,
            joints=False,
            alternate=False,
            color=color,
            label=f"β₁ = {beta:g}",
        )
    axs[1, 1].set_title("all three")
    axs[1, 1].legend(loc="lower left")
    return fig


def quadratic_beta_spline_figure(quad, P, betas):
    """Lecture 08, ``nb08-048`` (Fig. 10): the quadratic G1 Beta-spline's construction;
    ``betas`` are the β1 of its joints (for the title)."""
    fig, ax = new_figure(figsize=(8.8, 3.8))
    plot_beta_spline_construction(ax, quad, P)
    ax.legend(loc="lower right")
    values = ", ".join(f"{b:g}" for b in betas)
    ax.set_title(f"quadratic G1 Beta-spline, β₁ = {values} at the joints")
    return fig


def cubic_beta_spline_figure(cubic, P):
    """Lecture 08, ``nb08-062`` (Fig. 11 a, b): interior vertices, then junctions and curve."""
    fig, (a1, a2) = new_figure(2, 1, figsize=(8.8, 6.4))
    plot_beta_spline_construction(a1, cubic, P, show="interior")
    plot_beta_spline_construction(a2, cubic, P)
    a1.set_title("(a) interior Bézier vertices on the legs")
    a2.set_title("(b) junction vertices on the links, and the curve")
    for ax in (a1, a2):
        ax.set(xlim=(-0.8, 11.3), ylim=(-0.7, 3.9))
        ax.set_aspect("equal", adjustable="box")
    fig.legend(*a2.get_legend_handles_labels(), loc="outside lower center", ncol=2)
    return fig


def curvature_profiles_figure(curves: Mapping[str, object]):
    """Lecture 08, ``nb08-062b``: κ against arc length, one panel per ``title: curve``."""
    fig, axes = new_figure(1, len(curves), figsize=(8.8, 3.2))
    for ax, (title, curve) in zip(np.atleast_1d(axes), curves.items(), strict=True):
        plot_curvature_profile(ax, curve)
        ax.set_title(title)
    return fig


# ------------------------------------------------------------------------ lecture 01
def deformation_figure(Q, us):
    """Lecture 01, ``nb01-007`` (DeRose & Barsky 1985, Fig. 1): the oriented segment [0, 1]
    with unit tangents at ``us``, and its image, the curve ``Q``, with the same tangents."""
    domain = _bezier([[0, 0], [1, 0]])
    fig, (ax_u, ax_q) = new_figure(1, 2, figsize=(8.8, 3.0))
    plot_curve(ax_u, domain, polygon=False, points=False)
    plot_frame(ax_u, domain, us, curvature=False, length=0.1)
    plot_curve(ax_q, Q, polygon=False, points=False)
    plot_frame(ax_q, Q, us, curvature=False, length=0.4)
    ax_u.set_title("segment [0, 1], oriented")
    ax_q.set_title("its image, the curve Q([0, 1])")
    return fig


def joint_figure(qr):
    """Lecture 01, ``nb01-013`` (Barsky & DeRose 1988, Fig. 1): pieces q and r meeting at J."""
    fig, ax = new_figure(figsize=(8.6, 3.8))
    plot_curve(ax, qr, polygon=False, points=False)
    J = qr.segments[1][0]
    ax.annotate("J = q(1) = r(0)", xy=J, xytext=(J[0] + 0.15, J[1] + 0.3), fontsize=13)
    ax.text(0.6, 1.75, "q(u)", fontsize=13)
    ax.text(5.0, 0.9, "r(t)", fontsize=13)
    return fig


def example1_figure(ex1, dq, dr, typo=None):
    """Lecture 01, ``nb01-024`` (Fig. 2): Example 1 with the two velocities at J; with
    ``typo`` (``nb01-033``) also the unit tangent and the printed typo's vector."""
    J, below = np.asarray(ex1.segments[1][0], dtype=float), np.array([0.12, -0.24])
    vq, vr = (np.array(d, dtype=float).ravel() for d in (dq, dr))  # sympy -> numpy
    fig, ax = new_figure(figsize=(8.6, 4.2))
    plot_curve(ax, ex1, polygon=False, points=False)
    plot_vectors(
        ax,
        J - vq / 2 + below,
        vq,
        scale=0.5,
        color=ROLE_COLORS["segment_even"],
        label="q'(1) = (2, 1), drawn × ½",
    )
    plot_vectors(
        ax,
        J + below,
        vr,
        scale=0.5,
        color=ROLE_COLORS["segment_odd"],
        label="r'(0) = (4, 2), drawn × ½",
    )
    ax.set_title("Example 1: the velocity jumps at J, the direction does not")
    if typo is not None:
        plot_frame(ax, ex1, 1.0, curvature=False, length=1.0)
        T_typo = np.array(typo, dtype=float).ravel()
        plot_vectors(ax, J, T_typo, color=ROLE_COLORS["highlight"], label="typo (4/5, 3/5)")
    ax.legend(loc="upper left")
    return fig


def reparametrization_figure(Q, f, v0: float):
    """Lecture 02, ``nb02-039`` (Barsky & DeRose 1988, Fig. 3): ``Q`` and ``Q∘f``."""
    from course_lib.plotting.reparametrization_figure import plot_reparametrization

    fig, axes = new_figure(1, 2, figsize=(8.8, 4.2))
    plot_reparametrization(axes, Q, f, v0)
    return fig


def models_figure(Q, curves, p, titles):
    """Lecture 02, ``nb02-047`` (DeRose & Barsky 1985, Fig. 2): one panel per curve, the
    image of ``Q`` in grey and the curve's velocities at the parameters ``p``."""
    fig, axes = new_figure(1, len(curves), figsize=(8.8, 3.0))
    for ax, c, title in zip(axes, curves, titles, strict=True):
        plot_curve(ax, Q, polygon=False, points=False, alternate=False, color="0.6")
        plot_velocity(ax, c, p, scale=0.1, color=ROLE_COLORS["segment_odd"], width=0.014)
        ax.set_title(title)
        ax.label_outer()  # one column of y ticks, at the left
    return fig


# ------------------------------------------------------------------------ lecture 02
def names_figure(qr):
    """Lecture 03, ``nb03-018b`` (DeRose & Barsky 1985, Fig. 4): the 1985 paper's names,
    r arriving at J and q leaving it."""
    fig, ax = new_figure(figsize=(8.6, 3.6))
    plot_curve(ax, qr, polygon=False, points=False)
    J = qr.segments[1][0]
    ax.annotate("J = r(t₁) = q(u₀)", xy=J, xytext=(J[0] + 0.15, J[1] + 0.3), fontsize=13)
    ax.text(0.3, 1.75, "r(t), t ∈ [t₀, t₁]", fontsize=13)
    ax.text(3.4, 0.0, "q(u), u ∈ [u₀, u₁]", fontsize=13)
    ax.set_title("DeRose & Barsky's names: r arrives at J, q leaves it")
    return fig


def combs_figure(curves: Mapping[str, object]):
    """Lecture 04, ``nb04-044``: per ``name: curve`` a row with the curve and its curvature
    comb (80 teeth), and its curvature against arc length."""
    fig, axes = new_figure(len(curves), 2, figsize=(8.8, 3.1 * len(curves)))
    for row, (name, curve) in zip(np.atleast_2d(axes), curves.items(), strict=True):
        plot_curve(row[0], curve, polygon=False, points=False)
        plot_curvature_comb(row[0], curve, samples=80)
        plot_curvature_profile(row[1], curve)
        row[0].set_title(f"{name}: comb")
        row[1].set_title("its κ against arc length s")
    return fig


# ------------------------------------------------------------------------ lecture 03
def frame_figure(curve, t_left: float = 0.2, t_right: float = 0.8):
    """Lecture 05, ``nb05-018`` (Finn, Figs. 1 and 2): left, the frame T, N, dT/ds and the
    osculating circle at ``t_left``; right, the frame at both parameters."""
    fig, (a1, a2) = new_figure(1, 2, figsize=(8.8, 3.8))
    for ax in (a1, a2):
        plot_curve(ax, curve, polygon=False, points=False, joints=False)
    plot_osculating_circle(a1, curve, t_left)
    plot_frame(a1, curve, t_left, normal=True)
    plot_frame(a2, curve, [t_left, t_right], normal=True, labels=False)
    a1.legend(loc="lower right", fontsize=9)
    a1.set_title(f"T, N, dT/ds = κN and\nthe osculating circle (t = {t_left:g})")
    a2.set_title(f"κ({t_left:g}) > 0 (turns left),\nκ({t_right:g}) < 0 (turns right)")
    return fig


def rebuilt_figure(curve, rebuilt, moved):
    """Lecture 05, ``nb05-029``: a curve, its samples rebuilt from κ(s), and the same κ(s)
    started elsewhere in another direction."""
    fig, ax = new_figure(figsize=(7, 4.5))
    plot_curve(ax, curve, polygon=False, points=False, joints=False, label="original")
    ax.plot(*rebuilt.points.T, "o", ms=4, label="rebuilt from κ(s)")
    ax.plot(*moved.points.T, "s", ms=4, label="same κ(s), other start")
    ax.legend(loc="lower left")
    ax.set_title("one curvature function, one shape")
    return fig


def closeness_figure(circle, others, t):
    """Lecture 05, ``nb05-038`` (Finn, Fig. 3): top, each curve of ``others`` (a list of
    ``(curve or samples, label, title)``) over the circle (grey); bottom, their signed
    curvature against arc length over the circle's κ = 1.  A curve given as samples of
    :func:`~course_lib.geometry.differential_geometry.curve_from_curvature` (``s``, ``points``,
    ``angle``) has its curvature read off the tangent angle, κ = dθ/ds."""
    from course_lib.geometry.differential_geometry import signed_curvature

    ref = circle.evaluate(t)
    fig, axes = new_figure(2, len(others), figsize=(8.8, 5.6))
    for (top, bottom), (curve, label, title) in zip(axes.T, others, strict=True):
        top.plot(*ref.T, color="0.6", lw=3)
        if hasattr(curve, "angle"):
            pts, s, kappa = curve.points, curve.s, np.gradient(curve.angle, curve.s)
        else:
            pts = curve.evaluate(t)
            steps = np.linalg.norm(np.diff(pts, axis=0), axis=1)
            s, kappa = np.concatenate([[0.0], np.cumsum(steps)]), signed_curvature(curve, t)
        top.plot(*pts.T, lw=1.2)
        top.set_aspect("equal")
        top.locator_params(axis="x", nbins=4)
        top.set_title(f"{title}\n{label}", fontsize=10)
        bottom.axhline(1.0, color="0.6", lw=3)
        bottom.plot(s, kappa, lw=1.2 if np.ptp(kappa) < 5 else 0.5)
        bottom.set_ylim(-0.2, 2.2)
        if np.ptp(kappa) > 5:  # far off the scale: say how far
            bottom.text(
                0.5,
                0.95,
                f"κ from {kappa.min():.0f} to {kappa.max():.0f}",
                transform=bottom.transAxes,
                ha="center",
                va="top",
                fontsize=10,
                bbox={"facecolor": "white", "edgecolor": "0.7"},
            )
        bottom.set_xlabel("arc length s")
    axes[1, 0].set_ylabel("signed curvature κ")
    for ax in axes[1, 1:]:
        ax.tick_params(labelleft=False)
    return fig


def g1_joint_figure(curve, p):
    """Lecture 06, ``nb06-040`` (Finn, Fig. 4): two cubics joined G1 and their points p_i."""
    fig, ax = new_figure(figsize=(8, 3.8))
    plot_curve(ax, curve)
    plot_control_polygon(ax, p, labels="$p_{i}$", linestyle="none")
    ax.set_title("G1 joint: p₃ on the segment p₂p₄, not at its midpoint")
    return fig


def splines_figure(splines: Mapping[str, object], *, control_points=False, reference=None):
    """Lecture 06, ``nb06-048``, ``nb06-050``, ``nb06-061``: one panel per ``title: spline``;
    with ``control_points`` the Bézier points and joints too; a ``reference`` spline is drawn
    under each panel in grey, so that the joints' shifts stand out."""
    fig, axs = new_figure(1, len(splines), figsize=(8.8, 2.9 if len(splines) < 3 else 2.7))
    for ax, (title, c) in zip(np.atleast_1d(axs), splines.items(), strict=True):
        if reference is not None and reference is not c:
            plot_curve(
                ax,
                reference,
                polygon=False,
                points=False,
                joints=False,
                alternate=False,
                color="0.7",
            )
        if control_points or reference is not None:
            plot_curve(ax, c)
        else:
            plot_curve(ax, c, polygon=False, points=False, joints=False)
        ax.set_title(title)
        ax.label_outer()
    return fig


def knot_joint_figure(spline, joint: int, title: str):
    """Lecture 06, ``nb06-057`` (Finn, Fig. 7): a copy of the knot interval beside a leg."""
    from course_lib.plotting.constructions import plot_knot_joint_construction

    fig, ax = new_figure(figsize=(8.6, 4))
    plot_knot_joint_construction(ax, spline, joints=[joint], offset=-0.12)
    ax.set_title(title)
    return fig


# ------------------------------------------------------------------------ lecture 07
def quartic_conventions_figure(P, rows: Mapping[float, tuple]):
    """Lecture 09, ``nb09-021`` (DeRose & Barsky 1985, Fig. 5): per ``β2: (course, 1985)``
    a row of two quartic Beta-splines on the polygon ``P``, the course's reading left and the
    1985 paper's right.  Every panel has the same limits (the polygon's, with a margin), so
    the polygons compare point by point; a curve that leaves the frame is clipped."""
    P = np.asarray(P, dtype=float)
    lo, hi = P.min(axis=0), P.max(axis=0)
    pad = 0.12 * (hi - lo)
    fig, axs = new_figure(len(rows), 2, figsize=(8.8, 1.7 * len(rows) + 0.4))
    for row, (beta2, curves) in zip(np.atleast_2d(axs), rows.items(), strict=True):
        for ax, curve in zip(row, curves, strict=True):
            plot_control_polygon(ax, P)
            plot_curve(ax, curve, polygon=False, points=False)
            ax.set_aspect("equal", adjustable="box")
            ax.set(xlim=(lo[0] - pad[0], hi[0] + pad[0]), ylim=(lo[1] - pad[1], hi[1] + pad[1]))
            ax.label_outer()
        row[0].set_title(f"course: β = (1, {beta2:g}, 0)", fontsize=10)
        row[1].set_title(f"the 1985 reading: β = (1, {-beta2:g}, {3 * beta2**2:g})", fontsize=10)
    return fig


def domain_and_patch_figure(F):
    """Lecture 10, ``nb10-026`` (DeRose & Barsky 1985, Fig. 6): the domain and the patch."""
    from course_lib.plotting.surface_figures import plot_domain_and_patch

    fig, ax = new_figure(figsize=(7, 5.5), projection="3d")
    plot_domain_and_patch(ax, F)
    ax.set_title("the oriented domain D (grey) and its image, the patch")
    return fig


def parameter_lines_figure(F, to_uv):
    """Lecture 10, ``nb10-033`` (Fig. 8): parameter lines of ``F`` and of ``F∘to_uv``."""
    from course_lib.plotting.surface_figures import plot_parameter_lines

    fig, (a1, a2) = new_figure(1, 2, figsize=(8.8, 4.2), projection="3d")
    plot_parameter_lines(a1, F)
    plot_parameter_lines(a2, F, to_uv)
    a1.set_title("parameter lines of G")
    a2.set_title("the same surface: parameter lines of G̃")
    return fig


def patch_pairs_figure(F, pairs: Mapping[str, object]):
    """Lecture 10, ``nb10-047`` (Fig. 7): per ``title: G`` the pair F, G with the normals of
    both along their common boundary, seen from one low angle."""
    from course_lib.plotting.surfaces3d import plot_patch_pair

    fig, axes = new_figure(1, len(pairs), figsize=(8.2, 4.1), projection="3d")
    for ax, (title, G) in zip(np.atleast_1d(axes), pairs.items(), strict=True):
        plot_patch_pair(ax, F, G, net=False, length=1.0, zoom=1.3)
        ax.view_init(elev=12, azim=-15)
        ax.set_title(title)
    np.atleast_1d(axes)[-1].legend(loc="upper left", fontsize=9)
    return fig


# ------------------------------------------------------------------------ lecture 09
def glyph_points_figure(outline, implied):
    """Lecture 11, ``nb11-007``: a glyph's points and segments, its ``implied`` on-curve
    points marked."""
    from course_lib.plotting.outlines import plot_outline

    fig, ax = new_figure(figsize=(5.2, 5.2))
    plot_outline(ax, outline, comb=False, polygon=True, marks=(), legend=False)
    ax.plot(*np.asarray(implied).T, "o", ms=7, color=OKABE_ITO["bluish_green"], label="implied on-curve points")
    ax.legend(loc="lower right")
    ax.set_title(f"DejaVu Sans {outline.name!r}: points and segments")
    return fig


def _kind_legend(fig, kinds):
    """One legend for the joint kinds of all panels, without per-panel counts."""
    from matplotlib.lines import Line2D

    from course_lib.plotting.outlines import MARK_STYLES

    handles = [
        Line2D(
            [],
            [],
            ls="none",
            marker=MARK_STYLES[k]["marker"],
            ms=7,
            mfc=MARK_STYLES[k]["color"],
            mec="black",
            mew=0.6,
            label=MARK_STYLES[k]["label"],
        )
        for k in kinds
    ]
    fig.legend(handles=handles, title="joints", ncol=len(handles), loc="outside lower center")


def glyphs_figure(glyphs: Mapping[str, object]):
    """Lecture 11, ``nb11-014``: each glyph with its curvature comb and joints, two per row."""
    from course_lib.plotting.outlines import plot_outline

    rows = (len(glyphs) + 1) // 2
    fig, axes = new_figure(rows, 2, figsize=(8.8, 3.9 * rows))
    kinds = set()
    for ax, (c, outline) in zip(np.ravel(axes), glyphs.items(), strict=False):
        art = plot_outline(ax, outline, legend=False)
        kinds |= set(np.unique(art.table.kind))
        ax.set_title(f"'{c}'")
    _kind_legend(fig, [k for k in ("corner", "G1", "G2", "singular", "gap") if k in kinds])
    return fig


def outlines_figure(outlines, **style):
    """Lecture 11, ``nb11-022``: outlines side by side with combs, titled by their names."""
    from course_lib.plotting.outlines import plot_outline

    fig, axes = new_figure(1, len(outlines), figsize=(8.8, 4.2))
    for ax, outline in zip(np.atleast_1d(axes), outlines, strict=True):
        plot_outline(ax, outline, legend=False, **style)
        ax.set_title(outline.name)
    return fig
