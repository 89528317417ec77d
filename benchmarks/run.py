"""Run the course's benchmarks and write ``benchmarks/results.md`` (and ``results.json``).

Usage (from the repository root; ``make bench`` does the first)::

    python benchmarks/run.py                   # everything, about 1-2 minutes on 2 cores
    python benchmarks/run.py --skip-notebooks  # without the nbval timings
    python benchmarks/run.py --quick           # smoke run, small sizes, < 20 s, prints only
    python benchmarks/run.py --cpu             # CPU time, for a machine busy with other jobs

Items (each a median over repeats, with a ratio ``course_lib / reference`` where a
reference is measured in the same run):

1. evaluation of points and 1st/2nd derivatives of a 50-segment cubic spline at
   10^6 parameters: course_lib vs scipy's BSpline, geomdl, a per-point loop; one cubic
   at 10^6 points vs the ``bezier`` package (compiled) and at 10^3 vs scipy;
2. arc length to 1e-12: course_lib vs scipy.integrate.quad and the ``bezier`` package's
   ``Curve.length``, errors vs mpmath (``bezier`` is optional: rows say when it is missing);
3. symbolic Beta-constraints n = 1..8 (cold caches) vs sympy's Bell polynomials;
4. widget update latency (compute + Agg redraw), from ``widget_latency.py``;
5. ``import course_lib`` time vs ``import numpy`` and the heavy-package check;
6. nbval time per notebook and for the whole notebook suite;
7. the continuity report per joint vs a direct numpy G2 check (``bench_continuity.py``);
8. building and first evaluation of a 10^5-segment curve vs scipy (``bench_large_curve.py``);
9. every joint of every glyph of DejaVu Sans classified (``bench_outlines.py``) vs the
   continuity report per joint.

Nothing here is a test: the numbers depend on the machine and its load.  The
harness itself is smoke-tested by ``tests/test_benchmarks_smoke.py``.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from datetime import datetime, timezone
from pathlib import Path

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import bench_arc_length  # noqa: E402
import bench_beta_constraints  # noqa: E402
import bench_continuity  # noqa: E402
import bench_evaluation  # noqa: E402
import bench_import  # noqa: E402
import bench_large_curve  # noqa: E402
import bench_notebooks  # noqa: E402
import bench_outlines  # noqa: E402
import bench_widgets  # noqa: E402
from bench_common import (  # noqa: E402
    FULL,
    QUICK,
    Result,
    Sizes,
    machine_info,
    render_table,
    use_cpu_clock,
)

ITEMS = {
    "evaluation": bench_evaluation.run,
    "arc_length": bench_arc_length.run,
    "beta_constraints": bench_beta_constraints.run,
    "widgets": bench_widgets.run,
    "import": bench_import.run,
    "continuity": bench_continuity.run,
    "large_curve": bench_large_curve.run,
    "outlines": bench_outlines.run,
}


def run_all(sizes: Sizes, skip_notebooks: bool, only: list[str] | None = None) -> list[Result]:
    results: list[Result] = []
    for name, fn in ITEMS.items():
        if only and name not in only:
            continue
        t0 = time.perf_counter()
        try:
            rows = fn(sizes)
        except Exception as exc:  # a broken item must not hide the others
            rows = [Result(name, f"{name}: benchmark failed", met=False, note=repr(exc)[:200])]
        print(f"  {name}: {time.perf_counter() - t0:.1f} s", file=sys.stderr)
        results += rows
    if not only or "notebooks" in only:
        t0 = time.perf_counter()
        results += bench_notebooks.run(sizes, skip=skip_notebooks)
        print(f"  notebooks: {time.perf_counter() - t0:.1f} s", file=sys.stderr)
    return results


def report(
    results: list[Result], info: dict[str, str], sizes: Sizes, elapsed: float, cpu: bool = False
) -> str:
    stamp = datetime.now(timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    machine = "; ".join(f"{k}: {v}" for k, v in info.items() if k != "interpreter")
    missed = [f"{r.item} {r.name}" for r in results if r.met is False]
    lines = [
        "# Benchmarks",
        "",
        f"Run: {stamp}, mode `{sizes.name}`, {elapsed:.0f} s in total "
        f"(`python benchmarks/run.py{'' if sizes.name == 'full' else ' --' + sizes.name}"
        f"{' --cpu' if cpu else ''}`).",
        "",
        f"Machine: {machine}.",
        "",
        "Times are medians over repeats; *ratio* = course_lib time / reference time "
        "(below 1: course_lib is faster). Clock: "
        + ("process CPU time for items 1-4 (`--cpu`), wall time for 5-6." if cpu else "wall time."),
        "",
        render_table(results),
        "",
        "Goals missed: " + ("none." if not missed else "; ".join(missed) + "."),
        "",
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="small sizes, no notebooks (< 20 s)")
    parser.add_argument("--skip-notebooks", action="store_true", help="do not run nbval")
    parser.add_argument(
        "--cpu",
        action="store_true",
        help="time in-process work with process CPU time instead of wall time (items 1-4; "
        "for a machine shared with other jobs). Imports and notebooks stay wall time.",
    )
    parser.add_argument(
        "--only", nargs="+", choices=[*ITEMS, "notebooks"], help="run only these items"
    )
    parser.add_argument(
        "--output",
        type=Path,
        default=None,
        help="markdown file to write (default: benchmarks/results.md; the quick mode only "
        "prints, unless --output is given)",
    )
    args = parser.parse_args(argv)
    sizes = QUICK if args.quick else FULL
    use_cpu_clock(args.cpu)
    out = args.output or (None if args.quick else HERE / "results.md")
    info = machine_info()
    t0 = time.perf_counter()
    results = run_all(sizes, skip_notebooks=args.skip_notebooks or args.quick, only=args.only)
    elapsed = time.perf_counter() - t0
    try:
        info["load average (1 min) at end"] = f"{os.getloadavg()[0]:.2f}"
    except OSError:
        pass
    text = report(results, info, sizes, elapsed, cpu=args.cpu)
    print(text)
    if out is None:
        return 0
    out.write_text(text, encoding="utf-8")
    payload = {
        "mode": sizes.name,
        "clock": "process CPU time (items 1-4)" if args.cpu else "wall",
        "date": datetime.now(timezone.utc).isoformat(timespec="seconds"),
        "elapsed_s": elapsed,
        "machine": info,
        "results": [r.as_dict() for r in results],
    }
    out.with_suffix(".json").write_text(json.dumps(payload, indent=1), encoding="utf-8")
    print(f"wrote {out} and {out.with_suffix('.json')}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
