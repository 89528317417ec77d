"""Input checks shared by the public functions of :mod:`course_lib`.

Every public function validates its arguments here, at the boundary, so that
bad input produces a :class:`ValueError` or :class:`TypeError` that names the
parameter and the rule it broke -- never a silent NaN or a wrong picture.
Internal helpers call each other without re-checking.
"""

from __future__ import annotations

from collections.abc import Sequence
from numbers import Real

import numpy as np

__all__ = [
    "as_parameter_array",
    "as_points",
    "as_real_array",
    "check_finite_scalar",
    "check_integer",
    "check_knots",
    "check_positive",
    "check_shape_parameters",
    "scaled_norm",
]


def scaled_norm(x: np.ndarray, axis: int = -1) -> np.ndarray:
    """Euclidean norm along ``axis`` without overflow or underflow over the whole float
    range: where the plain formula overflows or loses precision to underflow (norms
    outside ``[1e-140, 1e150]``), the vectors are scaled by a power of two (exact) before
    squaring."""
    x = np.asarray(x, dtype=float)
    y = x if axis in (-1, x.ndim - 1) else np.moveaxis(x, axis, -1)
    with np.errstate(over="ignore", under="ignore"):
        v = np.sqrt(np.einsum("...i,...i->...", y, y))
    if v.size and 1e-140 < v.min() and v.max() < 1e150:
        return v
    big = np.max(np.abs(x), axis=axis, keepdims=True)
    _, e = np.frexp(np.where(big > 0, big, 1.0))
    y = np.ldexp(x, -e)
    return np.ldexp(np.sqrt(np.sum(y * y, axis=axis)), np.squeeze(e, axis=axis))


def as_real_array(value: object, name: str, what: str = "an array of real numbers") -> np.ndarray:
    """Return ``value`` as a float array, or raise a TypeError naming ``name``.

    The one conversion every public function uses, so that bad input is refused the same
    way everywhere: strings (bare or inside lists, even numeric ones like ``"1.0"``),
    complex numbers (never silently dropping the imaginary part), ``None``, and ragged
    nested lists all raise ``TypeError(f"{name} must be {what} ...")``.
    """
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be {what}, got {type(value).__name__}")
    if isinstance(value, np.ndarray):
        arr = value
    else:
        try:
            arr = np.asarray(value)
        except (TypeError, ValueError):
            raise TypeError(
                f"{name} must be {what}: a rectangular array (got a ragged nested sequence, "
                "rows of different lengths)"
            ) from None
    kind = arr.dtype.kind
    if kind == "c":
        raise TypeError(f"{name} must be {what}, got complex numbers")
    if kind in "USV":
        raise TypeError(f"{name} must be {what}, got strings (pass numbers, not text)")
    if kind == "O":
        for x in arr.ravel():
            if isinstance(x, (str, bytes, complex, np.complexfloating)) or x is None:
                raise TypeError(f"{name} must be {what}, got an element {x!r}")
    if kind in "biuf":
        return arr.astype(float, copy=False)
    try:
        return arr.astype(float)
    except (TypeError, ValueError) as exc:
        raise TypeError(f"{name} must be {what} ({exc})") from None


def as_points(
    value: object,
    name: str,
    *,
    min_points: int = 2,
    dims: Sequence[int] = (2, 3),
) -> np.ndarray:
    """Return ``value`` as a float array of shape ``(n_points, dim)``.

    Raises
    ------
    TypeError
        If ``value`` cannot be read as an array of real numbers.
    ValueError
        If it is not two-dimensional, has fewer than ``min_points`` rows, has a
        dimension not in ``dims``, or holds a non-finite value.
    """
    if isinstance(value, (str, bytes)) or value is None:
        raise TypeError(f"{name} must be an array of points, got {type(value).__name__}")
    arr = as_real_array(value, name, "an array of points (real numbers)")
    if arr.ndim != 2:
        raise ValueError(
            f"{name} must have shape (n_points, dim), one point per row; got shape {arr.shape}"
        )
    if arr.shape[1] not in dims:
        allowed = " or ".join(str(d) for d in dims)
        raise ValueError(
            f"{name} must hold points of dimension {allowed}; got dimension {arr.shape[1]}"
        )
    if arr.shape[0] < min_points:
        raise ValueError(f"{name} must have at least {min_points} points; got {arr.shape[0]}")
    if not np.isfinite(arr).all():
        bad = int(np.argwhere(~np.isfinite(arr))[0, 0])
        raise ValueError(
            f"{name} must contain only finite values; point {bad} is {arr[bad].tolist()}"
        )
    return arr


def as_parameter_array(value: object, name: str) -> tuple[np.ndarray, bool]:
    """Return ``value`` as a 1-d float array, and whether it was a scalar.

    Raises
    ------
    TypeError
        If ``value`` is not real-valued.
    ValueError
        If it is more than one-dimensional or not finite.
    """
    arr = as_real_array(value, name, "a real number or an array of them")
    scalar = arr.ndim == 0
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a scalar or a 1-d array; got shape {arr.shape}")
    arr = np.atleast_1d(arr)
    if not np.isfinite(arr).all():
        raise ValueError(f"{name} must contain only finite values")
    return arr, scalar


def check_finite_scalar(value: object, name: str) -> float:
    """Return ``value`` as a finite float, or raise naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (Real, np.floating, np.integer)):
        if isinstance(value, np.ndarray) and value.ndim == 0:
            value = value.item()
        else:
            raise TypeError(f"{name} must be a real number, got {type(value).__name__}")
    x = float(value)
    if not np.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x}")
    return x


def check_positive(value: object, name: str) -> float:
    """Return ``value`` as a float after checking that it is finite and > 0.

    Examples
    --------
    >>> check_positive(2, "beta1")
    2.0
    >>> check_positive(-1, "beta1")
    Traceback (most recent call last):
    ...
    ValueError: beta1 must be > 0, got -1.0
    """
    x = check_finite_scalar(value, name)
    if x <= 0:
        raise ValueError(f"{name} must be > 0, got {x}")
    return x


def check_integer(value: object, name: str, *, minimum: int = 0) -> int:
    """Return ``value`` as an int after checking that it is an integer >= ``minimum``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__}")
    n = int(value)
    if n < minimum:
        raise ValueError(f"{name} must be >= {minimum}, got {n}")
    return n


def check_knots(value: object, name: str = "knots", *, count: int | None = None) -> np.ndarray:
    """Return a strictly increasing, finite 1-d knot array.

    Parameters
    ----------
    count
        If given, the exact number of knots required.
    """
    arr, scalar = as_parameter_array(value, name)
    if scalar:
        raise ValueError(f"{name} must be a 1-d sequence of numbers, got a scalar")
    if count is not None and arr.size != count:
        raise ValueError(
            f"{name} must have {count} values (one more than the segments); got {arr.size}"
        )
    if arr.size < 2:
        raise ValueError(f"{name} must have at least 2 values; got {arr.size}")
    steps = np.diff(arr)
    if np.any(steps <= 0):
        i = int(np.argmax(steps <= 0))
        raise ValueError(
            f"{name} must be strictly increasing; {name}[{i}] = {arr[i]} is not < "
            f"{name}[{i + 1}] = {arr[i + 1]}"
        )
    return arr


def check_shape_parameters(
    value: object,
    name: str,
    count: int,
    *,
    positive: bool = False,
) -> np.ndarray:
    """Broadcast one shape parameter (scalar or one per joint) to ``count`` values.

    Parameters
    ----------
    value
        A scalar (global shape parameter) or a sequence of ``count`` values
        (one per joint).
    positive
        Require every value to be > 0 (the rule for β1).

    Raises
    ------
    ValueError
        Naming the joint index of the first offending value.
    """
    arr, scalar = as_parameter_array(value, name)
    if scalar:
        arr = np.full(count, arr[0])
    elif arr.size != count:
        raise ValueError(
            f"{name} must be a scalar or have one value per joint ({count}); got {arr.size}"
        )
    if positive and np.any(arr <= 0):
        j = int(np.argmax(arr <= 0))
        raise ValueError(f"{name} must be > 0 at every joint; at joint {j} it is {arr[j]}")
    return arr
