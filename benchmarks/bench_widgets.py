"""Item 4: widget update latency (compute + Agg redraw) of the course's demos.

The measurement itself lives in ``benchmarks/widget_latency.py`` (written with the
widgets, by their author); this adapter only runs it and puts its medians into the
table.  Goal: median update latency ≤ 25 ms.
"""

from __future__ import annotations

from bench_common import BENCH_DIR, Result, Sizes

GOAL_SECONDS = 0.025


def run(sizes: Sizes) -> list[Result]:
    if not (BENCH_DIR / "widget_latency.py").exists():
        return [
            Result(
                "4", "widget update latency (compute + Agg redraw)", goal="≤ 25 ms median",
                note="TODO: benchmarks/widget_latency.py (by the widgets' author) is not there "
                "yet; rerun `make bench` once it is",
            )
        ]
    import widget_latency

    return [
        Result("4", "widget update latency", note=f"TODO: adapt to {widget_latency.__name__}")
    ]
