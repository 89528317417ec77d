"""Immediate feedback for the homework and the lectures' "check your understanding" cells.

Students
--------
Every question of a homework is followed by a check cell::

    check("hw02.q3", answer_q3)        # -> ✓ / ✗ / … with a message in the course's terms

and the last cell checks everything at once::

    check_all(globals(), "hw02")

A check never raises and never shows a traceback: a placeholder (``...``) or a stub that
raises ``NotImplementedError`` is reported as "not answered yet"; ``None``, a wrong type or
shape, NaN, a function that raises (its exception type and message are shown) or never
returns are each explained.  Checks test *properties* of an answer (unit length, on the
ray, satisfies the Beta-constraint, ...); a value whose only test is its formula is compared
with an answer key (digests of the right value and of the usual mistakes,
:mod:`course_lib.homework.answer_keys`), and "?" says the key for the student's data is missing.
No check computes or prints an expected value.

They are only feedback: the grade comes from hidden tests that are not shipped with
``course_lib`` (see ``tools/grade.py``).  Both read answers with :mod:`course_lib.homework.answers`:
the check first turns the live answer into the plain data the grader receives, then applies
the same normalizers (numbers, arrays, choices, booleans; symbolic answers by their values at
points), so an answer the check marks ✓ earns full points (``tests/test_answer_equivalence.py``).

Lecture notebooks ("check your understanding")
----------------------------------------------
Lecture questions are practice and live in :mod:`course_lib.homework.checks.lectures`: multiple choice
with :func:`course_lib.homework.checks.lectures.quiz` (no hash is stored in a notebook: with a handful of
letter sets, a loop over the options would invert any hash, so the lectures do not pretend).
Answers are compared case-, space- and order-insensitively (``"B, d"`` == ``["d", "b"]``).
For a numeric answer in a lecture use :func:`course_lib.homework.checks.lectures.check_number`
(a plane vector: :func:`~course_lib.homework.checks.lectures.check_vector`), whose expected value is
computed at check time in :mod:`course_lib.homework.checks.lectures` (a lecture must not contain its
answers, not even as an expression)::

    from course_lib.homework.checks.lectures import check_number, check_vector
    check_number("lecture06.q2", my_beta1)
    check_vector("lecture02.q4", my_tangent)

:func:`check_value` compares against a value passed in by the caller and never prints it
(for solution notebooks and tests)::

    check_value("hw02.extra", my_kappa, expected=float(kappa_at_1), rtol=1e-6)

:func:`quiz` shows a question with its choices and the verdict in one call.

API
---
``check(question_id, answer) -> Verdict``
``check_all(namespace, homework=None) -> Report``
``check_choice(question_id, answer, correct_hash) -> Verdict``
``check_value(question_id, answer, expected, rtol=1e-9, atol=1e-12) -> Verdict``
``quiz(question_id, prompt, choices, answer, correct_hash) -> Verdict``
``answer_hash(answer, salt="") -> str``
``Verdict`` (``passed``, ``message``, ``status``; truthy iff passed) and ``Report``
(``all_passed``, ``verdicts``) display as coloured boxes in Jupyter.
"""

from __future__ import annotations

import importlib
import pkgutil
import re
from collections.abc import Mapping, Sequence

import numpy as np

from course_lib.homework import answers, variants
from course_lib.homework.checks._core import (
    FAIL,
    UNANSWERED,
    Report,
    Verdict,
    answer_hash,
    as_vector,
    is_unanswered,
    registry,
    run_validate,
    values_digest,
)

__all__ = [
    "HOMEWORKS",
    "Report",
    "Verdict",
    "answer_hash",
    "check",
    "check_all",
    "check_choice",
    "check_value",
    "questions",
    "quiz",
    "registry",
    "values_digest",
]


def _homework_modules() -> tuple[str, ...]:
    """The ``hwNN`` modules of this package, sorted: one per homework set."""
    names = (m.name for m in pkgutil.iter_modules(__path__))
    return tuple(sorted(n for n in names if re.fullmatch(r"hw\d\d", n)))


#: The homework sets whose questions are registered here: one module ``course_lib.homework.checks.hwNN``
#: each, found on disk (a new ``hwNN.py``, e.g. from ``tools/new_homework.py``, needs no entry).
HOMEWORKS = _homework_modules()


def _load(homework: str) -> None:
    if homework in HOMEWORKS:
        importlib.import_module(f"{__name__}.{homework}")


def questions(homework: str) -> list[str]:
    """The question ids of ``homework`` in order (e.g. ``["hw01.q1", ...]``)."""
    _load(homework)
    return [q for q in registry() if q.split(".")[0] == homework]


def check(question_id: str, answer: object) -> Verdict:
    """Check ``answer`` to the homework question ``question_id`` (e.g. ``"hw01.q3"``).

    Never raises; returns a :class:`Verdict` that shows ✓ or what is wrong.
    """
    if not isinstance(question_id, str):
        return Verdict(str(question_id), False, "the question id must be a string like 'hw01.q1'.")
    _load(question_id.split(".")[0])
    q = registry().get(question_id)
    if q is None:
        known = ", ".join(HOMEWORKS)
        return Verdict(
            question_id, False, f"unknown question id (homework sets: {known}; ids like 'hw01.q1')."
        )
    return run_validate(question_id, q.validate, answer)


def check_all(namespace: Mapping[str, object], homework: str | None = None) -> Report:
    """Check every question of ``homework`` with the answers found in ``namespace``.

    Call it as ``check_all(globals(), "hw01")``.  Without ``homework`` the notebook's
    ``HOMEWORK`` variable is used.  An answer missing from the namespace (never run, or
    deleted) is reported as such.
    """
    if homework is None:
        homework = namespace.get("HOMEWORK") if isinstance(namespace, Mapping) else None
    if homework not in HOMEWORKS:
        v = Verdict(str(homework), False, f"name the homework: check_all(globals(), 'hw01'); known: {HOMEWORKS}.")
        return Report(str(homework), (v,))
    _load(homework)
    verdicts = []
    for qid in questions(homework):
        q = registry()[qid]
        if not isinstance(namespace, Mapping) or q.answer_name not in namespace:
            verdicts.append(
                Verdict(
                    qid,
                    False,
                    f"`{q.answer_name}` is not defined -- run its cell (or was it deleted?).",
                    UNANSWERED,
                )
            )
            continue
        verdicts.append(run_validate(qid, q.validate, namespace[q.answer_name]))
    return Report(homework, tuple(verdicts), _variant_notes(namespace, homework))


def _variant_notes(namespace: object, homework: str) -> tuple[str, ...]:
    """A warning when a homework with per-student variants is checked on the example data."""
    if homework not in variants.generators() or not isinstance(namespace, Mapping):
        return ()
    code = namespace.get("VARIANT")
    if isinstance(code, str) and not code.strip():
        return (
            "VARIANT is empty, so these checks use the example data. If your course hands out "
            "variant codes, paste yours into the Preparations cell and run the notebook again: "
            "you are graded on your own data.",
        )
    return ()


def check_choice(question_id: str, answer: object, correct_hash: str) -> Verdict:
    """Compare a multiple-choice / short answer with the hash of the right one.

    ``correct_hash`` is ``answer_hash(right_answer, salt=question_id)``.  Only says right or
    wrong; the right answer is not stored anywhere in the notebook.
    """
    if is_unanswered(answer) or answer is None:
        return Verdict(question_id, False, "not answered yet (replace the ... by your choice).", UNANSWERED)
    if isinstance(answer, float) or callable(answer):
        return Verdict(question_id, False, "give the letter(s) of your choice, e.g. 'b' or 'a, c'.", FAIL)
    if answer_hash(answer, salt=question_id) == correct_hash:
        return Verdict(question_id, True, "right.", "passed")
    return Verdict(question_id, False, "not this one -- think again (re-read the statement).", FAIL)


def check_value(
    question_id: str,
    answer: object,
    expected: object,
    *,
    rtol: float = 1e-9,
    atol: float = 1e-12,
) -> Verdict:
    """Compare a numeric answer (number or array) with ``expected``; never prints ``expected``."""
    exp = np.asarray(expected, dtype=float)

    def validate(a):
        arr = as_vector(a, exp.shape, what="a number" if exp.ndim == 0 else "an array")
        if np.allclose(arr, exp, rtol=rtol, atol=atol):
            return True, "correct."
        return False, "not the expected value -- check your computation."

    return run_validate(question_id, validate, answer)


def quiz(
    question_id: str,
    prompt: str,
    choices: Sequence[str] | Mapping[str, str],
    answer: object,
    correct_hash: str,
) -> Verdict:
    """Show a multiple-choice question and the verdict on ``answer`` in one output.

    ``choices`` is a list (lettered a, b, c, ...) or a mapping letter -> text.
    """
    if not isinstance(choices, Mapping):
        choices = {chr(ord("a") + i): c for i, c in enumerate(choices)}
    lines = "; ".join(f"({k}) {v}" for k, v in choices.items())
    letters = "".join(str(k) for k in choices)
    if len(letters) == len(choices) and letters.isalpha():  # read it like a homework choice
        try:
            answer = answers.choice(answers.plain(answer), letters.lower())
        except answers.AnswerError as exc:
            status = UNANSWERED if exc.unanswered else FAIL
            return Verdict(question_id, False, f"{prompt} {lines} -- {exc.message}", status)
    v = check_choice(question_id, answer, correct_hash)
    return Verdict(v.question, v.passed, f"{prompt} {lines} -- {v.message}", v.status)

