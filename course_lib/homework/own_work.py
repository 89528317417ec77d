"""Points only for one's own work: the library does not do a homework's exercises.

Each function question of a homework (``hw03.q7``: write ``knot_ratio_beta1``) has
implementations in ``course_lib`` -- the very function the exercise asks for, or one that does
it in a call or two.  :data:`EXERCISES` maps each function question to them.  While a student's
function for a question is being evaluated -- by the grader's probe in the sandboxed kernel
(``course_lib.homework.protocol``) and by the question's feedback check in the student's own kernel
(``course_lib.homework.checks._core.call_answer``) -- those implementations raise :class:`ExerciseError`
with one sentence::

    course_lib.constructions.knot_splines.knot_ratio_beta1 is the exercise of hw03.q7: write it yourself

How it holds
------------
Each implementation calls :func:`require` with its own dotted name as its first statement, so
the guard is part of the function object itself: an alias bound before the check
(``f = knot_ratio_beta1``), ``importlib``, ``getattr`` and ``__wrapped__`` all reach the same
body, and there is no unguarded original (no wrapper, no closure holding one).  The exercise is
active while a frame of :func:`run_exercise` is on the calling thread's stack -- its local
``guarded`` names the implementations -- and, for other threads and child processes, while it
is listed in a process-wide set and in the environment variable ``COURSE_LIB_EXERCISE``.  The
evaluator activates it at evaluation time and restores the state afterwards, so nothing a
notebook sets before the check (a flag, a cleared list, a rebound name) switches it off.

In the grader's sandbox none of that decides alone: the grader writes the homework it grades
and the questions it is evaluating into a file the sandbox shows read-only at
:data:`GRADER_STATE_FILE` (``tools/grading/sandbox.py`` binds it, ``runner.py`` writes it
around each request), and :func:`require` reads it in every process there -- the kernel, its
threads, a child started with an empty environment (``subprocess.run(..., env={})``,
``multiprocessing`` spawn) -- so emptying the frame's ``guarded`` or ``_ACTIVE``, shedding the
environment or hiding ``HOMEWORK`` changes nothing the grader counts.  What a notebook's code
does to this module in the kernel is also flagged for the instructor by the grader's scan of
the notebook (``tools/grading/tamper.py``).

Value questions
---------------
A value (``answer_q1 = ...``) is computed when the notebook runs, not when the grader asks for
it, so :data:`VALUE_EXERCISES` is guarded by the notebook itself: once ``course_lib.homework.checks`` is
imported (every homework's Preparations cell does), an implementation called from code whose
globals hold ``HOMEWORK = "hwNN"`` -- any frame up the stack: a cell, a function of the
notebook, ``exec`` from a cell -- raises if it computes a value question of ``hwNN``.  Lectures
and the library's own users are untouched (they set no ``HOMEWORK``).

Before an evaluation, :func:`run_exercise` refuses (:class:`ExerciseError`, the question costs
its points) if a notebook switched the guard off by rebinding a name: ``own_work.require``, a
module's ``own_work``, a guarded function's ``__code__``.

What it does not stop (README, "The rule"): code in the same interpreter can always rewrite code
in it -- a notebook that replaces the probe, ``__import__`` or this module's own references
before the evaluation can call the library unguarded (in the grader such code is flagged, and
writing into this module's state costs the guarded questions), and in the student's own kernel
(no state file) one that hides ``HOMEWORK`` or computes in a thread gets a value past the
check; copying a function's source text out of ``course_lib`` is copying, as from a book.

Why this module is long: the guard and its tables are read together: the tables name what
the guard protects.
"""

from __future__ import annotations

import os
import sys
import threading
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

__all__ = [
    "EXERCISES",
    "VALUE_EXERCISES",
    "Exercise",
    "ExerciseError",
    "exercise_message",
    "questions_of",
    "require",
    "run_exercise",
]

ENV_VAR = "COURSE_LIB_EXERCISE"

#: Where the grader's sandbox shows the grader's state: a read-only file, bind-mounted by
#: ``tools/grading/sandbox.py`` and written only by the grader (outside the sandbox), naming the
#: homework being graded and the function questions being evaluated at this moment
#: (:func:`grader_state_text`).  Every process in the sandbox -- the kernel, its threads, a
#: child started with an empty environment -- reads it in :func:`require`, so no state a
#: submission can change (an environment variable, a list, a frame's locals, ``HOMEWORK``)
#: decides whether a guard holds there.
GRADER_STATE_FILE = "/run/course-lib/grading"


class ExerciseError(RuntimeError):
    """A library function was called while it is the exercise being evaluated.

    The exception itself is the marker "this is the exercise": the checks
    (``AnswerProblem(..., exercise=True)``), the probe (response kind ``"exercise"``) and the
    grader (``tools/grading/protocol.py``) recognise it by its type and read
    ``implementation``, ``question`` and ``switched_off``, never its text.
    """

    def __init__(self, implementation: str, question: str, switched_off: bool = False) -> None:
        self.implementation = str(implementation)
        self.question = str(question)
        self.switched_off = bool(switched_off)
        super().__init__(
            switched_off_message(self.implementation, self.question)
            if self.switched_off
            else exercise_message(self.implementation, self.question)
        )

    def __reduce__(self):  # pickled across processes (multiprocessing) with its fields
        return (type(self), (self.implementation, self.question, self.switched_off))


@dataclass(frozen=True)
class Exercise:
    """A function question: its answer name, what solves it in ``course_lib``, what it may use.

    ``implementations`` are dotted names (``"course_lib.constructions.knot_splines.knot_ratio_beta1"``) of
    functions whose body starts with ``require(<that name>)``; ``may_use`` is the sentence the
    homework text prints under the question.
    """

    question: str
    answer_name: str
    implementations: tuple[str, ...]
    may_use: str


def _ex(question: str, answer_name: str, may_use: str, *implementations: str) -> Exercise:
    return Exercise(
        question, answer_name, tuple(f"course_lib.{n}" for n in implementations), may_use
    )


_NUMPY_ONLY = "numpy (and plain Python); no function of `course_lib`"

_FUNCTIONS = (
    _ex(
        "hw01.q2",
        "chain_rule_derivatives",
        _NUMPY_ONLY,
        "geometry.reparametrization.faa_di_bruno",
        "geometry.chain_rule.compose_derivatives",
        "geometry.beta_constraints.apply_beta_constraints",
        "geometry.beta_constraints.beta_coefficients",
    ),
    _ex(
        "hw02.q3",
        "is_g1",
        _NUMPY_ONLY,
        "geometry.beta_constraints.solve_shape_parameters",
        "geometry.continuity.joint_continuity",
        "geometry.continuity.curve_continuity",
        "geometry.joint_kernel._arc_length_orders",
    ),
    _ex(
        "hw03.q2",
        "g1_bezier_control_points",
        _NUMPY_ONLY,
        "constructions.knot_splines.bezier_points_from_g1",
        "constructions.knot_splines.g1_knot_spline",
        "constructions.knot_splines._joint_points",
    ),
    _ex("hw03.q7", "knot_ratio_beta1", _NUMPY_ONLY, "constructions.knot_splines.knot_ratio_beta1"),
    _ex(
        "hw04.q2",
        "g2_stitch",
        _NUMPY_ONLY,
        "constructions.stitching.g1_stitch_points",
        "constructions.stitching.g2_stitch_points",
        "constructions.stitching._g2_points",
        "constructions.stitching.g2_stitch",
        "constructions.stitching.gn_stitch_points",
        "constructions.stitching.gn_stitch",
        "geometry.beta_constraints.apply_beta_constraints",
        "geometry.beta_constraints.beta_coefficients",
    ),
    _ex(
        "hw04.q4",
        "quadratic_beta_spline",
        _NUMPY_ONLY,
        "constructions.beta_splines.quadratic_cubic.quadratic_beta_spline",
        "constructions.beta_splines.quadratic_cubic._quadratic_polygons",
    ),
    _ex(
        "hw05.q2",
        "implied_is_g2",
        _NUMPY_ONLY,
        "constructions.outlines.classification.classify_joints",
        "geometry.continuity.joint_continuity",
        "geometry.continuity.curve_continuity",
        "geometry.joint_kernel._arc_length_orders",
    ),
    _ex(
        "hw05.q5",
        "g2_run",
        "numpy and `course_lib.constructions.beta_splines.cubic_beta_spline` (the B-spline itself); "
        "the phantom vertices are the exercise",
    ),
)

_BY_HAND = "numpy, scipy and sympy; no function of `course_lib` that computes it"
#: what solves hw02 q1 and q2 alike (the shape parameters of a joint, and its G-order)
_SHAPE_PARAMETERS_AND_G_ORDER = (
    "geometry.beta_constraints.solve_shape_parameters",
    "geometry.continuity.joint_continuity",
    "geometry.continuity.curve_continuity",
    "geometry.joint_kernel._arc_length_orders",
    "geometry.continuity._solve_betas",
)

#: Value questions whose answer a library call computes.  A value is computed in the notebook,
#: not when the grader asks for it, so these are guarded while the notebook's ``HOMEWORK`` is
#: that homework (see :func:`require`).  hw05's values are read off ``classify_joints``, the
#: tool its questions teach: they are practice, worth 0 points (README).
_VALUES = (
    _ex(
        "hw01.q1",
        "answer_q1",
        _BY_HAND,
        "geometry.differential_geometry.unit_tangent",
        "geometry.differential_geometry.frame_from_derivatives",
        "geometry.differential_geometry.arc_length_derivatives",
    ),
    _ex(
        "hw01.q4",
        "answer_q4",
        _BY_HAND,
        "geometry.differential_geometry.signed_curvature",
        "geometry.differential_geometry.curvature",
        "geometry.differential_geometry.curvature_vector",
        "geometry.differential_geometry.osculating_circle",
        "geometry.differential_geometry.frame_from_derivatives",
        "geometry.differential_geometry.arc_length_derivatives",
    ),
    _ex(
        "hw01.q5",
        "answer_q5",
        _BY_HAND,
        "geometry.reparametrization.faa_di_bruno",
        "geometry.chain_rule.compose_derivatives",
        "geometry.beta_constraints.apply_beta_constraints",
        "geometry.beta_constraints.beta_coefficients",
    ),
    _ex(
        "hw01.q7",
        "answer_q7",
        _BY_HAND,
        "geometry.differential_geometry.arc_length",
        "geometry.differential_geometry.cumulative_arc_length",
        "geometry.differential_geometry.parameter_at_arc_length",
        "geometry.arc_length.integrate_speed",
        "geometry.arc_length.segment_length",
        "geometry.arc_length.segment_lengths",
        "geometry.arc_length.robust_length",
        "geometry.arc_length.robust_hodograph_length",
        "geometry.arc_length.hodograph_lengths",
        "geometry.arc_length.piece_lengths",
    ),
    _ex("hw02.q1", "answer_q1", _BY_HAND, *_SHAPE_PARAMETERS_AND_G_ORDER),
    _ex("hw02.q2", "answer_q2", _BY_HAND, *_SHAPE_PARAMETERS_AND_G_ORDER),
    _ex(
        "hw02.q4",
        "answer_q4",
        _BY_HAND,
        "geometry.beta_constraints.beta_constraints",
        "geometry.beta_constraints._bell_constraints",
        "geometry.beta_constraints._chain_rule_constraints",
        "geometry.beta_constraints.beta_coefficients",
    ),
    _ex(
        "hw02.q5",
        "answer_q5",
        _BY_HAND,
        "geometry.beta_constraints.apply_beta_constraints",
        "geometry.beta_constraints.beta_coefficients",
        "geometry.chain_rule.compose_derivatives",
        "geometry.reparametrization.faa_di_bruno",
    ),
    _ex(
        "hw03.q1",
        "answer_q1",
        _BY_HAND,
        "constructions.knot_splines.bezier_points_from_g1",
        "constructions.knot_splines.g1_knot_spline",
        "constructions.knot_splines._joint_points",
    ),
    _ex(
        "hw03.q3",
        "answer_q3",
        _BY_HAND,
        "constructions.knot_splines.bezier_points_from_g1",
        "constructions.knot_splines.g1_knot_spline",
        "constructions.knot_splines._joint_points",
    ),
    _ex(
        "hw03.q5",
        "answer_q5",
        _BY_HAND,
        "constructions.knot_splines.bezier_points_from_g1",
        "constructions.knot_splines.g1_knot_spline",
        "constructions.knot_splines._joint_points",
    ),
    _ex(
        "hw04.q1",
        "answer_q1",
        _BY_HAND,
        "constructions.stitching.g1_stitch_points",
        "constructions.stitching.g1_stitch",
        "constructions.stitching.g2_stitch_points",
        "constructions.stitching._g2_points",
        "constructions.stitching.g2_stitch",
        "constructions.stitching.gn_stitch_points",
        "constructions.stitching.gn_stitch",
    ),
    _ex("hw04.q3", "answer_q3", _BY_HAND, "constructions.stitching.farin_boehm", "constructions.stitching.farin_boehm_gamma"),
    _ex(
        "hw04.q5",
        "answer_q5",
        _BY_HAND,
        "constructions.beta_splines.quadratic_cubic.cubic_beta_spline",
        "constructions.beta_splines.quadratic_cubic._cubic_points",
        "constructions.beta_splines.quadratic_cubic._junctions",
    ),
)

#: Function question -> :class:`Exercise` (read-only).  A new function question of a homework
#: gets a row here (``tests/test_own_work.py`` fails naming the missing one).
EXERCISES: Mapping[str, Exercise] = MappingProxyType({e.question: e for e in _FUNCTIONS})

#: Value question -> :class:`Exercise` (read-only): the library calls that compute its answer.
VALUE_EXERCISES: Mapping[str, Exercise] = MappingProxyType({e.question: e for e in _VALUES})

_getframe = sys._getframe
_lock = threading.Lock()
_ACTIVE: list[dict[str, str]] = []  # implementation -> question, per evaluation running here


def _from_environment() -> dict[str, str]:
    """Implementation -> question, for the questions a parent process was evaluating when it
    started this one."""
    return _guarded(tuple(os.environ.get(ENV_VAR, "").split(",")))


def _value_guards() -> dict[tuple[str, str], str]:
    """(homework, implementation) -> the value questions of that homework it computes."""
    out: dict[tuple[str, str], list[str]] = {}
    for q, e in VALUE_EXERCISES.items():
        for name in e.implementations:
            out.setdefault((q.split(".")[0], name), []).append(q)
    return {k: v[0] if len(v) == 1 else f"{', '.join(v[:-1])} and {v[-1]}" for k, v in out.items()}


_VALUE_GUARDS = _value_guards()
#: implementation -> the homeworks with a value question it computes
_VALUE_HOMEWORKS: dict[str, frozenset[str]] = {}
for _hw, _name in _VALUE_GUARDS:
    _VALUE_HOMEWORKS[_name] = _VALUE_HOMEWORKS.get(_name, frozenset()) | {_hw}


def questions_of(answer_name: object) -> tuple[str, ...]:
    """The function questions whose answer is named ``answer_name`` (e.g. ``("hw03.q7",)``)."""
    return tuple(q for q, e in EXERCISES.items() if e.answer_name == answer_name)


def exercise_message(implementation: str, question: str) -> str:
    """The one sentence of :class:`ExerciseError`."""
    return f"{implementation} is the exercise of {question}: write it yourself"


def switched_off_message(implementation: str, question: str) -> str:
    """The sentence of :class:`ExerciseError` when a notebook switched a guard off."""
    return (
        f"the guard of {question} was switched off in this kernel ({implementation}): write it "
        "yourself"
    )


def _owner(implementation: str, guarded: object) -> str | None:
    if isinstance(guarded, dict):
        return guarded.get(implementation)
    return None


def require(implementation: str) -> None:
    """Raise :class:`ExerciseError` if ``implementation`` is an exercise being evaluated now,
    or computes a value of the homework whose notebook calls it.

    The first statement of every implementation listed in :data:`EXERCISES` and
    :data:`VALUE_EXERCISES`.  Where neither the checks nor the probe are imported (benchmarks,
    scripts) it returns at once; else it walks up the calling frames.
    """
    if _GRADED:  # in the grader's sandbox: the grader's state decides, whatever else is set
        _graded_guard(implementation)
    if implementation in _INHERITED:  # started by a process that was evaluating it
        raise ExerciseError(implementation, _INHERITED[implementation])
    modules = sys.modules
    if not (_ACTIVE or "course_lib.homework.protocol" in modules or "course_lib.homework.checks" in modules):
        return  # no evaluation can be running (benchmarks, plain library use): no frame walk
    # one walk up the stack: an evaluation's frame (run_exercise) names the question first;
    # else a frame whose globals are a homework notebook's (HOMEWORK) names its value questions
    homeworks = _VALUE_HOMEWORKS.get(implementation) if "course_lib.homework.checks" in modules else None
    value_question, seen = None, None
    frame = _getframe(1)
    while frame is not None:
        if frame.f_code is _RUN_CODE:
            question = _owner(implementation, frame.f_locals.get("guarded"))
            if question is not None:
                raise ExerciseError(implementation, question)
        if homeworks and value_question is None and frame.f_globals is not seen:
            seen = frame.f_globals  # consecutive frames of one module share their globals
            homework = seen.get("HOMEWORK")
            if isinstance(homework, str) and homework in homeworks:
                value_question = _VALUE_GUARDS[(homework, implementation)]
        frame = frame.f_back
    for guarded in list(_ACTIVE):  # an evaluation on another thread of this process
        if implementation in guarded:
            raise ExerciseError(implementation, guarded[implementation])
    if value_question is not None:
        raise ExerciseError(implementation, value_question)


def _guarded(questions: tuple[str, ...]) -> dict[str, str]:
    out: dict[str, str] = {}
    for q in questions:
        exercise = EXERCISES.get(q)
        if exercise is not None:
            for name in exercise.implementations:
                out.setdefault(name, q)
    return out


_INHERITED = _from_environment()


def grader_state_text(homework: str, questions: tuple[str, ...] = ()) -> str:
    """The text of :data:`GRADER_STATE_FILE`: the homework graded, then the questions whose
    exercises are being evaluated now (one line each).

    Written by the grader (``tools/grading/runner.py``) before a request and after it.
    """
    for name, value in (("homework", homework), *(("questions", q) for q in questions)):
        if not isinstance(value, str) or not value.isprintable() or "\n" in value:
            raise ValueError(f"{name} must be a one-line string, got {value!r}")
    return "\n".join([homework, *questions]) + "\n"


def _read_state() -> tuple[str, tuple[str, ...]] | None:
    """``(homework, questions)`` from :data:`GRADER_STATE_FILE`, or None if unreadable."""
    try:
        fd = _OS_OPEN(GRADER_STATE_FILE, _O_RDONLY)
        try:
            data = _OS_READ(fd, 65536)
        finally:
            _OS_CLOSE(fd)
        lines = [line.strip() for line in data.decode("utf-8").splitlines()]
    except (OSError, UnicodeDecodeError):
        return None
    return (lines[0], tuple(lines[1:])) if lines else ("", ())


def _any_question(implementation: str) -> str | None:
    """The first question, function or value, that ``implementation`` is the exercise of."""
    for table in (EXERCISES, VALUE_EXERCISES):
        for q, e in table.items():
            if implementation in e.implementations:
                return q
    return None


def _graded_guard(implementation: str) -> None:
    """In the grader's sandbox: raise if the grader's state says ``implementation`` is guarded.

    An unreadable state (a submission that used up its file descriptors) guards everything.
    """
    state = _read_state()
    if state is None:
        question = _any_question(implementation)
        if question is not None:
            raise ExerciseError(implementation, question)
        return
    homework, questions = state
    question = _guarded(questions).get(implementation) or _VALUE_GUARDS.get(
        (homework, implementation)
    )
    if question is not None:
        raise ExerciseError(implementation, question)


_OS_OPEN, _OS_READ, _OS_CLOSE, _O_RDONLY = os.open, os.read, os.close, os.O_RDONLY
#: In the grader's sandbox (its state file is there from the sandbox's start, or never)
_GRADED = os.path.isfile(GRADER_STATE_FILE)


def _intact(dotted: str) -> bool:
    """Is ``dotted`` still the library's function, starting with its guard?"""
    module_name, name = dotted.rsplit(".", 1)
    module = sys.modules.get(module_name)
    if module is None:  # not imported yet: imported from its file, so as shipped
        return True
    if getattr(module, "own_work", None) is not sys.modules.get(__name__):
        return False
    func = getattr(module, name, None)
    code = getattr(func, "__code__", None)
    return code is None or (dotted in code.co_consts and "require" in code.co_names)


def _check_intact(guarded: Mapping[str, str]) -> None:
    """Refuse to evaluate an exercise whose guard a notebook switched off by rebinding a name
    (``own_work.require = ...``, ``knot_splines.own_work = ...``, a function's ``__code__``)."""
    me = sys.modules.get(__name__)
    switched_off = (
        me is None
        or getattr(me, "_GRADED", None) is not os.path.isfile(GRADER_STATE_FILE)
        or getattr(me, "require", None) is not _REQUIRE
        or _REQUIRE.__code__ is not _REQUIRE_CODE
        or getattr(me, "_getframe", None) is not _GETFRAME
    )
    for dotted, question in guarded.items():
        if switched_off or not _intact(dotted):
            raise ExerciseError(dotted, question, switched_off=True)


def run_exercise(
    questions: tuple[str, ...], func: Callable[..., Any], /, *args: Any, **kwargs: Any
) -> Any:
    """Call ``func(*args, **kwargs)`` with the exercises of ``questions`` guarded.

    The probe calls a student's function through this when the grader asks for it, and the
    feedback checks do too (:func:`course_lib.homework.checks._core.call_answer`); the state is restored
    afterwards, whatever happens.
    """
    guarded = _guarded(tuple(questions))  # read by require() in this frame's locals
    _check_intact(guarded)
    entry = dict(guarded)
    previous = os.environ.get(ENV_VAR)
    with _lock:
        _ACTIVE.append(entry)
    os.environ[ENV_VAR] = ",".join(sorted(set(questions)))
    try:
        return func(*args, **kwargs)
    finally:
        with _lock:
            try:
                _ACTIVE.remove(entry)
            except ValueError:  # a notebook emptied the list: nothing to restore
                pass
        if previous is None:
            os.environ.pop(ENV_VAR, None)
        else:
            os.environ[ENV_VAR] = previous


_RUN_CODE = run_exercise.__code__
_REQUIRE, _REQUIRE_CODE, _GETFRAME = require, require.__code__, sys._getframe
