"""The machinery behind :mod:`course_lib.homework.checks`: verdicts, the registry, safe answer handling.

Everything here turns a student's answer -- whatever it is -- into a :class:`Verdict`.
Nothing in this module ever lets an exception escape to the notebook: a check that
meets an answer it cannot read says so in words.
"""

from __future__ import annotations

import hashlib
import html
import signal
import sys
import threading
from collections.abc import Callable, Mapping
from contextlib import contextmanager
from dataclasses import dataclass, field

import numpy as np

from course_lib.homework import answers, own_work
from course_lib.homework.checks.keyed import Unchecked

__all__ = [
    "AnswerProblem",
    "Question",
    "Report",
    "Verdict",
    "answer_hash",
    "as_choice",
    "as_number",
    "as_vector",
    "call_answer",
    "fail",
    "is_unanswered",
    "ok",
    "refuse_if_traced",
    "register",
    "registry",
    "values_digest",
]

#: Seconds a student's function may run inside a feedback check before we give up.
FUNCTION_TIME_LIMIT = 5.0

PASS, FAIL, UNANSWERED = "passed", "failed", "not answered"
#: a value whose form is right but which this copy of the course has no answer key for
UNCHECKED = "not checked here"


@dataclass(frozen=True)
class Verdict:
    """The outcome of one check: ``passed`` and a message in the terms of the course.

    ``status`` is ``"passed"``, ``"failed"``, ``"not answered"`` or ``"not checked here"`` (a
    value the edition holds no answer key for: only the grader checks it).  A verdict is truthy
    exactly when it passed, so ``assert check(...)`` works in solution notebooks.
    """

    question: str
    passed: bool
    message: str
    status: str = FAIL

    def __bool__(self) -> bool:
        return self.passed

    @property
    def answered(self) -> bool:
        return self.status != UNANSWERED

    def _symbol(self) -> str:
        return {PASS: "✓", UNANSWERED: "…", UNCHECKED: "?"}.get(self.status, "✗")

    def _words(self) -> str:
        """What the symbol means, in words (a screen reader may skip "✗"; WCAG 1.1.1)."""
        words = {PASS: "", UNANSWERED: "", UNCHECKED: " (value not checked here)"}
        return words.get(self.status, " (not right yet)")

    def __str__(self) -> str:
        return f"{self._symbol()} {self.question}{self._words()}: {self.message}"

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        colour = {PASS: "#1b7f3b", UNANSWERED: "#8a6d00", UNCHECKED: "#1f4e8c"}.get(self.status, "#b00020")
        back = {PASS: "#e8f5ec", UNANSWERED: "#fff8e1", UNCHECKED: "#eaf1fb"}.get(self.status, "#fdecee")
        return (
            f'<div class="cl-verdict cl-verdict-{self.status.replace(" ", "-")}" '
            f'style="border-left:4px solid {colour};background:{back};padding:4px 8px;'
            f'margin:2px 0;font-family:sans-serif">'
            f'<b style="color:{colour}">{self._symbol()} {html.escape(self.question)}'
            f"{html.escape(self._words())}</b>: "
            f"{html.escape(self.message)}</div>"
        )


@dataclass(frozen=True)
class Report:
    """The verdicts of every question of one homework (see :func:`check_all`)."""

    homework: str
    verdicts: tuple[Verdict, ...] = field(default_factory=tuple)
    notes: tuple[str, ...] = ()  # what the student should know beyond the verdicts

    @property
    def all_passed(self) -> bool:
        return bool(self.verdicts) and all(v.passed for v in self.verdicts)

    @property
    def n_passed(self) -> int:
        return sum(v.passed for v in self.verdicts)

    def __bool__(self) -> bool:
        return self.all_passed

    def _summary(self) -> str:
        text = f"{self.homework}: {self.n_passed} of {len(self.verdicts)} checks passed"
        unchecked = sum(v.status == UNCHECKED for v in self.verdicts)
        return text + (f", {unchecked} not checked here (no answer key for your data)" if unchecked else "")

    def __str__(self) -> str:
        notes = [f"  ⚠ {n}" for n in self.notes]
        return "\n".join([self._summary(), *notes, *(f"  {v}" for v in self.verdicts)])

    def __repr__(self) -> str:
        return str(self)

    def _repr_html_(self) -> str:
        rows = "".join(v._repr_html_() for v in self.verdicts)
        notes = "".join(f"<p>⚠ {html.escape(n)}</p>" for n in self.notes)
        return (
            f'<div class="cl-check-report"><p><b>{html.escape(self._summary())}</b></p>'
            f"{notes}{rows}</div>"
        )


#: Raised inside a check to turn a malformed answer into a failed verdict (``unanswered=True``
#: marks a placeholder).  The same class the hidden tests' normalizers raise.
AnswerProblem = answers.AnswerError


def ok(message: str = "correct.") -> tuple[bool, str]:
    return True, message


def fail(message: str) -> tuple[bool, str]:
    return False, message


# --------------------------------------------------------------------------- registry
@dataclass(frozen=True)
class Question:
    """A registered question: its id, the notebook name of its answer, and its check.

    ``validate(answer)`` returns ``(passed, message)`` or raises :class:`AnswerProblem`;
    any other exception is a bug in the check and is reported as such, never raised.
    """

    qid: str
    answer_name: str
    validate: Callable[[object], tuple[bool, str]]
    title: str = ""


_REGISTRY: dict[str, Question] = {}


def register(qid: str, answer_name: str, title: str = ""):
    """Decorator: register ``validate`` as the check of question ``qid``."""

    def deco(validate: Callable[[object], tuple[bool, str]]):
        _REGISTRY[qid] = Question(qid, answer_name, validate, title)
        return validate

    return deco


def registry() -> Mapping[str, Question]:
    return dict(_REGISTRY)


# --------------------------------------------------------------------------- answers
is_unanswered = answers.is_unanswered

#: What a check says when a tracer or profiler runs: it would see the values the check computes
#: from the student's data (issue 27 §8), so the check computes nothing.
TRACED = (
    "the checks do not run under a tracer, profiler or debugger (sys.settrace, sys.setprofile, "
    "%prun, pdb): run the cell without it."
)
_gettrace, _getprofile = sys.gettrace, sys.getprofile


def refuse_if_traced() -> None:
    """Raise :class:`AnswerProblem` if a trace or profile function is set on this thread.

    Every reader of an answer calls it after reading (the answer's own code may have set one),
    :func:`call_answer` after the student's function returns, and :func:`run_validate` before a
    check starts, so nothing a check derives from the question's data runs while traced.
    """
    if _gettrace() is not None or _getprofile() is not None:
        raise AnswerProblem(TRACED)


def _describe(answer: object) -> str:
    return answers.describe(answer)


def _exception_text(exc: BaseException) -> str:
    msg = str(exc).strip()
    return f"{type(exc).__name__}: {msg}" if msg else type(exc).__name__


def as_number(answer: object, name: str = "your answer", hint: str = "") -> float:
    """Read a real number as the grader reads it (:func:`course_lib.homework.answers.number`)."""
    value = answers.number(answers.plain(answer, name), name, hint)
    refuse_if_traced()
    return value


def as_vector(
    answer: object,
    shape: tuple[int, ...],
    name: str = "your answer",
    what: str = "an array",
) -> np.ndarray:
    """Read an array of ``shape`` as the grader reads it (:func:`course_lib.homework.answers.array`)."""
    value = answers.array(answers.plain(answer, name), shape, name, what)
    refuse_if_traced()
    return value


class _TimeLimit(Exception):
    pass


@contextmanager
def _time_limit(seconds: float):
    """Raise :class:`_TimeLimit` after ``seconds`` (main thread on POSIX only; else no limit)."""
    usable = hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    if not usable:
        yield
        return

    def handler(signum, frame):
        raise _TimeLimit

    old = signal.signal(signal.SIGALRM, handler)
    previous = signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)
        if previous[0] > 0:  # someone else's timer was running: restore it
            signal.setitimer(signal.ITIMER_REAL, *previous)


def call_answer(func: object, *args, name: str = "your function", **kwargs) -> object:
    """Call a student's function; turn a stub, an exception or a hang into :class:`AnswerProblem`."""
    if is_unanswered(func):
        raise AnswerProblem("not answered yet (write the function).", unanswered=True)
    if func is None:
        raise AnswerProblem(f"{name} is None; a function is expected (def ...).")
    if not callable(func):
        raise AnswerProblem(f"a function is expected, but {name} is {_describe(func)}.")
    try:
        with _time_limit(FUNCTION_TIME_LIMIT):
            # the library's implementations of this exercise raise while it runs (own_work)
            result = own_work.run_exercise(own_work.questions_of(name), func, *args, **kwargs)
    except own_work.ExerciseError as exc:  # the exercise: carried as a flag, not as words
        raise AnswerProblem(f"{exc}.", exercise=True) from None
    except NotImplementedError:
        raise AnswerProblem(
            "not answered yet (the function still raises NotImplementedError).", unanswered=True
        ) from None
    except _TimeLimit:
        raise AnswerProblem(
            f"{name} did not return within {FUNCTION_TIME_LIMIT:g} s -- an endless loop?"
        ) from None
    except RecursionError:
        raise AnswerProblem(f"{name} recursed without end (RecursionError).") from None
    except Exception as exc:
        raise AnswerProblem(f"{name} raised {_exception_text(exc)}") from None
    refuse_if_traced()  # the function may have left a tracer behind
    if result is Ellipsis:
        raise AnswerProblem(f"not answered yet ({name} returns ...).", unanswered=True)
    if result is None:
        raise AnswerProblem(
            f"not answered yet, or a missing `return`: {name} returns None.", unanswered=True
        )
    return result


# --------------------------------------------------------------------------- hashing
def _normalize_choice(answer: object) -> str:
    """Canonical text of a multiple-choice answer: case, spaces and order do not matter."""
    if isinstance(answer, str):
        parts = [p for p in answer.replace(",", " ").replace(";", " ").split() if p]
        if len(parts) > 1:
            answer = parts
        else:
            return answer.strip().lower()
    if isinstance(answer, (list, tuple, set, frozenset)):
        items = sorted(str(a).strip().lower() for a in answer)
        return ",".join(items)
    if isinstance(answer, (bool, np.bool_)):
        return str(bool(answer)).lower()
    if isinstance(answer, (int, np.integer)):
        return str(int(answer))
    return str(answer).strip().lower()


def answer_hash(answer: object, salt: str = "") -> str:
    """SHA-256 (first 16 hex digits) of the canonical form of a choice answer.

    ``salt`` is normally the question id, so equal answers to different questions
    hash differently.  Use it to make the ``correct_hash`` of :func:`check_choice`.
    """
    text = f"{salt}|{_normalize_choice(answer)}"
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def run_validate(qid: str, validate: Callable[[object], tuple[bool, str]], answer: object) -> Verdict:
    """Apply ``validate`` to ``answer`` and wrap the outcome in a :class:`Verdict`; never raises."""
    try:
        refuse_if_traced()
        passed, message = validate(answer)
    except Unchecked as exc:
        return Verdict(qid, False, str(exc), UNCHECKED)
    except AnswerProblem as p:
        status = UNANSWERED if p.unanswered else FAIL
        return Verdict(qid, False, p.message, status)
    except Exception as exc:  # a check must never show a traceback
        return Verdict(
            qid,
            False,
            f"the check could not read your answer ({_exception_text(exc)}); "
            "look at its type and shape.",
            FAIL,
        )
    return Verdict(qid, bool(passed), message, PASS if passed else FAIL)


def as_choice(answer: object, options: str, name: str = "your answer", *, single: bool = False) -> str:
    """The canonical letters of a multiple-choice answer, as the grader reads them."""
    value = answers.choice(answers.plain(answer, name), options, name, single=single)
    refuse_if_traced()
    return value


def register_choice(
    qid: str,
    answer_name: str,
    correct_hash: str,
    title: str = "",
    *,
    options: str,
    single: bool = False,
) -> None:
    """Register a multiple-choice question checked against ``answer_hash(right, salt=qid)``.

    ``options`` are the question's letters (``"abcd"``); ``single`` if one letter is asked for.
    The answer is read by :func:`course_lib.homework.answers.choice`, like in the hidden tests.
    """

    def validate(answer):
        letters = as_choice(answer, options, answer_name, single=single)
        if answer_hash(letters, salt=qid) == correct_hash:
            return ok("right.")
        return fail("not this one -- think again (re-read the statement).")

    _REGISTRY[qid] = Question(qid, answer_name, validate, title)


def values_digest(salt: str, values) -> str:
    """A digest of a symbolic answer's values: the check compares digests, never expressions.

    Each value is rounded to 10 significant digits (its canonical text ``%.9e``) and hashed with
    ``salt`` (the question id) by SHA-256.  A check stores the digest of the right values,
    computed once by hand (``tests/test_own_work.py`` recomputes it from the closed form and
    proves that no right value lies near a rounding boundary), so the edition holds neither the
    expression nor its values.
    """
    parts = []
    for v in values:
        z = complex(v)
        parts.append(f"{z.real + 0.0:.9e},{z.imag + 0.0:.9e}")  # + 0.0: -0.0 is 0.0
    return hashlib.sha256((salt + "|" + ";".join(parts)).encode()).hexdigest()[:32]


def as_expression_values(answer: object, symbols, points, name: str = "your answer"):
    """``(free symbol names, values at points)`` of a symbolic answer, as the grader gets them."""
    value = answers.evaluate(answer, symbols, points, name)
    refuse_if_traced()
    return value


def expression_digest(answer: object, qid: str, symbols, points, name: str) -> str:
    """The :func:`values_digest` of a symbolic answer at ``points``, after the checks every
    symbolic answer gets (only ``symbols`` free, finite values) -- what a check compares with
    its stored digests."""
    free, values = as_expression_values(answer, symbols, points, name)
    answers.expression_matches(free, values, values, symbols, name)  # symbols, finite
    return values_digest(qid, values)


def unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def cross2(a: np.ndarray, b: np.ndarray) -> float:
    """z-component of the cross product of two plane vectors."""
    return float(a[0] * b[1] - a[1] * b[0])


def parallel(a: np.ndarray, b: np.ndarray, tol: float = 1e-9) -> bool:
    """True if ``a`` and ``b`` are parallel (either orientation), relative tolerance."""
    na, nb = np.linalg.norm(a), np.linalg.norm(b)
    if na == 0 or nb == 0:
        return False
    ca, cb = a / na, b / nb
    return bool(np.linalg.norm(ca - cb) < tol or np.linalg.norm(ca + cb) < tol)


close = answers.close
