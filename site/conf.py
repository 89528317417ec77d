"""Sphinx configuration of the course website (built by ``tools/build_site.py``).

The notebooks arrive here already executed (``nb_execution_mode = "off"``); MathJax 2.7 is
served from ``_static/mathjax`` (copied from the ``jupyter-server-mathjax`` package), so
the site loads nothing from the network.
"""

from __future__ import annotations

import re

project = "Geometric continuity of parametric curves"
language = "en"  # <html lang="en"> on every page, and so the handouts' /Lang (WCAG 3.1.1)
author = "the course authors"
copyright = "the course authors"
extensions = ["myst_nb"]
exclude_patterns = ["_build", "**.ipynb_checkpoints"]
source_suffix = {".md": "myst-nb", ".ipynb": "myst-nb"}

# ---- notebooks: executed by tools/build_site.py (cached), never here
nb_execution_mode = "off"
nb_merge_streams = True
nb_output_stderr = "remove-warn"
myst_enable_extensions = ["dollarmath", "amsmath", "colon_fence"]
myst_heading_anchors = 3
myst_dmath_double_inline = True
myst_update_mathjax = False  # its MathJax 3 settings; MathJax 2 is configured below  # $$...$$ inside a paragraph, as JupyterLab renders it
suppress_warnings = ["mystnb.unknown_mime_type", "myst.header"]

# ---- math: MathJax 2.7, local (relative to _static/)
mathjax_path = "mathjax/MathJax.js?config=TeX-AMS-MML_HTMLorMML-full"
mathjax2_config = {
    # MyST and MyST-NB write all math (prose and sympy's LaTeX outputs) as \(..\) / \[..\];
    # a stray "$" is left alone (and caught by tests/test_site.py).
    "tex2jax": {"inlineMath": [["\\(", "\\)"]], "displayMath": [["\\[", "\\]"]]},
    "HTML-CSS": {
        "availableFonts": ["STIX-Web"],
        "preferredFont": "STIX-Web",
        "webFont": "STIX-Web",
        "imageFont": None,
        "linebreaks": {"automatic": True},
    },
    # the menu (zoom, MathML, speech) on the right-click/context-menu key; formulas out of the
    # tab order: a keyboard user would otherwise meet one dead stop per formula (WCAG 2.4.3);
    # screen readers read the MathML MathJax adds next to each formula (AssistiveMML)
    "showMathMenu": True,
    "menuSettings": {"inTabOrder": False},
    "messageStyle": "none",
}

# ---- theme: sphinx-book-theme (pydata-sphinx-theme; its fonts and icons are bundled)
html_theme = "sphinx_book_theme"
html_title = "Geometric continuity"
html_static_path = ["_static"]
# _templates/search-button-field.html (the theme finds its components by name on
# templates_path): its search button, with the visible text as accessible name (WCAG 2.5.3)
templates_path = ["_templates"]
html_css_files = ["course.css"]
html_last_updated_fmt = None
html_copy_source = False
html_show_sourcelink = False
html_theme_options = {
    "show_toc_level": 2,
    "show_navbar_depth": 1,
    "use_download_button": False,
    "use_fullscreen_button": False,
    "use_repository_button": False,
    "home_page_in_toc": True,
    "navigation_with_keys": False,
    # no "pygments_light_style": the theme's default (a11y-high-contrast-light) keeps every
    # code token at 4.5:1 or more on the code background (WCAG 1.4.3)
}


# ---- browser-tab titles: plain text.  Sphinx fills <title> with the page title's text, so a
# heading with math ("... $G^n$ ...") would show its TeX source "\(G^n\)" in the tab; the
# heading itself keeps its math (MathJax renders it in the page).
_GREEK = {
    "alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "varepsilon": "ε", "epsilon": "ε",
    "kappa": "κ", "theta": "θ", "lambda": "λ", "mu": "μ", "pi": "π", "sigma": "σ",
    "tau": "τ", "varphi": "φ", "phi": "φ", "omega": "ω", "Gamma": "Γ", "Delta": "Δ",
    "cdot": "·", "cdots": "⋯", "dots": "…", "ldots": "…", "le": "≤", "leq": "≤", "ge": "≥",
    "geq": "≥", "to": "→", "times": "×", "infty": "∞", "circ": "∘", "in": "∈",
}
_SUP = dict(zip("0123456789+-=()nikj", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱᵏʲ", strict=True))
_SUB = dict(zip("0123456789+-=()aeijkmnrstux", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎ₐₑᵢⱼₖₘₙᵣₛₜᵤₓ", strict=True))
_INLINE_MATH = re.compile(r"\\\((.+?)\\\)|\$([^$]+)\$")


def _script(text: str, table: dict[str, str], mark: str) -> str:
    """``n`` as a superscript/subscript character where Unicode has one, else ``^n``/``_n``."""
    if all(ch in table for ch in text):
        return "".join(table[ch] for ch in text)
    return f"{mark}({text})" if len(text) > 1 else f"{mark}{text}"


def tex_to_text(tex: str) -> str:
    """Readable plain text for a bit of inline TeX: ``G^n`` -> ``Gⁿ``, ``\\beta_1`` -> ``β₁``."""
    out = re.sub(r"\\([A-Za-z]+)\s*", lambda m: _GREEK.get(m.group(1), ""), tex)
    out = re.sub(r"\\[,;:! ]", " ", out)
    for mark, table in (("^", _SUP), ("_", _SUB)):
        out = re.sub(
            re.escape(mark) + r"(?:\{([^{}]*)\}|(\S))",
            lambda m, t=table, k=mark: _script(m.group(1) or m.group(2), t, k),
            out,
        )
    return out.replace("{", "").replace("}", "").strip()


def plain_title(title: str) -> str:
    """A page title for the browser tab: inline math (``\\(…\\)`` or ``$…$``) as plain text."""
    return _INLINE_MATH.sub(lambda m: tex_to_text(m.group(1) or m.group(2)), title)


def _plain_tab_title(app, pagename, templatename, context, doctree):
    # after the theme's own handler (priority below): sphinx-book-theme prints the page title
    # as the first heading of a printed page (the handouts) from ``pagetitle``, which it fills
    # with the title's raw text ("G^n"); both become "Gⁿ"
    if context.get("title"):
        context["title"] = plain_title(context["title"])
        context["pagetitle"] = re.sub(r"<[^>]+>", "", context["title"])


def setup(app):
    # MathJax on every page: the navigation shows lecture titles with math on all of them
    app.set_html_assets_policy("always")
    app.connect("html-page-context", _plain_tab_title, priority=900)
