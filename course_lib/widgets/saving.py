"""No dead widgets on reopening: what JupyterLab saves of a demo.

A demo's output is a widget *view* that points at a model living in the kernel.  When
JupyterLab autosaves a notebook with outputs and the notebook is opened again later (new
kernel, no models), every demo shows "Error displaying widget: model not found".
:func:`strip_widget_outputs` replaces each widget view in the saved file by a one-line
text saying how to bring the demo back, and drops the saved widget state; ``make lab``
installs it as JupyterLab's pre-save hook (``.jupyter-course/jupyter_server_config.py``).
Figures, text and every other output are kept.
"""

from __future__ import annotations

__all__ = ["WIDGET_MIME", "WIDGET_PLACEHOLDER", "pre_save_hook", "strip_widget_outputs"]

WIDGET_MIME = "application/vnd.jupyter.widget-view+json"
WIDGET_PLACEHOLDER = "(live demo: run this cell to show it again)"


def strip_widget_outputs(nb: dict) -> int:
    """Replace the widget views of notebook ``nb`` (a dict, changed in place) by a text
    placeholder and drop ``metadata.widgets``.  Returns the number of views replaced."""
    n = 0
    for cell in nb.get("cells", ()):
        for out in cell.get("outputs", ()) or ():
            data = out.get("data")
            if isinstance(data, dict) and WIDGET_MIME in data:
                out["data"] = {"text/plain": WIDGET_PLACEHOLDER}
                out.get("metadata", {}).pop(WIDGET_MIME, None)
                n += 1
    meta = nb.get("metadata")
    if isinstance(meta, dict):
        meta.pop("widgets", None)
    return n


def pre_save_hook(model, **kwargs) -> None:
    """``ContentsManager.pre_save_hook``: strip widget views from notebooks being saved."""
    if model.get("type") == "notebook" and isinstance(model.get("content"), dict):
        strip_widget_outputs(model["content"])
