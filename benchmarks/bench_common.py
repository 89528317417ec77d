"""Shared pieces of the benchmark harness: sizes, timing, results, the markdown table.

Every benchmark reports a *median* over repeats and, where it makes sense, a ratio
against a reference measured in the same run (``ratio = course_lib / reference``,
so a ratio below 1 means course_lib is faster).
"""

from __future__ import annotations

import gc
import os
import platform
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import asdict, dataclass, field
from pathlib import Path

import numpy as np

BENCH_DIR = Path(__file__).resolve().parent
REPO = BENCH_DIR.parent


@dataclass(frozen=True)
class Sizes:
    """Problem sizes and repeat counts of one run mode."""

    name: str
    n_params: int  # parameters for the vectorized evaluation (course_lib, scipy)
    n_params_slow: int  # parameters for geomdl and the per-point loop (scaled per point)
    repeats: int  # repeats of fast operations
    repeats_slow: int  # repeats of slow operations (geomdl, per-point loop, subprocesses)
    beta_orders: tuple[int, ...]
    import_runs: int
    widget_repeats: int
    arc_segments: int  # segments of the spline whose arc length is timed (item 2)


FULL = Sizes("full", 10**6, 10**4, 7, 3, (*range(1, 9), 10), 10, 15, 50)
QUICK = Sizes("quick", 10**5, 10**3, 3, 1, tuple(range(1, 6)), 3, 3, 50)
TINY = Sizes("tiny", 2_000, 50, 2, 1, (1, 2, 3), 1, 1, 4)  # the smoke test


@dataclass
class Result:
    """One row of the results table. Times are seconds (medians over repeats)."""

    item: str  # "1. evaluation", ...
    name: str
    ours: float | None = None
    reference_name: str = ""
    reference: float | None = None
    goal: str = ""
    met: bool | None = None
    note: str = ""
    extra: dict = field(default_factory=dict)

    @property
    def ratio(self) -> float | None:
        if self.ours is None or self.reference is None or self.reference == 0:
            return None
        return self.ours / self.reference

    def as_dict(self) -> dict:
        d = asdict(self)
        d["ratio"] = self.ratio
        return d


#: The clock of the in-process timings: wall time by default; process CPU time with
#: ``run.py --cpu`` (a better estimate of the idle-machine time when other jobs share
#: the cores; all the timed code is single-threaded).  Set through :func:`use_cpu_clock`.
CLOCK: Callable[[], float] = time.perf_counter


def use_cpu_clock(cpu: bool) -> None:
    global CLOCK
    CLOCK = time.process_time if cpu else time.perf_counter


def clock() -> float:
    return CLOCK()


def median_time(fn: Callable[[], object], repeats: int, warmup: int = 1) -> float:
    """Median time (s, by :data:`CLOCK`) of ``fn()`` over ``repeats`` calls after ``warmup``.

    The garbage collector is off while timing, as in :mod:`timeit` (and, as there,
    not forced to run before: in a big process a full collection costs more than
    the things timed here).
    """
    for _ in range(warmup):
        fn()
    times = []
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(max(1, repeats)):
            t0 = CLOCK()
            fn()
            times.append(CLOCK() - t0)
    finally:
        if enabled:
            gc.enable()
    return float(np.median(times))


def paired_medians(
    fns: list[Callable[[], object]], repeats: int, number: int = 1, warmup: int = 1
) -> list[float]:
    """Median time (s per call, by :data:`CLOCK`) of each of ``fns``, their samples taken
    in turn (``a b a b ...``) so that a change of load on a shared machine hits all of
    them alike; each sample times ``number`` consecutive calls (for calls of a few µs).
    """
    for fn in fns:
        for _ in range(warmup):
            fn()
    samples: list[list[float]] = [[] for _ in fns]
    enabled = gc.isenabled()
    gc.disable()
    try:
        for _ in range(max(1, repeats)):
            for fn, out in zip(fns, samples, strict=True):
                t0 = CLOCK()
                for _ in range(number):
                    fn()
                out.append((CLOCK() - t0) / number)
    finally:
        if enabled:
            gc.enable()
    return [float(np.median(s)) for s in samples]


def optional_module(name: str):
    """The module ``name`` if it imports, else None (a benchmark-only reference that is
    not installed is skipped with a note, never a crash)."""
    try:
        return __import__(name)
    except Exception:
        return None


def fmt_time(seconds: float | None) -> str:
    """Human-readable duration: µs, ms or s with three significant digits."""
    if seconds is None:
        return "—"
    if seconds < 1e-3:
        return f"{seconds * 1e6:.3g} µs"
    if seconds < 1.0:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds:.3g} s"


def fmt_ratio(r: float | None) -> str:
    if r is None:
        return "—"
    if r >= 100:
        return f"{r:.0f}"
    if r >= 0.01:
        return f"{r:.3g}"
    return f"{r:.2g}"


def status(met: bool | None) -> str:
    return {True: "yes", False: "**NO**", None: ""}[met]


def render_table(results: list[Result]) -> str:
    """The results as one markdown table."""
    lines = [
        "| # | benchmark | course_lib | reference | ratio | goal | met | notes |",
        "|---|---|---:|---|---:|---|:---:|---|",
    ]
    for r in results:
        ref = f"{r.reference_name}: {fmt_time(r.reference)}" if r.reference_name else ""
        if r.reference_name and r.reference is None:
            ref = r.reference_name
        note = r.note.replace("|", "\\|")
        lines.append(
            f"| {r.item} | {r.name} | {fmt_time(r.ours)} | {ref} | {fmt_ratio(r.ratio)} | "
            f"{r.goal} | {status(r.met)} | {note} |"
        )
    return "\n".join(lines)


def _versions() -> dict[str, str]:
    out = {"python": platform.python_version()}
    for mod in ("numpy", "scipy", "sympy", "geomdl", "bezier", "matplotlib"):
        try:
            m = __import__(mod)
            out[mod] = getattr(m, "__version__", "?")
        except Exception:
            out[mod] = "not installed"
    return out


def machine_info() -> dict[str, str]:
    """CPU model, logical CPUs, OS, load average and package versions."""
    info: dict[str, str] = {}
    try:
        lscpu = subprocess.run(["lscpu"], capture_output=True, text=True, timeout=10).stdout
        for line in lscpu.splitlines():
            key, _, value = line.partition(":")
            if key.strip() in ("Model name", "L2 cache", "L3 cache", "Hypervisor vendor"):
                info[key.strip()] = value.strip()
    except (OSError, subprocess.SubprocessError):
        info["Model name"] = platform.processor() or "unknown"
    info["CPUs (nproc)"] = str(os.cpu_count())
    info["OS"] = f"{platform.system()} {platform.release()}"
    try:
        info["load average (1 min) at start"] = f"{os.getloadavg()[0]:.2f}"
    except OSError:
        pass
    info.update(_versions())
    info["interpreter"] = sys.executable
    return info
