"""Pictures tested without pixels: the data handed to the Axes is checked against
closed forms and independent computations (scipy quadrature, textbook end-curvature
formulas of Bézier curves), never against numbers produced by the plotting code."""

from __future__ import annotations

import subprocess
import sys
from math import comb

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.collections import LineCollection
from matplotlib.lines import Line2D
from scipy.integrate import quad

from course_lib import PiecewiseBezier
from course_lib.plotting import (
    course_style,
    new_figure,
    plot_control_polygon,
    plot_curvature_comb,
    plot_curvature_profile,
    plot_curve,
    plot_frame,
    plot_osculating_circle,
)
from course_lib.plotting.blending import blending_functions, plot_blending_functions
from course_lib.plotting.constructions import (
    plot_beta_spline_construction,
    plot_farin_boehm,
    plot_g1_stitch,
    plot_knot_joint_construction,
)
from course_lib.plotting.style import OKABE_ITO, segment_color

# y = x^2 for x in [-1, 1] as a quadratic Bézier curve: x(u) = 2u - 1, y = (2u - 1)^2.
PARABOLA = PiecewiseBezier([[[-1.0, 1.0], [0.0, -1.0], [1.0, 1.0]]])


def parabola_kappa(x):
    """Signed curvature of y = x^2 (closed form): 2 / (1 + 4x^2)^(3/2)."""
    return 2.0 / (1.0 + 4.0 * x**2) ** 1.5


def bezier_end_curvature(P, end):
    """Signed curvature at an end of a degree-d Bézier curve (Farin, *Curves and Surfaces
    for CAGD*, §10.1): kappa(0) = (d-1)/d * (dP0 x dP1) / |dP0|^3, mirrored at u = 1."""
    P = np.asarray(P, float)
    d = len(P) - 1
    if end == 0:
        a, b = P[1] - P[0], P[2] - P[1]
    else:
        a, b = P[-2] - P[-3], P[-1] - P[-2]
    cross = a[0] * b[1] - a[1] * b[0]
    L = np.linalg.norm(a if end == 0 else b)
    return (d - 1) / d * cross / L**3


# Two cubics: W1 on the ray V2 V3 (G1), W2 arbitrary (not G2).
V = np.array([[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 1.0]])
W = np.array([V[3], V[3] + 0.7 * (V[3] - V[2]), [6.5, 0.5], [8.0, 2.0]])
G1_CURVE = PiecewiseBezier([V, W])


@pytest.fixture
def ax():
    fig, ax = new_figure(pyplot=False)
    yield ax
    fig.clf()


# ------------------------------------------------------------------ curves
def test_plot_curve_segments_polygon_joints(ax):
    c = PiecewiseBezier([[[0, 0], [1, 1], [2, 0]], [[2, 0], [3, -1], [4, 0]], [[4, 0], [5, 1]]])
    arts = plot_curve(ax, c, per_segment=30)
    segs = arts.segments.get_segments()
    assert isinstance(arts.segments, LineCollection) and len(segs) == 3
    for s, P in zip(segs, c.segments, strict=True):
        assert s.shape == (30, 2)
        np.testing.assert_allclose(s[0], P[0], atol=1e-12)
        np.testing.assert_allclose(s[-1], P[-1], atol=1e-8)  # one-sided, 1e-10 before the end
    # neighbouring segments have different colours, from the Okabe-Ito palette
    cols = [matplotlib.colors.to_hex(c) for c in arts.segments.get_colors()]
    assert cols[0] != cols[1] and cols[1] != cols[2]
    assert set(map(str.upper, cols)) <= set(OKABE_ITO.values())
    np.testing.assert_array_equal(np.column_stack(arts.joints.get_data()), [[2, 0], [4, 0]])
    x, _y = arts.polygon.get_data()
    assert np.isnan(x).sum() == 2  # three polygons separated by NaN
    assert ax.get_aspect() == 1.0


def test_plot_curve_keeps_a_gap_visible(ax):
    c = PiecewiseBezier([[[0, 0], [1, 0]], [[1, 1], [2, 1]]])  # not even C0
    segs = plot_curve(ax, c).segments.get_segments()
    np.testing.assert_allclose(segs[0][-1], [1, 0], atol=1e-8)
    np.testing.assert_allclose(segs[1][0], [1, 1])


def test_curve_artists_update_in_place(ax):
    arts = plot_curve(ax, PARABOLA)
    lc = arts.segments
    arts.update(G1_CURVE)
    assert arts.segments is lc and len(lc.get_segments()) == 2
    np.testing.assert_allclose(lc.get_segments()[1][0], W[0])


def test_plot_curve_rejects_space_curves(ax):
    c = PiecewiseBezier([[[0, 0, 0], [1, 1, 1]]])
    with pytest.raises(ValueError, match="plane curves"):
        plot_curve(ax, c)


def test_plot_control_polygon_labels(ax):
    arts = plot_control_polygon(ax, V, labels="$V_{{{i}}}$")
    assert [t.get_text() for t in arts.labels] == [f"$V_{{{i}}}$" for i in range(4)]
    np.testing.assert_array_equal(np.column_stack(arts.line.get_data()), V)


# ------------------------------------------------------------------ comb
def test_comb_teeth_are_normal_and_proportional_to_curvature(ax):
    arts = plot_curvature_comb(ax, PARABOLA, samples=101, scale=0.5)
    teeth = arts.tooth_array()
    feet, tips = teeth[:, 0], teeth[:, 1]
    x = feet[:, 0]
    np.testing.assert_allclose(feet[:, 1], x**2, atol=1e-12)  # feet on the curve
    v = tips - feet
    tangent = np.column_stack([np.ones_like(x), 2 * x])  # (1, y'(x))
    cosang = np.abs(np.sum(v * tangent, axis=1)) / (
        np.linalg.norm(v, axis=1) * np.linalg.norm(tangent, axis=1)
    )
    assert np.max(cosang) < 1e-9  # perpendicular
    np.testing.assert_allclose(np.linalg.norm(v, axis=1), 0.5 * parabola_kappa(x), rtol=1e-8)
    assert np.all(v[:, 1] < 0)  # "outside": away from the centre of curvature (above)


def test_comb_inside_and_update(ax):
    arts = plot_curvature_comb(ax, PARABOLA, samples=20, scale=1.0, side="inside")
    v = np.diff(arts.tooth_array(), axis=1)[:, 0]
    assert np.all(v[:, 1] > 0)
    arts.update(G1_CURVE)
    assert len(arts.envelope.get_segments()) == 2
    with pytest.raises(ValueError, match="side"):
        plot_curvature_comb(ax, PARABOLA, side="left")


def test_comb_envelope_not_bridged_at_a_g2_break(ax):
    arts = plot_curvature_comb(ax, G1_CURVE, samples=200, scale=1.0)
    env = arts.envelope.get_segments()
    assert len(env) == 2
    # tooth tips at the joint from both sides: foot + scale * (-K) with K = kappa N
    N = (V[3] - V[2])[::-1] * [-1, 1] / np.linalg.norm(V[3] - V[2])
    kl, kr = bezier_end_curvature(V, 1), bezier_end_curvature(W, 0)
    np.testing.assert_allclose(env[0][-1], V[3] - kl * N, atol=1e-7)
    np.testing.assert_allclose(env[1][0], V[3] - kr * N, atol=1e-9)


# --------------------------------------------------------------- profile
def test_profile_shows_the_curvature_jump_of_a_g1_joint(ax):
    arts = plot_curvature_profile(ax, G1_CURVE, per_segment=60)
    segs = arts.lines.get_segments()
    assert len(segs) == 2  # one line per segment: the jump is not bridged
    kl, kr = bezier_end_curvature(V, 1), bezier_end_curvature(W, 0)
    assert abs(kr - kl) > 0.1  # the example really is not G2
    np.testing.assert_allclose(segs[0][-1, 1], kl, rtol=1e-7)
    np.testing.assert_allclose(segs[1][0, 1], kr, rtol=1e-9)
    np.testing.assert_allclose(segs[0][0, 1], bezier_end_curvature(V, 0), rtol=1e-9)
    # x is arc length: the joint sits at the length of the first segment (scipy quadrature)
    d1 = 3 * np.diff(V, axis=0)
    speed = lambda u: np.linalg.norm(  # noqa: E731
        d1[0] * (1 - u) ** 2 + 2 * d1[1] * u * (1 - u) + d1[2] * u**2
    )
    L0 = quad(speed, 0, 1, epsabs=1e-13)[0]
    np.testing.assert_allclose(segs[1][0, 0], L0, rtol=1e-10)
    np.testing.assert_allclose(segs[0][-1, 0], L0, rtol=1e-8)
    assert all(np.all(np.diff(s[:, 0]) > 0) for s in segs)
    jx = [seg[0][0] for seg in arts.joint_lines.get_segments()]
    np.testing.assert_allclose(jx, [L0], rtol=1e-10)
    ex, _ey = arts.ends.get_data()
    assert len(ex) == 4  # both ends of both segments


def test_profile_of_a_g2_curve_is_continuous(ax):
    # a C2 split of one cubic (de Casteljau at 1/2 by hand): no jump
    P = np.array([[0, 0], [1, 2], [3, 2], [4, 0]], float)
    L = [
        P[0],
        (P[0] + P[1]) / 2,
        (P[0] + 2 * P[1] + P[2]) / 4,
        (P[0] + 3 * P[1] + 3 * P[2] + P[3]) / 8,
    ]
    R = [L[3], (P[1] + 2 * P[2] + P[3]) / 4, (P[2] + P[3]) / 2, P[3]]
    segs = plot_curvature_profile(ax, PiecewiseBezier([L, R])).lines.get_segments()
    np.testing.assert_allclose(segs[0][-1], segs[1][0], rtol=1e-7)


def test_profile_against_parameter_and_unsigned(ax):
    arts = plot_curvature_profile(ax, PARABOLA, x="parameter", signed=False, per_segment=11)
    (s,) = arts.lines.get_segments()
    u = np.linspace(0, 1, 11)
    np.testing.assert_allclose(s[:, 0], u)
    np.testing.assert_allclose(s[:, 1], parabola_kappa(2 * u - 1), rtol=1e-9)
    with pytest.raises(ValueError, match="x must be"):
        plot_curvature_profile(ax, PARABOLA, x="time")


# ----------------------------------------------------------------- vectors
def test_frame_vectors(ax):
    t = np.array([0.25, 0.5, 0.9])
    arts = plot_frame(ax, PARABOLA, t, normal=True, length=2.0, curvature_scale=3.0)
    x = 2 * t - 1
    T = np.column_stack([np.ones_like(x), 2 * x]) / np.sqrt(1 + 4 * x**2)[:, None]
    np.testing.assert_allclose(np.column_stack([arts.tangent.U, arts.tangent.V]), 2 * T)
    Nrm = np.column_stack([-T[:, 1], T[:, 0]])
    np.testing.assert_allclose(np.column_stack([arts.normal.U, arts.normal.V]), 2 * Nrm)
    K = parabola_kappa(x)[:, None] * Nrm
    np.testing.assert_allclose(np.column_stack([arts.curvature.U, arts.curvature.V]), 3 * K)
    np.testing.assert_allclose(arts.tangent.get_offsets(), np.column_stack([x, x**2]))
    arts.update(PARABOLA, [0.5])
    np.testing.assert_allclose(np.column_stack(arts.point.get_data()), [[0.0, 0.0]], atol=1e-15)


def test_osculating_circle_of_the_parabola_vertex(ax):
    arts = plot_osculating_circle(ax, PARABOLA, 0.5)  # x = 0: radius 1/2, centre (0, 1/2)
    np.testing.assert_allclose(arts.circle.get_center(), [0.0, 0.5], atol=1e-14)
    np.testing.assert_allclose(arts.circle.get_radius(), 0.5)
    assert arts.circle.get_visible()


def test_osculating_circle_hidden_on_a_line(ax):
    line = PiecewiseBezier([[[0, 0], [1, 1], [2, 2]]])
    arts = plot_osculating_circle(ax, line, 0.5)  # curvature 0: no circle, no exception
    assert not arts.circle.get_visible()


# ---------------------------------------------------------------- blending
def test_blending_functions_of_a_bezier_curve_are_bernstein(ax):
    d = 4
    t, b = blending_functions(lambda P: PiecewiseBezier([P]), d + 1, per_segment=21)
    u = t[0]
    for k in range(d + 1):
        np.testing.assert_allclose(b[k, 0], comb(d, k) * u**k * (1 - u) ** (d - k), atol=1e-14)
    arts = plot_blending_functions(ax, lambda P: PiecewiseBezier([P]), d + 1, highlight=2)
    assert len(arts.lines) == d + 1 and arts.support is not None


def test_blending_functions_local_support_and_partition_of_unity(ax):
    # C0 piecewise-linear interpolation: hat functions, support [k-1, k+1]
    def polyline(P):
        return PiecewiseBezier([P[i : i + 2] for i in range(len(P) - 1)])

    _t, b = blending_functions(polyline, 5, per_segment=9)
    np.testing.assert_allclose(b.sum(axis=0), 1.0, atol=1e-14)
    assert np.all(b[2, 0] == 0) and np.all(b[2, 3] == 0)  # zero on segments 0 and 3
    with pytest.raises(ValueError, match="highlight"):
        plot_blending_functions(ax, polyline, 5, highlight=5)


# ----------------------------------------------------------- constructions
def test_g1_stitch_diagram(ax):
    b1 = 0.7
    dg = plot_g1_stitch(ax, V, W, b1)
    x, y = dg.artists["line:ray"].get_data()
    R = np.column_stack([x, y])
    np.testing.assert_allclose(R, [V[2], V[3], W[1]])
    # the drawn ray is straight and the lengths are in ratio 1 : beta1
    a, b = R[1] - R[0], R[2] - R[1]
    assert abs(a[0] * b[1] - a[1] * b[0]) < 1e-12
    np.testing.assert_allclose(np.linalg.norm(b) / np.linalg.norm(a), b1)
    assert dg.artists["label:V3"].get_text() == "$V_{3} = W_0$"
    texts = [dg.artists[f"ratio:{i}"].get_text() for i in range(2)]
    assert texts == ["1", "β₁ = 0.7"]


def farin_boehm_by_hand(V, b1, b2):
    """Seed 000 eq. (12) written out independently (d = 3)."""
    d = len(V) - 1
    g = (d - 1) * (1 + b1) / (b2 + b1 * (d - 1) * (1 + b1))
    W0 = V[-1]
    W1 = W0 + b1 * (V[-1] - V[-2])
    T = V[-2] + b1**2 * g * (V[-2] - V[-3])
    W2 = W1 + (W1 - T) / g
    return g, T, np.array([W0, W1, W2, [9.0, 1.0]])


def test_farin_boehm_diagram_and_update(ax):
    g, T, Wfb = farin_boehm_by_hand(V, 1.3, 2.0)
    dg = plot_farin_boehm(ax, V, Wfb, T, 1.3, g)
    leg = np.column_stack(dg.artists["line:leg"].get_data())
    fan = np.column_stack(dg.artists["line:fan"].get_data())
    np.testing.assert_allclose(leg, [V[1], V[2], T])
    np.testing.assert_allclose(fan, [T, Wfb[1], Wfb[2]])
    assert dg.artists["label:T"].get_text() == "$T$"
    # the diagram moves with new points (as in the widget)
    _g2, T2, W2 = farin_boehm_by_hand(V, 0.5, 0.0)
    dg.update({"T": T2, "W1": W2[1], "W2": W2[2]})
    np.testing.assert_allclose(
        np.column_stack(dg.artists["line:fan"].get_data()), [T2, W2[1], W2[2]]
    )
    np.testing.assert_allclose(dg.artists["label:T"].xy, T2)


def test_knot_joint_construction_links_are_parallel(ax):
    # Finn's joint rule by hand: p3i = (t_{i+1}-t_i)/(t_{i+1}-t_{i-1}) p3i-1 + (t_i-t_{i-1})/(...) p3i+1
    knots = np.array([0.0, 1.0, 3.0, 4.0])
    p = [
        np.array(q, float)
        for q in [[0, 0], [1, 2], [2, 2.5], None, [4, 1], [5, 0], None, [7, 1.5], [8, 3], [9, 2]]
    ]
    for i, (a, b) in ((1, (2, 4)), (2, (5, 7))):
        t0, t1, t2 = knots[i - 1 : i + 2]
        p[3 * i] = (t2 - t1) / (t2 - t0) * p[a] + (t1 - t0) / (t2 - t0) * p[b]
    c = PiecewiseBezier.from_control_points(np.array(p), 3, knots)
    dg = plot_knot_joint_construction(ax, c)
    for i in (1, 2):
        links = [
            np.diff(np.column_stack(dg.artists[f"line:link{i}_{m}"].get_data()), axis=0)[0]
            for m in range(3)
        ]
        np.testing.assert_allclose(links[0], links[1], atol=1e-12)
        np.testing.assert_allclose(links[0], links[2], atol=1e-12)
    assert dg.artists["label:tp2"].get_text() == "$t_{2}=3$"
    with pytest.raises(ValueError, match="joints must be in"):
        plot_knot_joint_construction(ax, c, joints=[3])


def test_knot_joint_construction_offset_sign_chooses_the_side(ax):
    # the knot copy and its labels go to the side the sign of `offset` says, for the notebook
    # to put them where the curve is not (nb04-057)
    c = PiecewiseBezier(
        [[[0, 0], [1, 2], [2, 2], [3, 1]], [[3, 1], [4, 0], [5, 0], [6, 1]]], knots=[0, 1, 3]
    )
    a, b = np.array([2.0, 2.0]), np.array([4.0, 0.0])  # p2 and p4
    side = np.array([-(b - a)[1], (b - a)[0]])  # left of p2 -> p4
    for offset, sign in ((0.12, -1), (-0.12, 1)):
        ax.clear()
        dg = plot_knot_joint_construction(ax, c, offset=offset)
        copy = np.array(dg.artists["label:ta1"].xy) - a
        assert sign * copy @ side > 0
        assert sign * np.array(dg.artists["label:ta1"].xyann) @ side > 0  # labels outward
    with pytest.raises(ValueError, match="offset must be a finite number"):
        plot_knot_joint_construction(ax, c, offset=float("nan"))


def test_beta_spline_construction_reads_the_segments(ax):
    Vp = np.array([[0, 0], [1, 2], [3, 2], [4, 0]], float)
    b1 = 2.0
    segs = [
        [(b1 * Vp[i - 1] + Vp[i]) / (1 + b1), Vp[i], (b1 * Vp[i] + Vp[i + 1]) / (1 + b1)]
        for i in (1, 2)
    ]  # seed 000 eq. (18)-(19)
    dg = plot_beta_spline_construction(ax, PiecewiseBezier(segs), Vp)
    J = np.column_stack(dg.artists["junctions"].get_data())
    np.testing.assert_allclose(J[1], (b1 * Vp[1] + Vp[2]) / (1 + b1))
    inner = np.column_stack(dg.artists["interior"].get_data())
    np.testing.assert_allclose(inner, Vp[1:3])


# ----------------------------------------------------------------- style
def test_course_style_is_scoped():
    before = dict(matplotlib.rcParams)
    with course_style():
        assert matplotlib.rcParams["font.size"] == 13
        assert matplotlib.rcParams["axes.prop_cycle"].by_key()["color"][0] == OKABE_ITO["blue"]
    assert matplotlib.rcParams["font.size"] == before["font.size"]
    assert segment_color(0) != segment_color(1) and segment_color(0) == segment_color(2)


def test_new_figure_agg_and_grid():
    fig, axs = new_figure(2, 2, pyplot=False)
    assert axs.shape == (2, 2) and type(fig.canvas).__name__ == "FigureCanvasAgg"
    _fig3, ax3 = new_figure(pyplot=False, projection="3d")
    assert ax3.name == "3d"


def test_importing_plotting_has_no_global_side_effects():
    code = (
        "import matplotlib, sys\n"
        # dict.items bypasses RcParams.__getitem__, whose 'backend' lookup imports pyplot
        "before = dict(dict.items(matplotlib.rcParams))\n"
        "import course_lib.plotting, course_lib.widgets\n"
        "after = dict(dict.items(matplotlib.rcParams))\n"
        "print(before == after, 'matplotlib.pyplot' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["True", "False"]


def test_plot_functions_return_artists_on_their_axes(ax):
    for arts in (plot_curve(ax, G1_CURVE), plot_curvature_comb(ax, G1_CURVE)):
        for a in arts.artists:
            assert a.axes is ax
    fr = plot_frame(ax, G1_CURVE, 0.5)
    assert isinstance(fr.point, Line2D) and fr.normal is None


# ------------------------------------------- with the course's constructions
def test_beta_spline_blending_functions_partition_of_unity_and_local_support(ax):
    from course_lib.constructions.beta_splines import cubic_beta_spline

    n = 8

    def construct(P):
        return cubic_beta_spline(P, beta1=1.7, beta2=4.0)

    _t, b = blending_functions(construct, n, per_segment=17)
    np.testing.assert_allclose(b.sum(axis=0), 1.0, atol=1e-12)  # affine invariance
    assert np.all(b > -1e-12)  # β1 > 0, β2 >= 0: convex hull property
    # b_k lives on at most 4 consecutive segments (segment s uses V_s .. V_{s+3})
    for k in range(n):
        live = np.flatnonzero(np.any(np.abs(b[k]) > 1e-13, axis=1))
        assert live.size <= 4 and np.all(np.diff(live) == 1)
    arts = plot_blending_functions(ax, construct, n, highlight=3)
    assert arts.support is not None


def test_stitching_diagram_from_a_g2_stitched_curve(ax):
    from course_lib.constructions.stitching import g2_stitch
    from course_lib.plotting.constructions import plot_stitching

    c = g2_stitch(V, 1.3, 2.0, [[9.0, 1.0]])
    g, T, _W = farin_boehm_by_hand(V, 1.3, 2.0)  # eq. (12) written out above
    dg = plot_stitching(ax, c)
    np.testing.assert_allclose(dg.points["T"], T, atol=1e-12)
    assert dg.artists["ratio:2"].get_text() == f"γ={g:.3g}"


def test_patch_pair_normals_along_the_boundary():
    from course_lib.constructions.surfaces import BezierPatch
    from course_lib.plotting.surfaces3d import plot_patch_pair

    # two bilinear-by-cubic patches forming a flat plane z = 0 (G1 trivially): normals (0,0,1)
    x = np.linspace(0, 1, 4)
    F = BezierPatch(np.array([[[a, b, 0.0] for b in x] for a in x]))
    G = BezierPatch(np.array([[[1 + a, b, 0.0] for b in x] for a in x]))
    _fig, ax3 = new_figure(pyplot=False, projection="3d")
    arts = plot_patch_pair(ax3, F, G, n_normals=5, length=0.5)
    for q in (arts.normals_F, arts.normals_G):
        segs = np.asarray(q._segments3d)[:5]  # shafts, stored by matplotlib as [tip, base]
        base = np.column_stack([np.ones(5), np.linspace(0, 1, 5), np.zeros(5)])
        np.testing.assert_allclose(segs[:, 1], base, atol=1e-12)
        np.testing.assert_allclose(segs[:, 0] - segs[:, 1], [[0, 0, 0.5]] * 5, atol=1e-12)
    assert ax3.get_zlim()[1] >= 0.5  # the arrow tips are inside the axes (not clipped)
    with pytest.raises(ValueError, match="3D Axes"):
        _fig2, ax2 = new_figure(pyplot=False)
        plot_patch_pair(ax2, F, G)


def test_patch_pair_zoom_fills_a_laptop_sized_figure():
    """Lecture 08's pair: two 3D panels in 8.2 inches (≤ 900 px at 100 dpi, with the
    file browser open on a 1366 px laptop); zoom trims the empty margin of each 3D box."""
    from io import BytesIO

    from course_lib.constructions.surfaces import BezierPatch
    from course_lib.plotting.surfaces3d import plot_patch_pair

    x = np.linspace(0, 1, 4)
    F = BezierPatch(np.array([[[a, b, a * (1 - a) * b] for b in x] for a in x]))
    G = BezierPatch(np.array([[[1 + a, b, -a * (1 - a) * b] for b in x] for a in x]))
    fig, axes = new_figure(1, 2, figsize=(8.2, 4.1), pyplot=False, projection="3d")
    plot_patch_pair(axes[0], F, G, net=False)
    plot_patch_pair(axes[1], F, G, net=False, zoom=1.3)
    box = [np.linalg.norm(ax.get_box_aspect()) for ax in axes]
    assert box[1] == pytest.approx(1.3 * box[0])  # the zoomed box is drawn 1.3 times larger
    buf = BytesIO()
    fig.savefig(buf, format="png", dpi=100, bbox_inches="tight")
    width = int.from_bytes(buf.getvalue()[16:20], "big")  # PNG IHDR
    assert width <= 860
    for bad in (0, -1.0, 10, "2"):
        with pytest.raises(ValueError, match="zoom"):
            plot_patch_pair(axes[0], F, G, zoom=bad)


def test_profile_with_sparse_arc_lengths_keeps_the_joints_exact():
    from course_lib.plotting import curvature_profile

    X1, k1 = curvature_profile(G1_CURVE, 16)
    X3, k3 = curvature_profile(G1_CURVE, 16, arc_length_every=3)
    np.testing.assert_array_equal(k1, k3)
    np.testing.assert_allclose(X3[:, [0, 3, 6]], X1[:, [0, 3, 6]], rtol=1e-13)
    # the dense reference stops 1e-10 of a segment before its end (ONE_SIDED_EPS); the
    # sparse sums reach the end itself, which is also where the next segment starts
    np.testing.assert_allclose(X3[:, 15], X1[:, 15], rtol=1e-9)
    np.testing.assert_allclose(X3[0, 15], X3[1, 0], rtol=1e-13)
    # linear in between: within 0.3 % of the length, under a pixel of a drawn profile
    np.testing.assert_allclose(X3, X1, atol=3e-3 * X1[-1, -1])
    assert np.all(np.diff(X3, axis=1) > 0)


# ------------------------------------------------- new_figure in a notebook
def test_new_figure_in_a_notebook_shows_every_figure():
    """ipykernel's inline backend turns interactive mode on when pyplot first loads it; that
    must not happen inside course_style() (whose exit would turn it off again: then only the
    first figure of a notebook is shown)."""
    import nbformat
    from nbclient import NotebookClient

    cells = [
        "from course_lib.plotting import new_figure\nfig, ax = new_figure()\nax.plot([0, 1]);",
        "fig, ax = new_figure()\nax.plot([1, 0]);",
        "import matplotlib.pyplot as plt\nfrom course_lib.plotting import course_style\n"
        "with course_style():\n    fig, ax = plt.subplots()\nax.plot([0, 2]);",
    ]
    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    NotebookClient(nb, timeout=60, kernel_name="python3").execute()
    pngs = [sum("image/png" in o.get("data", {}) for o in c.outputs) for c in nb.cells]
    assert pngs == [1, 1, 1]


def test_course_style_keeps_the_interactive_mode_set_inside():
    was = matplotlib.is_interactive()
    try:
        matplotlib.interactive(False)
        with course_style():
            matplotlib.interactive(True)  # what a backend activated here may do
        assert matplotlib.is_interactive()
        with course_style():
            matplotlib.interactive(False)
        assert not matplotlib.is_interactive()
    finally:
        matplotlib.interactive(was)


# ----------------------------------------------------------- arrows
def test_plot_vectors_draws_true_data_arrows(ax):
    from course_lib.plotting import plot_vectors

    P = np.array([[0.0, 0.0], [1.0, 2.0]])
    V = np.array([[2.0, 1.0], [-1.0, 3.0]])
    arts = plot_vectors(ax, P, V, scale=0.5, color="red", label="v")
    q = arts.quiver
    assert q.angles == "xy" and q.scale_units == "xy" and q.scale == 1.0  # data units
    np.testing.assert_allclose(q.get_offsets(), P)
    np.testing.assert_allclose(np.column_stack([q.U, q.V]), 0.5 * V)  # tip = P + scale V
    assert q.get_label() == "v" and arts.artists == [q] and q in ax.collections
    one = plot_vectors(ax, [1.0, 1.0], V)  # one base shared by every arrow
    np.testing.assert_allclose(one.quiver.get_offsets(), [[1.0, 1.0], [1.0, 1.0]])
    arts.update(P + 1, 2 * V)
    np.testing.assert_allclose(np.column_stack([q.U, q.V]), V)
    np.testing.assert_allclose(q.get_offsets(), P + 1)
    with pytest.raises(ValueError, match="2 arrows"):
        arts.update(P[:1] + 1, [[1.0, 1.0], [2.0, 2.0], [3.0, 3.0]])


@pytest.mark.parametrize(
    ("bases", "vectors", "kw", "match"),
    [
        ([[0, 0], [1, 1]], [[1, 0], [0, 1], [1, 1]], {}, "same number of rows"),
        ([[0, 0]], [[np.nan, 1.0]], {}, "finite"),
        ([[0, 0]], [[1.0, 1.0]], {"scale": 0.0}, "scale must be > 0"),
        ([[0, 0, 0]], [[1.0, 1.0, 1.0]], {}, "dimension 2"),
    ],
)
def test_plot_vectors_bad_input(ax, bases, vectors, kw, match):
    from course_lib.plotting import plot_vectors

    with pytest.raises(ValueError, match=match):
        plot_vectors(ax, bases, vectors, **kw)


def test_plot_velocity_of_the_parabola(ax):
    from course_lib.plotting import plot_velocity

    u = np.array([0.0, 0.25, 1.0])
    arts = plot_velocity(ax, PARABOLA, u, scale=0.1)
    x = 2 * u - 1  # c(u) = (x, x^2): c'(u) = (2, 4x), c''(u) = (0, 8)
    np.testing.assert_allclose(arts.quiver.get_offsets(), np.column_stack([x, x**2]), atol=1e-15)
    np.testing.assert_allclose(
        np.column_stack([arts.quiver.U, arts.quiver.V]), 0.1 * np.column_stack([2 + 0 * x, 4 * x])
    )
    acc = plot_velocity(ax, PARABOLA, 0.3, n=2)
    np.testing.assert_allclose([acc.quiver.U[0], acc.quiver.V[0]], [0.0, 8.0], atol=1e-12)
    with pytest.raises(ValueError, match="domain"):
        plot_velocity(ax, PARABOLA, 1.5)
    with pytest.raises(ValueError, match="plane"):
        plot_velocity(ax, PiecewiseBezier([[[0, 0, 0], [1, 1, 1]]]), 0.5)
    with pytest.raises(TypeError, match="parametrization"):
        plot_velocity(ax, [[0, 0], [1, 1]], 0.5)


# -------------------------------------------- fast sampling for live widgets
KNOTTED = PiecewiseBezier(
    [V, W, [W[-1], [9.0, 3.0], [10.0, 1.0], [11.0, 2.5]]], knots=[0.0, 0.7, 2.2, 2.5]
)


def test_cached_bernstein_samples_agree_with_the_math_layer():
    """Points, T and K on the segment grid (one matrix product per order) against
    differential_geometry, evaluated independently: inside the segments through the
    global parameter, at the segment ends through each segment on its own."""
    from course_lib.geometry import differential_geometry as dg
    from course_lib.geometry.sampling import segment_derivatives, segment_grid
    from course_lib.plotting.curvature import _frame_samples

    n = 9
    P, T, K = _frame_samples(KNOTTED, n)
    t = segment_grid(KNOTTED, n)
    inner = t[:, 1:-1].ravel()
    np.testing.assert_allclose(P[:, 1:-1].reshape(-1, 2), KNOTTED.evaluate(inner), atol=1e-12)
    np.testing.assert_allclose(T[:, 1:-1].reshape(-1, 2), dg.unit_tangent(KNOTTED, inner))
    np.testing.assert_allclose(
        K[:, 1:-1].reshape(-1, 2), dg.curvature_vector(KNOTTED, inner), rtol=1e-9, atol=1e-12
    )
    h = np.diff(KNOTTED.knots)
    for i in range(KNOTTED.n_segments):
        seg = KNOTTED.segment_curve(i)  # own parameter u in [0, 1]: K is intrinsic
        np.testing.assert_allclose(K[i, [0, -1]], dg.curvature_vector(seg, [0.0, 1.0]), atol=1e-12)
        d1 = segment_derivatives(KNOTTED, n, (1,))[0]
        np.testing.assert_allclose(d1[i, -1], seg.evaluate(1.0, 1) / h[i])  # chain rule
    # a curve whose segments differ in degree takes the general path: same answers
    mixed = PiecewiseBezier([[[0, 0], [1, 2], [2, 0]], [[2, 0], [3, -2], [4, 0], [5, 1]]])
    P2, _T2, K2 = _frame_samples(mixed, 5)
    np.testing.assert_allclose(P2[1, 2], mixed.evaluate(1.5))
    np.testing.assert_allclose(K2[1, 2], dg.curvature_vector(mixed, 1.5), rtol=1e-12)


def test_fast_arc_lengths_against_scipy_quadrature():
    from course_lib.geometry.arc_length import segment_arc_lengths

    n, idx = 16, np.array([0, 3, 6, 9, 12, 15])
    S = segment_arc_lengths(KNOTTED, n, idx)
    u = np.linspace(0, 1, n)[idx]
    start = 0.0
    for i, seg in enumerate(KNOTTED.segments):
        hod = 3 * np.diff(seg, axis=0)  # |dq/du| of a cubic: ds = |dq/du| du (knot-free)

        def speed(x, hod=hod):
            b = np.array([(1 - x) ** 2, 2 * x * (1 - x), x**2])
            return float(np.linalg.norm(b @ hod))

        ref = [start + quad(speed, 0.0, x, epsabs=1e-14, epsrel=1e-13)[0] for x in u]
        np.testing.assert_allclose(S[i], ref, rtol=1e-11)
        start = ref[-1]


def test_fast_frame_rejects_an_irregular_point(ax):
    cusp = PiecewiseBezier([[[0, 0], [2, 2], [0, 2], [2, 0]]])  # c'(1/2) = 0: a cusp
    arts = plot_frame(ax, cusp, 0.2)
    with pytest.raises(ValueError, match=r"not regular at t=0\.5"):
        arts.update(cusp, [0.5])
    with pytest.raises(ValueError, match="not regular"):
        plot_curvature_comb(ax, cusp, samples=21)  # the grid meets u = 1/2


def test_surface_figures_draw_the_domain_and_the_parameter_lines():
    from course_lib.constructions.surfaces import BezierPatch
    from course_lib.plotting.surface_figures import plot_domain_and_patch, plot_parameter_lines

    x = np.linspace(0, 3, 4)
    F = BezierPatch(np.array([[[a, b, 0.2 * a * b] for b in x] for a in x]))
    _fig, ax = new_figure(pyplot=False, projection="3d")
    art = plot_domain_and_patch(ax, F, below=1.0)
    assert art["label"].get_text() == "D"
    assert ax.get_zlim()[0] < -1.0  # the domain plane at z = -1 is inside the axes
    grid = plot_parameter_lines(ax, F)
    ident = plot_parameter_lines(ax, F, lambda s, t: (s, t))  # identity change
    np.testing.assert_allclose(np.asarray(grid._segments3d[0]), np.asarray(ident._segments3d[0]))
    with pytest.raises(ValueError, match="3D Axes"):
        _fig2, ax2 = new_figure(pyplot=False)
        plot_parameter_lines(ax2, F)


def test_farin_boehm_names_two_units_when_asked(ax):
    g, T, Wfb = farin_boehm_by_hand(V, 1.3, 2.0)
    dg = plot_farin_boehm(ax, V, Wfb, T, 1.3, g, lengths=True)
    texts = [dg.artists[f"ratio:{i}"].get_text() for i in range(4)]
    assert texts[0] == "a" and texts[3] == "b" and texts[2] == f"γ·b = {g:.3g} b"
    # the labelled lengths are right: |V1 V2| : |V2 T| = 1 : β1²γ and |T W1| : |W1 W2| = γ : 1
    a, b = np.linalg.norm(V[2] - V[1]), np.linalg.norm(Wfb[2] - Wfb[1])
    np.testing.assert_allclose(np.linalg.norm(T - V[2]), 1.3**2 * g * a)
    np.testing.assert_allclose(np.linalg.norm(Wfb[1] - T), g * b)


def test_beta_spline_construction_interior_only_and_labels_outside(ax):
    Vp = np.array([[0, 0], [1, 2], [3, 2], [4, 0]], float)
    segs = [[(Vp[i - 1] + Vp[i]) / 2, Vp[i], (Vp[i] + Vp[i + 1]) / 2] for i in (1, 2)]
    dg = plot_beta_spline_construction(ax, PiecewiseBezier(segs), Vp, show="interior")
    assert "curve" not in dg.artists and len(dg.artists["junctions"].get_xdata()) == 0
    # V1 = (1, 2) is a top corner: its label goes up and left, away from the curve below
    dx, dy = dg.artists["label:V1"].xyann
    assert dy > 0 and dx < 0
    with pytest.raises(ValueError, match="show"):
        plot_beta_spline_construction(ax, PiecewiseBezier(segs), Vp, show="half")


def test_reparametrization_figure_draws_parallel_velocities_side_by_side():
    from course_lib.geometry.reparametrization import ChangeOfVariables
    from course_lib.plotting.reparametrization_figure import plot_reparametrization

    Q = PiecewiseBezier([[[0, 0], [1, 2.2], [3.2, 2.4], [4, 0.4]]])
    f = ChangeOfVariables.polynomial([0, 1.6, -0.6], (0, 1), (0, 1))  # v + 0.6 v (1 - v)
    _fig, axes = new_figure(1, 2, pyplot=False)
    art = plot_reparametrization(axes, Q, f, 0.3, scale=0.25)
    qa, qb = art["velocity_Q"].quiver, art["velocity_Qf"].quiver
    uq = np.array([qa.U[0], qa.V[0]])
    uf = np.array([qb.U[0], qb.V[0]])
    u0 = 0.3 + 0.6 * 0.3 * 0.7
    np.testing.assert_allclose(uq, 0.25 * Q.evaluate(u0, 1))               # Q'(f(v)) × scale
    np.testing.assert_allclose(uf, 0.25 * (1.6 - 1.2 * 0.3) * Q.evaluate(u0, 1))  # chain rule
    bases = np.array([qa.X[0], qa.Y[0]]), np.array([qb.X[0], qb.Y[0]])
    assert np.linalg.norm(bases[0] - bases[1]) > 0  # side by side: neither hides the other


def test_closeness_figure_one_panel_per_curve():
    from course_lib.plotting.closeness_figure import plot_closeness

    ref = np.column_stack([np.cos(np.linspace(0, 3, 20)), np.sin(np.linspace(0, 3, 20))])
    _fig, axes = new_figure(1, 2, pyplot=False)
    lines = plot_closeness(axes, ref, [(ref * 1.01, "a", "A"), (ref * 0.99, "b", "B")])
    assert len(lines) == 4 and axes[1].get_title() == "B"
    np.testing.assert_allclose(lines[3].get_xydata(), ref * 0.99)
    with pytest.raises(ValueError, match="one Axes per curve"):
        plot_closeness(axes, ref, [(ref, "a", "A")])
