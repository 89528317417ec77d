"""Item 3: symbolic Beta-constraints of orders n = 1..8 and 10 (sympy).

Timed: ``course_lib.geometry.beta_constraints.beta_constraints(n)``, which derives the
constraints by differentiating ``q(u(t))`` with sympy for n <= 6 and, above, takes the
fast path through sympy's partial Bell polynomials (``method="auto"``; the unit tests
check both paths give the same matrices).  Every repeat starts cold:
the ``lru_cache`` of every course_lib function and sympy's own cache are cleared
before each call, and the whole measurement runs in a fresh interpreter (sympy is
imported before the clock starts).

Reference, measured in the same process: the same coefficient matrix written
down from sympy's built-in partial Bell polynomials,
``M[i-1, k-1] = sympy.bell(i, k, (β_1, ..., β_{i-k+1}))`` (Faà di Bruno's
formula), also cold.  The two matrices are checked to be equal (outside the clock).
"""

from __future__ import annotations

import json
import subprocess
import sys
import time

import bench_common
from bench_common import BENCH_DIR, REPO, Result, Sizes

GOAL_SECONDS_N8 = 1.0


def _clear_caches() -> None:
    import sympy

    for name, mod in list(sys.modules.items()):
        if name == "course_lib" or name.startswith("course_lib."):
            for obj in list(vars(mod).values()):
                if callable(getattr(obj, "cache_clear", None)):
                    obj.cache_clear()
    sympy.core.cache.clear_cache()


def _bell_matrix(n: int):
    import sympy as sp

    betas = sp.symbols(f"beta1:{n + 1}")
    M = sp.zeros(n, n)
    for i in range(1, n + 1):
        for k in range(1, i + 1):
            M[i - 1, k - 1] = sp.expand(sp.bell(i, k, betas[: i - k + 1]))
    return M


def measure(orders: tuple[int, ...], repeats: int, cpu: bool = False) -> dict:
    """Cold times (s) of beta_constraints(n) and of the Bell-polynomial reference."""
    import sympy as sp

    clock = time.process_time if cpu else time.perf_counter

    from course_lib.geometry import beta_constraints as bc

    ours: dict[int, list[float]] = {n: [] for n in orders}
    ref: dict[int, list[float]] = {n: [] for n in orders}
    agree: dict[int, bool] = {}
    for _ in range(repeats):
        for n in orders:
            _clear_caches()
            t0 = clock()
            result = bc.beta_constraints(n)
            ours[n].append(clock() - t0)
            _clear_caches()
            t0 = clock()
            M = _bell_matrix(n)
            ref[n].append(clock() - t0)
            if n not in agree:
                agree[n] = sp.expand(result.coefficients - M) == sp.zeros(n, n)
    med = {n: sorted(v)[len(v) // 2] for n, v in ours.items()}
    med_ref = {n: sorted(v)[len(v) // 2] for n, v in ref.items()}
    return {"ours": med, "reference": med_ref, "agree": agree}


def run(sizes: Sizes, in_process: bool = False) -> list[Result]:
    try:
        import course_lib.geometry.beta_constraints as bc
    except ImportError as exc:
        return [Result("3", "Beta-constraints", note=f"TODO: module missing ({exc})")]
    if not hasattr(bc, "beta_constraints"):
        return [Result("3", "Beta-constraints", note="TODO: no beta_constraints(n) function")]
    orders, repeats = sizes.beta_orders, sizes.repeats_slow
    cpu = bench_common.CLOCK is time.process_time
    if in_process:
        data = measure(orders, repeats, cpu)
    else:
        code = (
            f"import sys, json; sys.path.insert(0, {str(BENCH_DIR)!r}); "
            "import sympy, bench_beta_constraints as b; "
            f"d = b.measure({tuple(orders)!r}, {repeats}, {cpu}); "
            "print(json.dumps({k: {str(n): v for n, v in d[k].items()} for k in d}))"
        )
        proc = subprocess.run(
            [sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, timeout=300
        )
        if proc.returncode:
            return [Result("3", "Beta-constraints", note=f"failed: {proc.stderr[-300:]}")]
        raw = json.loads(proc.stdout.strip().splitlines()[-1])
        data = {k: {int(n): v for n, v in raw[k].items()} for k in raw}
    out = []
    for n in orders:
        goal = f"n = {n}: < 1 s" if n in (8, 10) else ""
        met = data["ours"][n] < GOAL_SECONDS_N8 if n in (8, 10) else None
        note = "same matrix as sympy.bell" if data["agree"][n] else "**differs from sympy.bell**"
        out.append(
            Result(
                "3",
                f"Beta-constraints n = {n} (cold caches)",
                data["ours"][n],
                "sympy.bell matrix",
                data["reference"][n],
                goal,
                met,
                note,
            )
        )
        if not data["agree"][n]:
            out[-1].met = False
    return out
