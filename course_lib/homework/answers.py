"""One reading of students' answers, shared by the feedback checks and the hidden tests.

The same functions read an answer in two places:

* in the student's kernel, inside :mod:`course_lib.homework.checks`, on the live object -- first turned
  into plain data by :func:`plain`, through the very encoding the grader uses
  (:mod:`course_lib.homework.protocol`);
* in the grader, inside the hidden tests (``solutions/hidden_tests/``), on the plain data that
  ``tools/grading/protocol.py`` decoded from the sandbox.

So an answer that a check reads is read the same way by the grader, and the grade never
depends on a form the check accepted.  Accepted forms:

numbers (:func:`number`)
    ``int``, ``float``, numpy scalars, exact sympy numbers, and size-1 arrays/lists
    (``np.array([2.5])``, ``[2.5]``); not ``bool``, strings, NaN or infinity.
arrays (:func:`array`)
    list, tuple, numpy array or sympy matrix of exactly the asked shape; for a vector of
    shape ``(n,)`` also a column or row ``(n, 1)``/``(1, n)``.
multiple choice (:func:`choice`)
    ``"b,d"``, ``"b, d"``, ``"bd"``, ``"(b) and (d)"``, ``["b", "d"]``, upper case; a
    character that is not an option is a *format* problem with a hint, not a wrong choice.
booleans (:func:`boolean`)
    ``True``/``False``, numpy booleans, a size-1 boolean array.
symbolic answers (:func:`evaluate`, :func:`expression_matches`)
    a sympy expression or a string, compared by its values at several points (never by
    parsing text in the grader): the check evaluates the live object with the same code the
    sandbox runs for the grader's ``student.expression(...)``.

Every problem with the *form* of an answer raises :class:`AnswerError` with a message for the
student; a wrong *value* is for the caller to judge.  :class:`AnswerError` subclasses
``AssertionError``, so in a hidden test it costs the question's points with its message as the
note, exactly like a failed ``assert``.

This module knows no expected value and no mathematics of the course: hidden tests may import
it (and only it) from ``course_lib``.

Why this module is long: the readers are one table of normalizers shared by the checks and
the hidden tests; in several modules the two could drift apart.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from course_lib.homework import protocol
from course_lib.homework.protocol import FunctionMarker, SymbolicText

__all__ = [
    "AnswerError",
    "FunctionMarker",
    "SymbolicText",
    "array",
    "boolean",
    "choice",
    "close",
    "describe",
    "evaluate",
    "expression_matches",
    "is_unanswered",
    "items",
    "known_mistake",
    "number",
    "partial_credit",
    "plain",
]


class AnswerError(AssertionError):
    """The answer cannot be read as asked (its form, not its value); the message says why.

    ``unanswered=True`` marks a placeholder (``...``) or a stub; ``exercise=True`` a library
    implementation that is the exercise being checked (``own_work.ExerciseError``).
    """

    def __init__(self, message: str, *, unanswered: bool = False, exercise: bool = False) -> None:
        super().__init__(message)
        self.message = message
        self.unanswered = unanswered
        self.exercise = exercise


NOT_ANSWERED = "not answered yet (replace the ... by your answer)."


def is_unanswered(answer: object) -> bool:
    """True for the placeholders of a blank homework: ``...`` (Ellipsis) anywhere on top."""
    if answer is Ellipsis:
        return True
    return isinstance(answer, (list, tuple)) and bool(answer) and all(a is Ellipsis for a in answer)


def _is_symbolic(value: object) -> bool:
    # decoded data holds no str subclass but this one: a student's object never arrives as is
    return isinstance(value, SymbolicText)


def _is_function(value: object) -> bool:
    return callable(value) and not isinstance(value, (type, np.ndarray))


def describe(value: object) -> str:
    """A short description of an answer's type and shape, for messages."""
    if value is None:
        return "None"
    if _is_symbolic(value):
        return f"a symbolic expression ({str(value)[:60]})"
    if isinstance(value, (bool, np.bool_)):
        return f"a bool ({bool(value)})"
    if isinstance(value, str):
        return f"a string ({value[:40]!r})"
    if isinstance(value, np.ndarray):
        return f"a numpy array of shape {value.shape}"
    if isinstance(value, (list, tuple)):
        return f"a {type(value).__name__} of length {len(value)}"
    if isinstance(value, dict):
        return "a dict"
    if isinstance(value, complex):
        return "a complex number"
    if _is_function(value) or isinstance(value, FunctionMarker):
        return "a function"
    kind = type(value).__name__
    return f"{'an' if kind[:1].lower() in 'aeiou' else 'a'} {kind}"


# ----------------------------------------------------------------- live object -> plain data


def plain(value: object, name: str = "your answer") -> Any:
    """``value`` as the grader receives it: the sandbox's encoding, decoded.

    Numbers become ``int``/``float``/``complex``, tuples and sympy matrices lists, numeric
    arrays float/int/bool arrays, symbolic expressions :class:`SymbolicText`, functions
    :class:`FunctionMarker`.  What cannot cross to the grader (an unknown type, a huge
    answer) raises :class:`AnswerError` here already, so the check fails it as the grader would.
    """
    if is_unanswered(value):
        raise AnswerError(NOT_ANSWERED, unanswered=True)
    try:
        encoded = protocol.encode(value)
        text = json.dumps(encoded, allow_nan=False)
    except protocol.Unsupported as exc:
        raise AnswerError(f"{name}: {exc} -- use numbers, lists or numpy arrays.") from None
    except Exception as exc:
        raise AnswerError(f"{name} cannot be read as data ({type(exc).__name__}).") from None
    try:
        return protocol.decode(json.loads(text))  # the grader's own (strict) decoder
    except protocol.Malformed as exc:
        raise AnswerError(f"{name} cannot be read as data ({exc}).") from None


# ----------------------------------------------------------------- numbers and arrays


def _not_missing(value: object, name: str) -> None:
    if is_unanswered(value):
        raise AnswerError(NOT_ANSWERED, unanswered=True)
    if value is None:
        raise AnswerError(f"{name} is None -- did a function forget to `return`?")


def _real_array(value: object, name: str, what: str) -> np.ndarray:
    """Lists / arrays of real numbers (no bools, strings, symbols, complex) as a float array."""
    if isinstance(value, np.ndarray) and value.dtype.kind in "iuf":
        return value.astype(float)
    if isinstance(value, np.ndarray) and value.dtype.kind == "b":
        raise AnswerError(f"{what} is expected, but {name} holds booleans (True/False).")

    def check(x):
        if isinstance(x, (list, tuple)):
            for y in x:
                check(y)
        elif isinstance(x, np.ndarray):
            if x.dtype.kind == "O":
                for y in x.ravel().tolist():
                    check(y)
            elif x.dtype.kind not in "iuf":
                raise AnswerError(f"{name} contains {describe(x)}; real numbers are expected.")
        elif isinstance(x, (bool, np.bool_)) or not isinstance(
            x, (int, float, np.integer, np.floating)
        ):
            if isinstance(x, complex) or _is_symbolic(x):
                raise AnswerError(
                    f"{name} contains {describe(x)}; real numbers are expected "
                    "(substitute the values, or call float())."
                )
            raise AnswerError(f"{name} contains {describe(x)}; only numbers are expected.")

    check(value)
    try:
        return np.asarray(value.tolist() if isinstance(value, np.ndarray) else value, dtype=float)
    except (TypeError, ValueError):
        raise AnswerError(
            f"{name} ({describe(value)}) cannot be read as an array of numbers "
            "(rows of different lengths?)."
        ) from None


def _finite(arr: np.ndarray, name: str) -> None:
    if np.isnan(arr).any():
        raise AnswerError(f"{name} contains NaN -- a 0/0 somewhere (a zero-length vector?).")
    if np.isinf(arr).any():
        raise AnswerError(f"{name} contains inf -- a division by zero somewhere?")


def number(value: object, name: str = "your answer", hint: str = "") -> float:
    """A real number: int, float, numpy scalar, exact sympy number, or a size-1 array/list.

    ``hint`` is added to the message when several numbers were given (e.g. what ``quad``
    returns).
    """
    _not_missing(value, name)
    if isinstance(value, (bool, np.bool_)):
        raise AnswerError(f"{name} is a bool ({bool(value)}); a number is expected here.")
    if _is_symbolic(value):
        raise AnswerError(
            f"a number is expected, but {name} is {describe(value)}; "
            "substitute the values or call float()."
        )
    if isinstance(value, str):
        raise AnswerError(
            f"a number is expected, but {name} is {describe(value)}; write it without quotes."
        )
    if isinstance(value, complex):
        raise AnswerError(f"a real number is expected, but {name} is complex.")
    if isinstance(value, (list, tuple, np.ndarray)):
        arr = _real_array(value, name, "a number")
        if arr.size != 1:
            more = f" ({hint})" if hint else ""
            raise AnswerError(
                f"a single number is expected, but {name} has {arr.size} entries{more}."
            )
        value = float(arr.reshape(()))
    if not isinstance(value, (int, float, np.integer, np.floating)):
        raise AnswerError(f"a number is expected here, but {name} is {describe(value)}.")
    try:
        x = float(value)
    except OverflowError:
        raise AnswerError(f"{name} is too large.") from None
    _finite(np.array([x]), name)
    return x


def array(
    value: object,
    shape: Sequence[int],
    name: str = "your answer",
    what: str = "an array",
) -> np.ndarray:
    """Real numbers of exactly ``shape`` (list, tuple or array; a vector also as a column/row)."""
    shape = tuple(int(n) for n in shape)
    if shape == ():
        return np.array(number(value, name))
    _not_missing(value, name)
    if (
        isinstance(value, (str, dict, bool, np.bool_, complex, int, float))
        or _is_function(value)
        or isinstance(value, FunctionMarker)
    ):
        raise AnswerError(f"{what} of shape {shape} is expected, but {name} is {describe(value)}.")
    arr = _real_array(value, name, what)
    if arr.shape != shape:
        n = int(np.prod(shape))
        if len(shape) == 1 and arr.size == n and sum(k != 1 for k in arr.shape) <= 1:
            arr = arr.reshape(shape)  # a column or row vector
        else:
            hint = (
                f" (it has the right number of entries: reshape it to {shape})"
                if arr.size == n > 0
                else ""
            )
            raise AnswerError(
                f"{what} of shape {shape} is expected; {name} has shape {arr.shape}{hint}."
            )
    _finite(arr, name)
    return arr


def items(value: object, n: int, name: str = "your answer", what: str = "items") -> list:
    """The ``n`` items of a list, tuple or array (along its first axis)."""
    _not_missing(value, name)
    if isinstance(value, np.ndarray) and value.ndim >= 1 and value.shape[0] == n:
        return [value[k] for k in range(n)]
    if isinstance(value, (list, tuple)) and len(value) == n:
        return list(value)
    raise AnswerError(f"{name} must be a list of {n} {what}; it is {describe(value)}.")


def boolean(value: object, name: str = "your answer") -> bool:
    """``True`` or ``False`` (also numpy booleans and size-1 boolean arrays)."""
    _not_missing(value, name)
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, np.ndarray) and value.dtype.kind == "b" and value.size == 1:
        return bool(value.reshape(()))
    raise AnswerError(f"{name} must be True or False; it is {describe(value)}.")


# ----------------------------------------------------------------- multiple choice

_SEPARATORS = re.compile(r"[\s,;/()\[\]{}.:&+'\"-]")


def choice(value: object, options: str, name: str = "your answer", *, single: bool = False) -> str:
    """The letters chosen, canonical: sorted, lower case, comma-separated (``"b,d"``).

    Accepts ``"b,d"``, ``"b d"``, ``"bd"``, ``"(b) and (d)"``, ``["b", "d"]``, ``("B",)``.
    ``options`` are the letters of the question (``"abcd"``).  A character that is not an option
    raises :class:`AnswerError` with a format hint; so do several letters when ``single``.
    """
    opts = options.lower()
    example = f"'{opts[1] if len(opts) > 1 else opts[0]}'" + (
        "" if single else f" or '{opts[0]}, {opts[-1]}'"
    )
    _not_missing(value, name)
    if isinstance(value, str):
        parts = [str(value)]
    elif isinstance(value, (list, tuple)) and all(isinstance(p, str) for p in value):
        parts = [str(p) for p in value]
    else:
        raise AnswerError(
            f"give the letter(s) of your choice as a string, e.g. {example}; {name} is {describe(value)}."
        )
    letters: set[str] = set()
    for part in parts:
        text = _SEPARATORS.sub("", re.sub(r"\band\b", " ", part.lower()))
        for ch in text:
            if ch not in opts:
                raise AnswerError(
                    f"{ch!r} is not one of the options ({', '.join(opts)}): answer with "
                    f"{'the letter' if single else 'letters'} only, e.g. {example}."
                )
            letters.add(ch)
    if not letters:
        raise AnswerError(f"no letter found in {name}: answer e.g. {example}.")
    if single and len(letters) > 1:
        raise AnswerError(f"choose one letter only (you gave {len(letters)}).")
    return ",".join(sorted(letters))


# ----------------------------------------------------------------- symbolic answers


def _decode_number(v: Any) -> complex:
    try:
        z = protocol.decode_number(v)
    except protocol.Malformed:
        z = None
    if isinstance(z, bool) or not isinstance(z, (int, float, complex)):
        raise AnswerError("the expression's values could not be read")
    return complex(z)


def evaluate(
    value: object, symbols: Sequence[str], points, name: str = "your answer"
) -> tuple[list[str], list[complex] | None]:
    """A live symbolic answer's free symbol names and its values at ``points``.

    The same computation as the grader's ``student.expression(name, symbols, points)``: the
    sandbox runs this very code (``course_lib.homework.protocol``) on the student's object.  ``values``
    is ``None`` when the answer has symbols outside ``symbols``.
    """
    _not_missing(value, name)
    from course_lib.homework import protocol

    pts = [[float(x) for x in p] for p in np.atleast_2d(np.asarray(points, dtype=float))]
    try:
        raw = protocol.evaluate_expression(value, [str(s) for s in symbols], pts)
        raw = json.loads(json.dumps(raw, allow_nan=False))
    except protocol.Unsupported as exc:
        raise AnswerError(str(exc)) from None
    values = raw["values"]
    return list(raw["symbols"]), None if values is None else [_decode_number(v) for v in values]


def expression_matches(
    free: Sequence[str],
    values: Sequence[complex] | None,
    expected: Sequence[float],
    symbols: Sequence[str],
    name: str = "your answer",
    rtol: float = 1e-9,
) -> bool:
    """Whether a symbolic answer's ``values`` (from :func:`evaluate` or ``student.expression``)
    equal ``expected`` at every point.

    Raises :class:`AnswerError` for symbols outside ``symbols`` or values that are not finite.
    """
    stray = sorted(set(free) - set(symbols))
    if stray or values is None:
        raise AnswerError(
            f"use only the symbols {', '.join(symbols)}; {name} contains {', '.join(stray) or '?'}."
        )
    vals = [complex(v) for v in values]
    if len(vals) != len(expected):
        raise AnswerError("the expression's values could not be read")
    if not all(math.isfinite(v.real) and math.isfinite(v.imag) for v in vals):
        raise AnswerError(f"{name} is not finite at some admissible values -- a division by zero?")
    return all(abs(v - e) <= rtol * max(abs(e), 1.0) for v, e in zip(vals, expected, strict=True))


# ----------------------------------------------------------------- comparing and scoring


def close(a: object, b: object, tol: float = 1e-9) -> bool:
    """``a`` equals the expected ``b`` up to ``tol``, relative to the size of ``b`` (at least 1).

    The one tolerance rule of the checks and the hidden tests, so that they agree on near misses.
    """
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return False
    scale = max(1.0, float(np.abs(b).max(initial=0.0)))
    return bool(np.allclose(a, b, rtol=tol, atol=tol * scale))


def known_mistake(value: object, known: Sequence, words: Mapping[str, str], note: str) -> str:
    """``note``, followed by the words of the first known mistake ``value`` is (``known``: the
    ``(tag, value)`` pairs of a hidden test's ``key_values``; the tag ``"right"`` is skipped),
    so the grade's feedback names the mistake the check named."""
    for tag, mistake in known:
        if tag != "right" and close(value, mistake, tol=1e-6):
            return f"{note}: {words[tag]}"
    return note


def partial_credit(cases: Sequence) -> tuple[float, str]:
    """Score a question case by case: each case is a function that returns ``None`` if the
    answer is right for it and raises ``AssertionError(note)`` (e.g. :class:`AnswerError`) if not.

    Returns ``(fraction of cases right, the notes joined)``, the form a hidden test returns.
    Anything else a case raises (the student's function raised, the answer is missing) is not
    caught: it costs the whole question, with the grader's note.
    """
    good, notes = 0, []
    for case in cases:
        try:
            case()
        except AssertionError as exc:
            notes.append(str(exc).rstrip(". ") or "wrong")
            continue
        good += 1
    return good / len(cases), "; ".join(dict.fromkeys(notes))


# ----------------------------------------------------------------- a notebook on one's own data
NOT_OWN_DATA = (
    "not graded: this notebook was not done on your own data (its DATA is another variant's: "
    "is VARIANT another student's code, or empty?); the functions and the symbolic answers, the "
    "same for everyone, earn points only in a notebook done on your own data"
)


def _canonical(value: Any) -> Any:
    """Plain nested lists, dicts, strings and floats: the form DATA crosses the boundary in."""
    if isinstance(value, dict):
        return {str(k): _canonical(v) for k, v in value.items()}
    if isinstance(value, np.ndarray):
        return _canonical(value.tolist())
    if isinstance(value, (list, tuple)):
        return [_canonical(v) for v in value]
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, float, np.integer, np.floating)):
        return float(value)
    return value


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b, strict=True))
    if isinstance(a, float) and isinstance(b, float):
        return math.isclose(a, b, rel_tol=1e-12, abs_tol=1e-300)
    return type(a) is type(b) and a == b


def require_own_data(notebook_data, data: dict, homework: str) -> None:
    """Raise :class:`AnswerError` unless a notebook graded on a variant was done on that variant.

    For the hidden tests of the questions that are the same for everyone (functions, symbolic
    answers): a friend's notebook, done with the friend's variant code, answers them just as well,
    so they earn points only where the notebook's ``DATA`` is the student's own ``data``
    (issue 24: a copied notebook is worth little).  ``notebook_data`` is a function fetching the
    notebook's ``DATA`` (``lambda: student["DATA"]``): it is called only when ``data`` is not the
    default variant's, so grading without a course secret, and notebooks done on the example
    data, are unaffected.
    """
    from course_lib.homework import variants

    default = variants.generators()[homework](None)
    if _same(_canonical(data), _canonical(default)):
        return
    if not _same(_canonical(notebook_data()), _canonical(data)):
        raise AnswerError(NOT_OWN_DATA)
