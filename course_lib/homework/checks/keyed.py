"""Answer-keyed checks: the verdict of a value the check does not know (issue 24).

The checks of hw01 q1, q4, q5, q7 and hw02 q5 ask :func:`key_tag` which known value a student's
answer is -- the right one, a named mistake, or none -- from the digests of
:mod:`course_lib.homework.answer_keys`; :class:`Unchecked` (the verdict "?") when the edition
has no key for the student's data.  :func:`typed_rounded` spots a number typed in rounded, so
its ✗ can say "keep the digits" rather than "the formula is wrong".
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np

from course_lib.homework import answer_keys

__all__ = ["NO_KEY_MESSAGE", "ROUNDED_HINT", "Unchecked", "key_tag", "typed_rounded"]


class Unchecked(Exception):
    """Raised by :func:`key_tag`: the edition has no answer key for this question's data."""


#: what a student reads when their value cannot be checked here (no key for their data)
NO_KEY_MESSAGE = (
    "the form of your answer is right, but this copy of the course holds no answer key for your "
    "data, so only the grader checks the value. Check that VARIANT is the code your instructor "
    "gave you; if it is, ask them for the student edition made with the class list."
)


def key_tag(qid: str, quantum: float, data: Mapping, value: object) -> str:
    """The answer key's tag of ``value`` for the question's ``data``: ``"right"``, the tag of a
    known mistake, or ``""`` (none of them); :class:`Unchecked` if there is no key
    (:mod:`course_lib.homework.answer_keys`: the check compares digests, never values)."""
    tag = answer_keys.keys().lookup(qid, quantum, data, value)
    if tag == answer_keys.NO_KEY:
        raise Unchecked(NO_KEY_MESSAGE)
    return tag


def typed_rounded(value: object) -> bool:
    """Does ``value`` look typed in rather than computed: every component a decimal of at most
    8 significant digits (``0.4104``, ``[-1.5, 0.22]``)?  A computed irrational value has ~16."""
    x = np.atleast_1d(np.asarray(value, dtype=float)).ravel()
    return bool(x.size) and all(len(f"{abs(c):.8g}".replace(".", "").lstrip("0")) < 9
                                and float(f"{c:.8g}") == c for c in x)  # fmt: skip


#: added to a ✗ of an answer-keyed value that looks typed in (:func:`typed_rounded`)
ROUNDED_HINT = (
    " If you typed a rounded number, compute it in Python instead: the check and the grader "
    "need about 9 decimals (this check cannot tell how close a rounded number is)."
)
