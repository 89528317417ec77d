"""Answer keys: a check that recognises a value answer without holding it.

Some homework answers are values whose only test *is* the formula the question asks for: the
signed curvature of the parabola at ``u0`` (hw01.q4), the second derivative after a change of
variables (hw01.q5), r''(0) = β1² q''(1) + β2 q'(1) (hw02.q5).  A check that computed the
value from the student's data, to compare, would hand it to anyone who reads the check or spies
on it once (issue 24).  So these checks compare *digests* instead, written by the instructor
(``tools/answer_keys.py``, from the hidden tests, for every student's data: ``make release
SECRET=... ROSTER=...``) into the key file :data:`KEY_FILE` of the edition.

How a key works
---------------
Each component of a value is rounded onto a grid of step ``quantum`` (the question's, smaller
than the grader's tolerance), and the grid point is hashed with scrypt (a deliberately slow,
salted hash; its cost is in the key file).  The salt is the *index* of the question's data: a
hash of the question id, the quantum and the data as the generator made it, so two students
with the same data share a key and no key says whose it is.  For a question, the key file
maps the digests of the right value and of the usual wrong ones (the sign flipped, one term
missing, ...) to a *tag* (``"right"``, ``"sign"``, ...); the check says what each tag means.

The check rounds the student's value the same way, hashes that grid point first and then its
neighbours (a right value within one step of a grid boundary lands on either side), and looks
the digests up.  It never computes the expected value, so neither reading nor tracing it finds
one.  What remains is a search: one scrypt per candidate grid point, with ~10⁹ points per
component at the quanta used here.

Examples
--------
>>> list(grid_candidates([0.5, -1.0], 0.25))[:3]
[(2, -4), (1, -5), (1, -4)]
"""

from __future__ import annotations

import hashlib
import itertools
import json
from collections.abc import Iterable, Iterator, Mapping
from importlib import resources
from pathlib import Path

import numpy as np

__all__ = [
    "GRADER_KEY_FILE",
    "KEY_FILE",
    "NO_KEY",
    "NO_MATCH",
    "AnswerKeys",
    "digest",
    "entry",
    "grid_candidates",
    "keys",
    "question_index",
    "use",
]

#: The key file of the installed package (the edition's, as ``make release`` wrote it).
KEY_FILE = "answer_keys.json"
#: Where the grader's sandbox shows the keys of the submission's own data (read-only): a
#: student's check cells say there what they say at home (``tools/grading/runner.py``).
GRADER_KEY_FILE = "/run/course-lib/answer_keys.json"
FORMAT = 1
#: scrypt's cost in an edition (about 30 ms per digest on a 2020s laptop); tests use less.
DEFAULT_COST = 2**13

NO_KEY = "no key"  # the key file holds nothing for this question's data
NO_MATCH = ""  # a key, and the answer is none of its values


def _canonical(value: object) -> object:
    """The question's data as plain JSON values (tuples as lists, numpy scalars as floats)."""
    if isinstance(value, Mapping):
        return {str(k): _canonical(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_canonical(v) for v in value]
    if isinstance(value, np.ndarray):
        return _canonical(value.tolist())
    if isinstance(value, (np.floating, np.integer)):
        return value.item()
    return value


def question_index(qid: str, quantum: float, data: Mapping) -> str:
    """The key's index: a SHA-256 of the question id, the quantum and the question's data."""
    text = json.dumps(
        [qid, repr(float(quantum)), _canonical(data)], sort_keys=True, ensure_ascii=True
    )
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def _grid(value: object, quantum: float) -> tuple[int, ...]:
    x = np.atleast_1d(np.asarray(value, dtype=float)).ravel()
    if not np.all(np.isfinite(x)):
        raise ValueError("value must be finite to be looked up in the answer keys")
    if not (isinstance(quantum, (int, float)) and quantum > 0):
        raise ValueError(f"quantum must be a positive number, got {quantum!r}")
    return tuple(round(float(c) / quantum) for c in x)


def grid_candidates(value: object, quantum: float) -> Iterator[tuple[int, ...]]:
    """The grid point of ``value``, then its neighbours (every component moved by −1, 0 or +1).

    A value within one ``quantum`` of the right one lands on the right point or a neighbour.
    """
    centre = _grid(value, quantum)
    yield centre
    for step in itertools.product((-1, 0, 1), repeat=len(centre)):
        if any(step):
            yield tuple(c + s for c, s in zip(centre, step, strict=True))


def digest(index: str, qid: str, point: tuple[int, ...], cost: int) -> str:
    """scrypt of one grid point, salted by the question's index (32 hex digits)."""
    password = f"{qid}|{','.join(map(str, point))}".encode()
    return hashlib.scrypt(password, salt=index.encode(), n=int(cost), r=8, p=1, dklen=16).hex()


def entry(
    qid: str,
    quantum: float,
    data: Mapping,
    values: Iterable[tuple[str, object]],
    cost: int = DEFAULT_COST,
) -> tuple[str, dict[str, str]]:
    """The key of one question's data: ``(index, {digest: tag})`` for the ``(tag, value)`` pairs.

    The tag ``"right"`` marks the right value (exactly one); the other tags are mistakes worth a
    message, and a tag may mark several values.  A mistake within three grid steps of the right
    value is left out, so a right answer is never told it made that mistake.
    """
    pairs = [(str(tag), value) for tag, value in values]
    rights = [value for tag, value in pairs if tag == "right"]
    if len(rights) != 1:
        raise ValueError(f"values must hold exactly one pair tagged 'right', got {len(rights)}")
    index = question_index(qid, quantum, data)
    right = np.array(_grid(rights[0], quantum))
    out: dict[str, str] = {digest(index, qid, tuple(right.tolist()), cost): "right"}
    for tag, value in pairs:
        point = _grid(value, quantum)
        if (
            tag == "right"
            or len(point) != right.size
            or np.max(np.abs(np.array(point) - right)) <= 3
        ):
            continue
        out.setdefault(digest(index, qid, point, cost), tag)
    return index, out


class AnswerKeys:
    """The keys of a key file: ``lookup(qid, quantum, data, value)`` gives the tag of a value."""

    def __init__(self, document: Mapping) -> None:
        if not isinstance(document, Mapping) or document.get("format") != FORMAT:
            raise ValueError(f"not an answer-key file of format {FORMAT}")
        cost = document.get("cost")
        if not (isinstance(cost, int) and cost >= 2 and cost & (cost - 1) == 0):
            raise ValueError("an answer-key file's cost must be a power of 2 (scrypt's n)")
        entries = document.get("keys", {})
        if not isinstance(entries, Mapping) or not all(
            isinstance(v, Mapping) for v in entries.values()
        ):
            raise ValueError("an answer-key file's keys must map each index to {digest: tag}")
        self.cost = cost
        self.entries: dict[str, dict[str, str]] = {
            str(k): {str(d): str(t) for d, t in v.items()} for k, v in entries.items()
        }

    def lookup(self, qid: str, quantum: float, data: Mapping, value: object) -> str:
        """The tag of ``value``, :data:`NO_MATCH` if it is none of the key's values, or
        :data:`NO_KEY` if the file has no key for this question's data."""
        index = question_index(qid, quantum, data)
        known = self.entries.get(index)
        if known is None:
            return NO_KEY
        for point in grid_candidates(value, quantum):
            tag = known.get(digest(index, qid, point, self.cost))
            if tag is not None:
                return tag
        return NO_MATCH

    def document(self) -> dict:
        """The key file's content (sorted, so the same keys give the same bytes)."""
        return {
            "about": "answer keys of course_lib's checks: scrypt digests, no answers "
            "(course_lib/homework/answer_keys.py)",
            "format": FORMAT,
            "cost": self.cost,
            "keys": {k: dict(sorted(v.items())) for k, v in sorted(self.entries.items())},
        }

    def write(self, path: Path) -> None:
        Path(path).write_text(json.dumps(self.document(), indent=1) + "\n", encoding="utf-8")


_IN_USE: list[AnswerKeys] = []


def keys() -> AnswerKeys:
    """The keys the checks use (read once): those given to :func:`use`, in the grader's sandbox
    :data:`GRADER_KEY_FILE`, else the package's key file."""
    if not _IN_USE:
        grader = Path(GRADER_KEY_FILE)
        if grader.is_file():
            text = grader.read_text(encoding="utf-8")
        else:
            text = (
                resources.files("course_lib.homework")
                .joinpath(KEY_FILE)
                .read_text(encoding="utf-8")
            )
        _IN_USE.append(AnswerKeys(json.loads(text)))
    return _IN_USE[-1]


def use(answer_keys: AnswerKeys | None) -> None:
    """Let the checks use ``answer_keys`` (``None``: the package's key file again).

    For the instructor's tests of other variants; a student's edition has its keys in its file.
    """
    _IN_USE.clear()
    if answer_keys is not None:
        _IN_USE.append(answer_keys)
