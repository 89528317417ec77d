"""Names for the sliders' handles: ipywidgets leaves each handle without an accessible name.

:data:`SLIDER_NAMES_JS` runs in the front end and gives each slider handle the name of its
label and a value text (WCAG 4.1.2), and lets Tab leave a demo's ipympl canvas, whose own key
handler would keep the focus there (a keyboard trap, WCAG 2.1.2);
:func:`publish_slider_names` sends it from a running kernel.  Kept apart from :mod:`course_lib.widgets.access` so that the assembly, which calls
it, and the keyboard controls, which use the assembly, import each other in one direction.
"""

from __future__ import annotations

SLIDER_NAMES_JS = r"""
(() => {
  if (window.__courseSliderNames) { window.__courseSliderNames(); return; }
  const fix = () => {
    // JupyterLab's command-mode shortcuts (arrows, Enter, ...) would take the keys from the
    // demo's selects, buttons and slider handles: Lumino skips an element with this attribute
    // (it must be on the focused element itself: the shortcut's selector matches it first)
    const controls = '.cl-demo select, .cl-demo input, .cl-demo button, .cl-demo [tabindex]';
    for (const el of document.querySelectorAll(controls)) {
      if (!el.hasAttribute('data-lm-suppress-shortcuts')) {
        el.setAttribute('data-lm-suppress-shortcuts', 'true');
      }
    }
    for (const box of document.querySelectorAll('.cl-demo .widget-slider')) {
      const handle = box.querySelector('.noUi-handle');
      const label = box.querySelector('.widget-label');
      const readout = box.querySelector('.widget-readout');
      if (!handle) continue;
      const name = label ? label.textContent.trim() : '';
      if (name && handle.getAttribute('aria-label') !== name) handle.setAttribute('aria-label', name);
      const text = readout ? readout.textContent.trim() : '';
      if (text && handle.getAttribute('aria-valuetext') !== text) handle.setAttribute('aria-valuetext', text);
      if (readout && name && readout.getAttribute('aria-label') !== name + ' value') {
        readout.setAttribute('aria-label', name + ' value');
      }
    }
    for (const canvas of document.querySelectorAll('.cl-demo canvas')) {
      if (!canvas.getAttribute('aria-label')) {
        canvas.setAttribute('role', 'img');
        const demo = canvas.closest('.cl-demo');
        const points = demo && demo.querySelector('.cl-point-controls');
        canvas.setAttribute('aria-label', 'demo figure, described by the report below it' +
          (points ? '; move a point with the point controls below the figure' : ''));
      }
    }
  };
  let queued = false;
  const later = () => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => { queued = false; fix(); });
  };
  window.__courseSliderNames = fix;
  // WCAG 2.1.2 (no keyboard trap): ipympl's canvas is a tab stop whose keydown handler calls
  // preventDefault on every key, Tab included, so Tab never leaves a demo's canvas (JupyterLab
  // and Voila alike).  Tab and Shift+Tab on a course demo's canvas are stopped here, in the
  // capture phase before ipympl sees them, and move the focus on as everywhere else.
  document.addEventListener('keydown', (e) => {
    const t = e.target;
    if (e.key === 'Tab' && t && t.classList &&
        t.classList.contains('jupyter-matplotlib-canvas-div') && t.closest('.cl-demo')) {
      e.stopPropagation();
    }
  }, true);
  new MutationObserver(later).observe(document.body, {
    subtree: true, childList: true, characterData: true,
    attributes: true, attributeFilter: ['aria-valuetext'],
  });
  fix();
})();
"""


def slider_names_bundle() -> dict:
    """The display bundle of :data:`SLIDER_NAMES_JS` (``application/javascript``).

    JupyterLab and Voilà run it for outputs of the running session (trusted); elsewhere it
    is inert and the sliders keep ipywidgets' own (unnamed) handles.
    """
    return {"application/javascript": SLIDER_NAMES_JS, "text/plain": ""}


def publish_slider_names() -> None:
    """Send :data:`SLIDER_NAMES_JS` to the front end (inside IPython only; else nothing)."""
    import sys

    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None else None
    if shell is None or not hasattr(shell, "display_pub"):
        return
    from IPython.display import publish_display_data

    publish_display_data(slider_names_bundle())
