"""The state of a curve demo: :class:`CurveDemoState`, and how a parameter is offered.

* :class:`SliderSpec` -- a shape parameter's slider range (the state refuses a value its
  slider could not show).
* :class:`CurveDemoState` -- the whole state of a demo (design points, shape parameters,
  selected joint, moving parameter, display switches) and the results derived from it (the
  curve, the continuity report of the selected joint, a warning).  ``update()`` recomputes
  and redraws; ``set_param``/``drag`` change it.  No widget and no pixel is needed to drive
  it, so tests can use it directly.

The math is called, never written here: every curve comes from the construction the demo
was given, every report from :func:`course_lib.geometry.continuity.joint_report`.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import numpy as np

from course_lib.geometry.continuity import joint_report
from course_lib.validation import as_points, check_finite_scalar, check_integer
from course_lib.widgets.report import warning_paragraph

__all__ = ["CurveDemoState", "DrawnState", "SliderSpec"]


@dataclass(frozen=True)
class SliderSpec:
    """How a shape parameter is offered to the user.

    ``log=True`` gives a FloatLogSlider over ``[min, max]`` (both > 0): the slider can
    never produce a value <= 0 (the rule for β1).
    """

    name: str
    description: str
    min: float
    max: float
    step: float
    css: str
    log: bool = False
    per_joint: bool = True

    def check(self, value) -> None:
        """Raise ``ValueError`` if ``value`` (a scalar or one value per joint) leaves
        ``[min, max]``: a demo must not start from a value its slider cannot show (the
        slider would silently clamp it while the state keeps the true value)."""
        a = np.atleast_1d(np.asarray(value, dtype=float))
        bad = ~((a >= self.min) & (a <= self.max))
        if np.any(bad):
            j = int(np.argmax(bad))
            at = f" at joint {j}" if a.size > 1 else ""
            raise ValueError(
                f"{self.name} must lie in [{self.min:g}, {self.max:g}] (the range of this "
                f"demo's {self.description} slider); got {a[j]:g}{at}"
            )


class DrawnState:
    """What every demo state shares: the view drawing it (set by the view) and the listeners
    told after each change.  :meth:`update` recomputes (the subclass's ``compute``), redraws,
    then tells the listeners."""

    def __init__(self) -> None:
        self.view = None  #: the view drawing this state, if any (it sets itself)
        self.listeners: list[Callable] = []

    def compute(self) -> None:  # pragma: no cover - every state defines its own
        raise NotImplementedError

    def notify(self) -> None:
        """Tell the listeners (the live report, the screen reader's region) of the new state."""
        for f in self.listeners:
            f(self)

    def update(self) -> None:
        """Recompute, redraw the view (if any), then notify the listeners."""
        self.compute()
        if self.view is not None:
            self.view.draw(self)
        self.notify()


class CurveDemoState(DrawnState):
    """The state of a curve demo and what follows from it.

    Parameters
    ----------
    build : callable ``(points, params) -> PiecewiseBezier``
        The construction (a call into the math layer).  Raises ``ValueError`` on
        bad data.
    points : array_like of shape (n, 2)
        The draggable design points.
    params : mapping of name -> float or array
        Shape parameters (arrays: one value per joint), knots, ...
    joint_of_param : callable ``(name, joint) -> index``, optional
        Which entry of a per-joint parameter array belongs to curve joint ``joint``
        (default: the same index).
    t : float, optional
        Global parameter of the moving point (default: middle of the domain).
    order : int, optional
        The continuity order the demo is about (default ``max_order``): the report shows
        orders up to it; higher orders, residuals and all β's only with ``show_details``.

    Raises
    ------
    ValueError
        If the initial data is invalid: the construction's own error, unchanged; if
        ``t`` lies outside the curve's domain.
    """

    def __init__(
        self,
        build: Callable[[np.ndarray, dict], object],
        points,
        params: Mapping[str, object] | None = None,
        *,
        joint_of_param: Callable[[str, int], int] | None = None,
        t: float | None = None,
        joint: int = 0,
        show_comb: bool = True,
        show_tangents: bool = True,
        show_curvature: bool = True,
        show_circle: bool = False,
        samples: int = 400,
        max_order: int = 3,
        min_points: int = 2,
        order: int | None = None,
        show_details: bool = False,
    ) -> None:
        self.build = build
        self.points = as_points(points, "points", min_points=min_points, dims=(2,)).copy()
        self.params = {
            k: (np.array(v, dtype=float) if np.ndim(v) else float(v))
            for k, v in (params or {}).items()
        }
        self.joint_of_param = joint_of_param or (lambda name, j: j)
        self.show_comb = bool(show_comb)
        self.show_tangents = bool(show_tangents)
        self.show_curvature = bool(show_curvature)
        self.show_circle = bool(show_circle)
        self.samples = check_integer(samples, "samples", minimum=2)
        self.max_order = check_integer(max_order, "max_order", minimum=1)
        #: the continuity order the demo is about (the report shows it first)
        self.order = self.max_order if order is None else check_integer(order, "order", minimum=0)
        if self.order > self.max_order:
            raise ValueError(f"order must be <= max_order = {self.max_order}; got {self.order}")
        self.show_details = bool(show_details)
        self.curve = build(self.points.copy(), self._params_copy())  # bad data raises here
        self.joint = self._check_joint(joint)
        a, b = self.curve.domain
        self.t = 0.5 * (a + b) if t is None else check_finite_scalar(t, "t")
        if not a <= self.t <= b:  # the t slider spans the domain: no silent clamping
            raise ValueError(f"t must lie in the curve's domain [{a:g}, {b:g}]; got {self.t:g}")
        self.report = None
        self.warning = ""
        super().__init__()
        self.compute()

    # ---------------------------------------------------------------- helpers
    def _params_copy(self) -> dict:
        return {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in self.params.items()}

    def _check_joint(self, j: int) -> int:
        j = check_integer(j, "joint", minimum=0)
        n = self.curve.n_joints
        if n and j >= n:
            raise ValueError(f"joint must be < {n} (the curve has {n} joints); got {j}")
        return j

    @property
    def n_joints(self) -> int:
        return self.curve.n_joints

    # ---------------------------------------------------------------- changes
    def set_param(self, name: str, value, joint: int | None = None) -> None:
        """Set a parameter (for all joints when ``joint`` is None), rebuild, redraw.

        Raises
        ------
        ValueError
            If the construction rejects the new value; the old value is kept.
        KeyError
            For an unknown parameter name.
        """
        if name not in self.params:
            raise KeyError(f"unknown parameter {name!r}; known: {sorted(self.params)}")
        old = self.params[name]
        new = old.copy() if isinstance(old, np.ndarray) else old
        if isinstance(new, np.ndarray):
            if joint is None and np.ndim(value) == 0:
                new[:] = float(value)
            elif joint is None:
                new = np.array(value, dtype=float)
            else:
                new[self.joint_of_param(name, joint)] = float(value)
        else:
            new = float(value)
        params = self._params_copy()
        params[name] = new
        self.curve = self.build(self.points.copy(), params)  # raises -> old state kept
        self.params = params
        self.update()

    def get_param(self, name: str, joint: int | None = None) -> float:
        """Value of a parameter at a joint (the first entry when ``joint`` is None)."""
        v = self.params[name]
        if isinstance(v, np.ndarray):
            return float(v[self.joint_of_param(name, 0 if joint is None else joint)])
        return float(v)

    def select_joint(self, j: int) -> None:
        self.joint = self._check_joint(j)
        self.update()

    def set_t(self, t: float) -> None:
        a, b = self.curve.domain
        self.t = float(np.clip(check_finite_scalar(t, "t"), a, b))
        self.update()

    def set_flag(self, name: str, value: bool) -> None:
        if name not in ("show_comb", "show_tangents", "show_curvature", "show_circle"):
            raise KeyError(f"unknown switch {name!r}")
        setattr(self, name, bool(value))
        self.update()

    def set_details(self, value: bool) -> None:
        """Show or hide the report's details (no recomputation, no redraw)."""
        self.show_details = bool(value)
        self.notify()

    def drag(self, k: int, x: float, y: float) -> None:
        """Move design point ``k`` to ``(x, y)`` and update.  Never raises on geometry:
        a degenerate configuration (e.g. two coincident points) becomes ``warning``."""
        k = check_integer(k, "k", minimum=0)
        if k >= len(self.points):
            raise ValueError(f"k must be < {len(self.points)} (number of points); got {k}")
        self.points[k] = (check_finite_scalar(x, "x"), check_finite_scalar(y, "y"))
        self.update(rebuild=True)

    # ----------------------------------------------------------------- results
    def compute(self, rebuild: bool = False, report: bool = True) -> None:
        """Rebuild the curve (if asked) and the report; problems become ``warning``."""
        warnings = []
        if rebuild:
            try:
                self.curve = self.build(self.points.copy(), self._params_copy())
            except ValueError as exc:
                warnings.append(f"The construction failed for these points: {exc}")
        a, b = self.curve.domain
        self.t = float(np.clip(self.t, a, b))
        if self.curve.n_joints:
            self.joint = min(self.joint, self.curve.n_joints - 1)
        self.warning = " ".join(warnings)
        if report:
            self.compute_report()

    def compute_report(self) -> None:
        """The continuity report of the selected joint (a failure becomes ``warning``)."""
        self.report = None
        if self.curve.n_joints:
            try:
                self.report = joint_report(self.curve, self.joint, self.max_order)
            except ValueError as exc:
                msg = f"Joint {self.joint} cannot be analysed: {exc}"
                self.warning = f"{self.warning} {msg}".strip()

    def update(self, rebuild: bool = False) -> None:
        """Recompute and redraw the view (if any), then the report, then notify listeners.

        The picture comes first: the canvas is redrawn before the (slower) continuity
        report is computed.
        """
        self.compute(rebuild=rebuild, report=False)
        if self.view is not None:
            self.view.draw(self)
        self.compute_report()
        self.notify()

    def report_html(self) -> str:
        """The live report: the selected joint's continuity, then any warning."""
        parts = []
        if self.warning:
            parts.append(warning_paragraph(self.warning))
        if self.report is not None:
            from course_lib.widgets.report import demo_report_html

            parts.append(demo_report_html(self.report, self.order, self.show_details))
        elif not self.warning:
            parts.append("<p>This curve has a single segment: no joint to report.</p>")
        return "".join(parts)
