"""Counts per glyph and per font: joints, corners, G1 and G2 smooth points."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from course_lib.constructions.outlines.classification import KINDS, classify_joints
from course_lib.constructions.outlines.contours import Outline
from course_lib.constructions.outlines.fonts import load_font, outline_from_glyf, resolve_font

__all__ = ["FontSummary", "GlyphSummary", "font_summary", "glyph_summary"]


@dataclass(frozen=True)
class GlyphSummary:
    """Counts of one outline's joints: ``joints = corners + g1 + g2 + singular + gaps``."""

    name: str
    contours: int
    joints: int
    corners: int
    g1: int
    g2: int
    singular: int
    gaps: int

    @property
    def smooth(self) -> int:
        """Smooth points (G1 or G2)."""
        return self.g1 + self.g2


def glyph_summary(outline: Outline, **kwargs) -> GlyphSummary:
    """Count an outline's corners and G1 / G2 smooth points (keywords: :func:`classify_joints`)."""
    return _summary(outline, classify_joints(outline, **kwargs).counts())


def _summary(outline: Outline, c: dict) -> GlyphSummary:
    return GlyphSummary(
        outline.name,
        len(outline.contours),
        sum(c.values()),
        c["corner"],
        c["G1"],
        c["G2"],
        c["singular"],
        c["gap"],
    )


@dataclass(frozen=True)
class FontSummary:
    """Per-glyph summaries of a whole font, and their totals."""

    font: str
    glyphs: tuple[GlyphSummary, ...]

    def total(self, name: str) -> int:
        """Sum of one count (``"joints"``, ``"corners"``, ``"g1"``, ``"g2"``, ...) over glyphs."""
        return sum(getattr(g, name) for g in self.glyphs)

    @property
    def g2_share(self) -> float:
        """Share of the smooth points that are G2."""
        smooth = self.total("smooth")
        return self.total("g2") / smooth if smooth else float("nan")

    def __str__(self) -> str:
        keys = ("joints", "corners", "g1", "g2", "singular", "gaps")
        counts = ", ".join(f"{k} {self.total(k)}" for k in keys)
        return (
            f"{self.font}: {len(self.glyphs)} glyphs, {counts}; "
            f"G2 share of smooth points {self.g2_share:.1%}"
        )


def font_summary(
    font: object = "DejaVuSans", glyphs: list[str] | None = None, **kwargs
) -> FontSummary:
    """Classify every joint of every glyph of a font (or of the named ``glyphs``).

    Keyword arguments go to :func:`classify_joints`; glyphs without contours (space,
    ...) are counted with zero joints.
    """
    path = str(resolve_font(font))
    tt, glyf, _cmap, upem, hmtx = load_font(path)
    names = tt.getGlyphOrder() if glyphs is None else list(glyphs)
    known = tt.getReverseGlyphMap()
    missing = [n for n in names if n not in known]
    if missing:
        raise ValueError(f"font {Path(path).stem} has no glyph named {missing[0]!r}")
    outs = [outline_from_glyf(glyf, hmtx, n, path, upem) for n in names]
    # One classification of all contours at once (vectorized), then counts per glyph.
    merged = Outline(tuple(c for o in outs for c in o.contours), "all glyphs", path)
    table = classify_joints(merged, **kwargs)
    glyph_of_contour = np.repeat(np.arange(len(outs)), [len(o.contours) for o in outs])
    code = np.zeros(len(table), int)
    for i, k in enumerate(KINDS):
        code[table.kind == k] = i
    counts = np.zeros((len(outs), len(KINDS)), int)
    np.add.at(counts, (glyph_of_contour[table.contour], code), 1)
    return FontSummary(
        Path(path).stem,
        tuple(
            _summary(o, dict(zip(KINDS, row, strict=True)))
            for o, row in zip(outs, counts.tolist(), strict=True)
        ),
    )
