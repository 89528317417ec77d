"""One consistent, projector- and print-friendly look for every picture of the course.

Colours come from a darkened Okabe-Ito palette (distinguishable with the common forms of
colour blindness and in greyscale print, with WCAG AA contrast on white); fonts and lines
are large enough to read from the back of a lecture room.  Nothing here changes matplotlib's global state at
import time: use :func:`course_style` as a context manager (or decorator), or create
figures with :func:`new_figure`, which applies it for you.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from types import MappingProxyType

__all__ = [
    "COLORS",
    "COURSE_RC",
    "OKABE_ITO",
    "OKABE_ITO_ORIGINAL",
    "ROLE_COLORS",
    "SIZES",
    "TEXT_COLOR_NAMES",
    "course_style",
    "new_figure",
    "resolve_pyplot_backend",
    "segment_color",
]

#: The eight Okabe-Ito colours as published (Okabe & Ito, "Color Universal Design", 2002).
#: Kept for reference only: on white, orange (2.25:1), sky blue (2.31:1), yellow (1.32:1) and
#: reddish purple are below WCAG 2.1's 3:1 for graphics (1.4.11), and bluish green (3.42:1)
#: and vermillion (3.87:1) below 4.5:1 for text (1.4.3).
OKABE_ITO_ORIGINAL = MappingProxyType(
    {
        "black": "#000000",
        "orange": "#E69F00",
        "sky_blue": "#56B4E9",
        "bluish_green": "#009E73",
        "yellow": "#F0E442",
        "blue": "#0072B2",
        "vermillion": "#D55E00",
        "reddish_purple": "#CC79A7",
    }
)

#: The course palette: the Okabe-Ito hues, darkened (HLS lightness lowered, hue kept) so that
#: every colour reaches 3:1 against white as a line or mark, and the colours of
#: :data:`TEXT_COLOR_NAMES` 4.5:1 as text (WCAG 2.1 AA, 1.4.11 and 1.4.3).  The lightness
#: of each was chosen so that every pair stays distinguishable with protanopia, deuteranopia
#: and tritanopia (simulated; CIELAB distance >= 10 for every pair;
#: tests/unit/test_palette_contrast.py).
OKABE_ITO = MappingProxyType(
    {
        "black": "#000000",  # 21:1
        "orange": "#9C6C00",  # 4.6:1
        "sky_blue": "#1D97DC",  # 3.2:1, lines and marks only
        "bluish_green": "#008460",  # 4.7:1
        "yellow": "#9C920C",  # 3.2:1 (an olive: a yellow cannot be darker), lines only
        "blue": "#0072B2",  # 5.2:1 (unchanged)
        "vermillion": "#934100",  # 7.0:1
        "reddish_purple": "#CA74A4",  # 3.2:1, lines and marks only
    }
)
#: Palette colours that may colour text on white (4.5:1 or more).
TEXT_COLOR_NAMES = frozenset({"black", "orange", "bluish_green", "blue", "vermillion"})
COLORS = OKABE_ITO

#: What each colour means in the course's pictures (the same role, the same colour, everywhere).
ROLE_COLORS = MappingProxyType(
    {
        "segment_even": OKABE_ITO["blue"],
        "segment_odd": OKABE_ITO["vermillion"],
        "polygon": "#6E6E6E",
        "control_point": OKABE_ITO["black"],
        "joint": OKABE_ITO["orange"],
        "tangent": OKABE_ITO["bluish_green"],
        "normal": OKABE_ITO["sky_blue"],
        "curvature": OKABE_ITO["reddish_purple"],
        "circle": OKABE_ITO["reddish_purple"],
        "comb": OKABE_ITO["sky_blue"],
        "comb_envelope": OKABE_ITO["blue"],
        "construction": OKABE_ITO["bluish_green"],
        "highlight": OKABE_ITO["orange"],
        "moving_point": OKABE_ITO["black"],
    }
)

#: rcParams of the course style (applied only inside :func:`course_style`).
COURSE_RC = MappingProxyType(
    {
        "font.size": 13,
        "axes.titlesize": 14,
        "axes.labelsize": 13,
        "legend.fontsize": 11,
        "xtick.labelsize": 11,
        "ytick.labelsize": 11,
        "lines.linewidth": 2.4,
        "lines.markersize": 7,
        "axes.linewidth": 1.0,
        "axes.grid": True,
        "grid.color": "#DDDDDD",
        "grid.linewidth": 0.8,
        "axes.spines.top": False,
        "axes.spines.right": False,
        "axes.prop_cycle": None,  # filled in lazily (needs matplotlib's cycler)
        "figure.dpi": 100,
        "savefig.dpi": 150,
        "savefig.bbox": "tight",
        "legend.frameon": False,
        "image.cmap": "cividis",
    }
)


def segment_color(i: int) -> str:
    """Colour of segment ``i``: neighbouring segments alternate, so every joint is visible."""
    return ROLE_COLORS["segment_even"] if i % 2 == 0 else ROLE_COLORS["segment_odd"]


def _rc() -> dict:
    from cycler import cycler

    rc = dict(COURSE_RC)
    order = ["blue", "vermillion", "bluish_green", "orange", "reddish_purple", "sky_blue", "black"]
    rc["axes.prop_cycle"] = cycler(color=[OKABE_ITO[k] for k in order])
    return rc


@contextmanager
def course_style() -> Iterator[None]:
    """Apply the course style inside a ``with`` block, restoring matplotlib's settings after.

    Examples
    --------
    >>> import matplotlib.pyplot as plt
    >>> with course_style():
    ...     fig, ax = plt.subplots()
    """
    import matplotlib as mpl

    resolve_pyplot_backend()
    with mpl.rc_context(_rc()):
        try:
            yield
        finally:
            interactive = mpl.is_interactive()
    # A backend activated inside the block may switch interactive mode on (ipykernel's
    # inline backend does, when pyplot first loads it); rc_context would switch it back
    # off on exit, and later figures would never be shown.  Keep what the block set.
    mpl.interactive(interactive)


def resolve_pyplot_backend() -> None:
    """Load pyplot's backend now, if pyplot is in use, so that its set-up is not undone.

    pyplot loads its backend lazily, at the first figure.  ipykernel's inline backend
    then switches interactive mode on (and may set rcParams); inside
    :func:`course_style` those changes would be rolled back when the block ends, and
    every later figure of the notebook would stay invisible.  Does nothing when pyplot
    has not been imported (bare ``Figure`` objects need no backend).
    """
    import sys

    plt = sys.modules.get("matplotlib.pyplot")
    if plt is None:
        return
    get_backend_mod = getattr(plt, "_get_backend_mod", None)  # matplotlib >= 3.6
    if get_backend_mod is not None:
        get_backend_mod()
    else:  # pragma: no cover - older matplotlib
        plt.switch_backend(plt.get_backend())


def new_figure(
    nrows: int = 1,
    ncols: int = 1,
    *,
    figsize: tuple[float, float] | None = None,
    pyplot: bool = True,
    projection: str | None = None,
    **subplot_kw: object,
):
    """A figure and its Axes in the course style.

    Parameters
    ----------
    nrows, ncols : int
        Grid of Axes.
    figsize : (width, height) in inches, optional
        Default ``(6.4 * ncols, 4.8 * nrows)`` scaled down to at most 12 inches wide.
    pyplot : bool
        True (default): create through ``pyplot`` so that notebooks display it;
        False: a bare :class:`matplotlib.figure.Figure` on the Agg canvas (for files,
        tests and widgets; never registered with pyplot).
    projection : str, optional
        ``"3d"`` for surface pictures.

    Returns
    -------
    fig : matplotlib.figure.Figure
    ax : Axes, or ndarray of Axes when ``nrows * ncols > 1``
    """
    if figsize is None:
        w = min(6.4 * ncols, 12.0)
        figsize = (w, w / (6.4 * ncols) * 4.8 * nrows)
    kw = dict(subplot_kw)
    if projection is not None:
        kw["projection"] = projection
    if pyplot:
        import matplotlib.pyplot as plt  # before course_style(), which then loads its backend
    with course_style():
        if pyplot:
            fig, ax = plt.subplots(
                nrows, ncols, figsize=figsize, subplot_kw=kw or None, layout="constrained"
            )
        else:
            from matplotlib.backends.backend_agg import FigureCanvasAgg
            from matplotlib.figure import Figure

            fig = Figure(figsize=figsize, layout="constrained")
            FigureCanvasAgg(fig)
            ax = fig.subplots(nrows, ncols, subplot_kw=kw or None)
    return fig, ax


#: Line widths and marker sizes used by the plotting functions (explicit, so a picture
#: looks the same whether or not it was drawn inside :func:`course_style`).
SIZES = MappingProxyType(
    {
        "curve": 2.8,
        "polygon": 1.3,
        "construction": 1.4,
        "comb": 0.9,
        "comb_envelope": 1.4,
        "control_point": 7.0,
        "joint": 9.0,
        "moving_point": 8.0,
        "label": 13.0,
    }
)
