"""The course palette meets WCAG 2.1 AA contrast on white and stays colour-blind-safe.

Contrast ratios follow WCAG 2.1's definition of relative luminance (sRGB, linearised);
colour blindness is simulated with the matrices of Machado, Oliveira & Fernandes (2009,
severity 1.0) applied in linear RGB, and colours are compared in CIELAB (D65).  Both are
computed here from their definitions, not with the code under test.
"""

from __future__ import annotations

import itertools
import math

import pytest

from course_lib.plotting.style import (
    OKABE_ITO,
    OKABE_ITO_ORIGINAL,
    ROLE_COLORS,
    TEXT_COLOR_NAMES,
)

WHITE = "#FFFFFF"
MACHADO = {
    "protanopia": (
        (0.152286, 1.052583, -0.204868),
        (0.114503, 0.786281, 0.099216),
        (-0.003882, -0.048116, 1.051998),
    ),
    "deuteranopia": (
        (0.367322, 0.860646, -0.227968),
        (0.280085, 0.672501, 0.047413),
        (-0.011820, 0.042940, 0.968881),
    ),
    "tritanopia": (
        (1.255528, -0.076749, -0.178779),
        (-0.078411, 0.930809, 0.147602),
        (0.004733, 0.691367, 0.303900),
    ),
}


def _linear(hex_colour: str) -> tuple[float, float, float]:
    h = hex_colour.lstrip("#")
    out = []
    for i in (0, 2, 4):
        c = int(h[i : i + 2], 16) / 255
        out.append(c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4)
    return tuple(out)


def luminance(hex_colour: str) -> float:
    r, g, b = _linear(hex_colour)
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast(a: str, b: str = WHITE) -> float:
    hi, lo = sorted((luminance(a), luminance(b)), reverse=True)
    return (hi + 0.05) / (lo + 0.05)


def _lab(rgb_linear) -> tuple[float, float, float]:
    r, g, b = (min(max(v, 0.0), 1.0) for v in rgb_linear)
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883

    def f(t):
        return t ** (1 / 3) if t > 216 / 24389 else (24389 / 27 * t + 16) / 116

    fx, fy, fz = f(x), f(y), f(z)
    return 116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)


def _simulate(hex_colour: str, matrix) -> tuple[float, float, float]:
    rgb = _linear(hex_colour)
    return tuple(sum(m * c for m, c in zip(row, rgb, strict=True)) for row in matrix)


def test_contrast_formula_on_known_pairs():
    assert contrast("#000000") == pytest.approx(21.0)
    assert contrast("#767676") == pytest.approx(4.54, abs=0.01)  # the classic AA grey
    assert contrast("#E69F00") == pytest.approx(2.25, abs=0.01)  # Okabe-Ito orange, as audited


@pytest.mark.parametrize("name", sorted(OKABE_ITO))
def test_every_palette_colour_reaches_3_to_1_as_a_line_or_mark(name):
    assert contrast(OKABE_ITO[name]) >= 3.0, f"{name} {OKABE_ITO[name]}"


@pytest.mark.parametrize("name", sorted(TEXT_COLOR_NAMES))
def test_text_colours_reach_4_5_to_1(name):
    assert contrast(OKABE_ITO[name]) >= 4.5, f"{name} {OKABE_ITO[name]}"


@pytest.mark.parametrize("role", sorted(ROLE_COLORS))
def test_every_role_colour_reaches_3_to_1(role):
    assert contrast(ROLE_COLORS[role]) >= 3.0, f"{role} {ROLE_COLORS[role]}"


def test_the_published_palette_would_fail():
    """The check can fail: the published Okabe-Ito colours do (orange, sky blue, yellow)."""
    low = {k for k, v in OKABE_ITO_ORIGINAL.items() if contrast(v) < 3.0}
    assert {"orange", "sky_blue", "yellow"} <= low


@pytest.mark.parametrize("kind", sorted(MACHADO))
def test_colours_stay_distinct_with_colour_blindness(kind):
    m = MACHADO[kind]
    worst = min(
        (math.dist(_lab(_simulate(a, m)), _lab(_simulate(b, m))), na, nb)
        for (na, a), (nb, b) in itertools.combinations(OKABE_ITO.items(), 2)
    )
    assert worst[0] >= 10.0, f"{kind}: {worst[1]} and {worst[2]} differ by ΔE {worst[0]:.1f}"


def test_darkened_colours_keep_their_hue():
    import colorsys

    for name, new in OKABE_ITO.items():
        old = OKABE_ITO_ORIGINAL[name]
        if old == "#000000":
            continue
        h_old = colorsys.rgb_to_hls(*(int(old[i : i + 2], 16) / 255 for i in (1, 3, 5)))[0]
        h_new = colorsys.rgb_to_hls(*(int(new[i : i + 2], 16) / 255 for i in (1, 3, 5)))[0]
        assert min(abs(h_old - h_new), 1 - abs(h_old - h_new)) < 0.02, name


def test_comb_teeth_are_opaque():
    import matplotlib

    matplotlib.use("Agg")
    from course_lib import PiecewiseBezier
    from course_lib.plotting import new_figure, plot_curvature_comb

    curve = PiecewiseBezier([[[0, 0], [1, 2], [3, 2], [4, 0]]])
    _fig, ax = new_figure(pyplot=False)
    arts = plot_curvature_comb(ax, curve)
    assert arts.teeth.get_alpha() in (None, 1.0)
    assert contrast(matplotlib.colors.to_hex(arts.teeth.get_color()).upper()) >= 3.0
