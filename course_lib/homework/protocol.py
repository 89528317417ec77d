"""The student side of the grading boundary: answers out as plain data, nothing else.

The grader (``tools/grade.py``) never runs a hidden test where student code runs.  It runs the
student's notebook in a sandboxed kernel and then asks that kernel, one request at a time, for
*data*: the value of a name, the result of calling the student's function on inputs the
grader chose, or the values of a symbolic answer at points the grader chose.  This module
answers those requests inside the kernel.  It is deliberately small and knows nothing about
expected values or hidden tests: everything it sends back is treated by the grader as untrusted
input, validated there, and compared there.

Requests and responses are JSON text (never pickle):

``{"op": "get", "name": "answer_q1"}``
    the value of a global name;
``{"op": "call", "name": "is_g1", "args": [...], "kwargs": {...}}``
    call the student's function; arrays travel as ``{"__ndarray__": nested list}``;
``{"op": "expr", "name": "answer_q4", "symbols": ["beta1", ...], "points": [[...], ...]}``
    a symbolic answer (a sympy expression or a string) evaluated at the given points, with the
    names of its free symbols.

A response is ``{"ok": true, "value": <encoded>}`` or ``{"ok": false, "error": KIND, "message":
TEXT}`` with KIND one of ``missing``, ``ellipsis``, ``not_implemented``, ``raised``,
``unsupported``, ``bad_request`` -- or ``exercise``, when a library implementation raised
:class:`course_lib.homework.own_work.ExerciseError` (it is the exercise being evaluated), with its
``implementation``, ``question`` and ``switched_off`` as fields: the grader writes the
sentence from those, checked against the registry, never from the text.  Encoded values
are JSON scalars and lists, plus the tagged objects ``__ndarray__`` (with ``shape`` and
``kind``), ``__complex__``, ``__float__`` (nan/inf), ``__callable__``, ``__dict__`` and
``__sympy__`` (a string, for display only: the grader never parses it).

Why this module is long: the wire format is one protocol (encoded in the student's kernel,
decoded by the grader) and is audited as one file.
"""

from __future__ import annotations

import json
import math
import sys
from typing import Any

import numpy as np

from course_lib.homework import own_work

MAX_ELEMENTS = 200_000
MAX_DEPTH = 8
MAX_STRING = 20_000
MAX_INT_BITS = 256
MAX_POINTS = 64
MAX_DECODE_DEPTH = 10

__all__ = [
    "FunctionMarker",
    "Malformed",
    "SymbolicText",
    "Unsupported",
    "decode",
    "decode_argument",
    "decode_number",
    "encode",
    "handle",
    "serve",
]


class Unsupported(Exception):
    """The value cannot be sent as plain data."""


class Malformed(ValueError):
    """Encoded data that no encoder of ours wrote (the grader treats it as a bad answer)."""


class SymbolicText(str):
    """A symbolic answer's text, for messages only: never parse it (use an ``expr`` request)."""


class FunctionMarker:
    """A function found where data was expected (the grader binds it to the student's function)."""

    def __init__(self, name: str) -> None:
        self.name = name

    def __call__(self, *args: Any, **kwargs: Any) -> Any:
        raise TypeError("a function inside an answer cannot be called")


class _Budget:
    def __init__(self) -> None:
        self.left = MAX_ELEMENTS

    def take(self, n: int = 1) -> None:
        self.left -= n
        if self.left < 0:
            raise Unsupported(f"the answer is too large (more than {MAX_ELEMENTS} numbers)")


def _float(x: float) -> Any:
    if math.isfinite(x):
        return x
    return {"__float__": "nan" if x != x else ("inf" if x > 0 else "-inf")}


def _sympy_module():
    return sys.modules.get("sympy")


def encode(value: Any, *, _depth: int = 0, _budget: _Budget | None = None) -> Any:
    """Encode ``value`` as plain JSON data, or raise :class:`Unsupported`.

    The kinds are tried in a fixed order (Python scalars, numpy, lists and dictionaries,
    sympy, callables): a ``numpy.float64`` is a ``float`` and is sent as one.
    """
    budget = _budget if _budget is not None else _Budget()
    budget.take()
    if _depth > MAX_DEPTH:
        raise Unsupported(f"the answer is nested more than {MAX_DEPTH} levels deep")
    for encoder in (_encode_scalar, _encode_numpy, _encode_container, _encode_sympy):
        out = encoder(value, _depth, budget)
        if out is not _NOT_MINE:
            return out
    if callable(value):
        return {"__callable__": str(getattr(value, "__name__", type(value).__name__))[:100]}
    raise Unsupported(f"a value of type {type(value).__name__} cannot be graded")


#: What an ``_encode_*`` helper returns for a value of a kind it does not handle
#: (``None`` is an answer: the encoding of ``None``).
_NOT_MINE = object()


def _complex(real: float, imag: float) -> dict:
    return {"__complex__": [_float(real), _float(imag)]}


def _encode_scalar(value: Any, _depth: int, _budget: _Budget) -> Any:
    """None, bool, int, float, complex, str (and their subclasses, sent as the base type)."""
    if value is None or isinstance(value, bool):
        return None if value is None else bool(value)
    if isinstance(value, int):
        if int.bit_length(value) > MAX_INT_BITS:
            raise Unsupported("an integer in the answer is too large")
        return int.__index__(value)
    if isinstance(value, float):
        return _float(float.__float__(value))
    if isinstance(value, complex):
        return _complex(value.real, value.imag)
    if isinstance(value, str):
        if len(value) > MAX_STRING:
            raise Unsupported(f"a string in the answer is longer than {MAX_STRING} characters")
        return str.__str__(value)
    return _NOT_MINE


def _encode_numpy(value: Any, depth: int, budget: _Budget) -> Any:
    """numpy scalars and arrays (only if the notebook imported numpy)."""
    np = sys.modules.get("numpy")
    if np is None:
        return _NOT_MINE
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, np.integer):
        return encode(int(value), _depth=depth, _budget=budget)
    if isinstance(value, np.floating):
        return _float(float(value))
    if isinstance(value, np.complexfloating):
        return _complex(float(value.real), float(value.imag))
    if isinstance(value, np.ndarray):
        return _encode_ndarray(np, value, depth, budget)
    return _NOT_MINE


def _encode_ndarray(np, value, depth: int, budget: _Budget) -> dict:
    """``{"__ndarray__": nested list, "shape", "kind"}`` for a numeric or object array."""
    if value.size > MAX_ELEMENTS:
        raise Unsupported(f"the answer is too large (more than {MAX_ELEMENTS} numbers)")
    kind = value.dtype.kind
    if kind in "biuf":
        budget.take(int(value.size))
        data = value.astype(float if kind == "f" else value.dtype).tolist()
        if kind == "f" and not bool(np.all(np.isfinite(value))):
            data = _map_nested(data, _float)
    elif kind == "c":
        budget.take(2 * int(value.size))
        data = _map_nested(value.tolist(), lambda z: _complex(z.real, z.imag))
    elif kind == "O":
        items = [encode(v, _depth=depth + 1, _budget=budget) for v in value.ravel().tolist()]
        data = _reshape(items, value.shape)
    else:
        raise Unsupported(f"an array of dtype {value.dtype} is not a numeric answer")
    return {"__ndarray__": data, "shape": list(value.shape), "kind": kind}


def _encode_container(value: Any, depth: int, budget: _Budget) -> Any:
    """Lists and tuples (as lists), dictionaries with string keys (as ``__dict__``)."""
    if isinstance(value, (list, tuple)):
        if len(value) > MAX_ELEMENTS:
            raise Unsupported(f"the answer is too large (more than {MAX_ELEMENTS} items)")
        return [encode(v, _depth=depth + 1, _budget=budget) for v in list.__iter__(list(value))]
    if isinstance(value, dict):
        out = {}
        for k, v in dict.items(value):
            if not isinstance(k, str):
                raise Unsupported("only dictionaries with string keys can be answers")
            out[str.__str__(k)] = encode(v, _depth=depth + 1, _budget=budget)
        return {"__dict__": out}
    return _NOT_MINE


def _encode_sympy(value: Any, depth: int, budget: _Budget) -> Any:
    """sympy matrices (as lists), booleans, numbers (as numbers), expressions (``__sympy__``
    text, for display only)."""
    sp = _sympy_module()
    if sp is None:
        return _NOT_MINE
    if isinstance(value, sp.MatrixBase):  # mutable matrices are not sp.Basic
        return [encode(row, _depth=depth + 1, _budget=budget) for row in value.tolist()]
    if isinstance(value, sp.logic.boolalg.BooleanAtom):
        return bool(value)
    if not isinstance(value, sp.Basic):
        return _NOT_MINE
    if getattr(value, "is_number", False):
        try:
            z = complex(value.evalf())
        except (TypeError, ValueError):
            raise Unsupported("a sympy number in the answer has no numeric value") from None
        if z.imag == 0 or z.imag != z.imag:
            return _float(z.real)
        return _complex(z.real, z.imag)
    return {"__sympy__": sp.sstr(value)[:MAX_STRING]}


def _map_nested(data: Any, fn) -> Any:
    if isinstance(data, list):
        return [_map_nested(d, fn) for d in data]
    return fn(data)


def _reshape(items: list, shape: tuple) -> Any:
    if len(shape) == 0:
        return items[0]
    if len(shape) == 1:
        return items
    step = len(items) // shape[0] if shape[0] else 0
    return [_reshape(items[i * step : (i + 1) * step], shape[1:]) for i in range(shape[0])]


def decode_argument(obj: Any) -> Any:
    """Turn a request's argument back into Python objects (arrays become numpy arrays)."""
    if isinstance(obj, list):
        return [decode_argument(o) for o in obj]
    if isinstance(obj, dict):
        if "__ndarray__" in obj:
            import numpy as np

            return np.array(obj["__ndarray__"], dtype=obj.get("dtype", "float"))
        if "__float__" in obj:
            return float(obj["__float__"])
        if "__dict__" in obj:
            return {k: decode_argument(v) for k, v in obj["__dict__"].items()}
        raise ValueError("unknown tagged argument")
    return obj


def _fail(kind: str, message: str) -> dict:
    return {"ok": False, "error": kind, "message": message[:500]}


def _exercise(exc: own_work.ExerciseError) -> dict:
    """The response for a library implementation that is the exercise being evaluated."""
    return {
        "ok": False,
        "error": "exercise",
        "implementation": str(exc.implementation)[:300],
        "question": str(exc.question)[:100],
        "switched_off": bool(exc.switched_off),
        "message": str(exc)[:500],
    }


def _lookup(namespace: dict, name: Any) -> tuple[bool, Any]:
    if not isinstance(name, str) or name not in namespace:
        return False, None
    return True, namespace[name]


def _as_sympy(value: Any):
    import sympy as sp

    try:
        if isinstance(value, str):
            if len(value) > MAX_STRING:
                raise Unsupported("the expression's text is too long")
            return sp.sympify(value)
        return sp.sympify(value, strict=True)
    except Unsupported:
        raise
    except Exception:  # SympifyError, SyntaxError, TypeError, ...: the student's form, not a crash
        what = "the text" if isinstance(value, str) else f"a {type(value).__name__}"
        raise Unsupported(
            f"a symbolic answer must be a sympy expression or its text; {what} could not be read "
            "as one"
        ) from None


def evaluate_expression(value: Any, symbols: list, points: list) -> dict:
    """Free symbol names of ``value`` and (if they are among ``symbols``) its values at ``points``.

    Used by :func:`handle` for the grader and by ``course_lib.homework.answers.evaluate`` for the
    feedback checks, so both see the same numbers.
    """
    import sympy as sp

    expr = _as_sympy(value)
    if not isinstance(expr, sp.Expr) or getattr(expr, "is_Matrix", False):
        if isinstance(expr, sp.Equality):
            what = "an equation (sp.Eq): give only the expression, e.g. the right-hand side"
        elif getattr(expr, "is_Matrix", False):
            what = "a matrix"
        else:
            kind = type(expr).__name__
            what = f"{'an' if kind[:1].lower() in 'aeiou' else 'a'} {kind}"
        raise Unsupported(f"a symbolic answer must be a single expression, not {what}")
    free = sorted({s.name for s in expr.free_symbols})
    values = None
    if set(free) <= set(symbols):
        by_name: dict = {}
        for s in expr.free_symbols:
            by_name.setdefault(s.name, []).append(s)  # beta1 and beta1(positive) are one name
        values = []
        for point in points[:MAX_POINTS]:
            pairs = zip(symbols, point, strict=False)
            subs = {s: sp.Float(x, 30) for n, x in pairs for s in by_name.get(n, ())}
            try:
                z = complex(sp.N(expr.xreplace(subs), 20))
            except (TypeError, ValueError):
                raise Unsupported(
                    "the expression does not evaluate to a number (is there an unevaluated "
                    "function or derivative left in it?)"
                ) from None
            values.append(
                _float(z.real)
                if z.imag == 0 or z.imag != z.imag
                else {"__complex__": [_float(z.real), _float(z.imag)]}
            )
    return {"symbols": free, "values": values}


def handle(request: dict, namespace: dict) -> dict:
    """Answer one request (see the module docstring) from the notebook's ``namespace``."""
    if not isinstance(request, dict):
        return _fail("bad_request", "the request is not an object")
    op = request.get("op")
    found, value = _lookup(namespace, request.get("name"))
    if not found:
        return _fail("missing", str(request.get("name")))
    if value is Ellipsis:
        return _fail("ellipsis", str(request.get("name")))
    try:
        if op == "get":
            return {"ok": True, "value": encode(value)}
        if op == "call":
            if not callable(value):
                return _fail("unsupported", f"`{request['name']}` is not a function")
            args = decode_argument(request.get("args", []))
            kwargs = decode_argument({"__dict__": request.get("kwargs", {})})
            # the library's implementations of this exercise raise while it runs (own_work)
            questions = own_work.questions_of(request.get("name"))
            result = own_work.run_exercise(questions, value, *args, **kwargs)
            return {"ok": True, "value": encode(result)}
        if op == "expr":
            symbols = [str(s) for s in request.get("symbols", [])]
            points = [[float(x) for x in p] for p in request.get("points", [])]
            return {"ok": True, "value": evaluate_expression(value, symbols, points)}
        return _fail("bad_request", f"unknown op {op!r}")
    except own_work.ExerciseError as exc:  # the marker of the exercise, by type, not by text
        return _exercise(exc)
    except Unsupported as exc:
        return _fail("unsupported", str(exc))
    except NotImplementedError:
        return _fail("not_implemented", "the function still raises NotImplementedError")
    except RecursionError:
        return _fail("raised", "RecursionError: the code recursed without end")
    except BaseException as exc:  # student code may raise anything, even SystemExit
        if isinstance(exc, KeyboardInterrupt):
            raise
        return _fail("raised", f"{type(exc).__name__}: {exc}")


def serve(request_json: str, namespace: dict, out_path: str) -> None:
    """Answer the request in ``request_json`` and write the JSON response to ``out_path``."""
    try:
        response = handle(json.loads(request_json), namespace)
        text = json.dumps(response, allow_nan=False)
    except BaseException as exc:  # anything at all: the grader gets a clear error
        if isinstance(exc, KeyboardInterrupt):
            raise
        text = json.dumps(
            _fail("unsupported", f"the answer could not be sent: {type(exc).__name__}")
        )
    with open(out_path, "w", encoding="utf-8") as fh:
        fh.write(text)


# ---------------------------------------------------------------- decoding (the grader's side)


def _decode_float(tag: Any) -> float:
    if tag == "nan":
        return math.nan
    if tag == "inf":
        return math.inf
    if tag == "-inf":
        return -math.inf
    raise Malformed("malformed answer (bad float tag)")


def decode_number(obj: Any) -> Any:
    if isinstance(obj, bool) or obj is None:
        return obj
    if isinstance(obj, (int, float)):
        return obj
    if isinstance(obj, dict) and set(obj) == {"__float__"}:
        return _decode_float(obj["__float__"])
    if isinstance(obj, dict) and set(obj) == {"__complex__"}:
        re_im = obj["__complex__"]
        if not (isinstance(re_im, list) and len(re_im) == 2):
            raise Malformed("malformed answer (bad complex)")
        re, im = (decode_number(x) for x in re_im)
        if not all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (re, im)):
            raise Malformed("malformed answer (bad complex)")
        return complex(re, im)
    raise Malformed("malformed answer (not a number)")


def _nested_shape(data: Any, shape: list[int]) -> bool:
    if not shape:
        return not isinstance(data, list)
    return (
        isinstance(data, list)
        and len(data) == shape[0]
        and all(_nested_shape(d, shape[1:]) for d in data)
    )


def _decode_array(obj: dict, depth: int) -> np.ndarray:
    if set(obj) != {"__ndarray__", "shape", "kind"}:
        raise Malformed("malformed answer (bad array)")
    shape, kind, data = obj["shape"], obj["kind"], obj["__ndarray__"]
    if not (isinstance(shape, list) and all(isinstance(n, int) and n >= 0 for n in shape)):
        raise Malformed("malformed answer (bad array shape)")
    if len(shape) > MAX_DECODE_DEPTH or not _nested_shape(data, shape):
        raise Malformed("malformed answer (array data does not match its shape)")
    flat: list = []

    def walk(d):
        if isinstance(d, list):
            for x in d:
                walk(x)
        else:
            flat.append(d)

    walk(data)
    if kind == "O":
        items = [decode(x, depth + 1) for x in flat]
        arr = np.empty(len(items), dtype=object)
        arr[:] = items
        return arr.reshape(shape)
    values = [decode_number(x) for x in flat]
    dtypes = {"b": bool, "i": np.int64, "u": np.uint64, "f": float, "c": complex}
    if kind not in dtypes:
        raise Malformed("malformed answer (bad array kind)")
    if kind in "iu" and any(isinstance(v, (float, complex)) for v in values):
        raise Malformed("malformed answer (bad integer array)")
    try:
        return np.array(values, dtype=dtypes[kind]).reshape(shape)
    except (OverflowError, ValueError, TypeError) as exc:
        raise Malformed(f"malformed answer ({exc})") from None


def decode(obj: Any, depth: int = 0) -> Any:
    """Validate and decode one encoded value (untrusted JSON data); raise :class:`Malformed`.

    The grader decodes every answer with this, and ``course_lib.homework.answers.plain`` decodes the
    checks' own encoding with it too, so both see exactly the same plain data.
    """
    if depth > MAX_DECODE_DEPTH:
        raise Malformed("malformed answer (nested too deeply)")
    if obj is None or isinstance(obj, (bool, int, float, str)):
        if isinstance(obj, float) and not math.isfinite(obj):
            raise Malformed("malformed answer (bare non-finite number)")
        return obj
    if isinstance(obj, list):
        return [decode(x, depth + 1) for x in obj]
    if isinstance(obj, dict):
        keys = set(obj)
        if keys in ({"__float__"}, {"__complex__"}):
            return decode_number(obj)
        if "__ndarray__" in keys:
            return _decode_array(obj, depth)
        if keys == {"__dict__"} and isinstance(obj["__dict__"], dict):
            return {str(k): decode(v, depth + 1) for k, v in obj["__dict__"].items()}
        if keys == {"__callable__"}:
            return FunctionMarker(str(obj["__callable__"])[:100])
        if keys == {"__sympy__"} and isinstance(obj["__sympy__"], str):
            return SymbolicText(obj["__sympy__"])
    raise Malformed("malformed answer (unknown data)")
