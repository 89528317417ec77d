"""The text alternative of a figure, shown as text under it in JupyterLab.

Convention of the course: a code cell that draws a figure carries its text alternative in
its cell metadata, ``{"mystnb": {"image": {"alt": "..."}}}`` -- written for someone who
cannot see the figure: what it shows and what to notice, in a sentence or two.

* The website (MyST-NB) uses it as the figure's ``alt`` and ``tools/build_site.py`` adds it
  as a visible caption ("Figure: ...").
* JupyterLab drops ``alt`` (figure outputs have none).  JupyterLab sends the cell's metadata
  with every execute request; when ``course_lib`` is imported in a kernel, :func:`register`
  adds a ``post_run_cell`` hook that prints the cell's alt text as a Markdown line under
  the cell's outputs, "*Figure:* ...", so it is read and seen next to the figure.  Nothing
  is needed in the cells themselves.  Kernels that get no cell metadata (nbclient, nbval,
  the site build) print nothing.

Importing this module loads nothing heavy; IPython is only used if it is already loaded.
"""

from __future__ import annotations

import sys

__all__ = ["CAPTION_PREFIX", "caption_markdown", "cell_alt", "register", "register_in_kernel"]

#: The visible line starts with this (site and JupyterLab alike).
CAPTION_PREFIX = "Figure:"


def cell_alt(metadata) -> str | None:
    """The alt text in a cell's metadata (``mystnb.image.alt``), stripped; None if absent
    or blank."""
    if not isinstance(metadata, dict):
        return None
    image = (metadata.get("mystnb") or {}).get("image") or {}
    alt = image.get("alt") if isinstance(image, dict) else None
    if not isinstance(alt, str) or not alt.strip():
        return None
    return " ".join(alt.split())


def caption_markdown(alt: str) -> str:
    """The Markdown line shown under a figure: ``*Figure:* <alt>``."""
    return f"*{CAPTION_PREFIX}* {alt}"


def _post_run_cell(result) -> None:
    info = getattr(result, "info", None)
    if getattr(result, "error_before_exec", None) or getattr(result, "error_in_exec", None):
        return
    if info is not None and getattr(info, "silent", False):
        return
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    kernel = getattr(shell, "kernel", None)
    if kernel is None or not hasattr(kernel, "get_parent"):
        return
    parent = kernel.get_parent("shell") or {}
    alt = cell_alt(parent.get("metadata"))
    if alt is None:
        return
    from IPython.display import publish_display_data

    publish_display_data(
        {"text/markdown": caption_markdown(alt), "text/plain": f"{CAPTION_PREFIX} {alt}"},
        metadata={"course_figure_alt": True},
    )


def register(shell) -> bool:
    """Add the hook to an IPython ``shell`` (once).  Returns True if it is registered."""
    events = getattr(shell, "events", None)
    if events is None:
        return False
    if _post_run_cell not in events.callbacks.get("post_run_cell", []):
        events.register("post_run_cell", _post_run_cell)
    return True


def register_in_kernel() -> bool:
    """:func:`register` in the running IPython kernel, if there is one (else nothing)."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is None or getattr(shell, "kernel", None) is None:
        return False
    return register(shell)
