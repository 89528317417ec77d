"""IPython start-up file of the site and handout build (never of a student's kernel).

``tools/build_site.py`` copies this file into a private ``IPYTHONDIR``
(``profile_default/startup/``) of the kernels that execute the notebooks for the website, so
the notebooks stay untouched and still render without a browser:

* every live demo draws its static fallback figure: any callable of ``course_lib.widgets``
  (and its submodules) that takes a ``static`` keyword is called with ``static=True``;
* ``%matplotlib widget`` / ``ipympl`` becomes ``%matplotlib inline`` (a static page has no
  kernel behind an ipympl canvas).

To run a demo live, open the notebook in JupyterLab (``make lab``) or Voilà.
"""

from __future__ import annotations


def _course_static_build() -> None:
    import functools
    import importlib
    import inspect
    import pkgutil

    from IPython import get_ipython
    from IPython.core.magic import register_line_magic

    ip = get_ipython()
    if ip is None:  # pragma: no cover - only ever run by an IPython kernel
        return

    # ---- %matplotlib widget -> inline
    original = ip.find_line_magic("matplotlib")

    @register_line_magic("matplotlib")
    def matplotlib(line: str = ""):
        gui = line.strip().split()
        if gui and gui[0] in ("widget", "ipympl", "notebook", "nbagg"):
            line = "inline"
        return original(line)

    ip.run_line_magic("matplotlib", "inline")

    # ---- demos: static=True
    try:
        pkg = importlib.import_module("course_lib.widgets")
    except Exception:  # a notebook without course_lib still builds
        return
    modules = [pkg]
    for info in pkgutil.iter_modules(pkg.__path__, pkg.__name__ + "."):
        try:
            modules.append(importlib.import_module(info.name))
        except Exception:
            continue

    def force_static(fn):
        if getattr(fn, "__course_static__", False):
            return fn

        sig = inspect.signature(fn)

        @functools.wraps(fn)
        def wrapper(*args, **kwargs):
            bound = sig.bind(*args, **kwargs)
            bound.arguments["static"] = True
            return fn(*bound.args, **bound.kwargs)

        wrapper.__course_static__ = True
        return wrapper

    wrapped: dict[int, object] = {}
    for mod in modules:
        for name, obj in list(vars(mod).items()):
            if name.startswith("_") or not inspect.isfunction(obj):
                continue
            try:
                params = inspect.signature(obj).parameters
            except (TypeError, ValueError):
                continue
            if "static" in params:
                new = wrapped.setdefault(id(obj), force_static(obj))
                setattr(mod, name, new)
        if hasattr(mod, "widgets_available"):  # the default of static=None
            mod.widgets_available = lambda: False


_course_static_build()
del _course_static_build
