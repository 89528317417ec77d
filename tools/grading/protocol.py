"""The grader's side of the grading boundary: untrusted answers in, validated plain data out.

Hidden tests run here, in the grader process, never in the student's kernel.  A hidden test
is a function ``qN(student)`` of the hidden-test module; ``student`` is a :class:`Student`:

``student["answer_q1"]``
    the value of a name in the student's notebook, as plain data: ``None``, ``bool``,
    ``int``, ``float``, ``complex``, ``str``, ``list``, ``dict`` (string keys) and
    ``numpy.ndarray`` (numeric; built here from validated lists).  A callable comes back as a
    :class:`RemoteFunction`.
``student.function("is_g1")(q, r)``
    calls the student's function *in the sandbox* on the arguments given here (numbers,
    lists, arrays) and returns its result as plain data.
``student.expression("answer_q4", symbols, points)``
    a symbolic answer (sympy expression or string) evaluated at points chosen here; returns
    ``(free_symbol_names, values)``.  The grader never parses student text with ``sympify``
    (which uses ``eval``): the sandbox evaluates, the grader compares numbers.

A hidden test returns ``None`` (full points), a fraction, or ``(fraction, note)``, or raises
``AssertionError(note)`` (no points).  :func:`run_question` turns any outcome -- a missing name,
an unanswered ``...``, a function that raises, a malformed answer, a broken channel -- into a
clamped fraction and a note; it never raises for anything the student did.

The transport is a function ``request dict -> response text``: :class:`LocalStudent` answers
in-process from a namespace (the feedback checks' equivalence tests use it), the grader's
kernel transport answers from a sandboxed kernel.  Both go through the same JSON encoding of
``course_lib.homework.protocol``, so a value reaches a hidden test in exactly the same form either way.
"""

from __future__ import annotations

import builtins
import json
import math
from collections.abc import Callable
from typing import Any

import numpy as np

from course_lib.homework import protocol as _probe

MAX_RESPONSE_BYTES = 4_000_000
MAX_DEPTH = 10

__all__ = [
    "BadAnswer",
    "ChannelBroken",
    "LocalStudent",
    "MissingAnswer",
    "NotAnswered",
    "RemoteFunction",
    "Student",
    "StudentRaised",
    "decode_value",
    "encode_arguments",
    "parse_response",
    "run_question",
]


class MissingAnswer(Exception):
    """The name is not defined in the notebook."""


class NotAnswered(Exception):
    """The name still holds ``...`` or the function still raises NotImplementedError."""


#: exception types a note may name: Python's own and a few of numpy/sympy/the course -- a
#: class a student defines could carry data in its name
_KNOWN_EXCEPTIONS = frozenset(
    name
    for name, value in vars(builtins).items()
    if isinstance(value, type) and issubclass(value, BaseException)
) | {"LinAlgError", "ExerciseError", "SympifyError", "PolificationFailed"}
_RECURSION = "RecursionError: the code recursed without end"


def raised_note(message: str) -> str:
    """What a feedback note may say of an exception raised by student code: its type only.

    The message of an exception is the student's text -- a function can raise
    ``ValueError(f"{inputs}")`` and read the hidden cases' inputs in its feedback -- so it is
    dropped.  Kept is the probe's note on endless recursion.  The own-work sentence never comes
    this way: it is the response kind ``exercise`` (:func:`exercise_note`).
    """
    text = str(message).strip()
    if text == _RECURSION:
        return text
    name = text.split(":", 1)[0].strip()
    if name in _KNOWN_EXCEPTIONS:
        return f"{name} (the message is not shown: run your function on your own data to see it)"
    return "an exception (run your function on your own data to see it)"


def exercise_note(response: dict) -> str:
    """The note for a response of kind ``exercise`` (:class:`course_lib.homework.own_work.ExerciseError`).

    The sentence is written here, by :mod:`course_lib.homework.own_work`, from the response's
    ``question`` and ``implementation`` -- only when that implementation really is that
    question's exercise in the registry; the response's text is never shown.
    """
    from course_lib.homework import own_work  # the registry the fields must name

    question, implementation = response.get("question"), response.get("implementation")
    if isinstance(question, str) and isinstance(implementation, str):
        # a value implementation names every question of its homework it computes ("hw03.q1,
        # hw03.q3 and hw03.q5"): each must list it
        named = question.replace(" and ", ", ").split(", ")
        rows = [own_work.EXERCISES.get(q) or own_work.VALUE_EXERCISES.get(q) for q in named]
        if all(row is not None and implementation in row.implementations for row in rows):
            if response.get("switched_off") is True:
                return own_work.switched_off_message(implementation, question)
            return own_work.exercise_message(implementation, question)
    return raised_note("ExerciseError")


class StudentRaised(AssertionError):
    """The student's function raised an exception (its message is the note).

    An ``AssertionError`` so that a hidden test scoring case by case
    (``course_lib.homework.answers.partial_credit``) charges it to that case only.
    """

    def __init__(self, note: str = "", *, exercise: bool = False) -> None:
        if note:
            super().__init__(note)
        else:
            super().__init__()
        #: a library implementation of the exercise raised (own_work.ExerciseError)
        self.exercise = exercise

    def __str__(self) -> str:
        return f"your code raised {self.args[0] if self.args else 'an exception'}"


class BadAnswer(AssertionError):
    """The answer cannot be used: unsupported type, too large, malformed.

    An ``AssertionError`` for the same reason as :class:`StudentRaised`.
    """


class ChannelBroken(Exception):
    """No valid response came back (the kernel died, timed out, or wrote garbage)."""


# ---------------------------------------------------------------- decoding untrusted data


def decode_value(obj: Any, depth: int = 0, student: Student | None = None) -> Any:
    """Validate and decode one encoded value (``course_lib.homework.protocol.decode``, strict)."""
    try:
        return _probe.decode(obj, depth)
    except _probe.Malformed as exc:
        raise BadAnswer(str(exc)) from None


def _decode_scalar_number(obj: Any) -> Any:
    try:
        return _probe.decode_number(obj)
    except _probe.Malformed as exc:
        raise BadAnswer(str(exc)) from None


def parse_response(text: str | bytes | None) -> Any:
    """Validate a response; return its decoded value or raise the matching exception."""
    if text is None:
        raise ChannelBroken("no result came back from the notebook")
    if isinstance(text, bytes):
        if len(text) > MAX_RESPONSE_BYTES:
            raise BadAnswer("the answer is too large")
        try:
            text = text.decode("utf-8")
        except UnicodeDecodeError:
            raise ChannelBroken("the result could not be read") from None
    if len(text) > MAX_RESPONSE_BYTES:
        raise BadAnswer("the answer is too large")

    def reject_constant(name):
        raise ValueError(name)

    try:
        response = json.loads(text, parse_constant=reject_constant)
    except (ValueError, RecursionError):
        raise ChannelBroken("the result could not be read") from None
    if not isinstance(response, dict) or not isinstance(response.get("ok"), bool):
        raise ChannelBroken("the result could not be read")
    if response["ok"]:
        if "value" not in response:
            raise ChannelBroken("the result could not be read")
        return response["value"]
    raise _error_of(response)


def _error_of(response: dict) -> Exception:
    """The exception a failed response stands for (its ``error`` kind and ``message``)."""
    kind = response.get("error")
    message = str(response.get("message", ""))[:300]
    if kind == "missing":
        return MissingAnswer(message)
    if kind == "ellipsis":
        return NotAnswered(message)
    if kind == "not_implemented":
        return NotAnswered("the function still raises NotImplementedError")
    if kind == "raised":
        return StudentRaised(raised_note(message))
    if kind == "exercise":
        return StudentRaised(exercise_note(response), exercise=True)
    if kind == "unsupported":
        return BadAnswer(message)
    return ChannelBroken("the result could not be read")


# ---------------------------------------------------------------- encoding grader data


def encode_arguments(value: Any) -> Any:
    """Encode the grader's own inputs for a call (trusted data: numbers, lists, arrays)."""
    if isinstance(value, np.ndarray):
        if value.dtype.kind not in "biuf":
            raise TypeError("only real numeric arrays can be sent to a student's function")
        data = value.astype(float).tolist()
        return {"__ndarray__": data, "dtype": "float"}
    if isinstance(value, (list, tuple)):
        return [encode_arguments(v) for v in value]
    if isinstance(value, dict):
        return {"__dict__": {str(k): encode_arguments(v) for k, v in value.items()}}
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        x = float(value)
        return x if math.isfinite(x) else {"__float__": repr(x)}
    if value is None or isinstance(value, str):
        return value
    raise TypeError(f"cannot send a {type(value).__name__} to a student's function")


# ---------------------------------------------------------------- the student proxy

Transport = Callable[[dict], "str | bytes | None"]


class RemoteFunction:
    """The student's function, called where the student's code runs."""

    def __init__(self, student: Student, name: str) -> None:
        self._student = student
        self.name = name

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        request = {
            "op": "call",
            "name": self.name,
            "args": encode_arguments(list(args)),
            "kwargs": {k: encode_arguments(v) for k, v in kwargs.items()},
        }
        return self._student._value(request)

    def __repr__(self) -> str:
        return f"<student function {self.name}>"


class Student:
    """What a hidden test sees of a submission: plain data, fetched through a transport."""

    def __init__(self, transport: Transport) -> None:
        self._transport = transport

    def _value(self, request: dict) -> Any:
        raw = parse_response(self._transport(request))
        value = decode_value(raw, student=self)
        return self._bind(value)

    def _bind(self, value: Any) -> Any:
        if isinstance(value, _probe.FunctionMarker):
            return RemoteFunction(self, value.name)
        return value

    def __getitem__(self, name: str) -> Any:
        value = self._value({"op": "get", "name": name})
        if isinstance(value, RemoteFunction):
            value.name = name  # call it by the notebook's name, not its __name__
        return value

    def function(self, name: str) -> RemoteFunction:
        value = self[name]
        if not isinstance(value, RemoteFunction):
            raise BadAnswer(f"`{name}` must be a function (def {name}(...): ...)")
        return value

    def expression(self, name: str, symbols: list[str], points) -> tuple[list[str], list | None]:
        """Free symbol names of a symbolic answer and its values at ``points``."""
        pts = [[float(x) for x in p] for p in np.atleast_2d(np.asarray(points, dtype=float))]
        raw = parse_response(
            self._transport({"op": "expr", "name": name, "symbols": list(symbols), "points": pts})
        )
        if not (isinstance(raw, dict) and set(raw) == {"symbols", "values"}):
            raise ChannelBroken("the result could not be read")
        names = raw["symbols"]
        if not (isinstance(names, list) and all(isinstance(s, str) for s in names)):
            raise ChannelBroken("the result could not be read")
        values = raw["values"]
        if values is None:
            return [s[:100] for s in names], None
        if not (isinstance(values, list) and len(values) == len(pts)):
            raise ChannelBroken("the result could not be read")
        return [s[:100] for s in names], [_decode_scalar_number(v) for v in values]


class LocalStudent(Student):
    """A :class:`Student` answered in-process from a namespace, through the same JSON encoding.

    For tests of the hidden tests and of the feedback checks; never for grading real
    submissions (their code must run in the sandbox).
    """

    def __init__(self, namespace: dict) -> None:
        from course_lib.homework import protocol as _probe

        def transport(request: dict) -> str:
            response = _probe.handle(json.loads(json.dumps(request)), namespace)
            return json.dumps(response, allow_nan=False)

        super().__init__(transport)


# ---------------------------------------------------------------- one question


def run_question(test: Callable[[Student], Any], student: Student) -> tuple[float, str]:
    """Run one hidden test; return ``(fraction in [0, 1], note)``.  Never raises."""
    fraction, note = 0.0, ""
    try:
        result = test(student)
        if result is None:
            fraction = 1.0
        elif isinstance(result, tuple):
            fraction, note = float(result[0]), str(result[1])
        else:
            fraction = float(result)
    except MissingAnswer as exc:
        note = (
            f"`{exc.args[0] if exc.args else '?'}` is not defined in the notebook "
            "(deleted, renamed, or its cell was not run / failed)"
        )
    except NotAnswered as exc:
        what = str(exc.args[0]) if exc.args else ""
        note = (
            "not answered (the function still raises NotImplementedError)"
            if "NotImplementedError" in what
            else f"not answered (`{what}` is still ...)"
        )
    except StudentRaised as exc:
        note = f"your code raised {exc.args[0] if exc.args else 'an exception'}"
    except BadAnswer as exc:
        note = str(exc) or "the answer cannot be used"
    except ChannelBroken as exc:
        note = f"no result: {exc}"
    except AssertionError as exc:
        note = str(exc) or "wrong answer"
    except Exception as exc:  # a hidden test tripping over a malformed answer: no points
        note = f"the answer could not be checked ({type(exc).__name__}: {str(exc)[:200]})"
    if not (isinstance(fraction, float) and math.isfinite(fraction)):
        fraction = 0.0
    return min(max(fraction, 0.0), 1.0), note[:500]
