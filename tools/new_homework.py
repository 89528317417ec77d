"""Scaffold a new homework set: its source, its feedback checks, its hidden-test stub, its notebooks.

Usage::

    python tools/new_homework.py hw05 "Are letters smooth?"

writes

* ``tools/homework_src/hw05_are_letters_smooth.py`` -- the source (format: the docstring of
  ``tools/build_homework.py``): title, how to work, Preparations with ``HOMEWORK = "hw05"``, one
  value question and one function question as examples, their check cells, "Check everything"
  and "Hand in";
* ``course_lib/homework/checks/hw05.py`` -- the feedback checks of the two example questions
  and the generator of every student's own data, ``generate(rng)`` (per-student variants,
  ``course_lib/homework/variants.py`` finds it there by name): the value question reads its data from
  ``DATA = variants.data(HOMEWORK, VARIANT)``, the check from ``variants.current``, the hidden
  test from its ``data`` argument;
* ``solutions/hidden_tests/hw05.py`` -- the hidden tests of the two example questions (form:
  ``solutions/hidden_tests/README.md``);
* ``exercises/hw05_are_letters_smooth.ipynb`` and ``solutions/...`` -- by running
  ``tools/build_homework.py``.

Nothing is registered by hand: the list of homework (``course_lib.homework.checks.HOMEWORKS``) and the
test suite's lists are derived from these files.  It never overwrites a file: if anything of
``hwNN`` exists already it stops and changes nothing.  What to do next is printed at the end and
written in CONTRIBUTING.md ("Homework: the rules the tests enforce").
"""

from __future__ import annotations

import argparse
import re
import sys
import unicodedata
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_HW = re.compile(r"hw(\d\d)")
MAX_TITLE = 80
MAX_SLUG = 40


def slug(title: str) -> str:
    """``"Are letters smooth?"`` -> ``"are_letters_smooth"`` (ASCII, at most 40 characters)."""
    text = unicodedata.normalize("NFKD", title).encode("ascii", "ignore").decode().lower()
    words = re.findall(r"[a-z0-9]+", text)
    out = ""
    for w in words:
        if len(out) + len(w) + (1 if out else 0) > MAX_SLUG:
            break
        out = f"{out}_{w}" if out else w
    return out or (words[0][:MAX_SLUG] if words else "")


def validate(homework: object, title: object) -> tuple[str, str, int]:
    """Check the arguments; return ``(homework, title, number)`` or raise ValueError/TypeError."""
    if not isinstance(homework, str) or not isinstance(title, str):
        raise TypeError(
            "homework and title must be strings, e.g. new_homework('hw05', 'Are letters smooth?')"
        )
    m = _HW.fullmatch(homework)
    if not m:
        raise ValueError(f"homework must look like 'hw05' (hw and two digits); got {homework!r}")
    number = int(m.group(1))
    if number == 0:
        raise ValueError("homework numbers start at 1: hw01, hw02, ...; got 'hw00'")
    title = title.strip()
    if not title:
        raise ValueError("title must not be empty")
    if len(title) > MAX_TITLE:
        raise ValueError(f"title must be at most {MAX_TITLE} characters; it has {len(title)}")
    bad = sorted({c for c in title if unicodedata.category(c).startswith("C") or c in '`"\\'})
    if bad:
        raise ValueError(
            f"title must be one line of plain text (no double quotes, backticks, backslashes or control "
            f"characters); it contains {bad}"
        )
    if not slug(title):
        raise ValueError(
            f"title must contain letters or digits (it names the files); got {title!r}"
        )
    return homework, title, number


def planned_files(homework: str, title: str, root: Path = ROOT) -> dict[str, Path]:
    stem = f"{homework}_{slug(title)}"
    return {
        "source": root / "tools" / "homework_src" / f"{stem}.py",
        "checks": root / "course_lib" / "homework" / "checks" / f"{homework}.py",
        "hidden": root / "solutions" / "hidden_tests" / f"{homework}.py",
        "exercise": root / "exercises" / f"{stem}.ipynb",
        "solution": root / "solutions" / f"{stem}.ipynb",
    }


def existing_files(homework: str, root: Path = ROOT) -> list[Path]:
    """Every file of ``homework`` already there, whatever its name after ``hwNN_``."""
    found = [
        *(root / "tools" / "homework_src").glob(f"{homework}_*.py"),
        *(root / "exercises").glob(f"{homework}_*.ipynb"),
        *(root / "solutions").glob(f"{homework}_*.ipynb"),
    ]
    found += [p for p in (root / "course_lib" / "homework" / "checks" / f"{homework}.py",
                          root / "solutions" / "hidden_tests" / f"{homework}.py") if p.exists()]  # fmt: skip
    return sorted(found)


# --------------------------------------------------------------------------- templates
# Placeholders: @HW@ (hw05), @N@ (5), @TITLE@, @STEM@ (hw05_are_letters_smooth).

SOURCE = r'''# Source of exercises/@STEM@.ipynb and solutions/@STEM@.ipynb.
# Edit here, then run `python tools/build_homework.py` (format: see that script's docstring).
# Scaffolded by tools/new_homework.py: replace the two example questions by yours (5 to 8 in all)
# and every TODO; the rules the tests enforce are in CONTRIBUTING.md.
# ruff: noqa: B018

# %% [markdown]
# *Geometric continuity of parametric curves* · Homework @N@ · after the lecture TODO (name the
# lecture notebook and the seed sections).
#
# # Homework @N@ — @TITLE@
#
# TODO: one paragraph on what this homework practises and why.
#
# **How to work.** Replace each `...` by your answer (or write the body of the function), run the
# cell, then run the **check cell** below it:
#
# - ✓ your answer has the properties it must have;
# - ✗ what is wrong, in the terms of the course;
# - … not answered yet.
#
# The checks are feedback, not the grade: the grade comes from other tests with other data, so
# write code that works in general. Keep the names (`answer_q1`, `unit_tangent`, ...), do not
# delete cells, and before you hand in run *Kernel → Restart Kernel and Run All Cells*.
#
# **Your own work.** Points are for what you write yourself. A function you write must not call
# the `course_lib` function that already does it (each function question says what you may
# use): while your function is checked or graded, those library functions raise an error --
# "… is the exercise of @HW@.q2: write it yourself" -- and the question earns 0 points. The
# checks do not hand out answers either: they say ✓ or ✗, and what kind of case went wrong.

# %% [markdown]
# ## Preparations

# %%
import numpy as np

from course_lib.homework import variants
from course_lib.homework.checks import check, check_all

HOMEWORK = "@HW@"
VARIANT = ""  # paste the code your instructor gave you, e.g. VARIANT = "KQW7MZP3XS"
DATA = variants.data(HOMEWORK, VARIANT)

# %% [markdown]
# ## Question 1 — a velocity (compute)
#
# TODO: an example of a value question on your own data; replace it. The plane curve
# $\mathbf c(t) = (t^2,\ t^3)$ is traced for increasing $t$. Compute its velocity
# $\mathbf c'(t_0)$ at the $t_0$ of your data (printed below, `DATA["q1"]["t"]`) as a numpy
# array of shape `(2,)`.

# %%
print(DATA["q1"]["text"])  # your data

# %%
### BEGIN SOLUTION
t = DATA["q1"]["t"]
answer_q1 = np.array([2 * t, 3 * t**2])  # c'(t) = (2t, 3t²)
### END SOLUTION
### STUDENT answer_q1 = ...

# %%
check("@HW@.q1", answer_q1)

# %% [markdown]
# ## Question 2 — the unit tangent (write a function)
#
# TODO: an example of a function question; replace it. Write `unit_tangent(v)` that returns
# the unit vector $\mathbf v / \lVert \mathbf v \rVert$ of a nonzero velocity `v` (a numpy array
# of shape `(dim,)`). It must work in the plane and in space.

# %%
def unit_tangent(v):
    """The unit vector along the nonzero vector v."""
    ### BEGIN SOLUTION
    v = np.asarray(v, dtype=float)
    return v / np.linalg.norm(v)
    ### END SOLUTION
    ### STUDENT raise NotImplementedError("write the body of unit_tangent")

# %%
check("@HW@.q2", unit_tangent)

# %% [markdown] solution
# A note in the solution copy only (TODO: explain the answer, or delete this cell): dividing by
# the length keeps the direction and makes the length 1, in any dimension.

# %% [markdown]
# ## Check everything
#
# Run this last cell before you hand in: it checks every answer at once.

# %%
report = check_all(globals(), HOMEWORK)
### BEGIN SOLUTION
assert report.all_passed, report
### END SOLUTION
report

# %% [markdown]
# ## Hand in
#
# Save the notebook, then hand it in with **one** of these. For `your-id` use the id your instructor
# gave you with your variant code (your id on the course roster, e.g. your student number / SIS id):
#
# * in a terminal, from the course folder: `make submit HW=@HW@ STUDENT=your-id`
# * in a new cell here: `from course_lib.homework.submit import submit; submit("@STEM@.ipynb", student="your-id")`
#
# Either runs the notebook top to bottom in a fresh kernel, as the grader will, lists the cells that
# fail, and writes `submissions/@HW@-your-id.ipynb`. Upload that file. The checks above are feedback;
# your grade comes from the grader's own tests with other data.
'''

CHECKS = r'''"""Feedback checks of homework @N@: @TITLE@.

Scaffolded by ``tools/new_homework.py``: replace the two example checks by the checks of your
questions -- one ``@register(...)`` (or ``register_choice(...)``) per question, in the order of
the notebook (``exercises/@STEM@.ipynb``).  The question data is stated in the notebook and
repeated here; the solution notebook, executed by the test suite, passes every check, which keeps
the two in step.  A check tests properties of the answer or compares it with a value computed here
at check time, reads the answer with the readers of ``_core`` (the grader's
:mod:`course_lib.homework.answers`) and never prints an expected value.

Question data
-------------
``generate(None)`` is the default data (the notebook's ``VARIANT = ""``); ``generate(rng)`` a
student's own variant (:mod:`course_lib.homework.variants` finds ``generate`` here by the
homework's name; the code the instructor hands out seeds ``rng``).  Emit only well-posed data: a
test over many codes should prove it (``tests/test_variants_hw01.py`` is the model).
"""

from __future__ import annotations

import numpy as np

from course_lib.homework import variants
from course_lib.homework.checks._core import as_vector, call_answer, close, fail, ok, register


# ============================================================ the question data: every student's variant
def generate(rng) -> dict:
    t = 2.0 if rng is None else float(rng.integers(2, 6))  # q1: t0 in 2..5, never 0
    return {"q1": {"t": t, "text": f"c(t) = (t², t³), t0 = {t:g}"}}


# ============================================================ the checks


@register("@HW@.q1", "answer_q1", "the velocity of c(t) = (t², t³) at your t0")
def _q1(answer):
    v = as_vector(answer, (2,), "answer_q1", "a plane vector np.array([x, y])")
    t = variants.current("@HW@")["q1"]["t"]  # the student's own data (their VARIANT)
    if close(v, [2 * t, 3 * t**2]):
        return ok("correct.")
    if close(v, [t**2, t**3]):
        return fail("that is the point c(t0); the velocity is the derivative c'(t0).")
    return fail("not c'(t0): differentiate each coordinate of c(t), then put t = t0.")


# a plane vector, a space vector, a tiny one (no absolute tolerance on the length)
_Q2_CASES = [np.array([3.0, 4.0]), np.array([1.0, -2.0, 2.0]), np.array([1e-8, 0.0])]


@register("@HW@.q2", "unit_tangent", "unit_tangent(v): v / ‖v‖ in the plane and in space")
def _q2(func):
    for v in _Q2_CASES:
        res = call_answer(func, v.copy(), name="unit_tangent")
        res = as_vector(res, v.shape, "the returned value", f"an array of shape {v.shape}")
        if not close(np.linalg.norm(res), 1.0):
            return fail("the result must have length 1: divide v by its length ‖v‖.")
        if not close(res, v / np.linalg.norm(v)):
            return fail("the result has length 1 but does not point along v: v / ‖v‖.")
    return ok(f"correct on {len(_Q2_CASES)} test cases (plane, space, a tiny vector).")
'''

HIDDEN = r'''"""Hidden tests of homework @N@: @TITLE@ (run by tools/grade.py in the grader; never shipped).

Scaffolded by ``tools/new_homework.py``: replace the two example tests by one ``qN(student)`` per
question of ``course_lib/homework/checks/@HW@.py``, in the same order in ``POINTS``.  Form and rules:
``solutions/hidden_tests/README.md``.  Expected values are computed here from ``DATA`` with
closed forms derived by hand (derivations next to them), never with course_lib's mathematics or
the solution notebook's code.
"""

from __future__ import annotations

import math

import numpy as np

from course_lib.homework import answers

HOMEWORK = "@HW@"
POINTS = {"q1": 1, "q2": 2}
#: per-student variants: the grader calls qN(student, data) with the student's own data
#: (``generate`` in ``course_lib/homework/checks/@HW@.py``); without data, the default data below
VARIANTS = True

#: The default data (what ``variants.data("@HW@", "")`` gives).
DATA = {
    "q1": {"t": 2.0},  # c(t) = (t², t³)
}

#: Other data than the feedback check's, with its traps: space, a tiny vector, a long one.
Q2_CASES = [
    np.array([-5.0, 12.0]),
    np.array([2.0, 3.0, 6.0]),
    np.array([0.0, 3e-9, -4e-9]),
    np.array([1e6, 0.0, 0.0]),
]


def q1(student, data=None):
    v = answers.array(student["answer_q1"], (2,), "answer_q1", "a plane vector")
    t = (data or DATA)["q1"]["t"]
    # differentiated by hand: c'(t) = (2t, 3t²)
    assert answers.close(v, [2 * t, 3 * t * t]), "the velocity c'(t0) is wrong"


def q2(student, data=None):  # the same for everyone: hidden cases of its own
    func = student.function("unit_tangent")

    def case(v):
        def run():
            # the length by Pythagoras: ‖v‖ = sqrt(the sum of the squared coordinates)
            expected = v / math.sqrt(sum(float(x) ** 2 for x in v))
            got = answers.array(func(v), v.shape, "unit_tangent's result")
            assert answers.close(got, expected), f"wrong for a vector in dimension {v.size}"

        return run

    # one point per case: a ✓ of the check cannot hide a special case
    return answers.partial_credit([case(v) for v in Q2_CASES])


def answers_for(data):
    """The worked answers of a variant (``tools/variant.py show``: office hours)."""
    t = data["q1"]["t"]
    return {"answer_q1": [2 * t, 3 * t * t], "unit_tangent": "v / ‖v‖ (any data)"}
'''

def _fill(template: str, homework: str, number: int, title: str, stem: str) -> str:
    for key, value in (
        ("@HW@", homework),
        ("@N@", str(number)),
        ("@TITLE@", title),
        ("@STEM@", stem),
    ):
        template = template.replace(key, value)
    return template


def _build_notebooks() -> int:
    from tools import build_homework

    return build_homework.main([])


NEXT_STEPS = """
Next:
  1. Write your questions (5 to 8) in {source}:
     replace the two examples and every TODO; then  python tools/build_homework.py
  2. One check per question in {checks} and one qN(student, data) per question in
     {hidden} (POINTS in the same order, >= 5 specific assert/comment/return lines);
     each student's data comes from generate() in {checks} (per-student variants):
     add a tests/test_variants_hwNN.py like tests/test_variants_hw01.py.
  3. One row per question in TABLE of tests/test_answer_equivalence.py (>= 2 accepted forms,
     >= 3 typical wrong answers) and a right answer in RIGHT of tests/unit/test_checks.py, then run
       pytest tests/test_homework_build.py tests/unit/test_checks.py tests/test_answer_equivalence.py
       pytest tests/test_grading.py -k solutions
The rules the tests enforce: CONTRIBUTING.md, "Homework: the rules the tests enforce".
"""


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("homework", help="hwNN, e.g. hw05")
    parser.add_argument("title", help='the title, e.g. "Are letters smooth?"')
    args = parser.parse_args(argv)
    try:
        homework, title, number = validate(args.homework, args.title)
    except (TypeError, ValueError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    there = existing_files(homework)
    if there:
        names = ", ".join(str(p.relative_to(ROOT)) for p in there)
        print(f"error: {homework} exists already ({names}); nothing written", file=sys.stderr)
        return 1
    files = planned_files(homework, title)
    stem = files["source"].stem
    for key, template in (("source", SOURCE), ("checks", CHECKS), ("hidden", HIDDEN)):
        path = files[key]
        path.parent.mkdir(parents=True, exist_ok=True)
        with open(path, "x", encoding="utf-8") as fh:  # "x": never overwrite
            fh.write(_fill(template, homework, number, title, stem))
        print(f"wrote {path.relative_to(ROOT)}")
    code = _build_notebooks()
    if code:
        print("error: tools/build_homework.py failed", file=sys.stderr)
        return code
    rel = {k: p.relative_to(ROOT) for k, p in files.items()}
    print(NEXT_STEPS.format(**rel))
    return 0


if __name__ == "__main__":
    sys.exit(main())
