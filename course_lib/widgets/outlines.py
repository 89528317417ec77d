"""The glyph demo: pick a character and a font, drag an off-curve point, watch the comb.

>>> from course_lib.widgets import glyph_demo
>>> glyph_demo("S")                    # doctest: +SKIP

The state (:class:`GlyphDemoState`) holds the glyph's raw TrueType points and asks the
math layer (:mod:`course_lib.constructions.outlines`) for the contours and their joint kinds; the
view draws them with :func:`~course_lib.plotting.outlines.plot_outline`.  Tests drive
the state without a browser: ``demo.state.drag(k, x, y)``, ``demo.state.set_glyph("g")``.
"""

from __future__ import annotations

import html
from collections.abc import Callable

import numpy as np

from course_lib.constructions.outlines import (
    KINDS,
    classify_joints,
    glyph_outline,
    truetype_outline,
)
from course_lib.widgets.assembly import Demo, resolve_static
from course_lib.widgets.view import make_figure

__all__ = ["DEMO_FONTS", "GlyphDemoState", "GlyphDemoView", "glyph_demo"]

#: Fonts offered by the demo's font selector (matplotlib ships them all).
DEMO_FONTS = ("DejaVuSans", "DejaVuSerif", "DejaVuSansMono", "STIXGeneral", "cmr10")


class GlyphDemoState:
    """A glyph whose off-curve points can be moved, and its joint classification.

    Parameters
    ----------
    char : str
        One character.
    font : str
        A font of :data:`DEMO_FONTS` (or any bundled font / ``.ttf`` file).

    Raises
    ------
    ValueError
        A character the font lacks (the math layer's message).
    """

    def __init__(self, char: str = "S", font: str = "DejaVuSans") -> None:
        self.listeners: list[Callable] = []
        self.warning = ""
        self.last: int | None = None
        self._load(char, font)

    def _load(self, char: str, font: str) -> None:
        outline = glyph_outline(char, font)
        if not outline.contours:
            raise ValueError(f"{char!r} has no outline in {font} (nothing to draw)")
        self.char, self.font, self.outline = char, font, outline
        self.points = [p.copy() for p, _ in outline.points]
        self.flags = [o.copy() for _, o in outline.points]
        self.table = classify_joints(outline)
        self.warning, self.last = "", None

    # ------------------------------------------------------------- changes
    def set_glyph(self, char: str | None = None, font: str | None = None) -> None:
        """Load another character and/or font (the previous one stays on bad input)."""
        self._load(self.char if char is None else char, self.font if font is None else font)
        self._notify()

    def offcurve_points(self) -> np.ndarray:
        """The draggable points: all off-curve points, contour after contour, ``(m, 2)``."""
        pts = [p[~o] for p, o in zip(self.points, self.flags, strict=True)]
        return np.vstack(pts) if pts else np.zeros((0, 2))

    def _locate(self, k: int) -> tuple[int, int]:
        for c, o in enumerate(self.flags):
            idx = np.flatnonzero(~o)
            if k < idx.size:
                return c, int(idx[k])
            k -= idx.size
        raise IndexError("off-curve point index out of range")

    def drag(self, k: int, x: float, y: float) -> None:
        """Move off-curve point ``k`` to ``(x, y)`` and reclassify the joints."""
        c, i = self._locate(int(k))
        old = self.points[c][i].copy()
        self.points[c][i] = (float(x), float(y))
        try:
            outline = truetype_outline(
                list(zip(self.points, self.flags, strict=True)),
                name=self.outline.name,
                source=self.outline.source,
                scale=self.outline.scale,
            )
            if [c.curve.n_segments for c in outline.contours] != [
                c.curve.n_segments for c in self.outline.contours
            ]:
                raise ValueError("this position makes a segment vanish; move it elsewhere")
        except ValueError as exc:
            self.points[c][i] = old
            self.warning = str(exc)
        else:
            self.outline, self.table, self.warning = outline, classify_joints(outline), ""
        self.last = int(k)
        self._notify()

    def _notify(self) -> None:
        for fn in list(self.listeners):
            fn(self)

    # ------------------------------------------------------------- report
    def counts(self) -> dict[str, int]:
        return self.table.counts()

    def report_html(self) -> str:
        """Counts per joint kind and, after a drag, the joints next to the moved point."""
        n = self.counts()
        rows = "".join(
            f"<tr><th style='text-align:left'>{html.escape(k)}</th><td>{n[k]}</td></tr>"
            for k in KINDS
            if n[k] or k in ("corner", "G1", "G2")
        )
        near = ""
        if self.last is not None:
            P = self.offcurve_points()[self.last]
            t = self.table
            d = np.linalg.norm(t.point - P, axis=1)
            lines = [
                f"{t.kind[j]}: angle {t.angle[j]:.3g}°, relative curvature jump {t.rel_jump[j]:.2g}"
                for j in np.argsort(d)[:2]
            ]
            near = "<p>joints next to the moved point:<br>" + "<br>".join(
                html.escape(s) for s in lines
            )
        title = f"{html.escape(self.outline.name)} ({html.escape(str(self.font))})"
        return (
            f"<table class='cl-joint-report'><caption>{title}: joints</caption>{rows}</table>"
            + near
        )


class GlyphDemoView:
    """The picture of a :class:`GlyphDemoState`: outline, comb, marks, draggable points."""

    def __init__(self, state: GlyphDemoState, *, static: bool) -> None:
        self.state = state
        self.static = static
        self.fig = make_figure((8.8, 6.2), static)
        self.ax = self.fig.add_axes((0.06, 0.08, 0.6, 0.86))
        self.dragger = None
        self.draw()
        state.listeners.append(self.on_change)

    def draw(self) -> None:
        from course_lib.plotting.outlines import plot_outline

        ax = self.ax
        ax.clear()
        st = self.state
        self.artists = plot_outline(ax, st.outline, legend=True)
        P = st.offcurve_points()
        (self.handles,) = ax.plot(
            P[:, 0], P[:, 1], ls="none", marker="o", ms=6, mfc="white", mec="#6E6E6E", zorder=7
        )
        ax.set_title(f"{st.outline.name} — {st.font}")
        self._shape = [c.curve.n_segments for c in st.outline.contours]
        self.fig.canvas.draw_idle()

    def on_change(self, state: GlyphDemoState) -> None:
        if [c.curve.n_segments for c in state.outline.contours] != self._shape:
            self.draw()  # another glyph: new artists
            return
        self.artists.update(state.outline)
        P = state.offcurve_points()
        self.handles.set_data(P[:, 0], P[:, 1])
        self.ax.legend(
            handles=list(self.artists.marks.values()), loc="upper left", bbox_to_anchor=(1.0, 1.0)
        )
        self.fig.canvas.draw_idle()


def glyph_demo(char: str = "S", font: str = "DejaVuSans", *, static: bool | None = None) -> Demo:
    """Pick a character and a font; drag an off-curve point; watch the comb and the counts.

    Parameters
    ----------
    char : str
        The initial character.
    font : str
        The initial font (one of :data:`DEMO_FONTS` for the selector).
    static : bool, optional
        A plain figure without widgets (default: when ipywidgets/ipympl are missing).

    Returns
    -------
    Demo
        ``demo.state`` is the :class:`GlyphDemoState`; ``demo.controls`` has ``"char"``
        (a text box) and ``"font"`` (a dropdown).
    """
    static = resolve_static(static)
    state = GlyphDemoState(char, font)
    view = GlyphDemoView(state, static=static)
    demo = Demo(state, view, static=static)
    demo.name = "glyph_demo"
    if static:
        return demo
    import ipywidgets as w

    from course_lib.widgets.interactor import PointDragger

    fonts = list(dict.fromkeys([font, *DEMO_FONTS]))
    text = w.Text(value=char, description="character", continuous_update=False)
    text.add_class("cl-char")
    drop = w.Dropdown(options=fonts, value=font, description="font")
    drop.add_class("cl-font")
    demo.controls.update({"char": text, "font": drop})

    def on_char(change):
        state.set_glyph(char=change["new"])

    def on_font(change):
        state.set_glyph(font=change["new"])

    text.observe(demo.guard(on_char), names="value")
    drop.observe(demo.guard(on_font), names="value")
    view.dragger = PointDragger(
        view.ax, state.offcurve_points, demo.guard(lambda k, x, y: state.drag(k, x, y))
    )
    from course_lib.widgets.access import point_controls

    keys = point_controls(demo, state.offcurve_points, demo.guard(state.drag), label="off-curve ")
    demo.build_widgets([text, drop, keys])
    return demo
