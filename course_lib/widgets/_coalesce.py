"""Drop stale input: when events arrive faster than a demo can redraw, draw the newest.

A kernel handles the browser's messages one after the other.  A hand moving a point or a
slider sends an event every ~33 ms; a frame of a demo (curve, comb, picture, report) may
take longer on a busy machine, and then events queue up: each is drawn in turn, and the
picture falls further and further behind the hand.

:class:`Coalescer` wraps a callback.  An event handled less than ``gap`` seconds after
the previous call finished was waiting in the queue behind it (a fresh event finds the
kernel idle): it only records its arguments and schedules one call on the kernel's event
loop ``delay`` seconds later, with the newest arguments.  The picture therefore always
shows where the hand is now, never where it was.  Without a running event loop (tests,
scripts) every event is handled at once.
"""

from __future__ import annotations

import time
from collections.abc import Callable

__all__ = ["Coalescer"]


class Coalescer:
    """Call ``fn(*args)`` for fresh events; for queued ones, once with the newest args.

    Parameters
    ----------
    fn : callable
    gap : float
        Seconds after the previous call finished within which an event counts as queued.
    delay : float
        Seconds after which the newest queued event is handled.
    may_defer : callable ``() -> bool``, optional
        Whether the event being handled may be deferred at all (e.g. only values that
        came from the browser: a value set by code runs at once, so that the next line
        of a notebook cell sees its effect).
    """

    def __init__(
        self,
        fn: Callable,
        gap: float = 0.004,
        delay: float = 0.015,
        may_defer: Callable[[], bool] | None = None,
    ) -> None:
        self.fn = fn
        self.may_defer = may_defer
        self.gap = float(gap)
        self.delay = float(delay)
        self.done_at = -1e9  # perf_counter() when the last call finished
        self.pending: tuple | None = None
        self.timer = None
        self.calls = 0
        self.dropped = 0

    def __call__(self, *args) -> None:
        if self.pending is not None:
            self.dropped += 1
        self.pending = args
        if (
            time.perf_counter() - self.done_at < self.gap
            and (self.may_defer is None or self.may_defer())
            and self._defer()
        ):
            return
        self.flush()

    def _defer(self) -> bool:
        if self.timer is not None:
            return True
        import asyncio

        try:
            loop = asyncio.get_running_loop()
        except RuntimeError:
            return False
        self.timer = loop.call_later(self.delay, self._fire)
        return True

    def _fire(self) -> None:
        self.timer = None
        self.flush()

    def flush(self) -> None:
        """Handle the newest pending event now (if any)."""
        if self.timer is not None:
            self.timer.cancel()
            self.timer = None
        if self.pending is None:
            return
        args, self.pending = self.pending, None
        try:
            self.fn(*args)
        finally:
            self.calls += 1
            self.done_at = time.perf_counter()
