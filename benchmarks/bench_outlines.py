"""Item 7: classify every joint of every glyph of DejaVu Sans (lecture 09).

``course_lib.constructions.outlines.font_summary`` reads each glyph (fontTools, implied on-curve
points made explicit) and classifies all its joints with the vectorized classifier.
Reference: the course's continuity report (``joint_continuity``, three
characterizations per joint), timed on a sample of joints and scaled to the font's
joint count.  Goal: the whole font in at most 30 s on 2 cores.

Sizes: the full run reads all glyphs (about 6,200 glyphs, 150,000 joints); ``quick``
the first 1,000; the smoke test's ``tiny`` the first 40.
"""

from __future__ import annotations

import numpy as np
from bench_common import Result, Sizes, clock, median_time

GOAL_SECONDS = 30.0
GLYPHS = {"full": None, "quick": 1000, "tiny": 40}
SAMPLE_JOINTS = {"full": 400, "quick": 100, "tiny": 20}


def _report_per_joint(outlines, n_joints: int) -> float:
    """Seconds per joint of the continuity report over the first ``n_joints`` joints."""
    from course_lib.geometry.continuity import joint_continuity

    pairs = []
    for out in outlines:
        for c in out.contours:
            cur = c.curve
            S = cur.n_segments
            for j in range(c.n_joints):
                pairs.append((cur.segment_curve(j), cur.segment_curve((j + 1) % S)))
        if len(pairs) >= n_joints:
            break
    pairs = pairs[:n_joints]

    def run():
        for q, r in pairs:
            try:
                joint_continuity(q, r, max_order=2)
            except ValueError:  # a singular joint: the report refuses it
                pass

    return median_time(run, 1, warmup=0) / max(len(pairs), 1)


def run(sizes: Sizes) -> list[Result]:
    from course_lib.constructions.outlines import font_glyph_names, font_summary, glyph_outline

    names = font_glyph_names("DejaVuSans")
    limit = GLYPHS.get(sizes.name, 1000)
    names = names if limit is None else names[:limit]
    font_summary("DejaVuSans", glyphs=names[:5])  # load the font file once
    times, fs = [], None
    for _ in range(max(1, min(sizes.repeats_slow, 3))):
        t0 = clock()
        fs = font_summary("DejaVuSans", glyphs=names)
        times.append(clock() - t0)
    ours = float(np.median(times))
    joints = fs.total("joints")
    sample = [glyph_outline(glyph=n) for n in names[: min(len(names), 200)]]
    per_joint = _report_per_joint(sample, SAMPLE_JOINTS.get(sizes.name, 100))
    full = limit is None
    note = (
        f"{len(names)} glyphs, {joints} joints: {fs.total('corners')} corners, "
        f"{fs.total('g1')} G1 and {fs.total('g2')} G2 smooth points "
        f"({fs.g2_share:.1%} of the smooth points are G2), {fs.total('singular')} singular"
    )
    return [
        Result(
            "7",
            f"outlines: read and classify every joint of {'all' if full else len(names)} "
            "DejaVu Sans glyphs",
            ours,
            "continuity report per joint (sample, scaled)",
            per_joint * joints,
            goal=f"≤ {GOAL_SECONDS:.0f} s (whole font)" if full else "",
            met=(ours <= GOAL_SECONDS) if full else None,
            note=note,
            extra={"joints": joints, "glyphs": len(names), "g2_share": fs.g2_share},
        )
    ]
