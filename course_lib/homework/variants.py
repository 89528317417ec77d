"""Every student their own homework data: variants from a code.

A homework that has variants defines a *generator* ``generate(rng) -> dict`` of its question
data (points, β's, knots, the order of multiple-choice options, ...) in its checks module
``course_lib.homework.checks.hwNN``, and optionally ``strata(data) -> {qid: label}``; this
module finds them there by the homework's name (nothing registers itself on import).  Each student gets a short **variant code** from the instructor:

    code = code_for(secret, "hw01", student_id)     # HMAC-SHA256 of homework and id

``secret`` is the course secret, which only the instructor has (``tools/variant.py``), so codes
cannot be made up or predicted.  In the notebook the student pastes their code
(``VARIANT = "..."``) and ``data("hw01", VARIANT)`` gives *their* data, reproducibly on any
machine; an empty code gives the homework's default data (the one printed in the notebook,
used by the test suite).  The grader recomputes the code from the student's id, so a notebook
done with a friend's code is graded on the student's own data and its answers are wrong.

The generators are public (they are in the student edition): only the secret is not.
"""

from __future__ import annotations

import hashlib
import hmac
from collections.abc import Callable

import numpy as np

__all__ = [
    "ALPHABET",
    "DEFAULT",
    "VariantCodeError",
    "code_for",
    "current",
    "data",
    "generator",
    "generators",
    "normalize",
    "rng_for",
    "strata",
]

DEFAULT = ""  # the code of the default data
CODE_LENGTH = 10

_CURRENT: dict[str, dict] = {}


def _checks_module(homework: str):
    """The checks module of ``homework`` (``course_lib.homework.checks.hwNN``), or None."""
    import importlib
    import re

    if not isinstance(homework, str) or not re.fullmatch(r"hw\d\d", homework):
        return None
    name = f"course_lib.homework.checks.{homework}"
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as exc:
        if exc.name == name:
            return None
        raise


def generator(homework: str) -> Callable[[np.random.Generator | None], dict] | None:
    """The data generator ``generate(rng)`` of ``homework`` (None if it has no variants)."""
    module = _checks_module(homework)
    fn = getattr(module, "generate", None)
    return fn if callable(fn) else None


def strata(homework: str, code: str) -> dict[str, str]:
    """The labels of a variant's questions (empty where the homework declares none).

    A label names the kind of variant a student got for a question (which letter is right,
    the sign of a coefficient, ...): the class summary compares success rates across labels and
    flags a question whose variants are not equally hard.  A homework declares them with a
    function ``strata(data) -> {qid: label}`` beside its ``generate``.
    """
    gen = generator(homework)
    label = getattr(_checks_module(homework), "strata", None)
    if gen is None or not callable(label):
        return {}
    return dict(label(gen(rng_for(homework, code))))


def generators() -> dict[str, Callable]:
    """The generators of every homework that has variants, by homework."""
    import pkgutil
    from pathlib import Path

    folder = Path(__file__).with_name("checks")  # found on disk, like checks.HOMEWORKS
    names = sorted(m.name for m in pkgutil.iter_modules([str(folder)]))
    found = {name: generator(name) for name in names}
    return {name: fn for name, fn in found.items() if fn is not None}


#: the characters of a code: no look-alikes (no 0/O, 1/I/L); 31 of them, a prime, so the
#: check character catches every single wrong character and every swap of two neighbours
ALPHABET = "ABCDEFGHJKMNPQRSTUVWXYZ23456789"
_RULE = (
    f"{CODE_LENGTH} characters from A-Z and 2-9 without I, L, O (no 0 or 1), the last one a "
    "check character"
)


class VariantCodeError(ValueError):
    """A VARIANT that is not a code: one sentence that names the rule, no traceback."""

    def _render_traceback_(self) -> list[str]:  # IPython shows this instead of a traceback
        return [f"VariantCodeError: {self}"]


def _check_char(body: str) -> str:
    total = sum((i + 1) * ALPHABET.index(c) for i, c in enumerate(body))
    # the weights 1..CODE_LENGTH and a prime modulus: sum of (i + 1) * value = 0 (mod 31)
    inverse = pow(CODE_LENGTH, -1, len(ALPHABET))
    return ALPHABET[(-total * inverse) % len(ALPHABET)]


def code_for(secret: bytes | str, homework: str, student: str) -> str:
    """The variant code of ``student`` for ``homework``: :data:`CODE_LENGTH` characters of
    :data:`ALPHABET`, the last a check character (made from an HMAC-SHA256 of both)."""
    key = secret.encode() if isinstance(secret, str) else bytes(secret)
    if len(key) < 16:
        raise ValueError("secret must be at least 16 bytes (make one with tools/variant.py secret)")
    if not isinstance(student, str) or not student.strip():
        raise ValueError("student must be a non-empty id")
    digest = hmac.new(key, f"{homework}:{student.strip()}".encode(), hashlib.sha256).digest()
    number, body = int.from_bytes(digest, "big"), ""
    for _ in range(CODE_LENGTH - 1):
        number, k = divmod(number, len(ALPHABET))
        body += ALPHABET[k]
    return body + _check_char(body)


def normalize(code: object) -> str:
    """The code as the generator reads it (upper case, without spaces and dashes), or
    :class:`VariantCodeError` (a ``ValueError``) saying in one sentence what is wrong.

    Examples
    --------
    >>> normalize("kqw7-mzp3 xs")
    'KQW7MZP3XS'
    """
    if not isinstance(code, str):
        raise TypeError(f"VARIANT must be the code your instructor gave you, as a string; got {code!r}")
    text = code.strip().upper().replace("-", "").replace(" ", "")
    if not text:
        return text
    where = "copy it again from your instructor's message (or use \"\" for the data printed in the notebook)"
    bad = sorted({c for c in text if c not in ALPHABET})
    if bad:
        raise VariantCodeError(
            f"VARIANT {code!r} is not a variant code: it contains {', '.join(map(repr, bad))}, but a "
            f"code is {_RULE}; {where}."
        )
    if len(text) != CODE_LENGTH:
        raise VariantCodeError(
            f"VARIANT {code!r} is not a variant code: it has {len(text)} characters, but a code is "
            f"{_RULE}; {where}."
        )
    if _check_char(text[:-1]) != text[-1]:
        raise VariantCodeError(
            f"VARIANT {code!r} is not a variant code: its check character does not match (a typo?); "
            f"{where}."
        )
    return text


_normalize = normalize  # the name the module used before


def rng_for(homework: str, code: str) -> np.random.Generator | None:
    """The random generator of a variant (None for the default data)."""
    text = normalize(code)
    if not text:
        return None
    seed = int.from_bytes(hashlib.sha256(f"{homework}:{text}".encode()).digest()[:8], "little")
    return np.random.default_rng(seed)


def data(homework: str, code: str = DEFAULT) -> dict:
    """The question data of ``homework`` for the variant ``code`` (and remember it for the checks)."""
    gen = generator(homework)
    if gen is None:
        raise ValueError(f"{homework} has no variants (homeworks with variants: {sorted(generators())})")
    result = gen(rng_for(homework, code))
    _CURRENT[homework] = result
    return result


def current(homework: str) -> dict:
    """The data of the variant last chosen in this kernel (the default data if none was)."""
    if homework not in _CURRENT:
        return data(homework, DEFAULT)
    return _CURRENT[homework]
