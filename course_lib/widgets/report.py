"""The live report of a demo: the orders the demo is about first, the rest behind a switch.

A demo that builds G2 joints shows G- and C-order up to 2, the gap, the tangent angle,
the curvature jump and β1, β2.  The analysis itself goes further (``max_order``, 3 by
default); those higher orders, the Beta-constraint residuals and the three
characterizations are shown when the student ticks "more detail", with one line that
says what they mean.  Every number comes from :class:`course_lib.geometry.continuity.JointReport`.
"""

from __future__ import annotations

import html

__all__ = ["DETAIL_NOTE", "NOISE", "demo_report_html", "warning_paragraph", "warning_span"]

#: How a warning looks everywhere in a demo (a dark orange that keeps 4.5:1 on white).
WARNING_STYLE = "color:#934100;font-weight:bold"


def warning_paragraph(text: str) -> str:
    """A warning inside a report's HTML (class ``cl-warning-text``), text escaped."""
    return f"<p class='cl-warning-text' style='{WARNING_STYLE}'>⚠ {html.escape(text)}</p>"


def warning_span(text: str) -> str:
    """A warning in a demo's warning widget (class ``cl-warning``), text escaped."""
    return f"<span style='{WARNING_STYLE}'>⚠ {html.escape(text)}</span>"


def live_html(text: str) -> str:
    """The content of a demo's live region (class ``cl-live-text``): ``role="status"``, read
    out whole by screen readers when it changes; text escaped."""
    return (
        "<div role='status' aria-live='polite' aria-atomic='true' class='cl-live-text'>"
        f"{html.escape(text)}</div>"
    )


#: The one-line explanation shown above the details.
DETAIL_NOTE = (
    "β_k is solved order by order; above the joint's G-order the k-th Beta-constraint does "
    "not hold, so β_k there is only a best fit and moves as you drag. A residual is how far "
    "the k-th constraint is from holding (0: it holds)."
)


#: below this, a gap, angle, jump or β is rounding noise of the computation and shows as 0
#: (a student reading "3.25e-15°" sees a number, not a tangent that is continuous)
NOISE = 1e-9


def _num(x: float, fmt: str) -> str:
    x = float(x)
    if abs(x) < NOISE:
        x = 0.0  # no "-2.7e-15", no "-0"
    return format(x, fmt)


def _row(k: str, v: str, cls: str = "") -> str:
    c = f" class='{cls}'" if cls else ""
    return (
        f"<tr{c}><th style='text-align:left;padding-right:0.8em'>{html.escape(k)}</th>"
        f"<td>{html.escape(v)}</td></tr>"
    )


def demo_report_html(report, order: int, details: bool = False) -> str:
    """HTML table of ``report`` (a JointReport) for a demo about continuity of ``order``.

    Parameters
    ----------
    report : JointReport
    order : int
        The order the demo is about (1 for G1 constructions, 2 for G2, ...); at most
        ``report.max_order``.
    details : bool
        Add the higher orders, all β's, the residuals and the three characterizations.
    """
    n = max(0, min(int(order), report.max_order))
    g, c = report.g_order, report.c_order

    def level(kind: str, k: int) -> str:
        if k < 0:
            return f"not {kind}0: the pieces do not meet"
        if k >= n:
            return f"{kind}{n} ✓"
        return f"{kind}{k} only (not {kind}{k + 1})"

    rows = [
        _row(f"geometric (G{n} wanted)", level("G", g), "cl-report-g"),
        _row("parametric", level("C", c), "cl-report-c"),
        _row("gap", _num(report.gap, ".2g")),
    ]
    if n >= 1:
        rows.append(_row("tangent angle", f"{_num(report.tangent_angle, '.3g')}°"))
    if n >= 2:
        rows.append(_row("curvature jump", _num(report.curvature_jump, ".3g")))
    if report.betas and g >= 1:
        shown = report.betas[: max(1, min(n, g))]
        rows.append(
            _row(
                "shape parameters",
                ", ".join(f"β{i + 1} = {_num(v, '.4g')}" for i, v in enumerate(shown)),
                "cl-report-betas",
            )
        )
    if details:
        from course_lib.geometry.continuity import CHARACTERIZATIONS

        cap = report.max_order
        rows.append(
            f"<tr class='cl-report-note'><td colspan='2' style='font-size:90%;"
            f"max-width:28em;white-space:normal'><i>{html.escape(DETAIL_NOTE)}</i></td></tr>"
        )

        def full(kind: str, k: int) -> str:
            return f"{kind}{k}" + (" (or higher)" if k == cap else "") if k >= 0 else "none"

        rows.append(_row(f"orders checked up to {cap}", f"{full('G', g)}, {full('C', c)}"))
        if report.betas:
            rows.append(
                _row(
                    "all β's",
                    ", ".join(f"β{i + 1} = {_num(v, '.4g')}" for i, v in enumerate(report.betas)),
                )
            )
            rows.append(
                _row(
                    "residuals, orders 1..",
                    ", ".join(_num(v, ".2g") for v in report.residuals),
                )
            )
        rows.append(
            _row(
                "G-order: reparam. / Beta / arc length",
                " / ".join(str(report.g_order_by[k]) for k in CHARACTERIZATIONS),
            )
        )
    title = "Joint" if report.index is None else f"Joint {report.index}"
    return (
        f"<table class='cl-joint-report'><caption style='text-align:left;font-weight:bold'>"
        f"{html.escape(title)}</caption>{''.join(rows)}</table>"
    )
