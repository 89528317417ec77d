"""Draggable points on a matplotlib canvas (the pattern of matplotlib's ``poly_editor`` example).

The interactor holds no geometry: it asks a callback for the current points, hit-tests
the mouse in *screen pixels* (so the tolerance does not depend on zoom or units), and
reports ``(index, x, y)`` moves to another callback that owns the geometry.  It works on
any canvas that emits matplotlib's mouse events: ipympl in a notebook, Agg in tests
(where events are synthesized, see ``tests/unit/test_widgets.py``).
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["PointDragger"]


class PointDragger:
    """Let the user drag the points returned by ``get_points`` with the left mouse button.

    Parameters
    ----------
    ax : Axes
        Where the points live (data coordinates of this Axes).
    get_points : callable ``() -> ndarray (n, 2)``
        Current positions (the geometry stays with the caller).
    on_move : callable ``(index, x, y) -> None``
        Called on every mouse motion while point ``index`` is held.
    on_release : callable ``(index) -> None``, optional
        Called when the button is released after a drag, after a last ``on_move`` to
        the release position (ipympl throttles mouse motion and may drop the last move:
        the release event carries where the mouse really is, so the point lands exactly
        under it).
    tolerance : float
        Hit radius in pixels.
    on_press : callable ``(index) -> None``, optional
        Called when a point is grabbed.
    coalesce : bool
        Drop stale motion events: when moves arrive faster than ``on_move`` returns, only
        the newest is handled (:class:`~course_lib.widgets._coalesce.Coalescer`).
    """

    def __init__(
        self,
        ax,
        get_points: Callable[[], np.ndarray],
        on_move: Callable[[int, float, float], None],
        on_release: Callable[[int], None] | None = None,
        tolerance: float = 10.0,
        on_press: Callable[[int], None] | None = None,
        coalesce: bool = True,
    ) -> None:
        from course_lib.widgets._coalesce import Coalescer

        self.ax = ax
        self.get_points = get_points
        self.on_move = on_move
        self.on_release = on_release
        self.on_press = on_press
        self.moves = Coalescer(lambda k, x, y: self.on_move(k, x, y)) if coalesce else None
        self.tolerance = float(tolerance)
        self.active: int | None = None
        canvas = ax.figure.canvas
        self._cids = [
            canvas.mpl_connect("button_press_event", self._press),
            canvas.mpl_connect("motion_notify_event", self._motion),
            canvas.mpl_connect("button_release_event", self._release),
        ]

    def hit(self, x_px: float, y_px: float) -> int | None:
        """Index of the point within ``tolerance`` pixels of ``(x_px, y_px)``, nearest first."""
        P = np.asarray(self.get_points(), dtype=float)
        if P.size == 0:
            return None
        xy = self.ax.transData.transform(P)
        d = np.hypot(xy[:, 0] - x_px, xy[:, 1] - y_px)
        k = int(np.argmin(d))
        return k if d[k] <= self.tolerance else None

    def _press(self, event) -> None:
        if event.inaxes is not self.ax or event.button != 1:
            return
        self.active = self.hit(event.x, event.y)
        if self.active is not None and self.on_press is not None:
            self.on_press(self.active)

    def _motion(self, event) -> None:
        if self.active is None or event.inaxes is not self.ax or event.xdata is None:
            return
        if self.moves is not None:
            self.moves(self.active, float(event.xdata), float(event.ydata))
        else:
            self.on_move(self.active, float(event.xdata), float(event.ydata))

    def _release(self, event) -> None:
        if self.active is None or event.button != 1:
            return
        k, self.active = self.active, None
        newest = None
        if self.moves is not None:  # the release position supersedes any queued move
            newest, self.moves.pending = self.moves.pending, None
            self.moves.flush()  # cancels the queued call: no stale move after the release
        xy = self._data_position(event)
        if xy is None and newest is not None:  # a release without a position: the newest
            xy = newest[1:]  # queued move is where the mouse was, never an older one
        if xy is not None:
            self.on_move(k, *xy)
        if self.on_release is not None:
            self.on_release(k)

    def _data_position(self, event) -> tuple[float, float] | None:
        """Data coordinates of the event, the pixel clamped into the Axes box (a release
        outside the Axes leaves the point at its edge, as motion does)."""
        if event.inaxes is self.ax and event.xdata is not None:
            return float(event.xdata), float(event.ydata)
        if event.x is None or event.y is None:
            return None
        box = self.ax.bbox
        px = min(max(float(event.x), box.x0), box.x1)
        py = min(max(float(event.y), box.y0), box.y1)
        x, y = self.ax.transData.inverted().transform((px, py))
        if not (np.isfinite(x) and np.isfinite(y)):
            return None
        return float(x), float(y)

    def disconnect(self) -> None:
        """Stop listening to the canvas."""
        for cid in self._cids:
            self.ax.figure.canvas.mpl_disconnect(cid)
        self._cids = []
