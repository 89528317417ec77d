"""A lighter picture while the mouse turns a 3D Axes, the full one on release.

On an interactive canvas (ipympl), every mouse motion that rotates a 3D Axes redraws the
whole figure: the surfaces, three axes with their ticks, and -- with constrained layout --
a layout pass that measures every tick label.  While the button is held,
:class:`LightWhileRotating` shows coarse surfaces instead of the full ones, hides the turning
Axes' panes, ticks and labels (they cost most of a 3D frame: measured 240 -> 44 ms per
draw on a busy 2-core machine) and freezes the layout (the Axes keep their place); on release it puts everything back and sends
one complete frame (a full image, not a diff: it also heals a frame the browser lost).

Only artists are swapped: no geometry is computed here (the coarse surfaces are made once
by the caller).  Static canvases (Agg, inline figures) are left alone.
"""

from __future__ import annotations

__all__ = ["LightWhileRotating", "is_interactive_canvas"]


def is_interactive_canvas(canvas) -> bool:
    """True for a canvas that shows mouse-driven redraws live (ipympl's widget canvas,
    matplotlib's web and GUI backends); False for Agg and the other file canvases."""
    mod = type(canvas).__module__
    return mod.startswith("ipympl") or any(
        k in mod
        for k in (
            "webagg",
            "nbagg",
            "backend_qt",
            "backend_tk",
            "backend_gtk",
            "backend_wx",
            "backend_macosx",
        )
    )


class LightWhileRotating:
    """Swap ``full`` artists for ``light`` ones while button 1 is held in ``ax``.

    Parameters
    ----------
    ax : 3D Axes
    full, light : sequences of artists
        Shown when idle / while rotating; ``light`` starts hidden.
    """

    def __init__(self, ax, full, light) -> None:
        self.ax = ax
        self.full = list(full)
        self.light = list(light)
        self.rotating = False
        self._layout = None
        self._axis_on = True
        for a in self.light:
            a.set_visible(False)
        canvas = ax.get_figure(root=True).canvas
        self._cids = [
            canvas.mpl_connect("button_press_event", self._press),
            canvas.mpl_connect("button_release_event", self._release),
        ]

    def _press(self, event) -> None:
        if event.inaxes is not self.ax or event.button != 1 or self.rotating:
            return
        self.rotating = True
        fig = self.ax.get_figure(root=True)
        self._layout = fig.get_layout_engine()
        if self._layout is not None:
            fig.set_layout_engine("none")  # keep the Axes where the last layout put them
        for a in self.full:
            a.set_visible(False)
        for a in self.light:
            a.set_visible(True)
        self._axis_on = bool(getattr(self.ax, "_axis3don", self.ax.axison))
        self.ax.set_axis_off()

    def _release(self, event) -> None:
        if not self.rotating:
            return
        self.rotating = False
        fig = self.ax.get_figure(root=True)
        if self._layout is not None:
            fig.set_layout_engine(self._layout)
            self._layout = None
        for a in self.light:
            a.set_visible(False)
        for a in self.full:
            a.set_visible(True)
        if self._axis_on:
            self.ax.set_axis_on()
        canvas = fig.canvas
        if hasattr(canvas, "_force_full"):
            canvas._force_full = True
        canvas.draw_idle()

    def disconnect(self) -> None:
        canvas = self.ax.get_figure(root=True).canvas
        for cid in self._cids:
            canvas.mpl_disconnect(cid)
        self._cids = []
