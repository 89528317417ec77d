"""Reparametrization: orientation-preserving changes of variables and equivalent parametrizations.

Seed 000 §4 (Barsky-DeRose) and seed 001 §2: two regular parametrizations ``Q`` on
``[u_0, u_f]`` and ``Q~`` on ``[ũ_0, ũ_f]`` are *equivalent* (describe the same oriented
curve) when ``Q~ = Q o f`` for a regular ``f: [ũ_0, ũ_f] -> [u_0, u_f]`` onto, with
``f' > 0`` -- an *orientation-preserving change of variables*.

* :class:`ChangeOfVariables` is such an ``f`` with derivatives of any order
  (constructors :meth:`~ChangeOfVariables.affine`, :meth:`~ChangeOfVariables.polynomial`,
  :meth:`~ChangeOfVariables.from_sympy`, :meth:`~ChangeOfVariables.from_betas`);
  it checks ``f(a) = c``, ``f(b) = d`` and ``f' > 0``.
* :class:`Reparametrized` is ``Q o f``; its derivatives of every order come from
  Faà di Bruno's formula ``(Q o f)^{(n)} = sum_k Q^{(k)}(f) B_{n,k}(f', ..., f^{(n-k+1)})``
  (:func:`faa_di_bruno`), which is also the content of the Beta-constraints.
* :func:`are_equivalent` decides numerically whether two parametrizations trace the
  same oriented curve, and returns the change of variables it found.

Derivative vectors are not intrinsic (they change under reparametrization); the unit
tangent and the curvature are (seed 000 §4).

Lesson: ``notebooks/02_reparametrization.ipynb``.

Why this module is long: changes of variables, reparametrized curves, Faà di Bruno and the
equivalence test are one idea (seed 000 §4) whose pieces call each other.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from math import factorial

import numpy as np

from course_lib.curves.parametrization import as_parametrization, check_domain, check_in_domain
from course_lib.geometry.chain_rule import check_chain_rule_order, compose_derivatives
from course_lib.homework import own_work
from course_lib.validation import (
    as_parameter_array,
    as_real_array,
    check_finite_scalar,
    check_integer,
)

__all__ = [
    "ChangeOfVariables",
    "EquivalenceResult",
    "Reparametrized",
    "are_equivalent",
    "faa_di_bruno",
]


def _close(x: float, y: float, scale: float) -> bool:
    return abs(x - y) <= 1e-10 * max(1.0, abs(scale))


class ChangeOfVariables:
    """An orientation-preserving change of variables ``f: [a, b] -> [c, d]`` (seed 000 §4).

    Prefer the constructors; the raw form takes ``deriv(x, n)`` returning the n-th
    derivative at a 1-d array ``x``.

    Parameters
    ----------
    deriv : callable ``(x: ndarray, n: int) -> ndarray``
    domain : (a, b)
    image : (c, d), optional
        Checked against ``(f(a), f(b))``; defaults to it.
    check_samples : int
        Number of sample points where ``f' > 0`` is checked (when no exact check
        is available).

    Raises
    ------
    ValueError
        If ``f(a) != c``, ``f(b) != d``, or ``f'`` is not > 0 on ``[a, b]``.
    """

    __slots__ = ("_deriv", "domain", "image", "name")

    def __init__(
        self,
        deriv: Callable[[np.ndarray, int], np.ndarray],
        domain: tuple[float, float],
        image: tuple[float, float] | None = None,
        *,
        name: str = "f",
        check_samples: int = 1025,
        _min_slope: Callable[[], tuple[float, float]] | None = None,
    ) -> None:
        if not callable(deriv):
            raise TypeError(f"deriv must be callable as deriv(x, n); got {type(deriv).__name__}")
        self._deriv = deriv
        self.domain = check_domain(domain)
        self.name = name
        a, b = self.domain
        fa, fb = (float(v) for v in self._raw(np.array([a, b]), 0))
        if not (np.isfinite(fa) and np.isfinite(fb)):
            raise ValueError(
                f"{name} must be finite at the ends of its domain; f(a) = {fa}, f(b) = {fb}"
            )
        if image is not None:
            c, d = check_domain(image, "image")
            if not _close(fa, c, c):
                raise ValueError(f"{name}({a}) must equal the start of the image {c}; it is {fa}")
            if not _close(fb, d, d):
                raise ValueError(f"{name}({b}) must equal the end of the image {d}; it is {fb}")
        else:
            c, d = fa, fb
        # orientation preserving: f' > 0 on [a, b]
        if _min_slope is not None:
            x_min, slope = _min_slope()
        else:
            xs = np.linspace(a, b, check_samples)
            s = self._raw(xs, 1)
            j = int(np.argmin(s))
            x_min, slope = float(xs[j]), float(s[j])
        if not slope > 0:
            raise ValueError(
                f"{name} must be orientation preserving ({name}' > 0 on [{a}, {b}]); "
                f"{name}'({x_min:.6g}) = {slope:.6g}"
            )
        if not c < d:
            raise ValueError(f"{name} must map [{a}, {b}] onto an interval c < d; got ({c}, {d})")
        self.image = (float(c), float(d))

    def _raw(self, x: np.ndarray, n: int) -> np.ndarray:
        return np.broadcast_to(np.asarray(self._deriv(x, n), dtype=float), x.shape)

    # ------------------------------------------------------------ constructors
    @classmethod
    def affine(cls, domain: tuple[float, float], image: tuple[float, float]) -> ChangeOfVariables:
        """``f(x) = c + (d - c)(x - a)/(b - a)``: the affine map of ``[a, b]`` onto ``[c, d]``.

        Example: seed 000 Example 2, ``f(ũ) = 2ũ`` from ``[0, 1/2]`` onto ``[0, 1]``.
        """
        a, b = check_domain(domain)
        c, d = check_domain(image, "image")
        k = (d - c) / (b - a)

        def deriv(x, n):
            if n == 0:
                return c + k * (x - a)
            return np.full(x.shape, k if n == 1 else 0.0)

        return cls(deriv, (a, b), (c, d), _min_slope=lambda: (a, k))

    @classmethod
    def polynomial(
        cls,
        coefficients: Sequence[float] | np.ndarray | np.polynomial.Polynomial,
        domain: tuple[float, float],
        image: tuple[float, float] | None = None,
    ) -> ChangeOfVariables:
        """A polynomial change of variables.

        Parameters
        ----------
        coefficients : sequence or numpy.polynomial.Polynomial
            Coefficients in *increasing* powers (numpy.polynomial convention):
            ``f(x) = c_0 + c_1 x + c_2 x^2 + ...``.
        domain, image
            ``image`` is checked against ``(f(a), f(b))`` when given.

        Notes
        -----
        ``f' > 0`` is checked exactly: at the ends and at the real critical points
        of ``f'`` inside the domain.
        """
        if isinstance(coefficients, np.polynomial.Polynomial):
            P = coefficients.convert(kind=np.polynomial.Polynomial, domain=[-1, 1], window=[-1, 1])
        else:
            c = as_real_array(coefficients, "coefficients", "a sequence of real numbers")
            if c.ndim != 1 or c.size < 2 or not np.all(np.isfinite(c)):
                raise ValueError(
                    "coefficients must be a finite 1-d sequence (c_0, c_1, ...) of length >= 2"
                )
            P = np.polynomial.Polynomial(c)
        a, b = check_domain(domain)
        derivs = [P]

        def get(n):
            while len(derivs) <= n:
                derivs.append(derivs[-1].deriv())
            return derivs[n]

        def deriv(x, n):
            return get(n)(x)

        def min_slope():
            d1, d2 = get(1), get(2)
            cand = [a, b]
            if d2.degree() >= 1:
                r = d2.roots()
                cand += [float(z.real) for z in r if abs(z.imag) < 1e-12 and a < z.real < b]
            vals = [float(d1(x)) for x in cand]
            j = int(np.argmin(vals))
            return cand[j], vals[j]

        return cls(deriv, (a, b), image, _min_slope=min_slope)

    @classmethod
    def from_sympy(
        cls,
        expr: object,
        symbol: object,
        domain: tuple[float, float],
        image: tuple[float, float] | None = None,
    ) -> ChangeOfVariables:
        """A change of variables given by a sympy expression in ``symbol``."""
        import sympy as sp

        if not isinstance(symbol, sp.Symbol):
            raise TypeError(f"symbol must be a sympy Symbol, got {type(symbol).__name__}")
        e = sp.sympify(expr)
        extra = e.free_symbols - {symbol}
        if extra:
            raise ValueError(f"expr depends on {sorted(map(str, extra))} besides {symbol}")
        cache: dict[int, Callable] = {}

        def deriv(x, n):
            if n not in cache:
                cache[n] = sp.lambdify(symbol, sp.diff(e, symbol, n), modules="numpy")
            return cache[n](x)

        return cls(deriv, domain, image)

    @classmethod
    def from_betas(
        cls,
        betas: Sequence[float] | np.ndarray,
        end: float = 1.0,
        image_end: float = 1.0,
        *,
        max_width: float = 1.0,
        image_start_min: float | None = None,
    ) -> ChangeOfVariables:
        """The Taylor polynomial ``u(ū) = image_end + sum_j β_j (ū - end)^j / j!``.

        It has ``u(end) = image_end`` and ``u^{(j)}(end) = β_j`` -- the change of
        variables behind the Beta-constraints (seed 000 §5, ``β_j = u^{(j)}(1)``).
        Its domain ``[end - w, end]`` is chosen with ``w <= max_width`` (halved as
        needed) small enough that ``u' > β_1 / 2`` at 257 sample points there
        (possible because ``β_1 > 0``) and, if given, ``u(end - w) >= image_start_min``.

        Raises
        ------
        ValueError
            If ``β_1 <= 0``.
        """
        b = as_real_array(betas, "betas", "a sequence of real numbers")
        if b.ndim != 1 or b.size == 0 or not np.all(np.isfinite(b)):
            raise ValueError("betas must be a finite 1-d sequence (β_1, ..., β_n)")
        if b[0] <= 0:
            raise ValueError(f"beta1 must be > 0 for an orientation-preserving change; got {b[0]}")
        end = check_finite_scalar(end, "end")
        image_end = check_finite_scalar(image_end, "image_end")
        coef = np.concatenate([[image_end], b / [factorial(j) for j in range(1, b.size + 1)]])
        # Evaluated in the shifted variable x = ū - end, so that the values at ū = end
        # are exactly image_end and β_j (no cancellation from re-expanding about 0).
        P = np.polynomial.Polynomial(coef)
        derivs = [P]
        for _ in range(b.size + 1):
            derivs.append(derivs[-1].deriv())
        w = check_finite_scalar(max_width, "max_width")
        if w <= 0:
            raise ValueError(f"max_width must be > 0; got {w}")
        for _ in range(200):
            xs = np.linspace(-w, 0.0, 257)
            ok = bool(np.all(derivs[1](xs) > 0.5 * b[0]))
            if ok and image_start_min is not None:
                ok = bool(P(-w) >= image_start_min)
            if ok:
                break
            w *= 0.5

        def deriv(x, n):
            if n < len(derivs):
                return derivs[n](x - end)
            return np.zeros(np.shape(x))

        def min_slope():
            xs = np.linspace(-w, 0.0, 257)
            v = derivs[1](xs)
            j = int(np.argmin(v))
            return float(xs[j] + end), float(v[j])

        return cls(deriv, (end - w, end), name="u", _min_slope=min_slope)

    # ---------------------------------------------------------------- values
    def __call__(self, x: float | np.ndarray, n: int = 0) -> float | np.ndarray:
        """``f^{(n)}(x)``; a scalar in gives a float, a 1-d array an array."""
        n = check_integer(n, "n", minimum=0)
        xx, scalar = as_parameter_array(x, "x")
        xx = check_in_domain(xx, self.domain, "x")
        out = self._raw(xx, n)
        return float(out[0]) if scalar else out.copy()

    def derivatives(self, x: float | np.ndarray, n: int) -> np.ndarray:
        """``f^{(1)}, ..., f^{(n)}`` at ``x``: shape (n,) or (n, m)."""
        n = check_integer(n, "n", minimum=1)
        xx, scalar = as_parameter_array(x, "x")
        xx = check_in_domain(xx, self.domain, "x")
        out = np.stack([self._raw(xx, k) for k in range(1, n + 1)])
        return out[:, 0] if scalar else out

    def inverse(self, y: float | np.ndarray) -> float | np.ndarray:
        """``f^{-1}(y)`` for ``y`` in the image (vectorized bisection, then Newton polish)."""
        yy, scalar = as_parameter_array(y, "y")
        yy = check_in_domain(yy, self.image, "y")
        lo = np.full(yy.shape, self.domain[0])
        hi = np.full(yy.shape, self.domain[1])
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            below = self._raw(mid, 0) < yy
            lo = np.where(below, mid, lo)
            hi = np.where(below, hi, mid)
        x = 0.5 * (lo + hi)
        for _ in range(2):
            x = np.clip(x - (self._raw(x, 0) - yy) / self._raw(x, 1), *self.domain)
        return float(x[0]) if scalar else x

    def __repr__(self) -> str:
        return f"ChangeOfVariables({self.name}: {list(self.domain)} -> {list(self.image)})"


class Reparametrized:
    """The reparametrization ``Q o f`` of a parametrization ``Q`` (seed 000 §4).

    Satisfies the parametrization protocol: ``domain = f.domain``,
    ``evaluate(t, n)`` = n-th derivative of ``Q(f(t))`` by Faà di Bruno's
    formula (any order, vectorized), ``dim = Q.dim``.

    Parameters
    ----------
    param : parametrization
        Any protocol object (PiecewiseBezier, ParametricCurve, Reparametrized).
    f : ChangeOfVariables
        Its image must lie in ``param.domain``.
    """

    __slots__ = ("dim", "domain", "f", "param")

    def __init__(self, param: object, f: ChangeOfVariables) -> None:
        self.param = as_parametrization(param, "param")
        if not isinstance(f, ChangeOfVariables):
            raise TypeError(f"f must be a ChangeOfVariables, got {type(f).__name__}")
        a, b = param.domain
        c, d = f.image
        tol = 1e-12 * max(1.0, abs(a), abs(b))
        if c < a - tol or d > b + tol:
            raise ValueError(
                f"the image of f, [{c}, {d}], must lie in the domain of param, [{a}, {b}]"
            )
        self.f = f
        self.domain = f.domain
        self.dim = param.dim

    @property
    def breakpoints(self) -> np.ndarray:
        """Preimages of the breakpoints (knots) of ``param`` inside the image of ``f``."""
        from course_lib.geometry.differential_geometry import breakpoints

        bp = breakpoints(self.param)
        c, d = self.f.image
        inner = bp[(bp > c) & (bp < d)]
        mids = np.atleast_1d(self.f.inverse(inner)) if inner.size else np.zeros(0)
        return np.concatenate([[self.domain[0]], mids, [self.domain[1]]])

    def evaluate(self, t: float | np.ndarray, n: int = 0) -> np.ndarray:
        """n-th derivative of ``Q(f(t))``; shape (dim,) or (m, dim)."""
        n = check_chain_rule_order(check_integer(n, "n", minimum=0), "n")
        tt, scalar = as_parameter_array(t, "t")
        tt = check_in_domain(tt, self.domain)
        x = np.clip(self.f._raw(tt, 0), *self.param.domain)
        if n == 0:
            out = self.param.evaluate(x)
        else:
            outer = np.stack([self.param.evaluate(x, k) for k in range(1, n + 1)])
            inner = np.stack([self.f._raw(tt, j) for j in range(1, n + 1)])
            out = compose_derivatives(outer, inner)[n - 1]
        return out[0] if scalar else out

    def __repr__(self) -> str:
        return f"Reparametrized({self.param!r} o {self.f!r})"


def faa_di_bruno(outer_derivs: np.ndarray, inner_derivs: np.ndarray) -> np.ndarray:
    """Derivatives of orders ``1..n`` of ``g o f`` by Faà di Bruno's formula.

    ``(g o f)^{(i)} = sum_{k=1}^{i} g^{(k)}(f) B_{i,k}(f', f'', ..., f^{(i-k+1)})``
    with the partial Bell polynomials ``B_{i,k}`` (seed 000 eq. (4): the functions
    ``CR_i`` of the chain rule).

    Parameters
    ----------
    outer_derivs : array_like of shape (n, ...)
        ``outer_derivs[k-1] = g^{(k)}(f(t))``: scalars, vectors ``(dim,)``, or
        ``(m, dim)`` for ``m`` parameters.
    inner_derivs : array_like of shape (n,) or (n, m)
        ``inner_derivs[j-1] = f^{(j)}(t)``.

    Returns
    -------
    ndarray shaped like ``outer_derivs``
        Row ``i - 1`` is ``(g o f)^{(i)}(t)``.

    Examples
    --------
    ``g(x) = x²`` after ``f(t) = 2t``, at ``t = 1`` (``f = 2``, so ``g' = 4``, ``g'' = 2``):
    ``(g o f)(t) = 4t²`` has derivatives 8 and 8 there.

    >>> import numpy as np
    >>> faa_di_bruno(np.array([4.0, 2.0]), np.array([2.0, 0.0]))
    array([8., 8.])
    """
    own_work.require("course_lib.geometry.reparametrization.faa_di_bruno")
    outer = as_real_array(outer_derivs, "outer_derivs", "an array of derivatives")
    inner = as_real_array(inner_derivs, "inner_derivs", "an array of derivatives")
    if outer.ndim == 0:
        raise ValueError(f"outer_derivs must have shape (n, ...); got a scalar {outer}")
    if inner.ndim not in (1, 2) or inner.shape[0] == 0:
        raise ValueError(
            f"inner_derivs must have shape (n,) or (n, m) with n >= 1; got {inner.shape}"
        )
    if outer.shape[0] != inner.shape[0] or outer.shape[1 : inner.ndim] != inner.shape[1:]:
        raise ValueError(
            f"outer_derivs must hold the same number n = {inner.shape[0]} of derivatives "
            f"(and the same m) as inner_derivs; got shapes {outer.shape} and {inner.shape}"
        )
    if not (np.all(np.isfinite(outer)) and np.all(np.isfinite(inner))):
        raise ValueError("outer_derivs and inner_derivs must be finite")
    check_chain_rule_order(inner.shape[0], "the number n of derivatives (len(inner_derivs))")
    return compose_derivatives(outer, inner)


@dataclass(frozen=True)
class EquivalenceResult:
    """Outcome of :func:`are_equivalent`.

    Attributes
    ----------
    equivalent : bool
    reason : str
        A sentence for a student: why (not).
    u : ndarray
        Sample parameters of the second parametrization ``q~``.
    f_of_u : ndarray
        The matching parameters ``f(u)`` of the first one, ``q~(u) = q(f(u))``
        (increasing); empty when the images differ.
    max_deviation : float
        ``max |q~(u) - q(f(u))|`` over the samples (matched by arc length).
    """

    equivalent: bool
    reason: str
    u: np.ndarray = field(repr=False)
    f_of_u: np.ndarray = field(repr=False)
    max_deviation: float

    def __bool__(self) -> bool:
        return self.equivalent


def are_equivalent(
    q: object, q_tilde: object, *, num: int = 65, rtol: float = 1e-8
) -> EquivalenceResult:
    """Do ``q`` and ``q_tilde`` describe the same oriented curve (seed 000 §4)?

    Equivalent regular parametrizations have equal lengths and equal arc-length
    parametrizations, so the change of variables is ``f = t_q o s_{q~}`` (arc length
    of ``q~``, then the parameter of ``q`` at that arc length), increasing by
    construction.  The test compares ``q~(u)`` with ``q(f(u))`` at ``num`` samples.

    Parameters
    ----------
    rtol : float
        Relative tolerance, scaled by the length of the curve.

    Examples
    --------
    A quadratic run twice as fast, on ``[0, 1/2]``, is the same oriented curve:

    >>> from course_lib import PiecewiseBezier
    >>> q = PiecewiseBezier([[[0, 0], [1, 2], [2, 0]]])
    >>> fast = Reparametrized(q, ChangeOfVariables.affine((0.0, 0.5), (0.0, 1.0)))
    >>> fast.evaluate(0.25), fast.evaluate(0.25, 1)  # Q(1/2), and twice Q'(1/2)
    (array([1., 1.]), array([4., 0.]))
    >>> are_equivalent(q, fast).equivalent
    True
    """
    from course_lib.geometry.differential_geometry import arc_length, parameter_at_arc_length

    q = as_parametrization(q, "q")
    q_tilde = as_parametrization(q_tilde, "q_tilde")
    num = check_integer(num, "num", minimum=2)
    empty = np.zeros(0)
    if q.dim != q_tilde.dim:
        return EquivalenceResult(
            False, f"different dimensions ({q.dim} and {q_tilde.dim})", empty, empty, np.inf
        )
    Lq, Lt = arc_length(q), arc_length(q_tilde)
    scale = max(Lq, Lt, 1e-300)
    if abs(Lq - Lt) > rtol * scale:
        return EquivalenceResult(
            False,
            f"different lengths ({Lq:.10g} and {Lt:.10g}): not the same curve",
            empty,
            empty,
            np.inf,
        )
    sig = np.linspace(0.0, 1.0, num)
    u = np.atleast_1d(parameter_at_arc_length(q_tilde, sig * Lt))
    fu = np.atleast_1d(parameter_at_arc_length(q, sig * Lq))
    P, Q = q_tilde.evaluate(u), q.evaluate(fu)
    dev = float(np.max(np.linalg.norm(P - Q, axis=-1)))
    if dev <= rtol * scale:
        return EquivalenceResult(
            True,
            "same oriented curve: q_tilde = q o f with f increasing (matched by arc length)",
            u,
            fu,
            dev,
        )
    rev = float(np.max(np.linalg.norm(P - Q[::-1], axis=-1)))
    if rev <= rtol * scale:
        return EquivalenceResult(
            False,
            "same point set traced in the opposite direction: f would be decreasing "
            "(orientation reversing), so not equivalent",
            u,
            empty,
            dev,
        )
    return EquivalenceResult(
        False,
        f"different curves: points at equal arc length differ by up to {dev:.3g}",
        u,
        empty,
        dev,
    )
