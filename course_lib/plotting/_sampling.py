"""Parameter grids for drawing: each segment sampled on its own, joints from both sides."""

from __future__ import annotations

import numpy as np

from .._validation import check_integer

#: The last sample of a segment is taken this fraction of the segment before its end,
#: so that global evaluation (which gives a joint to the segment that *starts* there)
#: returns the one-sided limit of the segment that *ends* there.  Curvature and points
#: of a polynomial segment change by O(1e-10) relative over that distance: invisible,
#: and far below the tolerances of the tests (tests/unit/test_plotting.py).
ONE_SIDED_EPS = 1e-10


def segment_grid(curve, per_segment: int) -> np.ndarray:
    """Global parameters of shape ``(S, per_segment)``: row ``i`` spans segment ``i``.

    Row ``i`` runs from ``t_i`` to (just before) ``t_{i+1}``, so evaluating row ``i``
    gives segment ``i`` only, including its own limits at both joints.
    """
    per_segment = check_integer(per_segment, "per_segment", minimum=2)
    k = np.asarray(curve.knots, dtype=float)
    u = np.linspace(0.0, 1.0, per_segment)
    h = np.diff(k)
    t = k[:-1, None] + h[:, None] * u[None, :]
    if t.shape[0] > 1:
        t[:-1, -1] = k[1:-1] - ONE_SIDED_EPS * h[:-1]
    return t


def segment_samples(curve, per_segment: int) -> tuple[np.ndarray, np.ndarray]:
    """``(t, points)`` with shapes ``(S, n)`` and ``(S, n, dim)``: each segment on its own."""
    t = segment_grid(curve, per_segment)
    pts = curve.evaluate(t.ravel()).reshape((*t.shape, curve.dim))
    return t, pts
