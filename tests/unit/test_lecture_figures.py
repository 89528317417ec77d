"""course_lib.plotting.lecture_figures: every figure function draws what its lecture says."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest

from course_lib.constructions.beta_splines import (
    cubic_beta_spline,
    quadratic_beta_spline,
    quartic_beta_spline,
)
from course_lib.constructions.catmull_rom import catmull_rom
from course_lib.geometry.closeness import rippled_circle
from course_lib.geometry.differential_geometry import curve_from_curvature
from course_lib.plotting import lecture_figures as lf

P = np.array([[0, 0], [0.5, 2.5], [2.5, 3.2], [4, 0.8], [6, 0.4], [7.5, 2.8], [9.5, 3.0],
              [10.5, 0.8]])


@pytest.fixture(autouse=True)
def _close():
    import matplotlib.pyplot as plt

    yield
    plt.close("all")


def test_every_public_function_returns_a_figure_of_one_column_at_most_900_px_wide():
    assert all(name.endswith("_figure") for name in lf.__all__)
    fig = lf.catmull_rom_figure(P, {b: catmull_rom(P, beta1=b) for b in (1.0, 0.5, 2.0)})
    assert fig.get_size_inches()[0] * 100 <= 900  # inline at dpi 100
    assert len(fig.axes) == 4
    assert [ax.get_title() for ax in fig.axes] == ["β₁ = 1", "β₁ = 0.5", "β₁ = 2", "all three"]


def test_quadratic_title_names_the_joint_values():
    b1 = np.array([1.0, 1.0, 0.5, 2.0, 1.0, 3.0, 1.0])
    fig = lf.quadratic_beta_spline_figure(quadratic_beta_spline(P, b1), P, b1[1:-1])
    assert fig.axes[0].get_title().endswith("β₁ = 1, 0.5, 2, 1, 3 at the joints")


def test_the_conventions_figure_puts_every_polygon_in_one_frame():
    rows = {b2: (quartic_beta_spline(P, 1, b2, 0), quartic_beta_spline(P, 1, -b2, 3 * b2**2))
            for b2 in (0, 20)}
    fig = lf.quartic_conventions_figure(P, rows)
    limits = {(ax.get_xlim(), ax.get_ylim()) for ax in fig.axes}
    assert len(fig.axes) == 4 and len(limits) == 1  # one frame for all panels


def test_the_closeness_figure_draws_curvature_against_arc_length():
    circle = rippled_circle(0, 1)
    bent = curve_from_curvature(lambda s: 1 + 0.05 * np.cos(3 * s), np.pi, start_point=(1, 0),
                                start_angle=np.pi / 2)
    t = np.linspace(0, np.pi, 401)
    fig = lf.closeness_figure(circle, [(rippled_circle(0.01, 8), "a", "b"), (bent, "c", "d")], t)
    bottom = fig.axes[2:] if len(fig.axes) == 4 else None
    kappa_slow, kappa_bent = (ax.lines[-1].get_ydata() for ax in (fig.axes[1], fig.axes[3]))
    assert bottom is not None
    assert np.ptp(kappa_slow) > 1.0  # close in tangent, not in curvature
    assert np.all(np.abs(kappa_bent - 1) < 0.06)  # close in curvature


def test_curvature_profiles_one_panel_per_curve():
    quad, cubic = quadratic_beta_spline(P), cubic_beta_spline(P)
    fig = lf.curvature_profiles_figure({"q": quad, "c": cubic})
    assert [ax.get_title() for ax in fig.axes] == ["q", "c"]
