"""Smoke test of the benchmark harness (benchmarks/run.py) on tiny sizes.

Runs the pure-compute items in-process -- evaluation (course_lib, scipy, geomdl,
per-point loop), arc length (vs scipy and mpmath), symbolic Beta-constraints (vs
sympy's Bell polynomials) -- and renders the report.  No timing is asserted: only
that the harness runs, that its correctness checks hold (the curves agree, the
arc lengths are accurate, the Beta-constraint matrices equal sympy's) and that the
check that guards the timing does fail on a wrong curve.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

BENCH = Path(__file__).resolve().parents[1] / "benchmarks"
# Tiny sizes keep this file at ~1.5 s on an idle machine; the timeout only guards against a
# hang (a tighter one would turn a loaded CI machine into a failure: no timing is asserted).
pytestmark = pytest.mark.timeout(60)


@pytest.fixture(scope="module")
def bench():
    with pytest.MonkeyPatch.context() as mp:
        mp.syspath_prepend(str(BENCH))
        import bench_arc_length
        import bench_beta_constraints
        import bench_common
        import bench_evaluation
        import run

        yield {
            "common": bench_common,
            "evaluation": bench_evaluation,
            "arc_length": bench_arc_length,
            "beta": bench_beta_constraints,
            "run": run,
        }


def _valid_time(x) -> bool:
    return x is not None and math.isfinite(x) and x > 0


def test_evaluation_item_runs_and_checks_agreement(bench):
    common = bench["common"]
    rows = bench["evaluation"].run(common.TINY)
    assert len(rows) >= 9 and all(r.item == "1" for r in rows)
    timed = [r for r in rows if r.reference_name]
    assert timed and all(_valid_time(r.ours) and _valid_time(r.reference) for r in timed)
    assert all(r.ratio == r.ours / r.reference for r in timed)
    table = common.render_table(rows)
    assert table.count("\n") == len(rows) + 1 and "scipy BSpline" in table


def test_bezier_conversion_is_checked_before_timing(bench):
    ev = bench["evaluation"]
    spline, curve, _, _ = ev.build_curves(n_segments=5)
    t = np.linspace(0.0, 5.0, 101)
    assert ev.check_agreement(spline, curve, t) <= 1e-12
    # Boehm's matrix row B_1 = (2 P1 + P2) / 3, checked independently: the Bézier
    # segment reproduces the spline's end derivative q'(0) = 3 (B_1 - B_0).
    B = curve.segments[2]
    np.testing.assert_allclose(3 * (B[1] - B[0]), spline(2.0, nu=1), rtol=1e-12)
    wrong = curve.transformed(np.eye(2), offset=np.array([1e-9, 0.0]))
    with pytest.raises(AssertionError, match="disagree"):
        ev.check_agreement(spline, wrong, t)


def test_arc_length_item_is_accurate(bench):
    rows = bench["arc_length"].run(bench["common"].TINY)
    assert rows and all(r.item == "2" for r in rows)
    for r in rows:
        if "bezier" in r.name:  # its `met` includes a timing goal: not asserted here
            if r.ours is None:
                assert "not installed" in r.note
            else:
                assert r.extra["error_course_lib"] <= 1e-12 and _valid_time(r.reference)
            continue
        assert r.met, r.note
        assert r.extra["error_course_lib"] <= 1e-12 and r.extra["error_scipy"] <= 1e-10


def test_missing_bezier_is_skipped_with_a_note(bench, monkeypatch):
    """bezier is a benchmark-only reference: without it the rows say so, nothing crashes."""
    common = bench["common"]
    monkeypatch.setattr(bench["arc_length"], "optional_module", lambda name: None)
    monkeypatch.setattr(bench["evaluation"], "optional_module", lambda name: None)
    arc = bench["arc_length"].bezier_rows(common.TINY)
    ev = bench["evaluation"].single_cubic_rows(common.TINY)
    skipped = [r for r in arc + ev if "bezier" in r.name]
    assert len(skipped) == 4 and all("not installed" in r.note and r.ours is None for r in skipped)
    assert any(r.reference_name == "scipy BSpline" and _valid_time(r.ours) for r in ev)
    common.render_table(arc + ev)


def test_arc_length_reference_on_a_closed_form(bench):
    """The mpmath reference itself: a straight cubic from (0,0) to (3,4) has length 5."""
    arc = bench["arc_length"]
    line = np.array([[0.0, 0.0], [1.0, 4 / 3], [2.0, 8 / 3], [3.0, 4.0]])
    assert abs(arc.reference_length(line) - 5.0) < 1e-14
    assert abs(arc.scipy_length(line) - 5.0) < 1e-12


def test_beta_constraints_item_matches_sympy_bell(bench):
    rows = bench["beta"].run(bench["common"].TINY, in_process=True)
    assert [r.name.split("=")[1].split()[0] for r in rows] == ["1", "2", "3"]
    assert all("same matrix" in r.note for r in rows)
    assert all(_valid_time(r.ours) and _valid_time(r.reference) for r in rows)


def test_report_renders(bench):
    common, run = bench["common"], bench["run"]
    rows = [
        common.Result("1", "a", 0.002, "ref", 0.004, "≤ 1.5", True),
        common.Result("4", "b", goal="≤ 25 ms", note="TODO | pipe"),
    ]
    text = run.report(rows, {"CPUs (nproc)": "2"}, common.TINY, 1.0)
    assert "| 1 | a | 2 ms | ref: 4 ms | 0.5 | ≤ 1.5 | yes |" in text
    assert "TODO \\| pipe" in text and "Goals missed: none." in text
    assert "process CPU time" in run.report(rows, {}, common.TINY, 1.0, cpu=True)


def test_cpu_clock_switch(bench):
    common = bench["common"]
    try:
        common.use_cpu_clock(True)
        assert common.median_time(lambda: sum(range(1000)), 3) > 0
    finally:
        common.use_cpu_clock(False)
    assert common.CLOCK is __import__("time").perf_counter
