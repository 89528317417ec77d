"""Item 5: ``import course_lib`` time in a fresh interpreter, against ``import numpy``.

Each run is a new interpreter started with ``-X importtime``; the time reported is
the cumulative import time of the top-level module (``course_lib`` includes numpy,
which it imports).  With ``run.py --cpu`` (a machine shared with other jobs) the
fastest run is reported instead of the median: an import cannot be timed in CPU
time (the child's CPU time includes interpreter start-up, teardown and BLAS
threads), and the fastest run is the least disturbed one.  Medians over ``Sizes.import_runs`` runs.  The same fresh
interpreter also reports which heavy packages ended up in ``sys.modules`` -- there
must be none (the real check is tests/unit/test_import_light.py).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import bench_common
import numpy as np
from bench_common import REPO, Result, Sizes

GOAL_SECONDS = 0.150
HEAVY = ("sympy", "matplotlib", "ipywidgets", "scipy")
MATH_SUBMODULES = (
    "curves.bezier", "curves.curve", "geometry.differential_geometry",
    "geometry.reparametrization", "geometry.beta_constraints", "geometry.continuity",
    "constructions.stitching", "constructions.catmull_rom", "constructions.beta_splines",
    "constructions.knot_splines", "constructions.surfaces",
)


def _env() -> dict[str, str]:
    """Environment of the fresh interpreters: bytecode caching on, as for a user.

    This machine sets PYTHONDONTWRITEBYTECODE, which would make every run recompile
    course_lib (but not numpy, whose installer wrote its caches): unfair and not what
    a student sees.  The caches go to a private prefix, not into the source tree.
    """
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPYCACHEPREFIX"] = str(Path(tempfile.gettempdir()) / "course_lib-bench-pycache")
    return env


def existing_math_submodules() -> list[str]:
    def exists(m: str) -> bool:
        path = REPO / "course_lib" / m.replace(".", "/")
        return path.with_suffix(".py").exists() or (path / "__init__.py").exists()

    return [m for m in MATH_SUBMODULES if exists(m)]


def _importtime(statement: str, prefix: str) -> float:
    """Import time (s) of the top-level imports named ``prefix`` or ``prefix.*``.

    Runs ``statement`` in a fresh interpreter with ``-X importtime`` and sums the
    cumulative times of the matching top-level entries (nested imports such as numpy
    inside course_lib are included in their parent's cumulative time).
    """
    proc = subprocess.run(
        [sys.executable, "-X", "importtime", "-c", statement],
        capture_output=True, text=True, cwd=REPO, timeout=120, check=True, env=_env(),
    )
    pattern = re.compile(r"import time:\s+\d+\s+\|\s+(\d+)\s+\|( +)(\S+)\s*$")
    total = 0.0
    found = False
    for line in proc.stderr.splitlines():
        m = pattern.match(line)
        if not m or len(m.group(2)) != 1:  # one space: a top-level import
            continue
        name = m.group(3)
        if name == prefix or name.startswith(prefix + "."):
            total += int(m.group(1)) * 1e-6
            found = True
    if not found:
        raise RuntimeError(f"no importtime line for {prefix!r}")
    return total


def heavy_modules_after(statement: str) -> list[str]:
    code = f"{statement}; import sys; print(' '.join(sorted(sys.modules)))"
    proc = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=REPO, timeout=120,
        check=True,
    )
    loaded = set(proc.stdout.split())
    return [h for h in HEAVY if h in loaded]


def run(sizes: Sizes) -> list[Result]:
    runs = sizes.import_runs
    subs = existing_math_submodules()
    everything = "import course_lib; " + "; ".join(f"import course_lib.{m}" for m in subs)
    _importtime(everything, "course_lib")  # warm-up: writes the bytecode caches
    # Interleaved, so that both see the same machine load.
    ours_t, all_t, numpy_t = [], [], []
    for _ in range(runs):
        numpy_t.append(_importtime("import numpy", "numpy"))
        ours_t.append(_importtime("import course_lib", "course_lib"))
        all_t.append(_importtime(everything, "course_lib"))
    # With --cpu (a machine shared with other jobs): the fastest run, the least disturbed.
    cpu = bench_common.CLOCK is time.process_time
    stat = np.min if cpu else np.median
    how = "-X importtime cumulative, " + (
        f"fastest of {runs} interleaved runs (--cpu)" if cpu else f"median of {runs} interleaved runs"
    )
    ours, all_, numpy = (float(stat(v)) for v in (ours_t, all_t, numpy_t))
    own = float(np.median(np.subtract(ours_t, numpy_t)))
    heavy = heavy_modules_after(everything)
    note = "no sympy/matplotlib/ipywidgets/scipy loaded" if not heavy else f"loads {heavy}"
    return [
        Result(
            "5", "import course_lib (fresh interpreter)", ours, "import numpy", numpy,
            "≤ 150 ms", ours <= GOAL_SECONDS,
            f"{how}"
            + ("" if cpu else f" (fastest {min(ours_t) * 1e3:.0f} ms, numpy "
               f"{min(numpy_t) * 1e3:.0f} ms)")
            + ", bytecode cached; "
            f"includes numpy; course_lib's own share ≈ {own * 1e3:.0f} ms",
        ),
        Result(
            "5", f"import course_lib + {len(subs)} math submodules", all_, "import numpy", numpy,
            "≤ 150 ms, nothing heavy", all_ <= GOAL_SECONDS and not heavy,
            f"{note}; submodules: {', '.join(subs)}",
        ),
    ]
