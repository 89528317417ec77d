"""A dragged point is released under the mouse, whatever the load.

On a busy machine the kernel handles mouse moves more slowly than they arrive: the
:class:`~course_lib.widgets._coalesce.Coalescer` of :class:`PointDragger` then queues them
and draws only the newest.  The release must still land where the mouse is: the release
event's position wins over any queued move, no queued move runs after the release, and a
release that carries no position falls back to the *newest* queued move, never an older
one.  Load is simulated, not waited for: ``on_move`` takes longer than the moves' spacing,
and the coalescer's ``gap`` is wide, so every move after the first is queued, deterministically
(the event loop runs in a thread of its own).
"""

from __future__ import annotations

import asyncio
import threading
import time

import numpy as np
from matplotlib.backend_bases import MouseEvent

from course_lib.widgets import curvature_comb_demo


def mouse(canvas, kind, xy_px, button=1):
    ev = MouseEvent(kind, canvas, float(xy_px[0]), float(xy_px[1]), button=button)
    canvas.callbacks.process(kind, ev)


def _in_a_loop(coro_fn):
    """Run ``coro_fn()`` on an event loop of its own (in a thread: the test thread's loop
    may be running already); return its result, re-raise its error."""
    box: dict = {}

    def target():
        try:
            box["result"] = asyncio.run(coro_fn())
        except BaseException as exc:  # handed back to the test thread
            box["error"] = exc

    worker = threading.Thread(target=target)
    worker.start()
    worker.join()
    if "error" in box:
        raise box["error"]
    return box.get("result")


def _busy_demo(seconds: float):
    """A comb demo whose every move takes ``seconds`` more (a loaded machine), logging moves."""
    demo = curvature_comb_demo()
    dragger = demo.dragger
    moves = []
    inner = dragger.on_move

    def slow_move(k, x, y):
        moves.append((x, y))
        time.sleep(seconds)
        inner(k, x, y)

    dragger.on_move = slow_move
    # every move within 10 s of the previous one counts as queued: the moves are queued
    # however fast or slow this machine happens to be (no timing decides the test)
    dragger.moves.gap = 10.0
    return demo, moves


def _path(demo, k, n=15):
    ax = demo.view.ax
    p = ax.transData.transform(demo.state.points[k])
    return [p + np.array([-2.0 * (i + 1), 0.5 * i]) for i in range(n)], ax


def test_release_under_load_lands_under_the_mouse_and_nothing_runs_after_it():
    demo, moves = _busy_demo(0.02)
    canvas, k = demo.figure.canvas, 5
    path, ax = _path(demo, k)

    async def drag():
        mouse(canvas, "button_press_event", ax.transData.transform(demo.state.points[k]))
        for xy in path:  # back to back: each arrives while the previous is being drawn
            mouse(canvas, "motion_notify_event", xy)
        queued = demo.dragger.moves.pending is not None
        mouse(canvas, "button_release_event", path[-1])
        at_release = demo.state.points[k].copy()
        await asyncio.sleep(0.2)  # any timer left behind would fire now
        return queued, at_release

    queued, at_release = _in_a_loop(drag)
    assert queued, "the moves were not queued: the test does not simulate load"
    end = ax.transData.inverted().transform(path[-1])
    np.testing.assert_allclose(at_release, end, atol=1e-9)
    np.testing.assert_allclose(demo.state.points[k], end, atol=1e-9)  # still there
    assert demo.dragger.moves.timer is None and demo.dragger.moves.pending is None
    assert len(moves) < len(path) + 1  # stale moves were dropped, not all drawn


def test_release_without_a_position_takes_the_newest_queued_move():
    demo, _moves = _busy_demo(0.02)
    canvas, k = demo.figure.canvas, 5
    path, ax = _path(demo, k)

    async def drag():
        mouse(canvas, "button_press_event", ax.transData.transform(demo.state.points[k]))
        for xy in path:
            mouse(canvas, "motion_notify_event", xy)
        ev = MouseEvent("button_release_event", canvas, None, None, button=1)
        ev.x = ev.y = None  # a release that carries no pixel position
        canvas.callbacks.process("button_release_event", ev)
        await asyncio.sleep(0.2)

    _in_a_loop(drag)
    end = ax.transData.inverted().transform(path[-1])
    np.testing.assert_allclose(demo.state.points[k], end, atol=1e-9)
    assert demo.dragger.active is None
