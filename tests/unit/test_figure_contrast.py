"""Every line, mark and text of the course's figures reaches WCAG 2.1 AA contrast on white:
3:1 for lines and marks (1.4.11), 4.5:1 for text (1.4.3).

The figures: the static picture of every demo (they use all the plotting functions of the
demos) and the blending-function, construction and outline plots.  Colours are read from
the artists (what the renderer paints), blended over white where an artist is translucent;
grid lines, tick lines and the frame are the axes' own.  Exempt: elements with no meaning of
their own (the light grid, ``#DDDDDD``), faint filled areas and invisible artists.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np
import pytest
from matplotlib.collections import Collection
from matplotlib.colors import to_rgba
from matplotlib.lines import Line2D
from matplotlib.text import Text

from course_lib import widgets


def _lin(c: float) -> float:
    return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4


def contrast_on_white(colour) -> float:
    r, g, b, a = to_rgba(colour)
    r, g, b = (a * v + (1 - a) for v in (r, g, b))  # over white
    lum = 0.2126 * _lin(r) + 0.7152 * _lin(g) + 0.0722 * _lin(b)
    return 1.05 / (lum + 0.05)


def _is_none(c) -> bool:
    return isinstance(c, str) and c.lower() == "none"


def artist_colours(fig):
    """``(kind, description, rgba)`` of every visible line, mark and text of ``fig``."""
    out = []
    grid = {id(line) for ax in fig.axes for line in (*ax.get_xgridlines(), *ax.get_ygridlines())}
    for art in fig.findobj(lambda a: a.get_visible()):
        if id(art) in grid:
            continue
        alpha = art.get_alpha()
        alpha = 1.0 if alpha is None else alpha
        if isinstance(art, Text):
            if art.get_text().strip():
                r, g, b, a = to_rgba(art.get_color())
                out.append(("text", repr(art.get_text()[:30]), (r, g, b, a * alpha)))
        elif isinstance(art, Line2D):
            data = art.get_xydata()
            if len(data) == 0 or not np.isfinite(data).any():
                continue
            if art.get_linestyle() not in ("None", "none", " ", ""):
                r, g, b, a = to_rgba(art.get_color())
                out.append(("line", art.get_label(), (r, g, b, a * alpha)))
            if art.get_marker() not in (None, "None", "none", ""):
                # a mark is seen by its fill, or by its outline when hollow: the darker counts
                cands = [
                    c
                    for c in (art.get_markerfacecolor(), art.get_markeredgecolor())
                    if not _is_none(c)
                ]
                if cands:
                    r, g, b, a = max((to_rgba(c) for c in cands), key=contrast_on_white)
                    out.append(("mark", art.get_label(), (r, g, b, a * alpha)))
        elif isinstance(art, Collection) and not hasattr(art, "get_facecolors3d"):
            cols = art.get_edgecolor()
            lw = np.atleast_1d(art.get_linewidth())
            if len(cols) and lw.max() > 0:
                for c in np.unique(np.round(cols, 4), axis=0):
                    out.append(("line", type(art).__name__, tuple(c)))
    return out


DECORATION = {"#dddddd"}  # the light grid (decoration, exempt from 1.4.11)


def low_contrast(fig) -> list[str]:
    bad = []
    for kind, what, rgba in artist_colours(fig):
        hexc = matplotlib.colors.to_hex(rgba[:3]).lower()
        if hexc in DECORATION or rgba[3] == 0:
            continue
        need = 4.5 if kind == "text" else 3.0
        ratio = contrast_on_white(rgba)
        if ratio < need:
            bad.append(f"{kind} {what}: {hexc} alpha {rgba[3]:.2f} -> {ratio:.2f}:1 < {need}:1")
    return sorted(set(bad))


DEMOS = [
    "beta_spline_demo",
    "catmull_rom_demo",
    "curvature_comb_demo",
    "g2_stitch_demo",
    "glyph_demo",
    "knot_spline_demo",
    "quartic_beta_spline_demo",
    "reparametrization_demo",
]


@pytest.mark.parametrize("name", DEMOS)
def test_demo_figures_reach_aa_contrast(name):
    demo = getattr(widgets, name)(static=True)
    demo.figure.canvas.draw()
    assert not low_contrast(demo.figure), "\n".join(low_contrast(demo.figure))


def test_the_check_finds_a_pale_line():
    from matplotlib.figure import Figure

    fig = Figure()
    ax = fig.subplots()
    ax.plot([0, 1], [0, 1], color="#E69F00")  # the published Okabe-Ito orange, 2.25:1
    ax.text(0.5, 0.5, "label", color="#009E73")  # bluish green, 3.42:1 as text
    problems = low_contrast(fig)
    assert any("#e69f00" in p for p in problems) and any("#009e73" in p for p in problems)


def test_blending_function_plot_reaches_aa_contrast():
    from course_lib.constructions.beta_splines import cubic_beta_spline
    from course_lib.plotting import new_figure, plot_blending_functions

    fig, ax = new_figure(pyplot=False)
    plot_blending_functions(ax, lambda V: cubic_beta_spline(V, beta1=1.5, beta2=2.0), 8)
    fig.canvas.draw()
    assert not low_contrast(fig), "\n".join(low_contrast(fig))
