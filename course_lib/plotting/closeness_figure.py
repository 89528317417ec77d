"""Seed 004 Fig. 3: a reference curve against curves close to it in different senses."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

__all__ = ["plot_closeness"]


def plot_closeness(axes, reference: np.ndarray, others: Sequence[tuple]) -> list:
    """One panel per ``(points, label, title)`` in ``others``: the reference points (grey,
    wide) under the other curve's points.  Returns the line artists, two per panel."""
    if len(axes) != len(others):
        raise ValueError(f"need one Axes per curve: {len(axes)} Axes, {len(others)} curves")
    lines = []
    for ax, (points, label, title) in zip(axes, others, strict=True):
        lines += ax.plot(*np.asarray(reference).T, color="0.6", lw=3, label="unit circle")
        lines += ax.plot(*np.asarray(points).T, lw=1.2, label=label)
        ax.legend(loc="lower center", fontsize=9)
        ax.set_aspect("equal")
        ax.locator_params(axis="x", nbins=4)  # narrow panels: tick labels must not touch
        ax.set_title(title)
    return lines
