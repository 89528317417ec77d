"""Smooth parametrizations that are not Bézier curves.

The course's analysis functions (:mod:`course_lib.geometry.differential_geometry`,
:mod:`course_lib.geometry.continuity`, ...) accept any object that satisfies the
*parametrization protocol* of ``CONTRIBUTING.md``, written down as :class:`CurveLike`::

    obj.domain            # (t0, t1)
    obj.evaluate(t, n=0)  # n-th derivative, t scalar -> (dim,), t 1-d -> (m, dim)
    obj.dim               # 2 or 3

:class:`ParametricCurve` is that protocol for the examples of the seeds that are
not Bézier curves: the lines of seed 000 Example 1, circles, the clothoid, the
parabola ``(t, t^2)``, ...  It is built either from sympy expressions (derivatives
of every order by :func:`sympy.diff`, compiled with :func:`sympy.lambdify` once and
cached) or from numpy callables, one per derivative order.

A parametrization is a *function*; the curve is its image (seed 000 §1-2, §4).

Lesson: ``notebooks/01_parametric_continuity.ipynb`` (seed 000 Examples 1-2).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Protocol, runtime_checkable

import numpy as np

from course_lib.validation import as_parameter_array, check_finite_scalar, check_integer

__all__ = ["CurveLike", "ParametricCurve", "as_parametrization", "check_domain", "check_in_domain"]


@runtime_checkable
class CurveLike(Protocol):
    """What every analysis function accepts: a parametrization given by its derivatives.

    ``PiecewiseBezier``, :class:`ParametricCurve` and
    :class:`~course_lib.geometry.reparametrization.Reparametrized` satisfy it (duck typing:
    no inheritance needed).  An optional attribute ``breakpoints`` (or ``knots``) tells the
    arc-length quadrature where the curve may fail to be smooth.

    Attributes
    ----------
    domain : tuple of float
        ``(t0, t1)``.
    dim : int
        2 or 3.
    """

    @property
    def domain(self) -> tuple[float, float]: ...

    @property
    def dim(self) -> int: ...

    def evaluate(self, t: float | np.ndarray, n: int = 0) -> np.ndarray:
        """Points (``n = 0``) or ``n``-th derivatives: scalar ``t`` -> ``(dim,)``, 1-d -> ``(m, dim)``."""
        ...


def check_domain(domain: object, name: str = "domain") -> tuple[float, float]:
    """The pair ``(start, end)`` as floats, or an error naming ``name`` and the rule ``start < end``."""
    try:
        a, b = domain  # type: ignore[misc]
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be a pair (start, end), got {domain!r}") from None
    a = check_finite_scalar(a, f"{name}[0]")
    b = check_finite_scalar(b, f"{name}[1]")
    if not a < b:
        raise ValueError(f"{name} must satisfy start < end; got ({a}, {b})")
    return a, b


def check_in_domain(tt: np.ndarray, domain: tuple[float, float], name: str = "t") -> np.ndarray:
    """Check that every value of ``tt`` lies in ``domain`` (up to rounding) and clip it there."""
    a, b = domain
    tol = 1e-12 * max(1.0, abs(a), abs(b), b - a)
    if tt.size and (tt.min() < a - tol or tt.max() > b + tol):
        bad = tt[(tt < a - tol) | (tt > b + tol)][0]
        raise ValueError(f"{name} must lie in the domain [{a}, {b}]; got {bad}")
    return np.clip(tt, a, b)


class ParametricCurve:
    """A smooth parametrization ``c: [t0, t1] -> R^dim`` given by functions.

    Parameters
    ----------
    funcs : sequence of callables
        ``funcs[k](t)`` is the k-th derivative ``c^{(k)}(t)``, ``k = 0, 1, ...``,
        for a 1-d float array ``t`` of length ``m``; it returns an array of shape
        ``(m, dim)`` (or a sequence of ``dim`` arrays/scalars, one per
        coordinate).  Derivatives beyond ``len(funcs) - 1`` are unavailable
        (``ValueError``) unless the curve was built with :meth:`from_sympy`.
    domain : (float, float)
        The parameter interval ``(t0, t1)``, ``t0 < t1``.
    name : str, optional
        A label for ``repr`` and reports.

    Examples
    --------
    >>> import numpy as np
    >>> line = ParametricCurve([lambda t: np.stack([2 * t, t], axis=-1),
    ...                         lambda t: np.stack([2 + 0 * t, 1 + 0 * t], axis=-1)], (0, 1))
    >>> line.evaluate(1.0)
    array([2., 1.])
    """

    __slots__ = ("_cache", "_factory", "_funcs", "dim", "domain", "exprs", "name")

    def __init__(
        self,
        funcs: Sequence[Callable[[np.ndarray], object]],
        domain: tuple[float, float],
        *,
        name: str | None = None,
        _factory: Callable[[int], Callable[[np.ndarray], object]] | None = None,
    ) -> None:
        if callable(funcs):
            funcs = [funcs]
        try:
            funcs = list(funcs)
        except TypeError:
            raise TypeError(
                "funcs must be a sequence of callables, funcs[k](t) giving the k-th derivative"
            ) from None
        if not funcs and _factory is None:
            raise ValueError("funcs must contain at least the position function funcs[0]")
        for k, f in enumerate(funcs):
            if not callable(f):
                raise TypeError(f"funcs[{k}] must be callable, got {type(f).__name__}")
        self.domain = check_domain(domain)
        self.name = name
        self.exprs: tuple | None = None
        self._funcs = funcs
        self._factory = _factory
        self._cache: dict[int, Callable[[np.ndarray], object]] = dict(enumerate(funcs))
        probe = self._call(0, np.array([self.domain[0]]))
        if probe.shape[1] not in (2, 3):
            raise ValueError(
                "the curve must take values in R^2 or R^3; funcs[0] returned dimension "
                f"{probe.shape[1]}"
            )
        self.dim = int(probe.shape[1])

    # ---------------------------------------------------------------- sympy
    @classmethod
    def from_sympy(
        cls,
        exprs: Sequence[object],
        symbol: object,
        domain: tuple[float, float],
        *,
        name: str | None = None,
    ) -> ParametricCurve:
        """Build a parametrization from sympy expressions in one symbol.

        Derivatives of any order are computed on demand by ``sympy.diff`` and
        compiled with ``sympy.lambdify`` (numpy backend) once per order.

        Parameters
        ----------
        exprs : sequence of sympy expressions (or strings sympy can parse)
            The coordinates ``x(t), y(t)[, z(t)]``.
        symbol : sympy.Symbol
            The parameter.
        domain : (float, float)

        Examples
        --------
        >>> import sympy as sp
        >>> t = sp.Symbol("t")
        >>> c = ParametricCurve.from_sympy([sp.cos(t), sp.sin(t)], t, (0, 1))
        >>> c.evaluate(0.0, n=1) + 0.0  # (-sin 0, cos 0)
        array([0., 1.])
        """
        import sympy as sp

        if not isinstance(symbol, sp.Symbol):
            raise TypeError(f"symbol must be a sympy Symbol, got {type(symbol).__name__}")
        try:
            coords = [sp.sympify(e) for e in exprs]
        except (TypeError, sp.SympifyError) as exc:
            raise TypeError(f"exprs must be a sequence of sympy expressions ({exc})") from None
        if len(coords) not in (2, 3):
            raise ValueError(f"exprs must hold 2 or 3 coordinates; got {len(coords)}")
        for k, e in enumerate(coords):
            extra = e.free_symbols - {symbol}
            if extra:
                raise ValueError(
                    f"exprs[{k}] = {e} depends on {sorted(map(str, extra))} besides {symbol}; "
                    "substitute numbers for them first"
                )
        cache: dict[int, list[object]] = {0: coords}

        def factory(n: int) -> Callable[[np.ndarray], object]:
            if n not in cache:
                cache[n] = [sp.diff(e, symbol, n) for e in coords]
            return sp.lambdify(symbol, cache[n], modules="numpy")

        obj = cls([], domain, name=name, _factory=factory)
        obj.exprs = tuple(coords)
        return obj

    # -------------------------------------------------------------- protocol
    def _get(self, n: int) -> Callable[[np.ndarray], object]:
        f = self._cache.get(n)
        if f is None:
            if self._factory is None:
                raise ValueError(
                    f"n must be <= {len(self._funcs) - 1}: this ParametricCurve was given "
                    f"derivative functions up to order {len(self._funcs) - 1} only"
                )
            f = self._cache[n] = self._factory(n)
        return f

    def _call(self, n: int, tt: np.ndarray) -> np.ndarray:
        raw = self._get(n)(tt)
        if isinstance(raw, np.ndarray) and raw.ndim == 2 and raw.shape[0] == tt.size:
            out = raw.astype(float, copy=False)
        else:
            cols = [np.broadcast_to(np.asarray(c, dtype=float), tt.shape) for c in raw]
            out = np.stack(cols, axis=-1)
        if out.shape[0] != tt.size:
            raise ValueError(
                f"derivative function of order {n} returned shape {out.shape} "
                f"for {tt.size} parameters"
            )
        return out

    def evaluate(self, t: float | np.ndarray, n: int = 0) -> np.ndarray:
        """Point (``n = 0``) or n-th derivative at ``t``.

        Returns
        -------
        ndarray of shape (dim,) for a scalar ``t`` or (m, dim) for a 1-d ``t``.

        Raises
        ------
        ValueError
            If some ``t`` lies outside :attr:`domain`, or the derivative of order
            ``n`` is unavailable, or the functions return non-finite values.
        """
        n = check_integer(n, "n", minimum=0)
        tt, scalar = as_parameter_array(t, "t")
        tt = check_in_domain(tt, self.domain)
        out = self._call(n, tt)
        if not np.all(np.isfinite(out)):
            i = int(np.argwhere(~np.all(np.isfinite(out), axis=-1))[0, 0])
            raise ValueError(f"the derivative of order {n} is not finite at t = {tt[i]}")
        return out[0] if scalar else out

    def __repr__(self) -> str:
        label = f"{self.name!r}, " if self.name else ""
        return f"ParametricCurve({label}dim {self.dim}, domain {self.domain})"


def as_parametrization(obj: object, name: str = "curve") -> CurveLike:
    """Return ``obj`` if it satisfies the parametrization protocol, else raise ``TypeError``.

    The protocol (``CONTRIBUTING.md``): attributes ``domain`` (a pair ``t0 < t1``),
    ``dim`` (2 or 3) and a method ``evaluate(t, n=0)``.
    """
    if not (
        hasattr(obj, "domain") and hasattr(obj, "dim") and callable(getattr(obj, "evaluate", None))
    ):
        raise TypeError(
            f"{name} must be a parametrization (an object with domain, dim and evaluate(t, n)), "
            f"such as PiecewiseBezier, ParametricCurve or Reparametrized; got {type(obj).__name__}"
        )
    return obj
