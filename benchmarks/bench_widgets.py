"""Item 4: widget update latency (compute + Agg redraw) of the course's demos.

The measurement itself lives in ``benchmarks/widget_latency.py`` (written with the
widgets, by their author: a 12-segment cubic Beta-spline demo with a 400-tooth
curvature comb, the β1 slider moving).  This adapter runs its ``measure()`` in a
fresh interpreter (matplotlib with the Agg backend stays out of this process) and
puts its medians into the table.  Goal: total update latency ≤ 25 ms median.
"""

from __future__ import annotations

import json
import subprocess
import sys
import time

import bench_common
from bench_common import BENCH_DIR, REPO, Result, Sizes

GOAL_SECONDS = 0.025
NAME = "widget update latency (compute + Agg redraw)"


def _measure(repeats: int, ipympl: bool, cpu: bool) -> dict:
    code = (
        f"import sys, json, dataclasses, time; sys.path.insert(0, {str(BENCH_DIR)!r}); "
        "import widget_latency as w; "
        + ("w.CLOCK = time.process_time; " if cpu else "")
        + f"r = w.measure(repeats={repeats}, ipympl={ipympl}); "
        + "print(json.dumps(dataclasses.asdict(r)))"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, timeout=600
    )
    if proc.returncode:
        raise RuntimeError(proc.stderr.strip().splitlines()[-1] if proc.stderr else "failed")
    return json.loads(proc.stdout.strip().splitlines()[-1])


def run(sizes: Sizes) -> list[Result]:
    if not (BENCH_DIR / "widget_latency.py").exists():
        return [
            Result(
                "4", NAME, goal="≤ 25 ms median",
                note="TODO: benchmarks/widget_latency.py (by the widgets' author) is not there "
                "yet; rerun `make bench` once it is",
            )
        ]
    try:
        cpu = bench_common.CLOCK is time.process_time
        d = _measure(sizes.widget_repeats, ipympl=sizes.name == "full", cpu=cpu)
    except Exception as exc:
        return [Result("4", NAME, goal="≤ 25 ms median", note=f"TODO: widget_latency failed: {exc}")]
    scene = f"Beta-spline demo, {d['segments']} segments, {d['comb_samples']}-tooth comb, β1 slider"
    ms = {k: v * 1e3 for k, v in d.items() if isinstance(v, float)}
    rows = [
        Result(
            "4", f"{scene}: total (compute + report + Agg blit)", d["total"],
            "full Agg redraw, no blitting", d["redraw_full"], "≤ 25 ms", d["total"] <= GOAL_SECONDS,
            f"median of {d['repeats']} slider moves; of which curve + artists "
            f"{ms['compute_curve_and_artists']:.1f} ms, continuity report {ms['report']:.1f} ms, "
            f"blit {ms['redraw_blit']:.1f} ms",
        ),
        Result(
            "4", f"{scene}: math only", d["math_only"], goal="≤ 2 ms (widgets issue)",
            met=d["math_only"] <= 0.002,
            note="construction, comb, samples, vectors, κ(s): no matplotlib",
        ),
    ]
    if d.get("ipympl_total") is not None:
        rows.append(
            Result(
                "4", f"{scene}: through ipympl (adds PNG encoding)", d["ipympl_total"],
                note="real slider widget and ipympl canvas, no browser",
            )
        )
    return rows
